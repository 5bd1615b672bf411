"""Playing one match inside a worker process: never raises, always returns a record.

A team that raises (``sys.exit`` included), returns a malformed command or overruns the time
budget forfeits the match; the record names the side at fault and keeps the traceback. The
side whose code is running is also marked where the parent can read it (see
:class:`_Watched`), so a crash of the whole worker inside a team's code is that team's
forfeit. The time budget is enforced twice: here by a timer signal that interrupts the match
where it hangs (so the traceback shows where), and by the parent, which kills a worker that
does not answer a while after that (a hang inside compiled code the signal cannot interrupt).
"""

from __future__ import annotations

import signal
import threading
import time
import traceback as tb
from collections.abc import Callable, Mapping, MutableSequence
from typing import TYPE_CHECKING, Protocol

from experiments.errors import ExperimentError
from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.runner.spec import MatchSpec

if TYPE_CHECKING:  # annotations only
    from soccer_sim import MatchResult


class MatchFigures(Protocol):
    """A match recorder (``on_start``/``on_cycle``/``on_end``) that also reports figures of the
    whole match once it is over (names prefixed ``match_`` by convention)."""

    def on_start(self, match) -> None: ...

    def on_cycle(self, match) -> None: ...

    def on_end(self, match) -> None: ...

    def figures(self) -> dict[str, float]: ...


class MatchTimeout(ExperimentError):
    """A match overran its time budget (the run's ``match_timeout``)."""

    def __init__(self, seconds: float) -> None:
        super().__init__(f"match exceeded its time budget of {seconds:g} s")
        self.seconds = seconds

    def __reduce__(self):
        return type(self), (self.seconds,)


class _Watched:
    """A team wrapped so the worker knows which side is running team code when something goes
    wrong: ``deciding[0]`` holds the side while its ``reset``, ``act`` or any other method runs
    (``statistics()``, drawing hooks, ...) and FORFEIT_NONE otherwise; ``deciding[1]`` the side
    whose ``act`` returned last. ``deciding`` may be shared memory the parent reads when the
    worker dies (see :mod:`experiments.runner.local`). A call that fails leaves its side marked."""

    def __init__(self, team: object, name: str, side: int, deciding: MutableSequence[int]) -> None:
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
        value = getattr(self._team, name)
        if not callable(value):
            return value

        def marked(*args, **kwargs):
            self._deciding[0] = self._side
            result = value(*args, **kwargs)
            self._deciding[0] = FORFEIT_NONE
            return result

        return marked


def make_team(name: str, options: Mapping[str, object] | None = None) -> tuple[object, str]:
    """(team object, display name) for a registered name, a ``module:Attribute`` path, a
    mixed-team name (:mod:`experiments.mixed_team`) or a checkpoint team name
    (``checkpoint:KIND:PATH?...``, :mod:`soccer_sim.env.checkpoint_teams`). ``options``: team
    options passed to a registered or path team's factory as keyword arguments
    (:func:`soccer_sim.resolve_team`); a mixed or checkpoint team takes none (ExperimentError)."""
    from experiments.mixed_team import is_mixed_name, mixed_team
    from soccer_sim import resolve_team
    from soccer_sim.env.checkpoint_teams import checkpoint_team, is_checkpoint_name

    if options and (is_mixed_name(name) or is_checkpoint_name(name)):
        raise ExperimentError(f"team {name!r} takes no team options ({', '.join(options)}): only a registered "
                              "name or a package.module:Attribute path does")
    if is_mixed_name(name):
        return mixed_team(name), name
    if is_checkpoint_name(name):
        return checkpoint_team(name), name
    return resolve_team(name, options)


def play_spec(spec: MatchSpec, config_hash: str, code_version: str, timeout: float | None,
              deciding: MutableSequence[int] | None = None,
              figures: Callable[[], MatchFigures] | None = None,
              report: Callable[[MatchResult], object] | None = None) -> MatchRecord:
    """Play ``spec`` and return its record; every failure becomes a forfeit or an error row.

    The record carries the code version of this process (the code that really played), not
    the ``code_version`` the caller expects; the caller compares them. ``deciding``: two
    integers (a worker's shared slot) set to [side running team code now, side whose act
    returned last], so a parent can blame the team whose code was running if the worker dies;
    a private list if None. ``figures``: makes a recorder whose figures of the whole match are
    added to both teams' statistics of a match played to its end. ``report``: a picklable
    function of the finished match's :class:`~soccer_sim.MatchResult` whose value the record
    carries back in :attr:`MatchRecord.report` (``soccer-sim play``'s match report; not for a
    study's own ``play`` function)."""
    from experiments.runner.fingerprint import code_version as running_code_version

    record = MatchRecord(spec.home, spec.away, spec.seed, config_hash, running_code_version())
    if deciding is None:
        deciding = [FORFEIT_NONE, FORFEIT_NONE]
    deciding[0] = deciding[1] = FORFEIT_NONE
    start = time.perf_counter()
    alarm = arm_timer(timeout)
    try:
        if spec.play is not None:  # a study's own unit of work (see MatchSpec.play)
            import importlib

            module, _, function = spec.play.partition(":")
            play = getattr(importlib.import_module(module), function)
            play(spec, record, lambda team, name, side: _Watched(team, name, side, deciding))
            disarm_timer(alarm)
        else:
            _play_match(spec, record, deciding, figures, report, alarm)
    except BaseException as exc:  # noqa: BLE001 - a worker must survive anything a team does
        disarm_timer(alarm)
        if isinstance(exc, KeyboardInterrupt) and timeout is None:
            raise
        record.forfeit = _culprit(exc, spec, deciding)
        record.error = failure_text(exc, spec, record.forfeit)
        record.traceback = tb.format_exc()
    deciding[0] = FORFEIT_NONE  # the match is over: no team's code runs until the next one
    record.wall_time = time.perf_counter() - start
    return record


