"""The default scenario is the regular match, bit for bit.

The expected fingerprints (score, cycles, hashes of every cycle's world, of the event log and
of the statistics) were recorded with ``tests/soccer_sim/scenario_fingerprint.py`` on the code
base before scenarios existed (commit d7c8672). The same matches played now, without a
scenario, with ``Scenario()`` and with the library's ``full-match``, must give them exactly.
"""

from __future__ import annotations

import pytest

from soccer_sim import Scenario
from soccer_sim.scenarios import get_scenario

from tests.soccer_sim.scenario_fingerprint import CASES, SLOW_CASES, fingerprint

RECORDED = {
    "bidding-press433-1": {"cycles": 6000, "events": "361cad72f11c840f3b5a1f65c205b9bf", "score": [0, 5],
                           "statistics": "234e12a4fe949c23ff0abbf3febcec78",
                           "trajectory": "886aa06cd015ccc51f8724b4f2f89f37"},
    "bidding-statues-4": {"cycles": 700, "events": "7bfdd623d5192a21144ea021e83e8d11", "score": [2, 0],
                          "statistics": "088a417f361d886ca42be67d5732ea3d",
                          "trajectory": "fb71eeb0cb522559255404b5dc88af44"},
    "chaser-chaser-0": {"cycles": 6000, "events": "03e2b91505f4563479e50de2fadad953", "score": [4, 3],
                        "statistics": "089157889def64c5adf91e5b4c632c1f",
                        "trajectory": "7500958a601f8c7b0a2c933478a694ac"},
    "chaser-chaser-1": {"cycles": 6000, "events": "8bbcd4d3e5da208f8b616fb6d4a2786b", "score": [8, 8],
                        "statistics": "247802776ec4d923c995c44e9b44b1de",
                        "trajectory": "11cd777e2aa6a4f3eb74220bb5be9e63"},
    "chaser-idle-2": {"cycles": 6000, "events": "8acde7becc862d027ffd6db0d86f63d1", "score": [20, 0],
                      "statistics": "ae9c92fbbd8daa5790bdc6cb05a36418",
                      "trajectory": "6e6603668c484d312cd9bf2e053c74c0"},
    "counter442-possession-2": {"cycles": 6000, "events": "89a719180d3d156af1238066f55bd975", "score": [0, 0],
                                "statistics": "88767a890156e9ae1abc5bff8437fb13",
                                "trajectory": "a0e38ad6ed45eee732a3509c5a210435"},
    "mmdr-mmd+msd2-0": {"cycles": 6000, "events": "85511ed971c4f815a8cf260610ee3e88", "score": [1, 0],
                        "statistics": "fa64d42cb3c6f2c630219f857b6787a7",
                        "trajectory": "fd4894195c913fb087d4db643b6af71a"},
    "mmdr-press433-3": {"cycles": 700, "events": "56397837035a6fae8bc881c386ef5c6e", "score": [0, 0],
                        "statistics": "abd8aed8306ae1bcb984e01d900181aa",
                        "trajectory": "d6741b890fca13017346177e5ce54742"},
    "static-chaser-5": {"cycles": 700, "events": "836129b75ad74ade583a8ac9e4b0c129", "score": [2, 0],
                        "statistics": "52ecc0b6dfec221a0cdfc89ad4bbeae1",
                        "trajectory": "12f1ff5e257541f6e1d90c345d0145d5"},
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_without_a_scenario_are_the_recorded_ones(name):
    assert fingerprint(*CASES[name]) == RECORDED[name]


@pytest.mark.parametrize("name", ["chaser-chaser-1", "bidding-statues-4"])
def test_the_default_scenario_and_the_library_full_match_are_the_recorded_matches(name):
    assert fingerprint(*CASES[name], scenario=Scenario()) == RECORDED[name]
    assert fingerprint(*CASES[name], scenario="full-match") == RECORDED[name]
    assert get_scenario("full-match").is_regular


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SLOW_CASES))
def test_full_matches_of_built_in_teams_are_the_recorded_ones(name):
    assert fingerprint(*SLOW_CASES[name], scenario=Scenario()) == RECORDED[name]
