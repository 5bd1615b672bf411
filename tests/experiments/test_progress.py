"""Progress of a run: quiet lines when the output is not a terminal."""

from __future__ import annotations

import io

from experiments.runner.progress import RunProgress


def test_quiet_lines_at_every_tenth_with_rate_eta_and_errors() -> None:
    stream = io.StringIO()
    with RunProgress(20, "tournament", stream=stream) as progress:
        for i in range(20):
            progress.advance(failed=i in (3, 4))
    lines = stream.getvalue().splitlines()
    assert len(lines) == 10
    assert lines[0].startswith("tournament: 2/20 matches") and "ETA" in lines[0] and "0 errors" in lines[0]
    assert lines[-1].startswith("tournament: 20/20 matches") and lines[-1].endswith("2 errors")
    assert (progress.done, progress.errors) == (20, 2)


def test_disabled_progress_prints_nothing() -> None:
    stream = io.StringIO()
    with RunProgress(5, "x", stream=stream, enabled=False) as progress:
        for _ in range(5):
            progress.advance()
    assert stream.getvalue() == "" and progress.done == 5
