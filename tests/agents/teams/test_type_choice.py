"""Heterogeneous player types in the built-in team: which type plays which role, and the
time factors the role assigners get."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from agents.teams import FormationTeam
from agents.teams.type_choice import time_scales, top_speed
from soccer_sim import MatchConfig, SideInfo
from soccer_sim.player_types import check_choice, default_type, draw_player_types

CONFIG = MatchConfig()
BASE = default_type(CONFIG)
SIDE = SideInfo(0, "us", "them", 11, 0, 11, 0)


def _speed_type(type_id: int, speed: float, **other: float):
    """A type whose real top speed is ``speed`` (m/cycle; decay kept, dash rate adjusted)."""
    rate = speed * (1.0 - BASE.player_decay) / (CONFIG.physics.dash_power_max * BASE.effort_max)
    return replace(BASE, id=type_id, dash_power_rate=rate, **other)


def _types() -> tuple:
    """Type 0 (top speed 1.0); 1-6 faster (1.049 down to 1.024) with little stamina; 7-9 slow
    with the most stamina recovery; 10 slow with the largest catchable area."""
    fast = [_speed_type(i, 1.05 - 0.005 * i, stamina_inc_max=40.0) for i in range(1, 7)]
    stamina = [_speed_type(i, 0.85, stamina_inc_max=60.0 - i) for i in range(7, 10)]
    keeper = [_speed_type(10, 0.8, stamina_inc_max=40.0, catchable_area_l_stretch=1.3)]
    return (BASE, *fast, *stamina, *keeper)


def test_fastest_types_to_forwards_and_wide_players_stamina_to_central_midfielders() -> None:
    team = FormationTeam("mmdr")  # 4-3-3: rows = shirt numbers - 1
    types = _types()
    assert top_speed(types[1]) > top_speed(types[6]) > top_speed(types[0]) > top_speed(types[7])
    choice = team.choose_player_types(types, SIDE)
    by_role = {role.name: choice[row] for row, role in enumerate(team.formation_set.roles)}
    # Forwards first (role order), then the full-backs: the six fastest types, fastest first.
    assert [by_role[n] for n in ("right winger", "centre forward", "left winger", "right back", "left back")] == \
        [1, 2, 3, 4, 5]
    # Central midfielders: the most stamina recovery.
    assert [by_role[n] for n in ("defensive midfielder", "right central midfielder", "left central midfielder")] == \
        [7, 8, 9]
    # Centre-backs: the fastest left (type 6, then the default type, faster than the rest).
    assert [by_role["right centre back"], by_role["left centre back"]] == [6, 0]
    assert by_role["goalkeeper"] == 10  # the largest catchable area
    check_choice(choice, types, 11, 1, "us")  # within pt_max = 1


def test_choice_from_drawn_types_obeys_pt_max() -> None:
    for seed in range(5):
        types = draw_player_types(CONFIG, seed)
        choice = FormationTeam("static").choose_player_types(types, SIDE)
        ids = check_choice(choice, types, 11, 1, "us")  # raises beyond pt_max
        used = ids[ids > 0]
        assert len(used) == len(set(used.tolist()))
        # No forward plays a type slower than one left unused.
        unused = [t for t in range(1, len(types)) if t not in set(ids.tolist())]
        slowest_forward = min(top_speed(types[ids[row]]) for row in (6, 8, 10))
        assert all(top_speed(types[t]) <= slowest_forward for t in unused)


def test_time_factors_none_for_equal_players_else_reference_over_speed() -> None:
    types = _types()
    outfield = np.arange(1, 11)
    assert time_scales(types, (0,) * 11, outfield, CONFIG) is None
    assert time_scales(types, (), outfield, CONFIG) is None
    own = (10, 1, 0, 0, 0, 0, 7, 0, 0, 0, 0)
    scale = time_scales(types, own, outfield, CONFIG)
    assert scale[0] == top_speed(types[0]) / top_speed(types[1]) < 1.0  # faster: its metres cost less
    assert scale[5] > 1.0 and scale[1] == 1.0
    team = FormationTeam("mmdr")
    team.reset(replace(SIDE, player_types=types, own_types=(0,) * 11), CONFIG, np.random.default_rng(0))
    assert team.pipeline.contexts[0].time_scale is None  # equal players: the assigners use plain distances
    team.reset(replace(SIDE, player_types=types, own_types=own), CONFIG, np.random.default_rng(0))
    assert np.array_equal(team.pipeline.contexts[0].time_scale, scale)
