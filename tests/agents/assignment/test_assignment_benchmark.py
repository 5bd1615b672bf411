"""The ``soccer-sim bench assignment`` module runs end to end on a tiny configuration."""

from __future__ import annotations

import argparse

import pytest

from experiments.benchmarks import assignment as bench


def _args(**overrides) -> argparse.Namespace:
    """The benchmark's options parsed from ``--name value`` for each override (so each value
    passes its option's range check, as on the command line)."""
    parser = argparse.ArgumentParser()
    bench.add_arguments(parser)
    return parser.parse_args([text for name, value in overrides.items()
                              for text in (f"--{name.replace('_', '-')}", str(value))])


def test_benchmark_prints_both_tables_and_explains_skipped_cells(capsys):
    args = _args(sizes="6,10,30", repeats=2, quality_instances=30, time_limit=5.0)
    assert bench.run(args) == 0
    out = " ".join(capsys.readouterr().out.split())  # undo the console's line wrapping
    assert "Median time of one assign() call" in out
    for label, *_ in bench.RUNTIME_ROWS:
        assert label in out
    assert "n = 30" in out
    assert "brute force enumerates n! assignments; limited to n <= 8" in out
    assert "subset dynamic programming needs 2^n states; limited to n <= 20" in out
    assert "Quality over 30 random instances" in out
    assert "average makespan" in out


def test_time_limit_skips_with_a_prediction(capsys):
    args = _args(sizes="10,2000", repeats=1, quality_instances=0, time_limit=1e-4, methods="msd")
    assert bench.run(args) == 0
    out = " ".join(capsys.readouterr().out.split())  # undo the console's line wrapping
    assert "msd: predicted" in out and "over the 0.0001 s limit" in out


def test_bad_arguments_are_explained(capsys):
    assert bench.run(_args(sizes="10", quality_instances=0, methods="msd,hungarian")) == 2
    err = " ".join(capsys.readouterr().err.split())
    assert "--methods: unknown row label(s) 'hungarian'" in err and "'mmdr (fast)'" in err
    for sizes, shown in (("10,1x0", "1x0"), ("0", "0"), ("10,1000000", "1000000")):
        with pytest.raises(SystemExit) as usage:
            _args(sizes=sizes, quality_instances=0)
        assert usage.value.code == 2
        assert (f"--sizes: each value must be a positive integer up to 100000 (robots), got {shown}"
                in capsys.readouterr().err)
