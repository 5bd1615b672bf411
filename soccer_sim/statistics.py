"""Per-team match statistics, collected by a recorder that observes the match loop.

* goals, kicks, shots and passes come from the event log;
* possession share: the share of the cycles in which the team's players touched the ball
  last, among the cycles in which anybody had (:mod:`soccer_sim.analysis.possession`, the
  definition replays use too);
* tackles, tackles won, fouls, yellow and red cards: from the event log (set plays, free kicks
  included, are counted by the match report);
* ignored commands: body commands sent but not executed (one per player and cycle, as
  rcssserver: tackle > catch > kick > move > dash);
* teammate contacts: new body contacts between two players of the team (the collision solver
  counts them; the role-assignment literature expects good assignment to avoid them);
* distance run: the sum over cycles of every player's displacement (m). Jumps longer than
  ``RELOCATION_FACTOR * player_speed_max`` in one cycle are the referee placing players
  (restarts, half time), not running, and are left out;
* plus whatever the team reports through the optional ``statistics()`` hook
  (:class:`~soccer_sim.team_hooks.ReportsStatistics`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.analysis.possession import Possession
from soccer_sim.kernels import add_distances
from soccer_sim.state import AWAY, HOME, EventKind
from soccer_sim.team import TeamError
from soccer_sim.team_hooks import ReportsStatistics

if TYPE_CHECKING:
    from soccer_sim.match import Match

RELOCATION_FACTOR = 3.0
"""A displacement above this many times the player speed limit in one cycle is a relocation."""


@dataclass
class TeamStatistics:
    """What one team did in a match (see the module docstring for definitions)."""

    goals: int = 0
    shots: int = 0
    """Kicks whose noiseless path crosses the opponents' goal line between the posts, plus every
    goal scored without such a kick (see the SHOT event in :mod:`soccer_sim.analysis.plays`)."""
    kicks: int = 0
    passes: int = 0
    """Kicks received by a team-mate (kick, body touch or catch) with no opponent touch between."""
    possession: float = 0.0
    """Share of the possession, in [0, 1]; the two teams' shares add up to 1 (0 if nobody touched the ball)."""
    teammate_contacts: int = 0
    distance_run: float = 0.0
    """Total over the team's players (m)."""
    tackles: int = 0
    """Tackles the team's players made (TACKLE events), successful or not."""
    tackles_won: int = 0
    """Tackles that reached the ball."""
    fouls: int = 0
    """Fouls called on the team's players (FOUL events)."""
    yellow_cards: int = 0
    red_cards: int = 0
    ignored_commands: int = 0
    """Body commands the team sent that were not executed: rcssserver executes one per player
    and cycle (tackle > catch > kick > move > dash; :func:`soccer_sim.kernels.one_body_command`)."""
    reported: dict[str, float] = field(default_factory=dict)
    """Figures the team reported itself (``Team.statistics()``), e.g. role switches."""

    def as_dict(self) -> dict[str, float]:
        """All figures in one flat dict (the team's own figures last)."""
        values: dict[str, float] = {
            "goals": self.goals, "shots": self.shots, "kicks": self.kicks, "passes": self.passes,
            "possession": self.possession, "teammate_contacts": self.teammate_contacts,
            "distance_run": self.distance_run, "tackles": self.tackles, "tackles_won": self.tackles_won,
            "fouls": self.fouls, "yellow_cards": self.yellow_cards,
            "red_cards": self.red_cards, "ignored_commands": self.ignored_commands,
        }
        values.update(self.reported)
        return values


class StatisticsRecorder:
    """Collects :class:`TeamStatistics` for both teams; ``result`` is set by ``on_end``."""

    def __init__(self) -> None:
        self.result: tuple[TeamStatistics, TeamStatistics] | None = None

    def on_start(self, match: Match) -> None:
        state = match.state
        self._n = state.sizes[0]
        """Home players: rows below it are home's."""
        self._relocation = RELOCATION_FACTOR * match.config.physics.player_speed_max
        self._previous = state.pos.copy()
        self._distance = np.zeros(state.pos.shape[0])
        self._possession = Possession(self._n)

    def on_cycle(self, match: Match) -> None:
        state = match.state
        add_distances(state.pos, self._previous, self._distance, self._relocation)
        self._possession.add(state.last_touch)

    def on_end(self, match: Match) -> None:
        events = match.events.as_arrays()
        kinds, teams, details = events["kind"], events["team"], events["detail"]
        tackles = kinds == EventKind.TACKLE
        n = self._n
        stats = []
        for team in (HOME, AWAY):
            mine = teams == team
            reported = _reported_figures(match.teams[team], match.team_names[team])
            stats.append(TeamStatistics(
                goals=int(match.state.score[team]),
                shots=int(np.count_nonzero(mine & (kinds == EventKind.SHOT))),
                kicks=int(np.count_nonzero(mine & (kinds == EventKind.KICK))),
                passes=int(np.count_nonzero(mine & (kinds == EventKind.PASS))),
                possession=self._possession.share(team),
                teammate_contacts=int(match.teammate_contacts[team]),
                distance_run=float((self._distance[:n] if team == HOME else self._distance[n:]).sum()),
                tackles=int(np.count_nonzero(mine & tackles)),
                tackles_won=int(np.count_nonzero(mine & tackles & (details % 2 == 1))),
                fouls=int(np.count_nonzero(mine & (kinds == EventKind.FOUL))),
                yellow_cards=int(np.count_nonzero(mine & (kinds == EventKind.YELLOW_CARD))),
                red_cards=int(np.count_nonzero(mine & (kinds == EventKind.RED_CARD))),
                ignored_commands=int(match.ignored_commands[team]),
                reported=reported,
            ))
        self.result = (stats[0], stats[1])


def _reported_figures(team: object, name: str) -> dict[str, float]:
    """The figures a :class:`ReportsStatistics` team reports (none for other teams), as floats;
    a TeamError naming the team if ``statistics()`` fails or reports something that is not a
    number."""
    if not isinstance(team, ReportsStatistics):
        return {}
    try:
        figures = team.statistics()
        return {str(key): float(value) for key, value in dict(figures).items()}
    except Exception as exc:
        raise TeamError(name, f"statistics() must return a dict of numbers; it failed with "
                              f"{type(exc).__name__}: {exc}") from exc
