"""The default scenario is the regular match, bit for bit.

The expected fingerprints (score, cycles, hashes of every cycle's world, of the event log and
of the statistics, in ``scenario_fingerprints.json``) were recorded with
``tests/soccer_sim/scenario_fingerprint.py``, first on the code base before scenarios existed
(commit d7c8672), again whenever play changed on purpose (see that module). The same matches
played now, without a scenario, with ``Scenario()`` and with the library's ``full-match``,
must give them exactly. The bits depend on the processor and the
numerical libraries, so the comparison with the recording runs where one exists for this
platform; everywhere, a match without a scenario and the same match with the default scenario
must be identical.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from soccer_sim import Scenario
from soccer_sim.scenarios import get_scenario
from tests.soccer_sim.scenario_fingerprint import CASES, SLOW_CASES, fingerprint, platform_key

RECORDINGS = json.loads(Path(__file__).with_name("scenario_fingerprints.json").read_text())
"""Platform -> fingerprint of every case (see scenario_fingerprint.py for when they were recorded)."""


def recorded(name: str) -> dict:
    """The recorded fingerprint of a case on this platform (the test is skipped where none is)."""
    platform = platform_key()
    if platform not in RECORDINGS:
        pytest.skip(f"no recording for platform {platform!r} (see scenario_fingerprint.py)")
    return RECORDINGS[platform][name]


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_without_a_scenario_are_the_recorded_ones(name):
    assert fingerprint(*CASES[name]) == recorded(name)


@pytest.mark.parametrize("name", ["chaser-chaser-1", "bidding-statues-4", "mmdr-press433-3"])
def test_the_default_scenario_and_the_library_full_match_are_the_regular_match(name):
    regular = fingerprint(*CASES[name])
    assert fingerprint(*CASES[name], scenario=Scenario()) == regular
    assert fingerprint(*CASES[name], scenario="full-match") == regular
    assert get_scenario("full-match").is_regular


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_CASES))
def test_full_matches_of_built_in_teams_are_the_recorded_ones(name):
    assert fingerprint(*SLOW_CASES[name], scenario=Scenario()) == recorded(name)
