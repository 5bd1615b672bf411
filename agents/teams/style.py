"""How a built-in team plays, apart from its role assigner: :class:`TeamStyle`."""

from __future__ import annotations

from dataclasses import dataclass, field

from agents import skills
from agents.skills.tackling import TackleParams
from agents.teams.looking import LookParams
from agents.teams.routines import RoutineParams
from agents.teams.shape import ShapeParams

ATTACKING_DECISIONS = skills.DecisionParams(
    shot=skills.ShotParams(threshold=0.2, lane_range=22.0, lane_pressure=6),
    dribbling=skills.DribbleParams(goal_weight=2.0, speed_fraction=0.85),
)
"""The built-in team's on-ball choices: shoot when a shot has a fair chance (the skill's own
threshold waits for a near-certain one, which against a goalkeeper almost never comes), or
from the edge of the box (22 m from the goal centre: the penalty area's depth plus a few
metres) through a lane no outfield defender can close, once a defender can close the shooter
down within 6 cycles (the decision's pressure horizon doubled), so the goalkeeper must save,
as real teams do (about nine shots a match); a shooter left alone carries the ball closer.
Dribble towards the goal rather than along the wings."""


@dataclass(frozen=True)
class TeamStyle:
    """How a team plays, apart from its role assigner."""

    system: str = "4-3-3"
    """Built-in formation set (``formations.builtin_names()``)."""
    depth: float = 0.0
    """Metres the outfield block is shifted towards the opponents' goal in open play (negative:
    a deeper block)."""
    attack_push: float = 14.0
    """Extra metres the outfield block moves up when we attack (win the race for the ball), at
    the pace :mod:`agents.teams.shape` allows; the back line stays behind as the rest defence."""
    box_narrowing: float = 0.5
    """When we attack with the ball in the final third, the forwards' targets move this share
    of the way towards the middle of the field (so that there are players in the box)."""
    pressers: int = 1
    """Players sent at the ball when the opponents win the race (1: just the fastest)."""
    decision: skills.DecisionParams = field(default_factory=lambda: ATTACKING_DECISIONS)
    """Thresholds of the on-ball decision (shoot, pass, dribble, clear)."""
    offside_margin: float = 1.0
    """Attackers without the ball stay this far behind the offside line (m)."""
    set_play_wait: int = 15
    """Cycles our set-play taker waits before kicking, so the others can take their places."""
    stationary: bool = False
    """Outfield players hold their kick-off spots and only kick a ball that comes to them (the
    baseline against which positioning is measured)."""
    shape: ShapeParams = field(default_factory=ShapeParams)
    """How the team keeps its shape in open play: the attack/defend switch's hysteresis, the
    pace of the block, rest defence, support and follow-up (:mod:`agents.teams.shape`)."""
    unfilled_distance: float = 10.0
    """A role counts as unfilled while the player assigned to it is farther than this (m)."""
    routines: RoutineParams = field(default_factory=RoutineParams)
    """Our corner-kick and kick-in routines (box runners, the short option, crosses, the ball
    down the line; :mod:`agents.teams.routines`)."""
    tackling: TackleParams = field(default_factory=TackleParams)
    """When our players tackle an opponent on the ball, where they push it, and whether they
    ever foul on purpose (:mod:`agents.skills.tackling`)."""
    agreement: str = "settled"
    """How the players agree on the role assignment under partial observation
    (:data:`agents.teams.speaking.AGREEMENTS`: ``"settled"``, ``"speaker"`` or ``"own"``). Default
    ``"settled"``: believed role conflicts in under 0.5 % of play-on cycles against 20-25 %
    for ``"own"``, and a fifth of the team-mate contacts of the other two (docs/results.md,
    "Agreement on the role assignment")."""
    shared_assignment: bool = False
    """Under partial observation, every player follows one assignment, computed on one belief
    (the first outfield player's) and known to all at once without a word: perfect agreement,
    the ablation that takes the cost of disagreement out (``soccer-sim experiment ablation``).
    A team that plays so no longer decides per player; under full observation it changes
    nothing (every player believes the truth)."""
    goalkeeper_goal_kicks: bool = True
    """Our goalkeeper takes our goal kicks (as in real play; an outfield player when the
    goalkeeper's attempt was retaken, or when there is none)."""
    ball_role: str = "keep"
    """Whether the player who goes for the ball keeps its role in the matching (``"keep"``) or
    leaves it to the others (``"leave"``: the other players take the roles that matter most;
    :mod:`agents.teams.ball_role`). Default ``"keep"``: in 144 matches (``mmdr``,
    ``mmd+msd2`` and ``static`` with each setting against the three reference opponents, 8
    per pairing) the settings' goal differences did not differ beyond their errors (leave
    minus keep -0.6 to +0.8 per pairing, SE about 0.5), while ``"leave"`` made roles change
    four times as often (about 310 against 70-80 switches a minute; ``static`` 171 against 0)
    without lowering the share of unfilled role-time (0.56-0.60 either way). ``"keep"`` is
    also the problem the assigners were designed for (all players to all roles); the
    ``<assigner>-leave`` teams measure the other setting."""
    scans: bool = False
    """Under partial observation our players choose where to look, turning their necks as
    helios-base's do (the ball when their belief of it is stale or it is near, else the field
    they have seen least recently; :mod:`agents.teams.looking`). False: they never turn their
    necks and look along their bodies, which face the ball."""
    looking: LookParams = field(default_factory=LookParams)
    """How the players choose where to look when ``scans`` is on."""
