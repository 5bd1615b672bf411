"""PASS and SHOT: what the players did with the ball, derived from kicks, touches and catches.

These are not rules (nothing is judged), so they live outside :mod:`soccer_sim.rules`; but
they follow the same hooks (:class:`~soccer_sim.rules.judge.Judge`), and the referee lists
:class:`PlayAnalysis` among its judges so that the event log records them as play happens.

* **PASS** (team/player = passer, detail = receiver index): a pass begins with a kick (a
  ball bouncing off one player's body to a team-mate is not a pass) and is received by a
  team-mate's kick, body touch or catch; a touch by anyone but the passer ends it, and so
  does any restart or dropped ball.
* **SHOT** (the first kicker of the shooting team, detail 0; it also has its KICK event): a
  kick whose unhindered path (decaying geometrically) takes the whole ball over the
  opponents' goal line between the posts.
* **Every goal is a shot**: a goal not preceded by a SHOT of the scoring team since the
  opponents last played the ball (a kick whose noiseless path fell short or wide but the
  ball's noise carried it in, or a goal off a body) records a SHOT with detail 1 in the
  goal's cycle, just before the GOAL, for the scorer, at the spot where its team last played
  the ball.

Event positions are the ball's, absolute frame.
"""

from __future__ import annotations

import math

from soccer_sim.config import MatchConfig
from soccer_sim.rules.judge import Judge
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventKind, EventLog, PlayMode, WorldState


class PlayAnalysis(Judge):
    """Records PASS and SHOT events; ``n`` is the number of home players (home rows first)."""

    name = "plays"

    def __init__(self, config: MatchConfig, events: EventLog, n: int) -> None:
        self.events = events
        self._n = n
        p, f = config.physics, config.field
        self._goal_x = f.half_length + p.ball_radius  # whole ball beyond the goal line
        self._post_y = f.goal_width / 2.0
        self._shot_reach = 1.0 / (1.0 - p.ball_decay) if p.ball_decay < 1.0 else math.inf
        """How far (in units of the kick velocity) an unhindered ball travels."""
        self._pass_from = NO_PLAYER
        """Row of the player whose kick the ball is travelling from, or NO_PLAYER."""
        self._shot_pending = [False, False]
        """Per team: its latest kick was a SHOT and the opponents have not played the ball since."""
        self._play_spot = [(math.nan, math.nan), (math.nan, math.nan)]
        """Per team: where the ball was when the team last played it (kick, touch or catch)."""

    def passer(self) -> int:
        """Row of the player whose kick the ball is travelling from, or NO_PLAYER (for the
        back-pass rule)."""
        return self._pass_from

    # ------------------------------------------------------------------ hooks

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        n = self._n
        self._played(state, rows, state.last_touch, x, y, kicked=True)
        teams = sorted({HOME if row < n else AWAY for row in rows})
        for team in teams:
            shot = self.is_shot(state, team, x, y)
            self._shot_pending[team] = shot
            if shot:
                shooter = next(r for r in rows if (HOME if r < n else AWAY) == team)
                self.events.add(state.cycle, EventKind.SHOT, team, shooter - team * n, x, y, 0)
        return False

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        self._played(state, rows, state.last_touch, x, y)
        return False

    def ball_caught(self, state: WorldState, row: int, x: float, y: float) -> None:
        self._played(state, [row], row, x, y)

    def goal_scored(self, state: WorldState, scorer: int, last_team: int, last_index: int) -> None:
        """The SHOT (detail 1) of a goal no SHOT announced."""
        if last_team == scorer and not self._shot_pending[scorer]:
            sx, sy = self._play_spot[scorer]
            self.events.add(state.cycle, EventKind.SHOT, scorer, last_index, sx, sy, 1)

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        self._pass_from = NO_PLAYER
        self._shot_pending = [False, False]

    def ball_dropped(self, state: WorldState, x: float, y: float) -> None:
        self._pass_from = NO_PLAYER

    # ------------------------------------------------------------------ definitions

    def is_shot(self, state: WorldState, team: int, bx: float, by: float) -> bool:
        """Whether the ball at (bx, by), with its current velocity and unhindered (decaying
        geometrically), takes the whole ball over the goal line of ``team``'s opponents
        between the posts."""
        direction = state.attack_direction(team)
        vx, vy = float(state.ball_vel[0]), float(state.ball_vel[1])
        if direction * vx <= 0.0:
            return False
        t = (direction * self._goal_x - bx) / vx  # path parameter, in units of the kick velocity
        if t < 0.0 or t >= self._shot_reach:
            return False
        return abs(by + t * vy) < self._post_y

    def _played(self, state: WorldState, rows: list[int], main: int, x: float, y: float, *,
                kicked: bool = False) -> None:
        """``rows`` (sorted) played the ball together at (x, y) this cycle (``kicked``: by a kick,
        else by a body touch or a catch), ``main`` (one of them if possible) counting as the
        player now on the ball. A PASS event if the ball comes from the kick of a team-mate of
        ``main`` that is not among ``rows``. A kick can start the next pass; a touch by anyone
        but the passer ends the pass. The opponents of the players in ``rows`` lose their
        pending shot."""
        if main not in rows:
            main = rows[0]
        prev = self._pass_from
        n = self._n
        if prev != NO_PLAYER and prev not in rows and (prev < n) == (main < n):
            team = HOME if main < n else AWAY
            self.events.add(state.cycle, EventKind.PASS, team, prev - team * n, x, y, main - team * n)
        if kicked:
            self._pass_from = main
        elif prev not in rows:
            self._pass_from = NO_PLAYER
        involved = (rows[0] < n, rows[-1] >= n)  # home / away players among rows (sorted)
        for team in (HOME, AWAY):
            if involved[team]:
                self._play_spot[team] = (x, y)
                self._shot_pending[1 - team] = False
