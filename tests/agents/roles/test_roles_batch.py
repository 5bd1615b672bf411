"""Many assignments in one call (RoleAssigner.assign_rows): every player of a decentralised team
assigns roles on its own view, and the distance-only assigners answer all of them at once, row
for row what one call per view gives."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents.roles import RoleError
from tests.agents.roles.role_situations import context, ready, run

K = 10
DISTANCE_ONLY = ("mmdr", "mmd+msd2", "msd", "msd2", "greedy")


def _views(problems: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """(problems, K, 2) players and targets: one team as several players see it (a shared
    picture with each view's own noise), with near ties between players."""
    rng = np.random.default_rng(seed)
    players = rng.uniform(-50, 50, (K, 2)) + rng.normal(0, 1.5, (problems, K, 2))
    targets = rng.uniform(-50, 50, (K, 2)) + rng.normal(0, 1.5, (problems, K, 2))
    players[:, 1] = players[:, 0] + 1e-9  # two players in the same spot in every view
    return players, targets


@pytest.mark.parametrize("name", DISTANCE_ONLY)
@pytest.mark.parametrize("scaled", [False, True])
def test_rows_are_what_one_call_per_view_gives(name: str, scaled: bool) -> None:
    players, targets = _views(12, seed=len(name))
    ctx = context()
    if scaled:  # players of different speeds: time costs
        ctx = replace(ctx, time_scale=np.linspace(0.8, 1.3, K))
    assigner = ready(name, K)
    rows = assigner.assign_rows(players, targets, ctx)
    assert rows.shape == (12, K) and rows.dtype == np.int64
    for r in range(12):
        np.testing.assert_array_equal(rows[r], run(assigner, players[r], targets[r], ctx=ctx))
        assert sorted(rows[r]) == list(range(K))


def test_assigners_with_memory_or_context_have_no_batch_form() -> None:
    players, targets = _views(3, seed=1)
    for name in ("static", "bidding", "greedy-offense", "random"):
        assert ready(name, K).assign_rows(players, targets, context()) is None


def test_bad_batches_are_refused_naming_the_problem() -> None:
    players, targets = _views(2, seed=2)
    assigner = ready("mmdr", K)
    with pytest.raises(RoleError, match=r"\(problems, 10, 2\)"):
        assigner.assign_rows(players[:, :9], targets[:, :9], context())
    with pytest.raises(RoleError, match=r"\(problems, 10, 2\)"):
        assigner.assign_rows(players[0], targets[0], context())
    players[1, 3, 0] = np.nan
    with pytest.raises(RoleError, match="finite"):
        assigner.assign_rows(players, targets, context())
    with pytest.raises(RoleError, match="reset"):
        from agents.roles import make_assigner

        make_assigner("mmdr").assign_rows(players, targets, context())
