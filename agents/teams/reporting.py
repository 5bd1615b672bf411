"""The built-in team's per-match figures of its role assignment (what
:meth:`FormationTeam.statistics <agents.teams.formation_team.FormationTeam.statistics>`
reports)."""

from __future__ import annotations

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.team_hooks import Drawing


class RoleFigures:
    """Role switches and the outfield players' distances to their role targets, summed over
    the cycles of play on (see :meth:`statistics`)."""

    def __init__(self, config: MatchConfig, roles: int) -> None:
        self.cycles_per_minute = 60.0 / config.physics.cycle_seconds
        """Cycles in a minute of game time."""
        self.roles = roles
        """Outfield roles filled (the players assigned)."""
        self.cycles = 0
        self.switches = 0
        self.distance_sum = 0.0
        self.makespan_sum = 0.0
        self.unfilled_role_cycles = 0
        self.samples = 0
        """Cycles sampled for the mechanism figures (:mod:`agents.teams.mechanism`)."""
        self.fixed_optimal = self.held_optimal = 0
        self.gap_sum = self.held_gap_sum = 0.0

    def add(self, switches: int, measured: bool, mean: float, largest: float, unfilled: int) -> None:
        """One cycle's figures: role switches (counted in every play mode) and, for a
        ``measured`` cycle of play on, the mean and the largest distance from a player to its
        role's target and the number of roles left unfilled."""
        self.switches += switches
        if measured:
            self.cycles += 1
            self.distance_sum += mean
            self.makespan_sum += largest
            self.unfilled_role_cycles += unfilled

    def add_sample(self, fixed: float, held: float, minimal: float) -> None:
        """One sampled cycle of :mod:`agents.teams.mechanism`: the makespans (m) of the fixed
        shirt-number roles, of the roles held at the previous cycle, and the minimal one."""
        self.samples += 1
        self.fixed_optimal += fixed <= minimal
        self.gap_sum += fixed - minimal
        self.held_optimal += held <= minimal
        self.held_gap_sum += held - minimal

    def statistics(self) -> dict[str, float]:
        """Role switches per minute of play, the mean and the largest distance from the
        outfield players to their role targets (averaged over cycles: the largest is the
        assignment's makespan), the share of role-cycles a role was unfilled, and over the
        sampled cycles the share in which fixed (and held) roles already had the minimal
        makespan and the mean makespan gap (m; :mod:`agents.teams.mechanism`)."""
        cycles = max(self.cycles, 1)
        samples = max(self.samples, 1)
        roles = max(self.roles, 1)
        return {
            "role_switches_per_minute": self.switches / max(self.cycles / self.cycles_per_minute, 1e-9)
            if self.cycles else 0.0,
            "target_distance_mean": self.distance_sum / cycles,
            "target_distance_max": self.makespan_sum / cycles,
            "role_unfilled_share": self.unfilled_role_cycles / (cycles * roles),
            "fixed_roles_optimal_share": self.fixed_optimal / samples,
            "makespan_gap": self.gap_sum / samples,
            "held_roles_optimal_share": self.held_optimal / samples,
            "held_makespan_gap": self.held_gap_sum / samples,
        }


def team_drawing(formation, targets: np.ndarray, outfield_roles, goals: np.ndarray, outfield: np.ndarray,
                 role_of_player: np.ndarray | None) -> Drawing:
    """What a replay may draw for the built-in team (team frame): each role's target
    (``targets``), where each player is going (``goals``), the outfield players with their roles
    and role targets (None before the first assignment), and the ``formation``'s sample balls
    and triangles. ``outfield_roles``: the rows of ``targets`` the outfield roles take."""
    assigned = None if role_of_player is None else targets[outfield_roles][role_of_player]
    return Drawing(targets=targets.copy(), goals=goals.copy(), outfield=outfield.copy(),
                   role_of_player=None if role_of_player is None else role_of_player.copy(),
                   assigned_targets=assigned, formation_balls=formation.balls,
                   formation_triangles=formation.triangles)
