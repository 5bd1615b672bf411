"""The per-cycle figures of ``bench soccer``, one definition for a live match and a game log.

:class:`CycleFigures` is fed one cycle at a time with what both a running match and an
rcssserver game log (``.rcg``) show: every player's position, the ball, every player's
stamina, which players are outfield players of which team, whether play is on, and
(optionally) each player's role label. Positions are in the game log's frame, in which the
home (left) team attacks +x in both halves; a live match turns its positions into that
frame first (:func:`log_frame`), so that the two sources measure the same thing.

Definitions (m; a cycle is 0.1 s):

* **distance run**: the sum over cycles of each player's displacement; a displacement above
  ``relocation`` in one cycle is the referee placing the player (restarts, half time) and is
  left out (the rule of :mod:`soccer_sim.statistics`). Per team, and per role label (the
  label the player had in that cycle), the latter scaled to one player over the whole match:
  distance with the label / player-cycles with the label x cycles.
* the rest counts **play-on cycles** only (set plays are stoppages):
  * **team length / width**: the extent in x / y (max - min) of a team's outfield players,
    the mean over cycles and over both teams; also over the cycles with the ball in
    midfield (``|ball x| < MIDFIELD_HALF_LENGTH``);
  * **stamina**: the share of outfield player-cycles with stamina below ``low_stamina``
    (rcssserver caps a dash below 100) and below the recovery threshold
    (``recover_dec_thr x stamina_max``: below it the server lowers the player's recovery);
  * **place by role label**: the mean x (m, towards the opponents' goal, 0 at the halfway
    line) and the mean |y| (m from the long axis) of the players holding that label;
  * **players near the ball**: the mean number of players (both teams) within
    ``CROWD_RADIUS`` of the ball (scrums: well-spaced teams keep it near 1-2).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from soccer_sim.config import STANDARD_FIELD

CROWD_RADIUS = 2.0
"""Players whose centre is within this distance of the ball's centre count as near it (m)."""
MIDFIELD_HALF_LENGTH = STANDARD_FIELD.length / 6.0
"""The ball is in midfield while ``|x|`` is below this (m): the middle third of rcssserver's pitch
(the simulator's default field)."""
LOW_STAMINA = 100.0
"""Stamina below which rcssserver caps a dash's power (the player is out of stamina)."""


def log_frame(pos: np.ndarray, home_attacks: int) -> np.ndarray:
    """Positions (or vectors) of soccer-sim's absolute frame in the game log's frame, where
    home attacks +x in both halves (the y axis flipped, as :mod:`soccer_sim.rcg.mapping` says)."""
    return pos * np.array([float(home_attacks), -float(home_attacks)])