def _play_match(spec: MatchSpec, record: MatchRecord, deciding: MutableSequence[int],
                figures: Callable[[], MatchFigures] | None, report: Callable[[MatchResult], object] | None,
                alarm) -> None:
    """Play the match between ``spec.home`` and ``spec.away`` into ``record``."""
    from soccer_sim import run_match

    home, away = (_Watched(*make_team(name), side, deciding) for side, name in enumerate((spec.home, spec.away)))
    recorders = [] if figures is None else [figures()]
    if spec.record is not None:
        from soccer_sim.replay import RerunRecorder

        recorders.append(RerunRecorder(spec.record))
    from experiments.recording import rcg_recording

    with rcg_recording(spec.rcg, "--rcg-dir") as logs:  # written whole or not at all
        result = run_match(home, away, seed=spec.seed, config=spec.config(), recorders=[*recorders, *logs],
                           scenario=spec.scenario)
    disarm_timer(alarm)
    record_result(record, result)
    if figures is not None:
        extra = recorders[0].figures()
        record.home_stats.update(extra)
        record.away_stats.update(extra)
    if report is not None:
        record.report = report(result)


def record_result(record: MatchRecord, result: MatchResult) -> None:
    """Fill ``record`` with a finished match's score, cycles and both teams' statistics."""
    record.home_goals, record.away_goals = (int(g) for g in result.score)
    record.cycles = int(result.cycles)
    record.home_stats, record.away_stats = (s.as_dict() for s in result.statistics)


def failure_text(exc: BaseException, spec: MatchSpec, side: int) -> str:
    """``record.error`` for a match ``exc`` stopped, ``Kind: what happened``: a TeamError as it
    stands (it names the team and the method), a timeout inside a team's method as a
    MatchTimeout naming both, anything else with the team ``side`` names (if any) appended."""
    from soccer_sim import TeamError

    if isinstance(exc, TeamError) and isinstance(exc.__cause__, MatchTimeout):
        method = exc.message.split("(", 1)[0]
        return (f"MatchTimeout: match exceeded its time budget of {exc.__cause__.seconds:g} s while team "
                f"{exc.team_name!r} was in {method}()")
    if isinstance(exc, TeamError):
        return f"TeamError: {exc}"
    return f"{type(exc).__name__}: {exc}{blame_suffix(spec, side)}"


def blame_suffix(spec: MatchSpec, side: int) -> str:
    """``; it was running the code of the away team 'name'`` for ``side`` (nothing for FORFEIT_NONE):
    what a failure's message adds when the worker's slot says whose code ran."""
    if side == FORFEIT_NONE:
        return ""
    return f"; it was running the code of the {('home', 'away')[side]} team {spec.key[side]!r}"


def _culprit(exc: BaseException, spec: MatchSpec, deciding: MutableSequence[int]) -> int:
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


TIMER_RESTRIKE_SECONDS = 0.2
"""Seconds after a timeout's raise when the timer strikes again, in case that raise was swallowed."""


class _Alarm:
    """An armed match timer: the SIGALRM handler it replaced, and whether it may still strike
    (cleared first thing on disarming, so a strike already on its way when the match ends
    raises nothing)."""

    def __init__(self, previous) -> None:
        self.previous = previous
        self.active = True


def arm_timer(timeout: float | None) -> _Alarm | None:
    """Start a timer that raises MatchTimeout in this (main) thread after ``timeout`` seconds;
    None where signals are unavailable (another thread, or no SIGALRM on this platform)."""
    if timeout is None or not hasattr(signal, "setitimer") or threading.current_thread() is not threading.main_thread():
        return None

    def _expired(signum, frame):
        if not alarm.active:
            return
        # Strike again soon: a raise inside a callback the interpreter guards (a garbage
        # collector's finaliser, e.g. pymunk freeing a space) is printed and swallowed, and the
        # match would play on. The disarm that follows a raise that lands comes well before this.
        signal.setitimer(signal.ITIMER_REAL, TIMER_RESTRIKE_SECONDS)
        raise MatchTimeout(timeout)

    alarm = _Alarm(signal.signal(signal.SIGALRM, _expired))
    signal.setitimer(signal.ITIMER_REAL, timeout)
    return alarm


def disarm_timer(alarm: _Alarm | None) -> None:
    """Stop the timer of :func:`arm_timer` and restore the signal handler it replaced."""
    if alarm is not None:
        alarm.active = False
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, alarm.previous)


def failed_record(spec: MatchSpec, config_hash: str, code_version: str, seconds: float, message: str,
                  forfeit: int = FORFEIT_NONE) -> MatchRecord:
    """The record of a match the parent had to give up on (its worker died or was stopped):
    ``forfeit`` is the side whose code was running then, if the worker's slot says so; nobody
    is blamed otherwise, and the message then names that team."""
    message += blame_suffix(spec, forfeit)
    return MatchRecord(spec.home, spec.away, spec.seed, config_hash, code_version, error=message,
                       traceback=message, forfeit=forfeit, wall_time=seconds)
