"""How the fingerprint tests judge a played match against the recordings: exactly, by library
versions; a library set without a recording fails (never skips) and says how to record; the
portable environment holds numba, numpy and glibc to baseline x86-64. (Fake matches: no match
is played here.)"""

from __future__ import annotations

import numba
import pytest

from tests.soccer_sim.scenario_fingerprint import (ALL_CASES, BASELINE_HIDDEN_HWCAPS, RECORD_COMMAND, cpu_name,
                                                   library_versions, load_recordings, portable_environment, check)

LIBS = "python-3.11 glibc-2.36 numpy-1 scipy-1 numba-1 llvmlite-1 pymunk-7 lap-0"
A = {"score": [1, 0], "trajectory": "aaa"}
B = {"score": [0, 0], "trajectory": "bbb"}
RECORDINGS = {LIBS: {"case": A}}


def test_a_recorded_library_set_must_match_its_recording_exactly() -> None:
    check("case", dict(A), RECORDINGS, libraries=LIBS)
    with pytest.raises(AssertionError, match="differs from its recording"):
        check("case", dict(B), RECORDINGS, libraries=LIBS)


def test_libraries_without_a_recording_fail_naming_them_and_the_command() -> None:
    other = LIBS.replace("numpy-1", "numpy-9")
    with pytest.raises(AssertionError, match="no fingerprints are recorded") as raised:
        check("case", dict(A), RECORDINGS, libraries=other)
    assert other in str(raised.value) and RECORD_COMMAND in str(raised.value)


def test_the_portable_environment_asks_for_baseline_machine_code() -> None:
    environment = portable_environment()
    assert environment["NUMBA_CPU_NAME"] == "generic" and environment["NUMBA_CPU_FEATURES"] == ""
    assert all(f"-{feature}" in environment["GLIBC_TUNABLES"] for feature in ("AVX2", "FMA", "AVX512F"))
    assert set(BASELINE_HIDDEN_HWCAPS) >= {"AVX", "AVX2", "FMA"}
    from numpy._core._multiarray_umath import __cpu_dispatch__
    assert environment["NPY_DISABLE_CPU_FEATURES"].split() == list(__cpu_dispatch__)


def test_cpu_name_is_what_numba_compiles_for(monkeypatch) -> None:
    monkeypatch.setattr(numba.config, "CPU_NAME", "generic")
    assert cpu_name() == "generic"


def test_the_installed_libraries_have_a_recording_of_every_case() -> None:
    recordings = load_recordings()
    assert library_versions() in recordings, f"install the pinned versions or record: {RECORD_COMMAND}"
    fields = {"score", "cycles", "trajectory", "events", "statistics"}
    for libraries, cases in recordings.items():
        assert set(cases) == set(ALL_CASES), libraries
        assert all(set(fingerprint) == fields for fingerprint in cases.values()), libraries
