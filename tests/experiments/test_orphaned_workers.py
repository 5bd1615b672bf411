"""The workers of a run whose process is killed (``kill -9``) end at once and quietly, even in
the middle of a match: no match played on for nobody, no BrokenPipeError traceback."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

from tests.experiments.helpers import SCRIPTED
from tests.experiments.scripted_teams import MARKER_VARIABLE

ROOT = Path(__file__).resolve().parents[2]

HANG_BOUND = 240.0
"""Seconds after which an orphaned worker counts as playing on (a bound: it ends at once)."""

RUN = f"""
import sys

from experiments.runner import MatchSpec, run_matches

run_matches([MatchSpec("idle", "{SCRIPTED}MarkingHangingTeam", 0, 100)], sys.argv[1], "tournament", {{}},
            cycles=100, workers=1, match_timeout=600.0, progress=False)
"""


def test_the_workers_of_a_killed_run_end_quietly(tmp_path) -> None:
    marker = tmp_path / "match-under-way"
    env = {**os.environ, MARKER_VARIABLE: str(marker),
           "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    run = subprocess.Popen([sys.executable, "-c", RUN, str(tmp_path / "r.sqlite")], cwd=ROOT, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + HANG_BOUND
        while not marker.exists():  # the worker is inside the team's act()
            assert run.poll() is None, run.communicate()
            assert time.monotonic() < deadline, "the match never started"
            time.sleep(0.05)
        run.kill()
        run.wait()
        # The pipes reach their end once every process holding them (the workers) has ended.
        out, err = run.communicate(timeout=HANG_BOUND)
    finally:
        if run.poll() is None:
            run.kill()
    assert out == "" and err == "", err
