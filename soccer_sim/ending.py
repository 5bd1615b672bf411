"""When a match, or an environment's episode, ends: decided here and nowhere else.

A match ends in one of three ways:

* **time**: after ``end_cycle`` cycles (the configuration's length, ``MatchConfig.total_cycles``,
  cut short by a scenario's ``cycle_limit``); the referee calls TIME_OVER in the last cycle
  (:meth:`MatchEnd.clock`, which also calls half time);
* **a scenario's end condition** (``Scenario.end_on``), judged on the events of the cycle
  (:meth:`MatchEnd.condition_met`); the match loop then has the referee stop play;
* an environment's episode may also end at the first goal (``end_on_goal``, *terminated*) or
  after its own step limit (*truncated*) (:meth:`MatchEnd.episode_end`).

The referee, the match loop, :meth:`soccer_sim.match.Match.finish` and the environment all ask
the :class:`MatchEnd` of their :class:`~soccer_sim.setup.MatchSetup`.
"""

from __future__ import annotations

from dataclasses import dataclass

from soccer_sim.state import EventKind, EventLog, PlayMode, WorldState

CLOCK_RUNS = 0
""":meth:`MatchEnd.clock`: nothing is due."""
HALF_TIME_DUE = 1
""":meth:`MatchEnd.clock`: the first half is over."""
TIME_OVER_DUE = 2
""":meth:`MatchEnd.clock`: the match is over."""

_TIME_OVER = PlayMode.TIME_OVER
_GOAL = int(EventKind.GOAL)
_END_KINDS = {_GOAL: "goal", int(EventKind.OUT): "out"}
_LOST_KINDS = frozenset({int(EventKind.KICK), int(EventKind.TOUCH), int(EventKind.CATCH), int(EventKind.SET_PLAY)})
"""Events of the defending side that mean the attackers lost the ball."""


@dataclass(frozen=True)
class MatchEnd:
    """The end conditions of one match (built by :meth:`soccer_sim.setup.MatchSetup.resolve`)."""

    end_cycle: int
    """Cycles the match lasts at most."""
    full_cycles: int
    """Cycles the configuration allows (``MatchConfig.total_cycles``); a match stopped by time
    before them was stopped by the scenario's cycle limit."""
    half_end: int
    """Cycles after which half time comes; -1 for none (one period)."""
    conditions: tuple[str, ...]
    """The scenario's end conditions, in the order they are judged
    (:data:`soccer_sim.scenarios.END_CONDITIONS`)."""
    defender: int
    """The side defending against the scenario's attacker (HOME or AWAY)."""

    def clock(self, cycles_done: int) -> int:
        """What the referee calls once ``cycles_done`` cycles have been played:
        :data:`TIME_OVER_DUE`, :data:`HALF_TIME_DUE` or :data:`CLOCK_RUNS`."""
        if cycles_done >= self.end_cycle:
            return TIME_OVER_DUE
        if cycles_done == self.half_end:
            return HALF_TIME_DUE
        return CLOCK_RUNS

    def is_over(self, state: WorldState) -> bool:
        """Whether no more cycles are played: time has been called (by the clock or an end
        condition) or the last cycle has been played."""
        return state.play_mode == _TIME_OVER or state.cycle >= self.end_cycle

    def condition_met(self, events: EventLog, start: int, stop: int) -> str | None:
        """The first of the scenario's end conditions (in :attr:`conditions` order) that the
        events ``start .. stop - 1`` meet, or None: a GOAL (of the attackers: ``"scored"``,
        own goals of the defenders included), an OUT, or the defending side playing the ball
        (kick, touch, catch) or being given a set play (``"lost"``)."""
        if not self.conditions or stop <= start:
            return None
        met = set()
        defender = self.defender
        for kind, team in zip(events.kind[start:stop], events.team[start:stop]):
            if kind in _END_KINDS:
                met.add(_END_KINDS[kind])
                if kind == _GOAL and team != defender:
                    met.add("scored")
            elif team == defender and kind in _LOST_KINDS:
                met.add("lost")
        for reason in self.conditions:
            if reason in met:
                return reason
        return None

    def reason(self, cycles: int, condition: str | None) -> str:
        """Why a match that ended after ``cycles`` cycles ended: the end condition met, else
        ``"cycle_limit"`` when the scenario's limit cut the configuration's length short, else
        ``"time_over"``."""
        if condition is not None:
            return condition
        if self.end_cycle <= cycles < self.full_cycles:
            return "cycle_limit"
        return "time_over"

    def episode_end(self, state: WorldState, *, goal_scored: bool, end_on_goal: bool, steps: int,
                    max_cycles: int | None) -> tuple[bool, bool]:
        """(terminated, truncated) of an environment episode after ``steps`` steps: terminated
        when the match is over (or, with ``end_on_goal``, a goal was scored in the step);
        otherwise truncated once ``max_cycles`` steps have been taken."""
        terminated = self.is_over(state) or (end_on_goal and goal_scored)
        truncated = not terminated and max_cycles is not None and steps >= max_cycles
        return terminated, truncated
