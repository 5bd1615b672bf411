"""PettingZoo's own checks (API, seeds, max cycles, render, state) over the environment's forms:
controlled left, right and both, both action modes, every shipped scenario. A representative
subset runs by default; the full matrix is marked slow."""

from __future__ import annotations

import functools
import itertools
import warnings
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from pettingzoo.test import (api_test, max_cycles_test, parallel_api_test, parallel_seed_test, render_test,
                             seed_test, state_test)

import soccer_sim.env as soccer_env
from soccer_sim.env import EVENT_KIND_NAMES, env, parallel_env
from soccer_sim.scenarios import get_scenario, library, scenario_names

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
CONTROLLED = ("left", "right", "both")
MODES = ("low_level", "high_level")


def _options(controlled: str, mode: str, scenario: str, max_cycles: int) -> dict:
    return dict(controlled=controlled, action_mode=mode, scenario=scenario, opponent="chaser", max_cycles=max_cycles)


def _fields_players(controlled: str, scenario: str) -> bool:
    from soccer_sim.env.options import CONTROLLED as SIDES_OF
    from soccer_sim.setup import MatchSetup

    sizes = MatchSetup.resolve(None, scenario).sizes
    return any(sizes[side] for side in SIDES_OF[controlled])


def _seeded(make, **options):
    """An environment (and its action space) already seeded, so that the checks' own
    ``reset()`` without a seed and their sampled actions are repeatable."""
    environment = make(**options)
    environment.reset(seed=0)
    environment.action_space(environment.possible_agents[0]).seed(0)  # one space object for all agents
    return environment


def _check_all(controlled: str, mode: str, scenario: str, cycles: int, record_dir: Path) -> None:
    options = _options(controlled, mode, scenario, cycles)
    parallel_api_test(parallel_env(**options), num_cycles=cycles)
    api_test(env(**options), num_cycles=cycles)
    seed_test(lambda: env(**options), num_cycles=cycles)
    parallel_seed_test(lambda: parallel_env(**options), num_cycles=cycles)
    state_test(env(**options), parallel_env(**options), num_cycles=cycles)
    # max_cycles_test needs episodes of at least 4 steps: the scenario without its end conditions
    # (a corner may be cleared in 2 cycles), so that the truncation is what ends them.
    fixed = {**options, "max_cycles": None, "scenario": replace(get_scenario(scenario), end_on=())}
    max_cycles_test(SimpleNamespace(parallel_env=lambda **kw: _seeded(parallel_env, **{**fixed, **kw}),
                                    env=lambda **kw: _seeded(env, **{**fixed, **kw})))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # "human" without a display: recorded into record_dir, with a warning
        render_test(lambda render_mode=None: _seeded(env, **options, render_mode=render_mode,
                                                     record_dir=str(record_dir)))


@pytest.mark.parametrize("controlled, mode, scenario", [
    ("both", "low_level", "full-match"),
    ("left", "high_level", "3-vs-1-with-keeper"),
    ("right", "low_level", "run-to-score-with-keeper"),
])
def test_pettingzoo_checks_on_a_representative_subset(controlled: str, mode: str, scenario: str,
                                                     tmp_path: Path) -> None:
    _check_all(controlled, mode, scenario, 12, tmp_path)


def test_pettingzoo_checks_with_the_action_mask_in_the_observation() -> None:
    options = dict(_options("left", "high_level", "counter-attack", 15), action_mask_in_observation=True)
    parallel_api_test(parallel_env(**options), num_cycles=15)
    api_test(env(**options), num_cycles=15)


@pytest.mark.slow
@pytest.mark.parametrize("controlled, mode, scenario", list(itertools.product(CONTROLLED, MODES, scenario_names())))
def test_pettingzoo_checks_on_every_form_and_scenario(controlled: str, mode: str, scenario: str,
                                                     tmp_path: Path) -> None:
    if not _fields_players(controlled, scenario):
        with pytest.raises(ValueError, match="fields no players on the controlled side"):
            parallel_env(**_options(controlled, mode, scenario, 10))
        return
    _check_all(controlled, mode, scenario, 40, tmp_path)
    # Every scenario's episodes run to their end (an end condition or the cycle limit), not only 40 steps.
    environment = parallel_env(**{**_options(controlled, mode, scenario, None), "max_cycles": 3000})
    environment.reset(seed=1)
    while environment.agents:
        *_, terminations, truncations, _ = environment.step(
            {a: environment.action_space(a).sample() for a in environment.agents})
    assert all(terminations.values()) or all(truncations.values())


def test_max_cycles_and_render_as_a_user_calls_them(tmp_path) -> None:
    max_cycles_test(soccer_env)

    def make(render_mode=None):  # "human" works everywhere: a viewer, or a recording where no display is
        return env(max_cycles=10, scenario="counter-attack", opponent="chaser", render_mode=render_mode,
                   record_dir=str(tmp_path))

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        render_test(make)


