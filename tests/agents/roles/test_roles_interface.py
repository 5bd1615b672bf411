"""The role-assigner interface: registry, offensive order, valid permutations, clear errors."""

from __future__ import annotations

import re

import numpy as np
import pytest

from agents.roles import ASSIGNERS, RoleContext, RoleError, assigner_names, make_assigner, offensive_order
from tests.agents.roles.role_situations import at_cycle, context, random_field_points, ready, run

NAMES = ("static", "greedy", "greedy-offense", "mmdr", "mmd+msd2", "msd", "msd2", "random", "bidding")


def test_every_assigner_of_the_specification_is_registered() -> None:
    assert assigner_names() == NAMES
    assert tuple(ASSIGNERS) == NAMES
    for name in NAMES:
        assert make_assigner(name).name == name


def test_offensive_order_is_by_target_x_descending_then_role_index() -> None:
    targets = np.array([[0.0, 0.0], [10.0, 5.0], [10.0, -5.0], [-3.0, 0.0], [10.0, 0.0]])
    assert offensive_order(targets).tolist() == [1, 2, 4, 0, 3]
    assert offensive_order(np.array([[1.0, 2.0]])).tolist() == [0]


@pytest.mark.parametrize("name", NAMES)
def test_every_assigner_returns_a_permutation_for_random_inputs(name: str) -> None:
    rng = np.random.default_rng(len(name))
    for k in range(1, 11):
        assigner = ready(name, k, seed=k)
        previous = None
        for cycle in range(6):
            ctx = context(ball=random_field_points(rng, 1)[0], cycle=cycle, attacking=bool(cycle % 2))
            players, targets = random_field_points(rng, k), random_field_points(rng, k)
            role_of_player = run(assigner, players, targets, previous, ctx)
            assert role_of_player.dtype == np.int64 and role_of_player.shape == (k,)
            assert sorted(role_of_player.tolist()) == list(range(k)), (name, k, cycle)
            goals = assigner.steer(players, targets, role_of_player, ctx)
            assert goals.shape == (k, 2) and np.isfinite(goals).all()
            ball = assigner.ball_player()
            assert ball is None or 0 <= ball < k
            previous = role_of_player


@pytest.mark.parametrize("name", NAMES)
def test_assigners_are_deterministic_given_the_generator(name: str) -> None:
    rng = np.random.default_rng(11)
    situations = [(random_field_points(rng, 10), random_field_points(rng, 10), random_field_points(rng, 1)[0])
                  for _ in range(8)]

    def play(seed: int) -> list[list[int]]:
        assigner, out, previous = ready(name, 10, seed=seed), [], None
        for cycle, (players, targets, ball) in enumerate(situations):
            previous = run(assigner, players, targets, previous, context(ball, cycle))
            out.append(previous.tolist())
        return out

    assert play(5) == play(5)


def test_reset_forgets_the_previous_match() -> None:
    rng = np.random.default_rng(2)
    players, targets = random_field_points(rng, 6), random_field_points(rng, 6)
    for name in ("random", "bidding"):
        assigner = ready(name, 6, seed=3)
        first = [run(assigner, players, targets, ctx=context((5.0, 5.0), c)).tolist() for c in range(3)]
        assigner.reset(6, np.random.default_rng(3))
        again = [run(assigner, players, targets, ctx=context((5.0, 5.0), c)).tolist() for c in range(3)]
        assert first == again, name


def test_the_default_steer_sends_each_player_to_its_role_target() -> None:
    targets = np.array([[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]])
    roles = np.array([2, 0, 1])
    goals = ready("mmdr", 3).steer(np.zeros((3, 2)), targets, roles, context())
    assert goals.tolist() == [[5.0, 6.0], [1.0, 2.0], [3.0, 4.0]]


def test_unknown_names_are_explained_with_the_known_ones() -> None:
    with pytest.raises(RoleError, match=r"unknown role assigner 'mmdx'; known: static, greedy, .*bidding"):
        make_assigner("mmdx")


def test_parameters_are_checked_by_name_and_value() -> None:
    with pytest.raises(RoleError, match="'static' does not take parameters min_hold"):
        make_assigner("static", min_hold=3)
    with pytest.raises(RoleError, match="unknown bidding parameter.*'hold'.*valid: .*min_hold"):
        make_assigner("bidding", hold=3)
    with pytest.raises(RoleError, match="min_hold must be an integer >= 0"):
        make_assigner("bidding", min_hold=-1)
    with pytest.raises(RoleError, match="FieldParams.wall_reach must be > 0"):
        make_assigner("bidding", wall_reach=0.0)
    assigner = make_assigner("bidding", min_hold=4, anchor_weight=0.9)
    assert assigner.params.min_hold == 4 and assigner.params.field.anchor_weight == 0.9


