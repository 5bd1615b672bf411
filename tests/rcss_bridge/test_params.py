"""The server's parameters as the project's MatchConfig and PlayerType (recorded from rcssserver 19)."""

from __future__ import annotations

import dataclasses
import re

import pytest

from rcss_bridge.errors import ProtocolError
from rcss_bridge.params import CONFIG_FIELDS, ServerParameters, player_type, read_parameters
from soccer_sim.player_types import PlayerType
from tests.rcss_bridge.recorded import received


def test_every_mapped_parameter_lands_in_its_field(parameters):
    config = parameters.match_config()
    for name, path, convert in CONFIG_FIELDS:
        part, _, leaf = path.rpartition(".")
        holder = config
        for step in part.split("."):
            holder = getattr(holder, step)
        assert getattr(holder, leaf) == convert(parameters.server[name]), name
    assert config.rules.half_cycles == 3000  # half_time 300 s of 100 ms steps
    assert config.observation.mode == "partial"
    assert config.player_types.types == 18 and config.player_types.pt_max == 1
    assert config.player_types.kickable_margin_delta_max == parameters.player["kickable_margin_delta_max"]


def test_the_server_defaults_are_the_projects(parameters):
    """rcssserver 19's defaults are the project's (its configuration says it follows them)."""
    from soccer_sim.config import MatchConfig
    from soccer_sim.perception.config import ObservationConfig

    assert parameters.match_config() == MatchConfig(observation=ObservationConfig(mode="partial"))


def test_player_types_keep_the_server_names_and_values(parameters):
    assert [t.id for t in parameters.types] == list(range(18))
    assert parameters.types[0].player_decay == 0.4 and parameters.types[0].kickable_margin == 0.7
    text = next(t for t in received("BRIDGE-1")[-1] if t.startswith("(player_type (id 5)"))
    five = parameters.types[5]
    assert isinstance(five, PlayerType)
    for name, value in dataclasses.asdict(five).items():  # each as printed in the recorded message
        printed = re.search(rf"\({name} ([-\d.e]+)\)", text).group(1)
        assert value == float(printed), name


def test_values_without_a_field_stay_at_hand(parameters):
    rest = parameters.unmapped()
    assert rest["synch_mode"] == 1.0 and rest["game_log_dir"] == "./" and "half_time" not in rest
    assert parameters.server["fixed_teamname_l"] == ""


def test_bad_parameter_messages_are_clear():
    with pytest.raises(ProtocolError, match="expected a .server_param"):
        read_parameters("(player_param (a 1))", "server_param")
    with pytest.raises(ProtocolError, match="no kick_rand"):
        player_type("(player_type (id 1)(player_speed_max 1)(stamina_inc_max 45)(player_decay 0.4)(inertia_moment 5)"
                    "(dash_power_rate 0.006)(player_size 0.3)(kickable_margin 0.7))")
    bad = ServerParameters({"player_decay": 1.5}, {}, ())
    with pytest.raises(ProtocolError, match="player_decay"):
        bad.match_config()