class CycleFigures:
    """Accumulates the per-cycle figures of one match (see the module docstring).

    ``team``: (P,) each player row's team (0 home, 1 away). ``relocation``: the largest
    displacement in one cycle that counts as running (m). ``recovery_threshold``: the stamina
    below which recovery falls."""

    def __init__(self, team: np.ndarray, relocation: float, recovery_threshold: float) -> None:
        self.team = np.asarray(team, dtype=np.intp)
        self.relocation = float(relocation)
        self.recovery_threshold = float(recovery_threshold)
        players = self.team.size
        self._previous: np.ndarray | None = None
        self.cycles = 0
        self.distance = np.zeros(2)
        self.label_distance: dict[str, float] = {}
        self.label_cycles: dict[str, int] = {}
        self.label_place: dict[str, list[float]] = {}  # label -> [sum of x towards attack, sum of |y|, cycles]
        self.play_on = 0
        self.near = 0
        self.extent = np.zeros((2, 2))  # [all cycles, midfield cycles] x [length, width], summed over teams
        self.extent_count = np.zeros(2)
        self.stamina_cycles = 0
        self.below_low = 0
        self.below_threshold = 0
        self._team_rows = [np.flatnonzero(self.team == t) for t in (0, 1)]
        self._steps = np.zeros(players)

    def start(self, pos: np.ndarray) -> None:
        """The positions the match starts from (not a cycle played)."""
        self._previous = np.array(pos, dtype=float)

    def add(self, pos: np.ndarray, ball: np.ndarray, stamina: np.ndarray, outfield: np.ndarray, play_on: bool,
            labels: Sequence[str | None] | None = None) -> None:
        """One cycle: ``pos`` (P, 2) and ``ball`` (2,) in the log frame, ``stamina`` (P,),
        ``outfield`` (P,) True for a present outfield player, ``labels``: each row's role label
        (None, or a None entry: not known)."""
        pos = np.asarray(pos, dtype=float)
        if self._previous is None:
            self._previous = pos.copy()
        offset = pos - self._previous
        steps = np.sqrt(np.einsum("ij,ij->i", offset, offset))
        steps[steps > self.relocation] = 0.0
        self.distance += np.bincount(self.team, weights=steps, minlength=2)
        self._previous = pos.copy()
        self.cycles += 1
        if labels is not None:
            distance, cycles = self.label_distance, self.label_cycles
            for label, step in zip(labels, steps.tolist()):
                if label is not None:
                    distance[label] = distance.get(label, 0.0) + step
                    cycles[label] = cycles.get(label, 0) + 1
        if not play_on:
            return
        self.play_on += 1
        if labels is not None:
            place = self.label_place
            forward = np.where(self.team == 0, pos[:, 0], -pos[:, 0]).tolist()  # the home team attacks +x
            for label, x, y in zip(labels, forward, np.abs(pos[:, 1]).tolist()):
                if label is not None:
                    sums = place.setdefault(label, [0.0, 0.0, 0])
                    sums[0] += x
                    sums[1] += y
                    sums[2] += 1
        near = pos - ball
        self.near += int(np.count_nonzero(np.einsum("ij,ij->i", near, near) <= CROWD_RADIUS ** 2))
        midfield = abs(float(ball[0])) < MIDFIELD_HALF_LENGTH
        for rows in self._team_rows:
            players = pos[rows[outfield[rows]]]
            if len(players) < 2:
                continue
            extent = players.max(axis=0) - players.min(axis=0)
            self.extent[0] += extent
            self.extent_count[0] += 1
            if midfield:
                self.extent[1] += extent
                self.extent_count[1] += 1
        energy = stamina[outfield]
        self.stamina_cycles += energy.size
        self.below_low += int(np.count_nonzero(energy < LOW_STAMINA))
        self.below_threshold += int(np.count_nonzero(energy < self.recovery_threshold))

    def figures(self) -> dict[str, float | None]:
        """The figures by name (None: nothing to measure, e.g. no play-on cycle)."""
        def ratio(a: float, b: float, scale: float = 1.0) -> float | None:
            return a / b * scale if b else None

        out: dict[str, float | None] = {
            "distance run per team (km)": float(self.distance.mean()) / 1000.0,
            "team length (m)": ratio(self.extent[0, 0], self.extent_count[0]),
            "team width (m)": ratio(self.extent[0, 1], self.extent_count[0]),
            "team length, ball in midfield (m)": ratio(self.extent[1, 0], self.extent_count[1]),
            "team width, ball in midfield (m)": ratio(self.extent[1, 1], self.extent_count[1]),
            "outfield stamina below 100 (%)": ratio(self.below_low, self.stamina_cycles, 100.0),
            "outfield stamina below recovery threshold (%)": ratio(self.below_threshold, self.stamina_cycles, 100.0),
            "players within 2 m of the ball": ratio(self.near, self.play_on) or 0.0,
        }
        return out

    def role_distances(self, groups: Mapping[str, str] | None = None) -> dict[str, float]:
        """Per role label: km run by one player holding that role for the whole match.
        ``groups`` (label -> group, e.g. a position's role kind): per group instead, over
        the labels it maps (labels it does not map are left out)."""
        distance: dict[str, float] = {}
        cycles: dict[str, int] = {}
        for label, count in self.label_cycles.items():
            key = label if groups is None else groups.get(label)
            if key is not None:
                distance[key] = distance.get(key, 0.0) + self.label_distance[label]
                cycles[key] = cycles.get(key, 0) + count
        return {key: distance[key] / count * self.cycles / 1000.0 for key, count in sorted(cycles.items()) if count}

    def role_places(self, groups: Mapping[str, str] | None = None) -> dict[str, tuple[float, float]]:
        """Per role label (or per group, as :meth:`role_distances`): the mean x towards the
        opponents' goal and the mean |y| (m) of its players over the play-on cycles."""
        sums: dict[str, list[float]] = {}
        for label, (x, y, count) in self.label_place.items():
            key = label if groups is None else groups.get(label)
            if key is not None:
                total = sums.setdefault(key, [0.0, 0.0, 0])
                total[0] += x
                total[1] += y
                total[2] += count
        return {key: (x / count, y / count) for key, (x, y, count) in sorted(sums.items()) if count}