@pytest.mark.parametrize("name", NAMES)
def test_bad_calls_name_the_assigner_and_the_problem(name: str) -> None:
    players, targets = np.zeros((3, 2)), np.arange(6.0).reshape(3, 2)
    with pytest.raises(RoleError, match=re.escape(f"role assigner '{name}'") + ".*reset"):
        make_assigner(name).assign(players, targets, np.arange(3), None, context())
    assigner = ready(name, 3)
    with pytest.raises(RoleError, match=r"reset for 3 roles.*players \(4, 2\)"):
        assigner.assign(np.zeros((4, 2)), targets, np.arange(3), None, context())
    with pytest.raises(RoleError, match=r"targets \(3, 3\)"):
        assigner.assign(players, np.zeros((3, 3)), np.arange(3), None, context())
    with pytest.raises(RoleError, match="n_roles must be a positive integer"):
        make_assigner(name).reset(0, np.random.default_rng(0))
    with pytest.raises(RoleError, match="rng must be a numpy Generator"):
        make_assigner(name).reset(3, 7)


@pytest.mark.parametrize("name", ["greedy-offense", "bidding"])
def test_a_role_order_that_is_not_a_permutation_is_refused(name: str) -> None:
    assigner = ready(name, 3)
    for order in ([0, 0, 1], [0, 1, 3], [0, 1]):
        with pytest.raises(RoleError, match=r"role_order must be a permutation of range\(3\)"):
            assigner.assign(np.zeros((3, 2)), np.arange(6.0).reshape(3, 2), np.array(order), None, context())


def test_context_defaults_are_rcssserver_penalty_area() -> None:
    from soccer_sim.config import STANDARD_FIELD

    ctx = context()
    assert isinstance(ctx, RoleContext)
    assert ctx.penalty_area_length == 16.5 and ctx.penalty_area_half_width == pytest.approx(40.32 / 2)
    # One source: the simulator's default field.
    assert (ctx.penalty_area_length, ctx.penalty_area_half_width) == (
        STANDARD_FIELD.penalty_area_length, STANDARD_FIELD.penalty_area_width / 2.0)
    assert at_cycle(ctx, 9).cycle == 9


@pytest.mark.parametrize("name", NAMES)
def test_an_assigner_that_ignores_the_role_order_says_so(name: str) -> None:
    """Where ``uses_role_order`` is False, the answer is the same for any order and for None
    (the team then skips working it out); where it is True, the order matters somewhere."""
    rng = np.random.default_rng(3)
    differs = False
    for cycle in range(30):
        players, targets = random_field_points(rng, 6), random_field_points(rng, 6)
        ctx = context(ball=random_field_points(rng, 1)[0], cycle=0)
        answers = []
        for order in (offensive_order(targets), rng.permutation(6), None):
            if order is None and make_assigner(name).uses_role_order:
                continue
            answers.append(ready(name, 6, seed=1).assign(players, targets, order, None, ctx).tolist())
        differs |= any(a != answers[0] for a in answers)
    assert differs == make_assigner(name).uses_role_order


def test_every_error_of_the_assigners_and_the_solvers_is_an_agents_error_and_a_value_error() -> None:
    import importlib
    import inspect
    import pkgutil

    import agents.assignment
    import agents.roles
    from agents.assignment import AssignmentError
    from agents.errors import AgentsError

    found = set()
    for package in (agents.roles, agents.assignment):
        for info in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
            for _, cls in inspect.getmembers(importlib.import_module(info.name), inspect.isclass):
                if issubclass(cls, BaseException) and cls.__module__.startswith(package.__name__):
                    found.add(cls)
                    assert issubclass(cls, AgentsError) and issubclass(cls, ValueError), cls
    assert {RoleError, AssignmentError} <= found


def test_bad_input_to_an_assigner_is_a_role_error() -> None:
    from agents.errors import AgentsError
    from agents.roles.matching import MethodAssigner

    with pytest.raises(RoleError, match="MethodAssigner: unknown method 'best'"):
        MethodAssigner("best")
    assigner = ready("msd", 2)
    with pytest.raises(RoleError, match="role assigner 'msd': players and targets must be finite") as caught:
        assigner.assign(np.array([[0.0, np.nan], [1.0, 1.0]]), np.zeros((2, 2)), None, None, context())
    assert isinstance(caught.value, AgentsError) and isinstance(caught.value, ValueError)
