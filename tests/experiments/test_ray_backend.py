"""The Ray backend plays a small tournament on a local Ray instance with 2 CPUs and stores the
same results as the local process pool."""

from __future__ import annotations

import pytest

from experiments.cli import main
from experiments.results.store import ResultStore
from tests.experiments.helpers import outcome

pytest.importorskip("ray")
pytestmark = pytest.mark.xdist_group("ray")  # one Ray instance at a time on the machine


@pytest.mark.slow  # the Ray cluster tests keep a Ray run in the default suite
def test_ray_backend_plays_a_small_tournament(tmp_path, capsys) -> None:
    common = ["tournament", "--teams", "chaser,idle", "--games", "4", "--cycles", "200", "--workers", "2",
              "--no-progress"]
    assert main([*common, "--backend", "ray", "--out", str(tmp_path / "ray.sqlite")]) == 0
    printed = capsys.readouterr().out
    assert "4 matches in" in printed and "on 2 worker(s)" in printed and "0 failed" in printed
    assert main([*common, "--out", str(tmp_path / "local.sqlite")]) == 0
    with ResultStore.open(tmp_path / "ray.sqlite") as ray, ResultStore.open(tmp_path / "local.sqlite") as local:
        assert outcome(ray.records()) == outcome(local.records())
        assert len(ray.records()) == 4
