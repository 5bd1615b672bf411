"""Small scripted teams for the runner's tests: they misbehave on purpose, or play a fixed,
recognisable command (named by ``tests.experiments.scripted_teams:Class`` paths)."""

from __future__ import annotations

import os
import signal
import sys
import time

import numpy as np

from soccer_sim import TeamCommand


class _Still:
    """Stands still; subclasses change one thing."""

    fail_at = 20

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        if view.cycle >= self.fail_at:
            self.misbehave()
        return self.command

    def misbehave(self) -> None:
        pass


class RaisingTeam(_Still):
    def misbehave(self) -> None:
        raise RuntimeError("scripted failure")


class NaNTeam(_Still):
    def misbehave(self) -> None:
        self.command.dash[3] = np.nan


class HangingTeam(_Still):
    """Sleeps for ever in act(): the worker's timer must stop the match."""

    def misbehave(self) -> None:
        while True:
            time.sleep(0.05)


class DeafHangingTeam(_Still):
    """Hangs deaf to the worker's timer (as in compiled code that never returns to Python):
    the parent must kill the worker."""

    def misbehave(self) -> None:
        signal.signal(signal.SIGALRM, signal.SIG_IGN)
        while True:
            time.sleep(0.05)


class DeafAtOnceTeam(DeafHangingTeam):
    """Hangs deaf to the timer from its first act() (nothing else is under way when the timer
    is due, so the team is surely the one whose code runs)."""

    fail_at = 0


class CrashingTeam(_Still):
    """Ends its worker process abruptly (as a crash in native code would)."""

    def misbehave(self) -> None:
        os._exit(3)


class ExitingTeam(_Still):
    """Calls sys.exit inside act(): its own fault, like any exception."""

    def misbehave(self) -> None:
        sys.exit(1)


class CrashingFigures:
    """A match recorder (a ``figures`` factory of the runner) that ends its worker abruptly at
    cycle 5, outside any team's code: a failure no team is to blame for."""

    def on_start(self, match) -> None:
        pass

    def on_cycle(self, match) -> None:
        if match.state.cycle >= 5:
            os._exit(1)

    def on_end(self, match) -> None:
        pass

    def figures(self) -> dict[str, float]:
        return {}


class Constant:
    """Every player dashes by ``dash`` and kicks by ``kick``; the goalkeeper asks to catch if ``catch``."""

    dash, kick, catch = (0.0, 0.0), (0.0, 0.0), False

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.seen = []
        self.command = TeamCommand(dash=np.tile(self.dash, (n, 1)), kick=np.tile(self.kick, (n, 1)), catch=self.catch)

    def act(self, view) -> TeamCommand:
        self.seen.append(view.own_pos.shape)
        return self.command


class Forward(Constant):
    dash, kick, catch = (0.01, 0.0), (0.5, 0.0), True


class Sideways(Constant):
    dash, kick, catch = (0.0, 0.02), (0.0, 0.0), False


class RaisingBaseException(_Still):
    """Raises a BaseException that is not an Exception (as a bare ``raise BaseException``)."""

    def misbehave(self) -> None:
        raise BaseException("scripted base exception")


class QuietlyExitingTeam(_Still):
    """Ends its process at once with status 0 (``os._exit(0)``): no exception, no report."""

    def misbehave(self) -> None:
        os._exit(0)


class SelfKillingTeam(_Still):
    """Kills its own process with SIGKILL."""

    def misbehave(self) -> None:
        os.kill(os.getpid(), signal.SIGKILL)


class PrintingTeam(_Still):
    """Prints on stdout every cycle (Python's print and the process's file descriptor 1)."""

    fail_at = 0

    def misbehave(self) -> None:
        print("team says hello")
        os.write(1, b"team writes to fd 1\n")


class SelfAlarmingTeam(_Still):
    """Restores SIGALRM's default action (end the process) and sets a timer of its own."""

    def misbehave(self) -> None:
        signal.signal(signal.SIGALRM, signal.SIG_DFL)
        signal.setitimer(signal.ITIMER_REAL, 0.01)
        time.sleep(5)


MARKER_VARIABLE = "SOCCER_SIM_TEST_MARKER"
"""The environment variable naming the file :class:`MarkingHangingTeam` creates."""


class MarkingHangingTeam(_Still):
    """Creates the file the environment variable MARKER_VARIABLE names, then sleeps for ever in
    act() (a test knows the match is under way once the file exists)."""

    fail_at = 0

    def misbehave(self) -> None:
        with open(os.environ[MARKER_VARIABLE], "w"):
            pass
        while True:
            time.sleep(0.05)
