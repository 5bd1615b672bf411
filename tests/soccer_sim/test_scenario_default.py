"""The default scenario is the regular match, bit for bit.

The expected fingerprints (score, cycles, hashes of every cycle's world, of the event log and
of the statistics, in ``scenario_fingerprints.json``) were recorded with
``tests/soccer_sim/scenario_fingerprint.py``, first on the code base before scenarios existed
(commit d7c8672), again whenever play changed on purpose (see that module). The same matches
played now, without a scenario, with ``Scenario()`` and with the library's ``full-match``,
must give them exactly. The bits depend on the processor and the
numerical libraries, so the comparison with the recording runs where one exists for this
platform (or an identical one of another processor); elsewhere each match must at least come
out identical when played twice, and the test is skipped with a warning that names the
processor and the command that records it. Everywhere, a match without a scenario and the
same match with the default scenario must be identical.
"""

from __future__ import annotations

import warnings

import pytest

from soccer_sim import Scenario
from soccer_sim.scenarios import get_scenario
from tests.soccer_sim.scenario_fingerprint import (CASES, SLOW_CASES, UnrecordedPlatformWarning, fingerprint,
                                                   load_recordings, verdict)

RECORDINGS = load_recordings()
"""Platform -> fingerprint of every case (see scenario_fingerprint.py for when they were recorded)."""


def check_recorded(name: str, case: tuple, **match_kwargs: object) -> None:
    """Play ``case`` and compare it with the recordings (see ``scenario_fingerprint.verdict``);
    where none applies, warn and skip, naming the processor and the recording command."""
    result = verdict(name, lambda: fingerprint(*case, **match_kwargs), RECORDINGS)
    if not result.checked:
        warnings.warn(result.message, UnrecordedPlatformWarning, stacklevel=2)
        pytest.skip(result.message)


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_without_a_scenario_are_the_recorded_ones(name):
    check_recorded(name, CASES[name])


@pytest.mark.parametrize("name", ["chaser-chaser-1", "bidding-statues-4", "mmdr-press433-3"])
def test_the_default_scenario_and_the_library_full_match_are_the_regular_match(name):
    regular = fingerprint(*CASES[name])
    assert fingerprint(*CASES[name], scenario=Scenario()) == regular
    assert fingerprint(*CASES[name], scenario="full-match") == regular
    assert get_scenario("full-match").is_regular


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_CASES))
def test_full_matches_of_built_in_teams_are_the_recorded_ones(name):
    check_recorded(name, SLOW_CASES[name], scenario=Scenario())
