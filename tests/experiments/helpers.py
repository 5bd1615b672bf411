"""Helpers shared by the experiments tests, always imported as ``tests.experiments.helpers``."""

from __future__ import annotations

SCRIPTED = "tests.experiments.scripted_teams:"
"""The module path prefix of the scripted test teams (``SCRIPTED + "Forward"``)."""


def outcome(records) -> list[tuple]:
    """What must not depend on workers, backend or resuming: key, score, statistics, failure."""
    return [(r.home, r.away, r.seed, r.config_hash, r.home_goals, r.away_goals, r.cycles, r.home_stats,
             r.away_stats, r.error, r.forfeit) for r in records]


def _ctrl_c_as_at_a_terminal() -> None:
    """In the child before it runs: SIGINT's default disposition, as a command started at a
    terminal has it. A test run started in the background (``pytest &`` in a script) ignores
    SIGINT, every process it starts inherits that, and Python then never turns Ctrl-C into
    KeyboardInterrupt: a test of what Ctrl-C does would wait for nothing."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_DFL)


def start_until_in_act(argv: list[str], marker, root, bound: float):
    """Start ``argv`` (a subprocess with the project on its path and pipes for its output) whose
    team touches ``marker`` when its worker is inside ``act()`` (:data:`scripted_teams.MARKER_VARIABLE`),
    and return the process once that happened (an AssertionError after ``bound`` seconds or if it
    ended first)."""
    import os
    import subprocess
    import time

    from tests.experiments.scripted_teams import MARKER_VARIABLE

    env = {**os.environ, MARKER_VARIABLE: str(marker),
           "PYTHONPATH": os.pathsep.join([str(root), os.environ.get("PYTHONPATH", "")])}
    process = subprocess.Popen(argv, cwd=root, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               preexec_fn=_ctrl_c_as_at_a_terminal)
    deadline = time.monotonic() + bound
    while not marker.exists():
        if process.poll() is not None or time.monotonic() >= deadline:
            process.kill()
            out, err = process.communicate()
            raise AssertionError(f"the match never reached act() (exit {process.returncode}): {err[-2000:]}")
        time.sleep(0.05)
    return process
