"""How the fingerprint tests judge a played match against the recordings: exact on a recorded
platform; elsewhere determinism always, the recordings of other processors with the same
libraries when one matches, and an explicit unchecked verdict naming the processor and the
recording command otherwise. (Fake matches: no match is played here.)"""

from __future__ import annotations

import itertools

import numba
import pytest

from tests.soccer_sim.scenario_fingerprint import (CASES, RECORD_COMMAND, SLOW_CASES, cpu_name, library_versions,
                                                   load_recordings, platform_key, verdict)

LIBS = "numpy-1 scipy-1 numba-1 pymunk-7 lap-0"
A = {"score": [1, 0], "trajectory": "aaa"}
B = {"score": [0, 0], "trajectory": "bbb"}
RECORDINGS = {f"znver4 {LIBS}": {"case": A}, f"rocketlake {LIBS}": {"case": A},
              "skylake numpy-0 scipy-0 numba-0 pymunk-6 lap-0": {"case": B}}


def always(fingerprint):
    return lambda: dict(fingerprint)


def test_a_recorded_platform_must_match_its_recording_exactly() -> None:
    result = verdict("case", always(A), RECORDINGS, platform=f"znver4 {LIBS}")
    assert result.checked and "znver4" in result.message
    with pytest.raises(AssertionError, match="differs from the recording"):
        verdict("case", always(B), RECORDINGS, platform=f"znver4 {LIBS}")


def test_an_unrecorded_platform_still_requires_two_identical_runs() -> None:
    runs = itertools.cycle([A, B])
    with pytest.raises(AssertionError, match="played twice"):
        verdict("case", lambda: next(runs), RECORDINGS, platform=f"sapphirerapids {LIBS}")


def test_an_unrecorded_processor_is_checked_against_others_with_the_same_libraries() -> None:
    result = verdict("case", always(A), RECORDINGS, platform=f"sapphirerapids {LIBS}")
    assert result.checked
    assert "rocketlake" in result.message and "sapphirerapids" in result.message


def test_an_unmatched_platform_is_reported_unchecked_naming_cpu_and_command() -> None:
    differs = verdict("case", always(B), RECORDINGS, platform=f"sapphirerapids {LIBS}")
    assert not differs.checked
    assert "sapphirerapids" in differs.message and RECORD_COMMAND in differs.message
    assert "differs from the recordings of ['rocketlake', 'znver4']" in differs.message
    new_libs = verdict("case", always(A), RECORDINGS, platform="znver4 numpy-9 scipy-9 numba-9 pymunk-9 lap-9")
    assert not new_libs.checked and "no recording of these libraries" in new_libs.message


def test_the_platform_key_names_the_processor_numba_compiles_for(monkeypatch) -> None:
    monkeypatch.setattr(numba.config, "CPU_NAME", "generic")
    assert cpu_name() == "generic"
    assert platform_key() == f"generic {library_versions()}"


def test_every_recorded_platform_holds_every_case() -> None:
    names = set(CASES) | set(SLOW_CASES)
    fields = {"score", "cycles", "trajectory", "events", "statistics"}
    for platform, cases in load_recordings().items():
        assert set(cases) == names, platform
        assert all(set(fingerprint) == fields for fingerprint in cases.values()), platform
