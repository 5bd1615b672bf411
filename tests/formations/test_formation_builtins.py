"""The shipped formation sets: complete, covering, sensible, and up to date."""

from __future__ import annotations

from importlib import resources

import numpy as np
import pytest

import formations
from formations import Situation
from formations.design import SYSTEMS, design_set, set_play_distance
from formations.files import dumps
from soccer_sim.config import STANDARD_FIELD

NAMES = ["4-3-3", "4-4-2"]
HL, HW = STANDARD_FIELD.half_length, STANDARD_FIELD.half_width
GRID = np.array([(x, y) for x in np.linspace(-HL, HL, 22) for y in np.linspace(-HW, HW, 13)])
"""Ball positions on and inside the field lines."""


def kinds(formation, kind: str) -> np.ndarray:
    return np.array([role.kind == kind for role in formation.roles])


def test_builtin_names_and_loading():
    assert formations.builtin_names() == NAMES
    for name in NAMES:
        team = formations.load_builtin(name)
        assert team.name == name
        assert team.situations == tuple(Situation)
        assert team.roles[0].number == 1 and team.roles[0].kind == "goalkeeper"
        assert sorted(r.number for r in team.roles) == list(range(1, 12))
    with pytest.raises(ValueError, match="no built-in formation set 'x'.*4-3-3"):
        formations.load_builtin("x")


@pytest.mark.parametrize("name", NAMES)
def test_shipped_files_are_what_the_design_generates(name):
    shipped = resources.files("formations").joinpath("data", f"{name}.json").read_text(encoding="utf-8")
    assert shipped == dumps(design_set(name, STANDARD_FIELD)), (
        "run `python -m tests.formations.write_builtin_sets` to regenerate")


@pytest.mark.parametrize("name", NAMES)
def test_samples_cover_the_whole_field(name):
    penalty_depth = STANDARD_FIELD.penalty_area_length
    penalty_half_width = STANDARD_FIELD.penalty_area_width / 2
    for situation, formation in formations.load_builtin(name).own_formations().items():
        balls = formation.balls
        assert formation.n_samples >= 40
        for corner in ((-HL, -HW), (-HL, HW), (HL, -HW), (HL, HW)):
            assert np.any(np.all(balls == corner, axis=1)), (situation, corner)
        for side in (-HW, HW):
            on_touchline = balls[balls[:, 1] == side]
            assert len(on_touchline) >= 5 and np.ptp(on_touchline[:, 0]) == 2 * HL
        for goal_line in (-HL, HL):
            in_box = (np.abs(balls[:, 0] - goal_line) <= penalty_depth) & (np.abs(balls[:, 1]) <= penalty_half_width)
            assert in_box.sum() >= 6, (situation, goal_line)
        # The hull is the whole field, so no ball in the field is extrapolated.
        projected = np.array([formation.nearest_covered_ball(b) for b in GRID])
        np.testing.assert_allclose(projected, GRID, atol=1e-9)


@pytest.mark.parametrize("name", NAMES)
def test_goalkeeper_in_goal_area_and_everyone_on_the_field(name):
    depth, half_width = STANDARD_FIELD.goal_area_length, STANDARD_FIELD.goal_area_width / 2
    outside = np.array([(x, y) for x in (-70.0, -55.0, 0.0, 56.0, 80.0) for y in (-50.0, -36.0, 0.0, 35.0, 45.0)])
    for situation, formation in formations.load_builtin(name).own_formations().items():
        positions = formation.positions_many(np.vstack((GRID, outside)))
        keeper = positions[:, formation.index_of(1)]
        assert np.all(keeper[:, 0] >= -HL) and np.all(keeper[:, 0] <= -HL + depth), situation
        assert np.all(np.abs(keeper[:, 1]) <= half_width), situation
        assert np.all(np.abs(positions[..., 0]) <= HL) and np.all(np.abs(positions[..., 1]) <= HW)


@pytest.mark.parametrize("name", NAMES)
def test_lines_keep_their_order(name):
    team = formations.load_builtin(name)
    for situation in (Situation.NORMAL, Situation.ATTACK, Situation.DEFEND):
        formation = team.formation(situation)
        positions = formation.positions_many(GRID)
        defence = positions[:, kinds(formation, "defender"), 0].mean(axis=1)
        midfield = positions[:, kinds(formation, "midfielder"), 0].mean(axis=1)
        attack = positions[:, kinds(formation, "forward"), 0].mean(axis=1)
        assert np.all(defence < midfield) and np.all(midfield < attack), situation