def test_many_steps_are_determined_by_the_seed_and_actions() -> None:
    """PettingZoo's seed tests compare a few steps; this compares whole episodes of a scenario
    with a randomised start (its start state drawn from the seed), and a long stretch of a match."""
    def episode(seed: int, scenario: str, steps: int) -> list[np.ndarray]:
        environment = parallel_env(scenario=scenario, controlled="both", max_cycles=steps)
        seen = [environment.reset_arrays(seed=seed)]
        rng = np.random.default_rng(7)
        while environment.agents:
            obs, rewards, *_ = environment.step_arrays(rng.uniform(-1, 1, (len(environment.possible_agents), 5)))
            seen.append(np.concatenate([obs.ravel(), rewards, environment.state()]))
        return seen

    first, second = episode(5, "counter-attack", 400), episode(5, "counter-attack", 400)
    assert len(first) == len(second) > 20 and all(np.array_equal(a, b) for a, b in zip(first, second))
    assert not np.array_equal(first[0], episode(6, "counter-attack", 400)[0])  # the start is drawn from the seed
    long_a, long_b = episode(2, "full-match", 800), episode(2, "full-match", 800)
    assert len(long_a) == 801 and all(np.array_equal(a, b) for a, b in zip(long_a, long_b))


# ----------------------------------------------------------------------------- as a user calls them
RERUNS = 20
"""Each check as a user calls it is repeated this many times: no seed, so every rerun plays
other episodes with other random actions."""
ENDS_EARLY_BY_DESIGN = {"corner": "corner-until-goal", "3-vs-1-with-keeper": "3-vs-1-with-keeper-until-goal"}
"""Scenarios whose episodes random actions may end within the 4 cycles of ``max_cycles_test``
by design (docs/scenarios.md, "Episodes that end early"), with the library variant that
passes it in their place: a corner kicked out of play is over, and so is an attack whose
ball is kicked straight at the defender."""


def _as_a_user(scenario: str) -> SimpleNamespace:
    """The module form PettingZoo's ``max_cycles_test`` takes: the environment makers with the
    scenario and nothing else (no seed, default options)."""
    return SimpleNamespace(parallel_env=functools.partial(parallel_env, scenario=scenario),
                           env=functools.partial(env, scenario=scenario))


def _checks_as_a_user(scenario: str, num_cycles: int | None = None, max_cycles: bool = True) -> None:
    """PettingZoo's API, seed and (with ``max_cycles``) max-cycles checks as a user calls them
    on ``scenario``."""
    cycles = {} if num_cycles is None else {"num_cycles": num_cycles}
    parallel_api_test(parallel_env(scenario=scenario), **cycles)
    api_test(env(scenario=scenario), **cycles)
    seed_test(functools.partial(env, scenario=scenario), **cycles)
    parallel_seed_test(functools.partial(parallel_env, scenario=scenario), **cycles)
    if max_cycles:
        max_cycles_test(_as_a_user(ENDS_EARLY_BY_DESIGN.get(scenario, scenario)))


@pytest.mark.slow
@pytest.mark.parametrize("scenario", scenario_names())
def test_every_library_scenario_passes_pettingzoos_checks_as_a_user_calls_them(scenario: str) -> None:
    for _ in range(RERUNS):
        _checks_as_a_user(scenario)


def test_pettingzoos_checks_as_a_user_calls_them_on_a_few_scenarios() -> None:
    """The fast representative of the slow test above: one rerun each, shorter API checks; the
    max-cycles check on the variants random actions cannot end within its 4 cycles."""
    _checks_as_a_user("3-vs-1-with-keeper", num_cycles=40)
    _checks_as_a_user("corner", num_cycles=40)
    for _ in range(3):
        max_cycles_test(_as_a_user("corner-until-goal"))
        max_cycles_test(_as_a_user("3-vs-1-with-keeper-until-goal"))


def test_a_corner_ends_early_only_when_the_ball_is_kicked_out() -> None:
    """Why the corner is in ENDS_EARLY_BY_DESIGN: under random actions a fair share of its
    episodes end within 4 cycles, every one of them by the ball going out of play (the taker
    kicks it over a line from 1 m inside the corner); its variant plays on."""
    early = []
    for seed in range(40):
        environment = parallel_env(scenario="corner")
        environment.reset(seed=seed)
        space = environment.action_space(environment.possible_agents[0])
        space.seed(seed)
        steps = 0
        while environment.agents and steps < 4:
            *_, infos = environment.step({a: space.sample() for a in environment.agents})
            steps += 1
        if not environment.agents:
            events = next(iter(infos.values()))["events"]
            early.append({kind for kind in ("out", "goal") if events[EVENT_KIND_NAMES.index(kind)]})
    assert len(early) >= 5 and all(kinds == {"out"} for kinds in early)
    corner, variant = library()["corner"], library()[ENDS_EARLY_BY_DESIGN["corner"]]
    assert variant.end_on == ("goal",) and replace(variant, name=corner.name, description=corner.description,
                                                   end_on=corner.end_on) == corner
