"""Interception of a ball lying on a line: still in play, so still reachable."""

import numpy as np

from agents import skills
from soccer_sim import MatchConfig


def test_a_ball_on_the_touchline_can_be_reached() -> None:
    model = skills.MotionModel.even_sides(MatchConfig())
    ctx = skills.SkillContext(model)
    half_width = MatchConfig().field.half_width
    ball = np.array([-36.0, half_width + 0.05])  # over the line, but not wholly: in play
    pos = np.array([[-36.0, half_width - 5.0]])
    players = skills.Players(model, pos, np.zeros((1, 2)))
    result = skills.intercept(ctx, ball, np.zeros(2), players)
    assert result.first == 0 and 0 < result.first_cycle < 10
    gone = skills.intercept(ctx, ball + (0.0, 0.1), np.zeros(2), players)  # wholly out
    assert gone.first == -1


def test_checked_entry_is_the_same_search() -> None:
    """intercept_checked (inputs already in the kernel's form) gives what intercept_many gives,
    with limits, a reaction delay, first-only searches and single-player lanes."""
    from agents.skills.interception import intercept_checked, intercept_many
    from agents.skills.interception_kernels import EVERYONE, NO_LIMITS

    model = skills.MotionModel.even_sides(MatchConfig())
    ctx = skills.SkillContext(model)
    rng = np.random.default_rng(3)
    players = skills.Players(model, rng.uniform(-30, 30, (11, 2)), rng.uniform(-0.5, 0.5, (11, 2)))
    ball, vels = np.array([[1.0, -2.0]]), rng.uniform(-2.5, 2.5, (8, 2))
    limit, only = rng.integers(0, 40, 8).astype(np.int64), rng.integers(0, 11, 8).astype(np.int64)
    for args, checked in (((None, 0, False, None), (NO_LIMITS, 0, False, EVERYONE)),
                          ((limit, 1, True, None), (limit, 1, True, EVERYONE)),
                          ((limit, 0, False, only), (limit, 0, False, only))):
        want = intercept_many(ctx, ball, vels, players, 1.0, *args)
        got = intercept_checked(ctx, ball, vels, players, 1.0, *checked)
        assert np.array_equal(want[0], got[0]) and np.array_equal(want[1], got[1])
        assert (got[0] < skills.UNREACHABLE).any()


def test_the_run_bound_skips_no_interception(monkeypatch) -> None:
    """The search skips a player's hit tests while its run cannot yet reach the ball's path; a
    copy of the kernel compiled without that bound (``_MARGIN`` infinite) finds the same
    cycles and points, bit for bit, on many scenes: standing and moving players, slow and fast
    balls, catches in a penalty area, reaction delays, first-only searches and limits."""
    from numba import njit

    from agents.skills import interception_kernels as kernels

    monkeypatch.setattr(kernels, "_MARGIN", np.inf)
    unbounded = njit(kernels.intercept_kernel.py_func)  # compiled now, with the bound off
    model = skills.MotionModel.even_sides(MatchConfig())
    ctx = skills.SkillContext(model)
    rng = np.random.default_rng(11)
    skipped = 0
    for scene in range(60):
        pos = rng.uniform((-52.0, -34.0), (52.0, 34.0), (11, 2))
        vel = rng.uniform(-0.6, 0.6, (11, 2)) * (scene % 2)
        players = skills.Players(model, pos, vel, effort=rng.uniform(0.6, 1.0, 11))
        ball = rng.uniform((-50.0, -30.0), (50.0, 30.0), (1, 2))
        vels = rng.uniform(-3.0, 3.0, (6, 2)) * rng.uniform(0.0, 1.0, (6, 1))
        limits = rng.integers(-1, 60, 6).astype(np.int64)
        delay, first_only, side = int(scene % 3), bool(scene % 4 == 0), (-1.0, 1.0)[scene % 2]
        args = (ball, vels, players.runners, model.tables, limits, kernels.EVERYONE)
        got = np.empty((6, 11), dtype=np.int64), np.empty((6, 11, 2))
        want = np.empty((6, 11), dtype=np.int64), np.empty((6, 11, 2))
        tail = (ctx.intercept_params, side, delay, first_only)
        kernels.intercept_kernel(*args, *got, *tail)
        unbounded(*args, *want, *tail)
        assert np.array_equal(got[0], want[0]) and np.array_equal(got[1], want[1]), scene
        skipped += int(((got[0] > 5) & (got[0] < skills.UNREACHABLE)).sum())
    assert skipped > 50  # far players who reach the ball late: the bound had hit tests to skip
