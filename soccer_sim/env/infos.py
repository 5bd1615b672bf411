"""The environment's ``infos``: numbers and fixed-shape arrays only, and the episode's statistics.

Every agent's info holds, at every step (reset included), the same keys with the same shapes,
so libraries that build specs from the first info (TorchRL) or stack infos across environments
(Tianshou) take them as they are:

======================  ===============  ==================================================================
key                     value            what
======================  ===============  ==================================================================
``play_mode``           int              the play mode after the step, a code of :data:`PLAY_MODE_NAMES`
``cycle``               int              cycles played
``score``               int64 (2,)       goals (home, away); home is the ``left`` side
``events``              int64 (17,)      events of the step, counted per kind (:data:`EVENT_KIND_NAMES`)
``episode_goals``       int64 (2,)       (home, away) goals so far in the episode
``episode_shots``       int64 (2,)       shots so far (SHOT events: kicks on target, see ``EventKind``)
``episode_passes``      int64 (2,)       passes received so far (PASS events)
``episode_possession``  float32 (2,)     possession shares so far (:mod:`soccer_sim.analysis.possession`)
``action_mask``         int8 (A,)        high-level action mode only, unless ``action_mask_in_observation`` puts it in the
                                         observation instead: 1 where the action can be taken
======================  ===============  ==================================================================

The ``episode_*`` values of the last step are the episode's statistics. With
``event_texts=True`` each info also holds ``play_mode_name`` (str) and ``event_texts`` (a list
of the step's events as text, as the match report words them): readable, but not for
libraries that need fixed shapes. The arrays are read-only and shared by the agents' infos.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from soccer_sim.analysis.possession import Possession
from soccer_sim.state import EventKind, PlayMode

PLAY_MODE_NAMES = tuple(mode.name.lower() for mode in PlayMode)
"""``play_mode`` code -> name: 0 play_on, 1 kick_off, 2 kick_in, 3 corner_kick, 4 goal_kick,
5 free_kick, 6 goalie_holds, 7 time_over, 8 after_goal."""
EVENT_KIND_NAMES = tuple(kind.name.lower() for kind in EventKind)
"""Index of ``events`` -> event kind: 0 kick, 1 pass, 2 shot, 3 goal, 4 catch, 5 out, 6 set_play,
7 offside, 8 drop_ball, 9 half_time, 10 time_over, 11 touch, 12 back_pass, 13 tackle, 14 foul,
15 yellow_card, 16 red_card."""
KINDS = len(EventKind)
_SHOT, _PASS = int(EventKind.SHOT), int(EventKind.PASS)


def _frozen(array: np.ndarray) -> np.ndarray:
    array.flags.writeable = False
    return array


class EpisodeInfo:
    """Counts an episode's events and possession step by step and builds the numeric infos."""

    def __init__(self, home_players: int, event_texts: bool = False) -> None:
        self.event_texts = event_texts
        self._possession = Possession(home_players)
        self._by_team = np.zeros((2, KINDS), dtype=np.int64)
        self.counts = np.zeros(KINDS, dtype=np.int64)
        """The last step's events per kind."""
        self._texts: list[str] = []

    def update(self, match: Any, start: int) -> None:
        """Count the match's events from index ``start`` on (the step's) and the step's possession."""
        log = match.events
        stop = len(log)
        self.counts = np.zeros(KINDS, dtype=np.int64)
        if stop > start:
            kinds = np.array(log.kind[start:stop], dtype=np.int64)
            teams = np.array(log.team[start:stop], dtype=np.int64)
            self.counts = np.bincount(kinds, minlength=KINDS)
            mine = teams >= 0
            np.add.at(self._by_team, (teams[mine], kinds[mine]), 1)
        self._possession.add(match.state.last_touch)
        if self.event_texts:
            from soccer_sim.analysis.events import describe_event

            names = match.team_names
            self._texts = [describe_event(names, log.kind[k], log.team[k], log.player[k], log.x[k], log.y[k],
                                          log.detail[k]) for k in range(start, stop)]

    def info(self, state: Any) -> dict[str, Any]:
        """The info every agent shares for the world ``state`` after the last :meth:`update`."""
        cycles = self._possession.cycles
        total = cycles[0] + cycles[1]
        share = np.array(cycles, dtype=np.float32) / total if total else np.zeros(2, dtype=np.float32)
        info: dict[str, Any] = {
            "play_mode": int(state.play_mode), "cycle": int(state.cycle),
            "score": _frozen(state.score.astype(np.int64)), "events": _frozen(self.counts),
            "episode_goals": _frozen(state.score.astype(np.int64)),
            "episode_shots": _frozen(self._by_team[:, _SHOT].copy()),
            "episode_passes": _frozen(self._by_team[:, _PASS].copy()),
            "episode_possession": _frozen(share),
        }
        if self.event_texts:
            info["play_mode_name"] = PLAY_MODE_NAMES[int(state.play_mode)]
            info["event_texts"] = list(self._texts)
        return info
