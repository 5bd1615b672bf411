"""The rules of the game: a play-mode state machine and one judge per rule, as rcssserver's
``Stadium`` and its ``Referee`` subclasses.

* :mod:`~soccer_sim.rules.judge`: the hooks every judge receives (:class:`Judge`) and their
  dispatch (:class:`Hooks`);
* :mod:`~soccer_sim.rules.play_modes`: set plays, restarts, kick-offs, the pause after a goal,
  half time and time over (:class:`PlayModes`);
* the judges: :mod:`~soccer_sim.rules.restarts` (goals, the ball out, the last touch),
  :mod:`~soccer_sim.rules.offside`, :mod:`~soccer_sim.rules.goal_kick`,
  :mod:`~soccer_sim.rules.goalkeeper` (catch, hold, back pass),
  :mod:`~soccer_sim.rules.stuck_ball`, :mod:`~soccer_sim.rules.fouls` (fouls, cards, players
  sent off);
* :mod:`~soccer_sim.rules.spots`: where restarts are taken and how players are moved away.

:class:`soccer_sim.referee.Referee` puts them together for the match loop.
"""

from soccer_sim.rules.fouls import FoulJudge
from soccer_sim.rules.goal_kick import GoalKickJudge
from soccer_sim.rules.goalkeeper import GoalkeeperJudge
from soccer_sim.rules.judge import HOOKS, Hooks, Judge
from soccer_sim.rules.offside import OffsideJudge, mark_offside_positions
from soccer_sim.rules.play_modes import PlayModes
from soccer_sim.rules.restarts import BallOutJudge, TouchJudge
from soccer_sim.rules.stuck_ball import BallStuckJudge

__all__ = ["HOOKS", "BallOutJudge", "BallStuckJudge", "FoulJudge", "GoalKickJudge", "GoalkeeperJudge", "Hooks", "Judge",
           "OffsideJudge", "PlayModes", "TouchJudge", "mark_offside_positions"]
