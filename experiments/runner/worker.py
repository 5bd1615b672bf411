"""Playing one match inside a worker process: never raises, always returns a record.

A team that raises, returns a malformed command or overruns the time budget forfeits the
match; the record names the side at fault and keeps the traceback. The time budget is
enforced twice: here by a timer signal that interrupts the match where it hangs (so the
traceback shows where), and by the parent, which kills a worker that does not answer a while
after that (a hang inside compiled code the signal cannot interrupt).
"""

from __future__ import annotations

import signal
import threading
import time
import traceback as tb

from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.runner.spec import MatchSpec


class MatchTimeout(Exception):
    """A match overran its time budget (``--match-timeout``)."""

    def __init__(self, seconds: float) -> None:
        super().__init__(f"match exceeded its time budget of {seconds:g} s")
        self.seconds = seconds

    def __reduce__(self):
        return type(self), (self.seconds,)


class _Watched:
    """A team wrapped so the worker knows which side was deciding when something went wrong.

    Forwards every other attribute (``statistics()``, drawing hooks, ...) to the team."""

    def __init__(self, team: object, name: str, side: int, deciding: list[int]) -> None:
        self._team, self.name, self._side, self._deciding = team, name, side, deciding

    def reset(self, side_info, config, rng) -> None:
        self._deciding[0] = self._side
        self._team.reset(side_info, config, rng)
        self._deciding[0] = FORFEIT_NONE

    def act(self, view):
        self._deciding[0] = self._side
        command = self._team.act(view)
        self._deciding[1] = self._side
        self._deciding[0] = FORFEIT_NONE
        return command

    def __getattr__(self, name: str):
        return getattr(self._team, name)


def make_team(name: str) -> tuple[object, str]:
    """(team object, display name) for a registered name, a ``module:Attribute`` path or a
    mixed-team name (:mod:`experiments.mixed_team`)."""
    from experiments.mixed_team import is_mixed_name, mixed_team
    from soccer_sim import resolve_team

    if is_mixed_name(name):
        return mixed_team(name), name
    return resolve_team(name)


def play_spec(spec: MatchSpec, config_hash: str, code_version: str, timeout: float | None) -> MatchRecord:
    """Play ``spec`` and return its record; every failure becomes a forfeit or an error row.

    The record carries the code version of this process (the code that really played), not
    the ``code_version`` the caller expects; the caller compares them."""
    from experiments.runner.fingerprint import code_version as running_code_version
    from soccer_sim import run_match

    record = MatchRecord(spec.home, spec.away, spec.seed, config_hash, running_code_version())
    deciding = [FORFEIT_NONE, FORFEIT_NONE]
    """[side inside reset/act now, side whose act returned last]."""
    start = time.perf_counter()
    alarm = _arm_timer(timeout)
    try:
        home, away = (_Watched(*make_team(name), side, deciding) for side, name in enumerate((spec.home, spec.away)))
        recorders = []
        if spec.record is not None:
            from soccer_sim.replay import RerunRecorder

            recorders.append(RerunRecorder(spec.record))
        result = run_match(home, away, seed=spec.seed, config=spec.config(), recorders=recorders)
        _disarm_timer(alarm)
        record.home_goals, record.away_goals = (int(g) for g in result.score)
        record.cycles = int(result.cycles)
        record.home_stats, record.away_stats = (s.as_dict() for s in result.statistics)
    except BaseException as exc:  # noqa: BLE001 - a worker must survive anything a team does
        _disarm_timer(alarm)
        if isinstance(exc, KeyboardInterrupt) and timeout is None:
            raise
        record.error = f"{type(exc).__name__}: {exc}"
        record.traceback = tb.format_exc()
        record.forfeit = _culprit(exc, spec, deciding)
    record.wall_time = time.perf_counter() - start
    return record


def _culprit(exc: BaseException, spec: MatchSpec, deciding: list[int]) -> int:
    """The side at fault: the one deciding when the failure struck, else the side a TeamError
    names (its last act() when both sides share the name), else nobody."""
    from soccer_sim import TeamError

    if deciding[0] != FORFEIT_NONE:
        return deciding[0]
    if isinstance(exc, TeamError):
        sides = [side for side, name in enumerate((spec.home, spec.away)) if name == exc.team_name]
        if len(sides) == 1:
            return sides[0]
        return deciding[1]
    return FORFEIT_NONE


def _arm_timer(timeout: float | None):
    """Start a timer that raises MatchTimeout in this (main) thread after ``timeout`` seconds;
    None where signals are unavailable (another thread, or no SIGALRM on this platform)."""
    if timeout is None or not hasattr(signal, "setitimer") or threading.current_thread() is not threading.main_thread():
        return None

    def _expired(signum, frame):
        raise MatchTimeout(timeout)

    previous = signal.signal(signal.SIGALRM, _expired)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    return previous


def _disarm_timer(previous) -> None:
    if previous is not None:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def failed_record(spec: MatchSpec, config_hash: str, code_version: str, seconds: float, message: str) -> MatchRecord:
    """The record of a match the parent had to give up on (its worker died or was stopped):
    nobody is blamed, as the worker could not say which side was deciding."""
    return MatchRecord(spec.home, spec.away, spec.seed, config_hash, code_version, error=message,
                       traceback=message, forfeit=FORFEIT_NONE, wall_time=seconds)
