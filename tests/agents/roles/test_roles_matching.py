"""The distance-matching assigners on hand-made situations and against brute force."""

from __future__ import annotations

import numpy as np
import pytest

from tests.agents.roles.role_situations import all_assignments, context, distances, ready, run

# Two players, two roles: greedy grabs the shortest pair (player 0 -> role 0, 1 m) and leaves
# player 1 a 10 m walk; the minimal-makespan assignment crosses over (5 m and 4 m).
CROSSING_PLAYERS = [[0.0, 0.0], [5.0, 0.0]]
CROSSING_TARGETS = [[1.0, 0.0], [-5.0, 0.0]]


def makespan(players, targets, role_of_player) -> float:
    d = distances(players, targets)
    return float(d[np.arange(len(role_of_player)), role_of_player].max())


def test_static_is_the_identity_whatever_the_positions() -> None:
    assigner = ready("static", 4)
    players = [[9.0, 9.0], [0.0, 0.0], [5.0, 5.0], [-20.0, 3.0]]
    targets = [[0.0, 0.0], [5.0, 5.0], [9.0, 9.0], [30.0, 0.0]]
    first = run(assigner, players, targets)
    assert first.tolist() == [0, 1, 2, 3]
    first[0] = 3  # the returned array is the caller's
    assert run(assigner, players, targets).tolist() == [0, 1, 2, 3]


def test_greedy_and_mmdr_disagree_on_the_crossing_instance() -> None:
    assert run(ready("greedy", 2), CROSSING_PLAYERS, CROSSING_TARGETS).tolist() == [0, 1]
    assert makespan(CROSSING_PLAYERS, CROSSING_TARGETS, np.array([0, 1])) == pytest.approx(10.0)
    for name in ("mmdr", "mmd+msd2"):
        roles = run(ready(name, 2), CROSSING_PLAYERS, CROSSING_TARGETS)
        assert roles.tolist() == [1, 0]
        assert makespan(CROSSING_PLAYERS, CROSSING_TARGETS, roles) == pytest.approx(5.0)


def _greedy_reference(d: np.ndarray) -> list[int]:
    """Shortest remaining pair first, by hand."""
    d = d.copy()
    role = [-1] * d.shape[0]
    for _ in range(d.shape[0]):
        i, r = np.unravel_index(np.argmin(d), d.shape)
        role[i] = int(r)
        d[i, :] = np.inf
        d[:, r] = np.inf
    return role


def test_greedy_takes_the_shortest_remaining_pair_each_time() -> None:
    rng = np.random.default_rng(4)
    for _ in range(30):
        players, targets = rng.uniform(-40, 40, (10, 2)), rng.uniform(-40, 40, (10, 2))
        assert run(ready("greedy", 10), players, targets).tolist() == _greedy_reference(distances(players, targets))


def test_greedy_offense_gives_the_most_offensive_role_to_its_nearest_player() -> None:
    # Role 1 (x = 13) is the most offensive: player 0 (3 m from it) takes it, although player 0
    # and role 0 are the shortest pair (0.5 m), which greedy by pairs takes first.
    players = [[10.0, 0.0], [0.0, 0.0]]
    targets = [[10.5, 0.0], [13.0, 0.0]]
    assert run(ready("greedy-offense", 2), players, targets).tolist() == [1, 0]
    assert run(ready("greedy", 2), players, targets).tolist() == [0, 1]
    # Three roles in offensive order 2, 0, 1: each to the nearest player still free.
    players = [[0.0, 0.0], [20.0, 0.0], [10.0, 0.0]]
    targets = [[12.0, 0.0], [5.0, 0.0], [30.0, 0.0]]
    assert run(ready("greedy-offense", 3), players, targets).tolist() == [1, 2, 0]


def test_greedy_offense_follows_the_order_it_is_given() -> None:
    assigner = ready("greedy-offense", 2)
    targets = np.array([[4.0, 0.0], [6.0, 0.0]])
    players = np.array([[5.5, 0.0], [0.0, 0.0]])  # player 0 is nearer to both roles: the first role's
    assert assigner.assign(players, targets, np.array([0, 1]), None, context()).tolist() == [0, 1]
    assert assigner.assign(players, targets, np.array([1, 0]), None, context()).tolist() == [1, 0]


@pytest.mark.parametrize("seed", range(5))
def test_scram_and_sum_methods_are_optimal_against_brute_force(seed: int) -> None:
    rng = np.random.default_rng(seed)
    players, targets = rng.uniform(-40, 40, (6, 2)), rng.uniform(-40, 40, (6, 2))
    d = distances(players, targets)
    rows = np.arange(6)
    chosen = {p.tobytes(): d[rows, p] for p in all_assignments(6)}
    best_makespan = min(v.max() for v in chosen.values())
    best_squares_at_makespan = min((v ** 2).sum() for v in chosen.values() if v.max() <= best_makespan + 1e-9)
    got = {name: d[rows, run(ready(name, 6), players, targets)] for name in ("mmdr", "mmd+msd2", "msd", "msd2")}
    assert got["mmdr"].max() == pytest.approx(best_makespan)
    assert got["mmd+msd2"].max() == pytest.approx(best_makespan)
    assert (got["mmd+msd2"] ** 2).sum() == pytest.approx(best_squares_at_makespan)
    assert got["msd"].sum() == pytest.approx(min(v.sum() for v in chosen.values()))
    assert (got["msd2"] ** 2).sum() == pytest.approx(min((v ** 2).sum() for v in chosen.values()))


def test_mmdr_minimises_the_sorted_distances_lexicographically() -> None:
    rng = np.random.default_rng(9)
    players, targets = rng.uniform(-40, 40, (6, 2)), rng.uniform(-40, 40, (6, 2))
    d = distances(players, targets)
    rows = np.arange(6)
    best = min(tuple(np.round(np.sort(d[rows, p])[::-1], 9)) for p in all_assignments(6))
    roles = run(ready("mmdr", 6), players, targets)
    assert tuple(np.round(np.sort(d[rows, roles])[::-1], 9)) == best


def test_random_is_reproducible_for_a_seed_changes_every_call_and_differs_across_seeds() -> None:
    players, targets = np.zeros((10, 2)), np.arange(20.0).reshape(10, 2)
    one = [run(ready("random", 10, seed=1), players, targets).tolist() for _ in range(2)]
    assert one[0] == one[1]
    assigner = ready("random", 10, seed=1)
    draws = [tuple(run(assigner, players, targets).tolist()) for _ in range(5)]
    assert draws[0] == tuple(one[0]) and len(set(draws)) == 5
    assert run(ready("random", 10, seed=2), players, targets).tolist() != one[0]
    # It draws from the generator given to reset, and from nothing else.
    rng = np.random.default_rng(1)
    assert draws[0] == tuple(rng.permutation(10).tolist())
