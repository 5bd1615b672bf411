"""The regression guard: whole matches, bit for bit, on any x86-64 machine.

The fingerprints (score, cycles, hashes of every cycle's world, of the event log and of the
statistics, in ``scenario_fingerprints.json``) are recorded and played in a child process held
to baseline x86-64 machine code (``tests/soccer_sim/scenario_fingerprint.py``), so the same
code and library versions give the same bits on every machine: a change of play fails here,
never skips. A changed rule constant is shown to fail. In this process, a match without a
scenario, with ``Scenario()`` and with the library's ``full-match`` must be identical.
"""

from __future__ import annotations

import functools

import pytest

from soccer_sim import Scenario
from soccer_sim.scenarios import get_scenario
from tests.soccer_sim.scenario_fingerprint import (CASES, SLOW_CASES, check, fingerprint, load_recordings,
                                                   play_portable)

RECORDINGS = load_recordings()
"""Library versions -> fingerprint of every case (see scenario_fingerprint.py)."""

pytestmark = pytest.mark.xdist_group("fingerprints")  # one worker plays them (one portable child, one compile)


@functools.cache
def portable_fast_cases() -> dict[str, dict[str, object]]:
    """Every fast case, played once in the portable child process."""
    return play_portable(sorted(CASES))


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_are_the_recorded_ones(name):
    check(name, portable_fast_cases()[name], RECORDINGS)


def test_a_changed_rule_constant_fails_the_fingerprints():
    name = "chaser-chaser-1"
    changed = play_portable([name], ball_decay=0.95)[name]
    with pytest.raises(AssertionError, match="differs from its recording"):
        check(name, changed, RECORDINGS)


@pytest.mark.parametrize("name", ["chaser-chaser-1", "bidding-statues-4", "mmdr-press433-3"])
def test_the_default_scenario_and_the_library_full_match_are_the_regular_match(name):
    regular = fingerprint(CASES[name])
    assert fingerprint(CASES[name], scenario=Scenario()) == regular
    assert fingerprint(CASES[name], scenario="full-match") == regular
    assert get_scenario("full-match").is_regular


@pytest.mark.slow
def test_full_matches_of_built_in_teams_are_the_recorded_ones():
    played = play_portable(sorted(SLOW_CASES))
    for name in sorted(SLOW_CASES):
        check(name, played[name], RECORDINGS)