@pytest.mark.parametrize("name", NAMES)
def test_defensive_line_stays_behind_the_ball_when_defending(name):
    formation = formations.load_builtin(name).formation(Situation.DEFEND)
    balls = GRID[GRID[:, 0] >= -40.0]  # nearer our goal line the line meets the goal
    defenders = formation.positions_many(balls)[:, kinds(formation, "defender"), 0]
    assert np.all(defenders < balls[:, 0:1] - 3.5)


@pytest.mark.parametrize("name", NAMES)
def test_width_in_attack_and_compactness_in_defence(name):
    team = formations.load_builtin(name)
    attack = team.positions_many(GRID, "attack")[..., 1]
    defend = team.positions_many(GRID, "defend")[..., 1]
    attack_width = attack.max(axis=1) - attack.min(axis=1)
    defend_width = defend.max(axis=1) - defend.min(axis=1)
    assert np.all(attack_width >= 45.0)
    assert np.all(attack_width > defend_width + 5.0)


@pytest.mark.parametrize("name", NAMES)
def test_kick_offs(name):
    team = formations.load_builtin(name)
    ours = team.positions((0.0, 0.0), "our_kickoff")
    theirs = team.positions((0.0, 0.0), "their_kickoff")
    assert np.all(ours[:, 0] <= -0.5) and np.all(theirs[:, 0] <= -0.5)
    # Our kick-off taker stands at the ball; at theirs everybody is outside the centre circle.
    assert np.hypot(*ours.T).min() <= 1.5
    assert np.all(np.hypot(*theirs.T) >= STANDARD_FIELD.centre_circle_radius)


def their_restart_spots() -> dict[str, np.ndarray]:
    """Ball positions (team-relative) where the opponents restart play in a match."""
    xs = np.linspace(-HL, HL, 211)
    their_half = np.array([(x, y) for x in np.linspace(0.0, HL, 36) for y in np.linspace(-HW, HW, 35)])
    return {
        "kick-off": np.array([[0.0, 0.0]]),
        "kick-ins": np.vstack([np.column_stack((xs, np.full_like(xs, side))) for side in (-HW, HW)]),
        "corners": np.array([[-HL, -HW], [-HL, HW]]),
        "goal kicks": np.array([[HL - STANDARD_FIELD.goal_area_length, s * STANDARD_FIELD.goal_area_width / 2] for s in (-1, 1)]),
        "free kicks in their half": their_half,
    }


@pytest.mark.parametrize("name", NAMES)
def test_everyone_keeps_clear_at_their_restarts(name):
    formation = formations.load_builtin(name).formation(Situation.THEIR_SET_PLAY)
    outfield = ~kinds(formation, "goalkeeper")
    in_our_box = (formation.balls[:, 0] < -HL + STANDARD_FIELD.penalty_area_length) & (
        np.abs(formation.balls[:, 1]) < STANDARD_FIELD.penalty_area_width / 2
    )
    for ball, positions in zip(formation.balls[~in_our_box], formation.sample_positions[~in_our_box]):
        distance = np.hypot(*(positions[outfield] - ball).T)
        assert distance.min() >= set_play_distance(STANDARD_FIELD) - 0.01, ball
    # Between the samples too (interpolated), wherever the opponents can restart play.
    for label, balls in their_restart_spots().items():
        positions = formation.positions_many(balls)[:, outfield]
        distance = np.linalg.norm(positions - balls[:, None, :], axis=-1)
        worst = int(distance.min(axis=1).argmin())
        assert distance.min() >= STANDARD_FIELD.centre_circle_radius, (label, balls[worst].tolist())


@pytest.mark.parametrize("name", NAMES)
def test_no_two_players_on_the_same_spot(name):
    balls = np.vstack((GRID, [(x, y) for x in (-60.0, -53.0, 0.0, 54.0, 62.0) for y in (-45.0, -35.0, 0.0, 35.0, 45.0)]))
    pairs = np.triu_indices(11, 1)
    for situation, formation in formations.load_builtin(name).own_formations().items():
        positions = formation.positions_many(balls)
        gaps = np.linalg.norm(positions[:, pairs[0]] - positions[:, pairs[1]], axis=-1)
        ball, pair = np.unravel_index(int(gaps.argmin()), gaps.shape)
        where = (situation.value, balls[ball].tolist(), formation.roles[pairs[0][pair]].name, formation.roles[pairs[1][pair]].name)
        assert gaps.min() >= 1.5, where


def test_systems_have_eleven_roles_with_shirt_numbers():
    for system in SYSTEMS.values():
        assert sorted(d.role.number for d in system.roles) == list(range(1, 12))
