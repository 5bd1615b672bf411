"""The hooks every judge receives, and their dispatch.

A judge applies one rule (offside, the goalkeeper's catch, the stuck ball, ...), as each of
rcssserver's ``Referee`` subclasses does (``OffsideRef``, ``CatchRef``, ``BallStuckRef``,
``FreeKickRef``, ``TouchRef``; its ``Stadium`` keeps them in one list and calls every one
at the same points). :class:`Judge` is that base class: every hook does nothing, and a
subclass overrides the hooks its rule needs. :class:`Hooks` calls, for each hook, only the
judges that override it, in the order they were given, so a rule costs nothing in the
cycles it does not look at.

Hooks and their rcssserver equivalents:

================== ===================== =====================================================
hook               rcssserver            when
================== ===================== =====================================================
kick_taken         ``kickTaken``         kicks applied this cycle (before the physics step)
ball_touched       ``ballTouched``       bodies touched the ball during the step (play on)
ball_caught        ``ballCaught``        a goalkeeper's catch succeeded
analyse            ``analyse``           end of a play-on cycle
play_mode_change   ``playModeChange``    after every play-mode switch
ball_placed        (``award*`` helpers)  a restart put the ball on its spot
ball_dropped       (``awardDropBall``)   a stuck ball was dropped where it lies (play goes on)
goal_scored        (``TouchRef`` goal)   a goal, before its GOAL event
half_time          (``TimeRef``)         the second half begins (same ends)
tackle_taken       ``tackleTaken``       a tackle pushed the ball (after the kick judges)
================== ===================== =====================================================

``kick_taken``, ``ball_touched`` and ``analyse`` return True when the judge stopped play (a
restart, or the ball out of the field): the judges after it do not see that event. A tackle
that pushes the ball is a kick to the ``kick_taken`` judges (rcssserver's judges treat
``tackleTaken`` as ``kickTaken``), and then ``tackle_taken`` lets the foul judge
(:mod:`soccer_sim.rules.fouls`) decide on fouls and cards.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from soccer_sim.state import PlayMode, WorldState

HOOKS = ("kick_taken", "ball_touched", "ball_caught", "analyse", "play_mode_change", "ball_placed",
         "ball_dropped", "goal_scored", "half_time", "tackle_taken")
"""The hook names, in the order of the table above."""


class Judge:
    """One rule of the game (rcssserver's ``Referee`` base class). Every hook does nothing;
    rows are player rows of the :class:`~soccer_sim.state.WorldState` (home first), sorted."""

    name = "judge"
    """Short name, for tests and messages."""

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        """``rows`` kicked the ball at (x, y) in ``mode`` (the play mode before the kick); the
        ball's velocity is the kick's. True: play was stopped (``kickTaken``)."""
        return False

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        """``rows`` touched the ball with their bodies in play on; it lies at (x, y). True:
        play was stopped (``ballTouched``)."""
        return False

    def ball_caught(self, state: WorldState, row: int, x: float, y: float) -> None:
        """The goalkeeper ``row`` caught the ball at (x, y) (``ballCaught``)."""

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        """End of a play-on cycle; the ball lay at (x, y) after the step. True: the ball is out
        of play for the rest of this cycle (``analyse``)."""
        return False

    def play_mode_change(self, state: WorldState, mode: PlayMode) -> None:
        """The play mode became ``mode`` (``playModeChange``)."""

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        """Play was interrupted and the ball put on (x, y): every pass, offside position and
        pending decision ends."""

    def ball_dropped(self, state: WorldState, x: float, y: float) -> None:
        """A stuck ball was dropped where it lies, (x, y); play goes on."""

    def goal_scored(self, state: WorldState, scorer: int, last_team: int, last_index: int) -> None:
        """``scorer`` scored; the last touch was ``last_index`` of ``last_team`` (NO_TEAM if
        nobody). Called before the score changes and the GOAL event is recorded."""

    def half_time(self, state: WorldState) -> None:
        """Half time: the second half is about to start (the teams keep their ends)."""

    def tackle_taken(self, state: WorldState, row: int, foul: bool, dashed: np.ndarray) -> None:
        """``row``'s tackle pushed the ball (``foul``: a foul tackle); ``dashed``: (P,) bool,
        which players dashed this cycle or the one before (``tackleTaken``)."""


def overrides(judge: Judge, hook: str) -> bool:
    """Whether ``judge``'s class overrides ``hook`` of :class:`Judge`."""
    return getattr(type(judge), hook) is not getattr(Judge, hook)


class Hooks:
    """The judges of one match and, per hook, the bound methods to call (only overriding
    judges, in order)."""

    def __init__(self, judges: Sequence[Judge] = ()) -> None:
        self.judges: list[Judge] = []
        self._calls: dict[str, tuple[Callable, ...]] = {}
        self.set(judges)

    def set(self, judges: Sequence[Judge]) -> None:
        """Replace the judges (in the order their hooks are called)."""
        self.judges = list(judges)
        self._calls = {hook: tuple(getattr(j, hook) for j in self.judges if overrides(j, hook)) for hook in HOOKS}
        self.kick_judges = self._calls["kick_taken"]
        self.touch_judges = self._calls["ball_touched"]
        self.analyse_judges = self._calls["analyse"]

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        """Call ``kick_taken`` until a judge stops play; whether one did."""
        for call in self.kick_judges:
            if call(state, rows, mode, x, y):
                return True
        return False

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        """Call ``ball_touched`` until a judge stops play; whether one did."""
        for call in self.touch_judges:
            if call(state, rows, x, y):
                return True
        return False

    def analyse(self, state: WorldState, x: float, y: float) -> None:
        """Call ``analyse`` until a judge puts the ball out of play."""
        for call in self.analyse_judges:
            if call(state, x, y):
                return

    def ball_caught(self, state: WorldState, row: int, x: float, y: float) -> None:
        for call in self._calls["ball_caught"]:
            call(state, row, x, y)

    def play_mode_change(self, state: WorldState, mode: PlayMode) -> None:
        for call in self._calls["play_mode_change"]:
            call(state, mode)

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        for call in self._calls["ball_placed"]:
            call(state, x, y)

    def ball_dropped(self, state: WorldState, x: float, y: float) -> None:
        for call in self._calls["ball_dropped"]:
            call(state, x, y)

    def goal_scored(self, state: WorldState, scorer: int, last_team: int, last_index: int) -> None:
        for call in self._calls["goal_scored"]:
            call(state, scorer, last_team, last_index)

    def half_time(self, state: WorldState) -> None:
        for call in self._calls["half_time"]:
            call(state)

    def tackle_taken(self, state: WorldState, row: int, foul: bool, dashed: np.ndarray) -> None:
        for call in self._calls["tackle_taken"]:
            call(state, row, foul, dashed)
