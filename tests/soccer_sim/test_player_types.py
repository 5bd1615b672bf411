"""rcssserver's heterogeneous player types: draws within the hetero ranges, derived parameters
by the server's trade-off formulas, determinism per seed, and the teams' choice (pt_max)."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim.config import ConfigError, MatchConfig, PlayerTypeConfig
from soccer_sim.player_types import check_choice, default_type, draw_player_types
from soccer_sim.team import TeamError
from soccer_sim.team_hooks import ChoosesPlayerTypes

CONFIG = MatchConfig()


def _types(seed: int = 7):
    return draw_player_types(CONFIG, np.random.SeedSequence(seed))


def test_eighteen_types_type_zero_is_the_configs_default():
    types = _types()
    assert len(types) == 18 and [t.id for t in types] == list(range(18))
    base = types[0]
    assert base == default_type(CONFIG)
    assert (base.player_speed_max, base.player_decay, base.inertia_moment, base.dash_power_rate) == (1.05, 0.4, 5.0, 0.006)
    assert (base.kickable_margin, base.kick_rand, base.extra_stamina, base.effort_max, base.effort_min) == (
        0.7, 0.1, 50.0, 1.0, 0.6)
    assert base.stamina_inc_max == 45.0 and base.kick_power_rate == pytest.approx(0.027)
    assert base.catchable_area_l_stretch == 1.0 and base.foul_detect_probability == 0.5


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_draws_within_rcssserver_ranges_and_trade_offs(seed):
    for t in _types(seed)[1:]:
        d_decay = t.player_decay - 0.4
        assert -0.1 <= d_decay <= 0.1
        assert t.inertia_moment == pytest.approx(5.0 + 25.0 * d_decay)
        d_dash = t.dash_power_rate - 0.006
        assert -0.0012 <= d_dash <= 0.0008
        assert t.stamina_inc_max == pytest.approx(45.0 - 6000.0 * d_dash)
        d_margin = t.kickable_margin - 0.7
        assert -0.1 <= d_margin <= 0.1
        assert t.kick_rand == pytest.approx(0.1 + d_margin)
        d_extra = t.extra_stamina - 50.0
        assert 0.0 <= d_extra <= 50.0
        assert t.effort_max == pytest.approx(1.0 - 0.004 * d_extra)
        assert t.effort_min == pytest.approx(0.6 - 0.004 * d_extra)
        assert 1.0 <= t.catchable_area_l_stretch <= 1.3
        # zero-width default ranges: unchanged
        assert t.player_speed_max == 1.05 and t.player_size == CONFIG.physics.player_radius
        assert t.kick_power_rate == pytest.approx(0.027) and t.foul_detect_probability == 0.5
        # the acceptance test on the reachable top speed
        top = 100.0 * t.dash_power_rate * t.effort_max / (1.0 - t.player_decay)
        assert 0.75 - 1e-10 < top < t.player_speed_max + 1e-10


def test_deterministic_per_seed_and_different_across_seeds():
    assert _types(5) == _types(5)
    assert _types(5)[1:] != _types(6)[1:]
    assert len({t.player_decay for t in _types(5)[1:]}) == 17


def test_fallback_to_default_after_max_trials():
    # no draw can reach the top speed floor: every type falls back to the default values
    config = MatchConfig(player_types=PlayerTypeConfig(player_speed_max_min=5.0, max_trials=3))
    types = draw_player_types(config, 1)
    assert all(t.player_decay == 0.4 and t.kickable_margin == 0.7 for t in types)
    assert [t.id for t in types] == list(range(18))


def test_config_rejects_bad_values():
    with pytest.raises(ConfigError, match="PlayerTypeConfig.pt_max"):
        PlayerTypeConfig(pt_max=0).validate()
    with pytest.raises(ConfigError, match="PlayerTypeConfig.kick_rand_delta_factor"):
        MatchConfig(player_types=PlayerTypeConfig(kick_rand_delta_factor=float("nan")))


def test_pt_max_enforced_with_the_team_and_player_named():
    types = _types()
    ok = check_choice([0, 1, 2, 0, 3, 0, 0, 0, 0, 0, 17], types, 11, 1, "blue")
    assert ok.tolist() == [0, 1, 2, 0, 3, 0, 0, 0, 0, 0, 17]
    with pytest.raises(TeamError, match=r"team 'blue', player 4: player type 2 is chosen by more than pt_max=1"):
        check_choice([0, 1, 2, 0, 2, 0, 0, 0, 0, 0, 0], types, 11, 1, "blue")
    assert check_choice([2, 2, 0], types, 3, 2, "blue").tolist() == [2, 2, 0]
    with pytest.raises(TeamError, match=r"player 1: player type 18 is not a type id"):
        check_choice([0, 18, 0], types, 3, 1, "red")
    with pytest.raises(TeamError, match="must return 3 type ids"):
        check_choice([0, 0], types, 3, 1, "red")


def test_hook_protocol_and_choices_of_the_wrong_kind():
    types = _types()
    with pytest.raises(TeamError, match=r"player 1: player type 1.0 is not a type id"):
        check_choice([0, 1.0, 0], types, 3, 1, "red")
    assert check_choice(np.array([0, 5, 6], dtype=np.int32), types, 3, 1, "red").tolist() == [0, 5, 6]
    with pytest.raises(TeamError, match="must return a sequence of type ids"):
        check_choice(None, types, 3, 1, "red")
    with pytest.raises(TeamError, match="must return a sequence of type ids"):
        check_choice(np.array(3), types, 3, 1, "red")
    with pytest.raises(TeamError, match="must return 3 type ids, got 1"):
        check_choice(np.zeros((1, 3), dtype=int), types, 3, 1, "red")
    class Chooser:
        def choose_player_types(self, types, side_info):
            return [0] * side_info.players_per_team

    assert isinstance(Chooser(), ChoosesPlayerTypes) and not isinstance(object(), ChoosesPlayerTypes)
