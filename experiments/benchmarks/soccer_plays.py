"""Passes and shots as a game log shows them, one definition for a live match and a log.

soccer-sim's own PASS and SHOT events (:mod:`soccer_sim.analysis.plays`) need what a game
log does not hold (the ball's velocity at the kick, before it moved and was perturbed). So
that ``bench soccer`` can set passes and shots beside a real server's, :class:`PlayFigures`
counts them from what a show line does hold, fed per cycle by both sources: which players
kicked, caught, won a tackle or had the ball bounce off their body in the cycle, the ball
after the cycle (log frame: home attacks +x) and whether play is on. These are the
definitions of the reference kit's ``rcg_stats.py``, with which the real server's figures
were first measured:

* a **play** is a kick, a catch or a won tackle; **pass (kick to kick)**: a play by a
  player of the team that played the ball last by a kick or a tackle, by a different
  player, with nothing in between that ends it: a cycle in which several players played
  the ball, a catch (it ends the chain), the ball bouncing off an opponent, or a stoppage
  (a cycle not in play on);
* **shot (ball path)**: a kick, the only play of its cycle, after which the ball (as it is
  after the cycle: moved once, decayed once, noise included) rolling on unhindered,
  decaying geometrically, takes its centre over the opponents' goal line plus a ball
  radius between the posts.
"""

from __future__ import annotations

import numpy as np

NOBODY = -1


class PlayFigures:
    """Counts passes and shots over a match (see the module docstring). ``team``: (P,) each
    row's team (0 home, attacking +x in the log frame; 1 away). ``half_length``, ``goal_width``,
    ``ball_radius``: the pitch (m); ``ball_decay``: the ball's speed kept per cycle."""

    def __init__(self, team: np.ndarray, half_length: float, goal_width: float, ball_radius: float,
                 ball_decay: float) -> None:
        self.team = np.asarray(team, dtype=np.intp)
        self.goal_line = half_length + ball_radius
        self.post = goal_width / 2.0
        self.reach = 1.0 / (1.0 - ball_decay) if ball_decay < 1.0 else np.inf
        self.passes = 0
        self.shots = 0
        self.team_passes = [0, 0]
        """Passes of home and away (together :attr:`passes`)."""
        self.team_shots = [0, 0]
        """Shots of home and away (together :attr:`shots`)."""
        self._last = NOBODY
        """Row of the player whose kick or tackle the ball comes from, or NOBODY."""

    def add(self, kicks: np.ndarray, catches: np.ndarray, tackles: np.ndarray, touches: np.ndarray,
            ball: np.ndarray, play_on: bool) -> None:
        """One cycle: the rows that kicked, caught, won a tackle and had the ball bounce off
        them; the ball (x, y, vx, vy) after the cycle; whether play is on."""
        if not play_on:
            self._last = NOBODY
            return
        plays = np.unique(np.concatenate((kicks, catches, tackles))).astype(np.intp)
        if plays.size == 1:
            row = int(plays[0])
            last = self._last
            if last != NOBODY and last != row and self.team[last] == self.team[row]:
                self.passes += 1
                self.team_passes[int(self.team[row])] += 1
            caught = row in set(np.asarray(catches).tolist())
            self._last = NOBODY if caught else row
            if not caught and row in set(np.asarray(kicks).tolist()) and self.is_shot(int(self.team[row]), ball):
                self.shots += 1
                self.team_shots[int(self.team[row])] += 1
        elif plays.size > 1:
            self._last = NOBODY
        elif self._last != NOBODY and np.any(self.team[np.asarray(touches, dtype=np.intp)] != self.team[self._last]):
            self._last = NOBODY

    def is_shot(self, team: int, ball: np.ndarray) -> bool:
        """Whether the ball (x, y, vx, vy), rolling on unhindered, crosses the goal line that
        ``team`` attacks (+x for home) between the posts."""
        x, y, vx, vy = (float(v) for v in ball)
        sign = 1.0 if team == 0 else -1.0
        if vx * sign <= 0.0:
            return False
        t = (sign * self.goal_line - x) / vx  # path still to roll, in units of the velocity
        return 0.0 <= t < self.reach and abs(y + t * vy) < self.post

    def figures(self) -> dict[str, float]:
        return {"passes (kick to kick)": float(self.passes), "shots (ball path)": float(self.shots)}
