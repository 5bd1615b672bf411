"""Distributed assignment under limited communication (ETSP ASSGMT and GRID ASSGMT)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from agents.assignment import AssignmentError, distributed_assign
from agents.assignment.distributed_grid import cells_per_side

ALGORITHMS = ("etsp", "grid")


def _check_complete(result, agents, targets) -> None:
    """Every target (every agent, if fewer) held by exactly one agent standing on it."""
    n, m = len(agents), len(targets)
    assert result.completed
    held = result.target_of[result.target_of >= 0]
    assert held.size == min(n, m)
    assert np.unique(held).size == held.size, "a target is held by two agents"
    holders = np.flatnonzero(result.target_of >= 0)
    np.testing.assert_array_equal(result.positions[holders], np.asarray(targets, float)[held])
    assert result.completion_time == pytest.approx(np.nanmax(result.arrival_times))
    assert result.max_message_distance <= result.model.r_comm
    # An agent's path is at least the straight line from its start to its final position.
    straight = np.linalg.norm(result.positions - np.asarray(agents, float), axis=1)
    assert (result.distances >= straight - 1e-9).all()


def _uniform(seed: int, n: int, m: int, side: float) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    return rng.uniform(0, side, (n, 2)), rng.uniform(0, side, (m, 2))


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("seed", range(6))
def test_random_starts_complete(algorithm, seed):
    rng = np.random.default_rng(100 + seed)
    n = int(rng.integers(2, 60))
    side = float(rng.uniform(10, 120))
    r_comm = float(rng.uniform(3, 25))
    agents, targets = _uniform(seed, n, n, side)
    result = distributed_assign(agents, targets, side, r_comm, algorithm=algorithm)
    _check_complete(result, agents, targets)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("n, m", [(30, 12), (12, 30), (1, 1), (1, 5), (5, 1)])
def test_unequal_numbers_complete(algorithm, n, m):
    agents, targets = _uniform(n * 100 + m, n, m, 60.0)
    result = distributed_assign(agents, targets, 60.0, 8.0, algorithm=algorithm)
    _check_complete(result, agents, targets)
    assert (result.target_of < 0).sum() == max(0, n - m)


def _adversarial(kind: str, n: int, side: float) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(7)
    line = np.linspace(0.0, side, n)
    if kind == "corner cluster, targets on a line":
        return rng.uniform(0, 0.03 * side, (n, 2)), np.c_[line, np.full(n, 0.8 * side)]
    if kind == "all agents at one point":
        return np.full((n, 2), 0.5 * side), rng.uniform(0, side, (n, 2))
    if kind == "opposite corners":
        return rng.uniform(0, 0.1 * side, (n, 2)), side - rng.uniform(0, 0.1 * side, (n, 2))
    if kind == "targets on the far edge":
        return np.c_[line[::-1], np.zeros(n)], np.c_[np.full(n, side), line]
    if kind == "isolated clusters, one free target last":
        # Theorem 4.2's construction: targets in clusters farther apart than 2 r_comm, every
        # agent but one already on a target, the free target in the farthest cluster.
        k = math.isqrt(n - 1) + 1
        centres = (np.stack(np.meshgrid(np.arange(k), np.arange(k)), -1).reshape(-1, 2) + 0.5) * side / k
        targets = centres[:n] + rng.uniform(-0.01, 0.01, (n, 2)) * side
        agents = targets.copy()
        agents[-1] = (0.0, 0.0)
        return agents, targets
    raise ValueError(kind)


ADVERSARIAL = (
    "corner cluster, targets on a line",
    "all agents at one point",
    "opposite corners",
    "targets on the far edge",
    "isolated clusters, one free target last",
)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("kind", ADVERSARIAL)
def test_adversarial_starts_complete(algorithm, kind):
    side, r_comm = 80.0, 6.0
    agents, targets = _adversarial(kind, 40, side)
    result = distributed_assign(agents, targets, side, r_comm, algorithm=algorithm)
    _check_complete(result, agents, targets)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_lone_agent_searches_far_in_the_isolated_cluster_construction(algorithm):
    """All agents but one start on targets and stay (monotonic); the last walks to the free target."""
    agents, targets = _adversarial("isolated clusters, one free target last", 40, 80.0)
    result = distributed_assign(agents, targets, 80.0, 6.0, algorithm=algorithm)
    _check_complete(result, agents, targets)
    np.testing.assert_array_equal(result.target_of[:-1], np.arange(39))
    assert (result.distances[:-1] == 0).all()
    assert result.target_of[-1] == 39
    assert result.distances[-1] > np.linalg.norm(targets[39] - agents[39])


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_agents_starting_on_distinct_targets_finish_at_time_zero(algorithm):
    targets = _uniform(3, 25, 25, 50.0)[1]
    result = distributed_assign(targets.copy(), targets, 50.0, 5.0, algorithm=algorithm)
    _check_complete(result, targets, targets)
    assert result.completion_time == 0.0
    np.testing.assert_array_equal(result.target_of, np.arange(25))
    assert (result.distances == 0).all()


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_held_targets_stay_held(algorithm):
    """Monotonic: once an agent stands on a target, some agent stands on it at every later round."""
    agents, targets = _uniform(11, 40, 40, 40.0)
    result = distributed_assign(agents, targets, 40.0, 6.0, algorithm=algorithm, record_trace=True)
    _check_complete(result, agents, targets)
    occupied = (result.trace[:, :, None, :] == targets[None, None, :, :]).all(axis=3).any(axis=1)  # (rounds, m)
    assert occupied[-1].all()
    assert not (occupied[:-1] & ~occupied[1:]).any()


def _first_contact(trace: np.ndarray, group_a: np.ndarray, group_b: np.ndarray, r_comm: float) -> int:
    """First round index at which an agent of group A is within r_comm of one of group B."""
    for k in range(trace.shape[0]):
        gap = np.linalg.norm(trace[k, group_a][:, None, :] - trace[k, group_b][None, :, :], axis=2)
        if (gap <= r_comm).any():
            return k
    return trace.shape[0]


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_a_group_behaves_as_if_alone_until_it_meets_the_other(algorithm):
    """Decisions depend only on agents within r_comm: a group of agents, with the same targets,
    moves exactly as it would without the far-away second group until the groups first come
    within communication range."""
    side, r_comm = 100.0, 5.0
    rng = np.random.default_rng(21)
    group_a = rng.uniform(0, 25, (20, 2))
    group_b = rng.uniform(75, 100, (20, 2))
    targets = np.vstack([rng.uniform(0, 30, (20, 2)), rng.uniform(70, 100, (20, 2))])
    both = distributed_assign(np.vstack([group_a, group_b]), targets, side, r_comm, algorithm=algorithm,
                              record_trace=True)
    alone = distributed_assign(group_a, targets, side, r_comm, algorithm=algorithm, record_trace=True)
    _check_complete(both, np.vstack([group_a, group_b]), targets)
    _check_complete(alone, group_a, targets)
    a, b = np.arange(20), np.arange(20, 40)
    contact = _first_contact(both.trace, a, b, r_comm)
    assert contact > 30, "the groups should stay apart for a while"
    horizon = min(contact, alone.trace.shape[0] - 1)
    np.testing.assert_array_equal(both.trace[: horizon + 1, a], alone.trace[: horizon + 1])
    # ... and the group was not idle meanwhile: its agents moved and talked to each other.
    assert (both.trace[horizon, a] != both.trace[0, a]).any()
    assert alone.messages > 0
    # Alone, the group must also fill the far targets, so the runs do differ eventually.
    assert alone.completion_time != both.completion_time


def test_etsp_agents_out_of_range_go_straight_to_their_nearest_target():
    """With nobody in range there is no message: each agent drives to its nearest target."""
    targets = np.array([[10.0, 10.0], [90.0, 10.0], [10.0, 90.0], [90.0, 90.0]])
    agents = targets + np.array([[5.0, 3.0], [-4.0, 2.0], [3.0, -5.0], [-2.0, -2.0]])
    result = distributed_assign(agents, targets, 100.0, 2.0, algorithm="etsp")
    _check_complete(result, agents, targets)
    assert result.messages == 0
    np.testing.assert_array_equal(result.target_of, np.arange(4))
    np.testing.assert_allclose(result.distances, np.linalg.norm(agents - targets, axis=1))


def test_etsp_conflict_goes_to_the_closer_agent():
    """Two agents heading for the same target: the farther one gives way and takes the other."""
    targets = np.array([[50.0, 50.0], [50.0, 20.0]])
    agents = np.array([[53.0, 50.0], [50.0, 56.0]])  # both nearest to target 0; agent 0 closer
    result = distributed_assign(agents, targets, 100.0, 10.0, algorithm="etsp")
    _check_complete(result, agents, targets)
    assert result.target_of.tolist() == [0, 1]


def test_grid_cells_with_enough_targets_keep_their_agents():
    """GRID ASSGMT: when every cell holds at least as many targets as agents, every agent is
    matched inside its own cell and never crosses a cell border."""
    side, r_comm = 40.0, 10.0
    b = cells_per_side(side, r_comm)
    s = side / b
    rng = np.random.default_rng(5)
    cells = np.stack(np.meshgrid(np.arange(b), np.arange(b)), -1).reshape(-1, 2)
    agents = np.vstack([(c + rng.uniform(0.05, 0.95, (2, 2))) * s for c in cells])
    targets = np.vstack([(c + rng.uniform(0.05, 0.95, (3, 2))) * s for c in cells])
    result = distributed_assign(agents, targets, side, r_comm, algorithm="grid")
    _check_complete(result, agents, targets)
    same_cell = (np.floor(agents / s) == np.floor(result.positions / s)).all(axis=1)
    assert same_cell.all()
    np.testing.assert_allclose(result.distances, np.linalg.norm(result.positions - agents, axis=1))


def test_grid_messages_stay_within_range_and_sensing_matches_full_knowledge():
    agents, targets = _uniform(9, 200, 200, 30.0)
    full = distributed_assign(agents, targets, 30.0, 6.0, algorithm="grid")
    sensing = distributed_assign(agents, targets, 30.0, 6.0, algorithm="grid", r_sense=math.sqrt(0.4) * 6.0)
    _check_complete(full, agents, targets)
    assert 0 < full.max_message_distance <= 6.0
    np.testing.assert_array_equal(full.target_of, sensing.target_of)
    assert full.completion_time == sensing.completion_time


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_same_seed_same_run(algorithm):
    runs = []
    for _ in range(2):
        agents, targets = _uniform(42, 50, 50, 45.0)
        runs.append(distributed_assign(agents, targets, 45.0, 7.0, algorithm=algorithm, record_trace=True))
    first, second = runs
    np.testing.assert_array_equal(first.trace, second.trace)
    np.testing.assert_array_equal(first.target_of, second.target_of)
    np.testing.assert_array_equal(first.arrival_times, second.arrival_times)
    assert (first.completion_time, first.rounds, first.messages) == (second.completion_time, second.rounds,
                                                                     second.messages)


def test_max_time_stops_an_unfinished_run():
    agents, targets = _uniform(1, 30, 30, 100.0)
    result = distributed_assign(agents, targets, 100.0, 5.0, algorithm="etsp", max_time=3.0)
    assert not result.completed
    assert math.isnan(result.completion_time)
    assert result.rounds == 6  # round_time 0.5


def test_no_agents_or_no_targets():
    result = distributed_assign(np.zeros((0, 2)), [[1.0, 1.0]], 5.0, 1.0)
    assert result.completed and result.target_of.shape == (0,)
    result = distributed_assign([[1.0, 1.0]], [], 5.0, 1.0, algorithm="etsp")
    assert result.completed and result.target_of.tolist() == [-1]


@pytest.mark.parametrize(
    "kwargs, message",
    [
        (dict(r_comm=0.0), "r_comm must be a positive finite number"),
        (dict(r_comm=-2.0), "r_comm must be a positive finite number"),
        (dict(r_comm=float("nan")), "r_comm must be a positive finite number"),
        (dict(side=0.0), "side must be a positive finite number"),
        (dict(side="ten"), "side must be a positive number"),
        (dict(v_max=True), "v_max must be a positive number"),
        (dict(r_sense=-1.0), "r_sense must be a positive finite number"),
        (dict(round_time=0.0), "round_time must be a positive finite number"),
        (dict(round_time=10.0), "more than r_comm"),
        (dict(max_time=float("inf")), "max_time must be a positive finite number"),
        (dict(algorithm="auction"), "unknown distributed algorithm 'auction'"),
        (dict(r_sense=1.0), "r_sense 1 is too short for GRID ASSGMT"),
        (dict(algorithm="etsp", r_sense=5.0), "ETSP ASSGMT needs full target knowledge"),
        (dict(agents=[[1.0, 1.0], [2.0, np.nan]]), r"agents\[1, 1\] is nan"),
        (dict(targets=[[1.0, 1.0], [np.inf, 2.0]]), r"targets\[1, 0\] is inf"),
        (dict(agents=[[1.0, 1.0, 1.0]]), r"agents must have shape \(count, 2\)"),
        (dict(targets=[1.0, 2.0]), r"targets must have shape \(count, d\)"),
        (dict(agents=[[1.0, 1.0], [2.0, 11.0]]), r"agents\[1\] = \(2, 11\) lies outside the environment \[0, 10\]\^2"),
        (dict(targets=[[1.0, 1.0], [3.0, 3.0], [1.0, 1.0]]), r"targets\[0\] and targets\[2\] are both at \(1, 1\)"),
    ],
)
def test_bad_input_is_refused_with_a_clear_error(kwargs, message):
    call = dict(agents=[[1.0, 1.0], [2.0, 2.0]], targets=[[3.0, 3.0], [4.0, 4.0]], side=10.0, r_comm=3.0)
    call.update(kwargs)
    with pytest.raises(AssignmentError, match=message):
        distributed_assign(call.pop("agents"), call.pop("targets"), call.pop("side"), call.pop("r_comm"), **call)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_coarsest_rounds_and_tightly_clustered_targets_complete(algorithm):
    """Rounds as rare as allowed (an agent crosses r_comm between two) and 60 targets within
    half a unit: many agents reach a target mid-round and wait, yet the run completes."""
    rng = np.random.default_rng(4)
    targets = 50 + rng.uniform(0, 0.5, (60, 2))
    agents = rng.uniform(0, 100, (60, 2))
    result = distributed_assign(agents, targets, 100.0, 40.0, algorithm=algorithm, round_time=40.0)
    _check_complete(result, agents, targets)


@pytest.mark.slow
@pytest.mark.parametrize("algorithm, area_per_agent, limit", [("etsp", 4.0, 15.0), ("grid", None, 5.0)])
def test_a_thousand_agents_simulate_in_seconds(algorithm, area_per_agent, limit):
    """n = 1000 at the densities of the reproduced results: ETSP ASSGMT with |E| = 4 r² n (thousands
    of rounds), GRID ASSGMT dense with |E| = r² n / (6 ln n)."""
    import time

    n, r_comm = 1000, 10.0
    area = area_per_agent * r_comm**2 * n if area_per_agent else r_comm**2 * n / (6 * math.log(n))
    side = math.sqrt(area)
    agents, targets = _uniform(1, 20, 20, side)
    distributed_assign(agents, targets, side, r_comm, algorithm=algorithm)  # load the compiled kernels
    agents, targets = _uniform(2, n, n, side)
    start = time.perf_counter()
    result = distributed_assign(agents, targets, side, r_comm, algorithm=algorithm)
    assert time.perf_counter() - start < limit
    _check_complete(result, agents, targets)
