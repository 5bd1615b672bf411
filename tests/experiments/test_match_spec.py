"""A match spec's identity covers everything that changes play (teams, seed, the whole resolved
configuration, the scenario's content, a study's play function and arguments), and a results
file holds the matches of one configuration and scenario."""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, replace

import pytest

from experiments.errors import ParameterError
from experiments.results.store import ResultStore
from experiments.runner import MatchSpec, config_for, config_hash, run_matches


def test_equal_specs_have_equal_identities() -> None:
    spec = MatchSpec("chaser", "idle", 3, 100)
    assert spec.identity == MatchSpec("chaser", "idle", 3, 100).identity
    assert spec.identity == replace(spec, record="somewhere.rrd").identity       # a replay is not play
    explicit = MatchSpec("chaser", "idle", 3, configuration=config_for(100))
    assert explicit == spec and explicit.identity == spec.identity and explicit.cycles == 100


def test_teams_seed_and_cycles_are_part_of_the_identity() -> None:
    spec = MatchSpec("chaser", "idle", 3, 100)
    others = [MatchSpec("idle", "chaser", 3, 100), MatchSpec("chaser", "idle", 4, 100),
              MatchSpec("chaser", "idle", 3, 200), replace(spec, play="m:f"), replace(spec, play_args=(("k", 1),))]
    assert len({spec.identity, *(other.identity for other in others)}) == 1 + len(others)


def test_a_physics_rule_or_stamina_parameter_changes_the_identity() -> None:
    config = config_for(100)
    spec = MatchSpec("chaser", "idle", 3, configuration=config)
    changed = [replace(config, physics=replace(config.physics, ball_radius=config.physics.ball_radius * 2)),
               replace(config, rules=replace(config.rules, half_cycles=config.rules.half_cycles + 1)),
               replace(config, stamina=replace(config.stamina, **_changed_number(config.stamina)))]
    for other in changed:
        different = MatchSpec("chaser", "idle", 3, configuration=other)
        assert different != spec and different.identity != spec.identity
        assert different.identity == MatchSpec("chaser", "idle", 3, configuration=other).identity


def test_the_scenario_content_not_only_its_name_changes_the_identity() -> None:
    from soccer_sim.scenarios import get_scenario

    scenario = get_scenario("empty-goal")
    moved = replace(scenario, ball=replace(scenario.ball, position=(scenario.ball.position[0] + 1.0,
                                                                    scenario.ball.position[1])))
    assert moved.name == scenario.name
    plain, with_scenario, with_moved = (MatchSpec("chaser", "idle", 3, 100, scenario=s) for s in (None, scenario, moved))
    assert len({plain.identity, with_scenario.identity, with_moved.identity}) == 3
    assert with_scenario.identity == MatchSpec("chaser", "idle", 3, 100, scenario=get_scenario("empty-goal")).identity
    config = config_for(100)
    assert config_hash(config, scenario) != config_hash(config, moved) != config_hash(config)


def test_the_hash_of_a_configuration_alone_is_the_one_stored_results_files_hold() -> None:
    config = config_for(300)
    described = asdict(config)
    del described["observation"]  # a field added later: left out at its default (full observation)
    legacy = hashlib.sha256(json.dumps(described, sort_keys=True, default=str).encode()).hexdigest()[:16]
    assert config_hash(config) == legacy


def test_a_configuration_that_contradicts_the_cycles_is_refused() -> None:
    with pytest.raises(ParameterError, match="max_cycles") as caught:
        MatchSpec("chaser", "idle", 3, 200, configuration=config_for(100))
    assert caught.value.parameter == "cycles" and isinstance(caught.value, ValueError)


def test_a_run_plays_one_setting_and_keys_its_matches_by_teams_and_seed(tmp_path) -> None:
    from soccer_sim.scenarios import get_scenario

    scenario = get_scenario("empty-goal")
    mixed = [MatchSpec("chaser", "idle", 0, 60), MatchSpec("chaser", "idle", 1, 60, scenario=scenario)]
    with pytest.raises(ParameterError) as caught:
        run_matches(mixed, tmp_path / "mixed.sqlite", "tournament", {}, cycles=60, progress=False)
    assert caught.value.parameter == "specs"
    clash = [MatchSpec("chaser", "idle", 0, 60, play_args=(("k", 1),)), MatchSpec("chaser", "idle", 0, 60)]
    with pytest.raises(ParameterError, match="teams or seed"):
        run_matches(clash, tmp_path / "clash.sqlite", "tournament", {}, cycles=60, progress=False)
    assert not (tmp_path / "mixed.sqlite").exists() and not (tmp_path / "clash.sqlite").exists()

    specs = [MatchSpec("chaser", "idle", seed, 60, scenario=scenario) for seed in (0, 1)]
    out = tmp_path / "s.sqlite"
    first = run_matches(specs[:1], out, "tournament", {}, cycles=60, workers=1, progress=False)
    resumed = run_matches(specs, out, "tournament", {}, cycles=60, workers=1, progress=False)
    assert (first.played, resumed.played, resumed.errors) == (1, 1, 0)
    with ResultStore.open(out) as store:
        assert store.config_hash == config_hash(config_for(60), scenario)
        assert {r.key for r in store.records()} == {spec.key for spec in specs}
    with pytest.raises(Exception, match="different match configuration"):     # another scenario: refused
        run_matches([MatchSpec("chaser", "idle", 0, 60)], out, "tournament", {}, cycles=60, progress=False)


def _changed_number(parameters) -> dict[str, float]:
    """One numeric field of a parameter dataclass, changed."""
    for name, value in asdict(parameters).items():
        if isinstance(value, float) and value > 0:
            return {name: value * 1.5}
    raise AssertionError("no numeric field")
