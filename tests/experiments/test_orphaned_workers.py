"""The workers of a run whose process is killed (``kill -9``) end at once and quietly, even in
the middle of a match: no match played on for nobody, no BrokenPipeError traceback."""

from __future__ import annotations

import sys
from pathlib import Path

from tests.experiments.helpers import SCRIPTED, start_until_in_act

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
    run = start_until_in_act([sys.executable, "-c", RUN, str(tmp_path / "r.sqlite")],
                             tmp_path / "match-under-way", ROOT, HANG_BOUND)
    try:
        run.kill()
        run.wait()
        # The pipes reach their end once every process holding them (the workers) has ended.
        out, err = run.communicate(timeout=HANG_BOUND)
    finally:
        if run.poll() is None:
            run.kill()
    assert out == "" and err == "", err
