"""Fingerprints of whole matches: the regression guard that notices any change of play.

A fingerprint hashes every cycle's world (player and ball positions and velocities, play
mode, score), the whole event log and both teams' statistics of one match. The recordings in
``scenario_fingerprints.json`` are compared exactly, so a change that should not change play
must leave them equal, and one that does must record them again, on purpose::

    python -m tests.soccer_sim.scenario_fingerprint > tests/soccer_sim/scenario_fingerprints.json

**The same bits on every x86-64 machine.** Floating-point results depend on which machine
code computes them, and three libraries choose that code by the processor they run on: numba
compiles the kernels for the host CPU (FMA, AVX-512 ...), numpy dispatches its loops to the
widest SIMD extension present, and glibc's libm picks FMA or AVX2 variants of ``sin``,
``atan2``, ``exp`` .... The fingerprint matches are therefore played in a child process held to
baseline x86-64 (:func:`portable_environment`): numba compiles for ``NUMBA_CPU_NAME=generic``,
numpy's run-time dispatch is switched off (``NPY_DISABLE_CPU_FEATURES``) and glibc's
``hwcaps`` tunable hides AVX, AVX2, AVX-512 and FMA from libm. What is left depends only on
the code and on the library versions, which the test extra pins; the recordings are kept
per :func:`library_versions` (Python, the C library and the numerical libraries) and no
longer per processor. The child checks that numba compiled for ``generic``.

A library set without a recording fails the tests with the command above in the message; it
never skips (a skip let a change of play pass unnoticed on any machine but the one that
recorded).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import platform
import subprocess
import sys
from dataclasses import dataclass, replace
from importlib import metadata
from pathlib import Path

import numpy as np

import soccer_sim
from soccer_sim.perception.config import ObservationConfig

ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Case:
    """One fingerprinted match."""

    home: str
    away: str
    seed: int
    max_cycles: int | None
    """None: a full match."""
    observation: str = "full"
    """``"full"`` or ``"partial"`` (:class:`soccer_sim.perception.config.ObservationConfig`)."""


CASES: dict[str, Case] = {
    "chaser-chaser-0": Case("chaser", "chaser", 0, None),
    "chaser-chaser-1": Case("chaser", "chaser", 1, None),
    "chaser-idle-2": Case("chaser", "idle", 2, None),
    "mmdr-press433-3": Case("mmdr", "press-433", 3, 700),
    "bidding-statues-4": Case("bidding", "statues", 4, 700),
    "static-chaser-5": Case("static", "chaser", 5, 700),
    "mmdr-counter442-partial-6": Case("mmdr", "counter-442", 6, 500, "partial"),
}
"""Fast cases: trivial teams over full matches, built-in teams over their first cycles (one
of them under partial observation)."""

SLOW_CASES: dict[str, Case] = {
    "mmdr-mmd+msd2-0": Case("mmdr", "mmd+msd2", 0, None),
    "bidding-press433-1": Case("bidding", "press-433", 1, None),
    "counter442-possession-2": Case("counter-442", "possession", 2, None),
    "mmd+msd2-static-partial-3": Case("mmd+msd2", "static", 3, None, "partial"),
}
"""Full matches between built-in teams."""

ALL_CASES: dict[str, Case] = {**CASES, **SLOW_CASES}

RECORDINGS_PATH = Path(__file__).with_name("scenario_fingerprints.json")
RECORD_COMMAND = f"python -m tests.soccer_sim.scenario_fingerprint > {RECORDINGS_PATH.relative_to(ROOT)}"
"""Plays every case in the portable environment and prints the recordings file."""

PINNED_LIBRARIES = ("numpy", "scipy", "numba", "llvmlite", "pymunk", "lap")
"""The libraries whose versions the bits depend on (pinned by the ``test`` extra)."""

BASELINE_HIDDEN_HWCAPS = ("AVX", "AVX2", "FMA", "FMA4", "AVX512F", "AVX512CD", "AVX512DQ", "AVX512BW", "AVX512VL")
"""CPU features glibc's ifuncs (libm's ``sin``, ``atan2``, ``exp`` ...) are told are absent."""


class TrajectoryHash:
    """A recorder hashing the world after the opening kick-off and after every cycle."""

    def __init__(self) -> None:
        self._hash = hashlib.sha256()

    def _add(self, match: object) -> None:
        state = match.state
        h = self._hash
        for array in (state.pos, state.vel, state.ball, state.ball_vel, state.score):
            h.update(np.ascontiguousarray(array).tobytes())
        h.update(bytes((int(state.play_mode), int(state.mode_team) + 1)))

    def on_start(self, match: object) -> None:
        self._add(match)

    def on_cycle(self, match: object) -> None:
        self._add(match)

    def on_end(self, match: object) -> None:
        pass

    def hexdigest(self) -> str:
        return self._hash.hexdigest()


def cpu_name() -> str:
    """The processor numba compiles for: ``NUMBA_CPU_NAME`` when set (``generic`` in the
    portable environment), else the host's."""
    import llvmlite.binding
    import numba

    return numba.config.CPU_NAME or llvmlite.binding.get_host_cpu_name()


def library_versions() -> str:
    """The key of the recordings: Python's minor version, the C library's (its libm computes
    ``sin``, ``atan2`` ... for numba's kernels and pymunk) and the :data:`PINNED_LIBRARIES`'."""
    major, minor, _ = platform.python_version_tuple()
    libc, libc_version = platform.libc_ver()
    versions = " ".join(f"{name}-{metadata.version(name)}" for name in PINNED_LIBRARIES)
    return f"python-{major}.{minor} {libc or 'libc'}-{libc_version or 'unknown'} {versions}"


def portable_environment() -> dict[str, str]:
    """The variables that hold numba, numpy and glibc's libm to baseline x86-64 machine code
    (module docstring), added to this process's environment."""
    from numpy._core._multiarray_umath import __cpu_dispatch__

    hidden = ",".join(f"-{feature}" for feature in BASELINE_HIDDEN_HWCAPS)
    return {**os.environ, "NUMBA_CPU_NAME": "generic", "NUMBA_CPU_FEATURES": "",
            "NPY_DISABLE_CPU_FEATURES": " ".join(__cpu_dispatch__),
            "GLIBC_TUNABLES": f"glibc.cpu.hwcaps={hidden}"}


def load_recordings() -> dict[str, dict[str, dict[str, object]]]:
    """Library versions -> case name -> recorded fingerprint."""
    return json.loads(RECORDINGS_PATH.read_text())


FIGURES_ADDED_LATER = ("tackles", "tackles_won", "fouls", "yellow_cards", "red_cards")
"""Statistics figures left out of the statistics hash: each counts events of the event log,
which the events hash covers already."""


def recorded_figures(figures: dict[str, float]) -> dict[str, float]:
    """``figures`` without the :data:`FIGURES_ADDED_LATER`."""
    return {key: value for key, value in figures.items() if key not in FIGURES_ADDED_LATER}


def fingerprint(case: Case, config: soccer_sim.MatchConfig | None = None,
                **match_kwargs: object) -> dict[str, object]:
    """Play ``case`` here (with ``config``'s rules if given) and return its score, cycles and
    hashes of trajectory, events and statistics."""
    config = replace(config or soccer_sim.MatchConfig(), max_cycles=case.max_cycles,
                     observation=ObservationConfig(mode=case.observation))
    trace = TrajectoryHash()
    result = soccer_sim.run_match(case.home, case.away, seed=case.seed, config=config, recorders=[trace],
                                  **match_kwargs)
    events = hashlib.sha256()
    for name, array in sorted(result.events.as_arrays().items()):
        events.update(name.encode())
        events.update(array.tobytes())
    stats = hashlib.sha256(repr([sorted(recorded_figures(s.as_dict()).items()) for s in result.statistics]).encode())
    return {
        "score": list(result.score), "cycles": result.cycles, "trajectory": trace.hexdigest()[:32],
        "events": events.hexdigest()[:32], "statistics": stats.hexdigest()[:32],
    }


def play_portable(names: list[str], ball_decay: float | None = None, timeout: float = 1800.0) -> dict[str, dict]:
    """Play the cases ``names`` in a child process held to baseline x86-64
    (:func:`portable_environment`); ``ball_decay`` replaces the rule's constant (to show that the
    fingerprints notice). Returns name -> fingerprint."""
    command = [sys.executable, "-m", "tests.soccer_sim.scenario_fingerprint", "--play", ",".join(names)]
    if ball_decay is not None:
        command += ["--ball-decay", repr(ball_decay)]
    done = subprocess.run(command, cwd=ROOT, env=portable_environment(), capture_output=True, text=True,
                          timeout=timeout)
    if done.returncode != 0:
        raise RuntimeError(f"the portable fingerprint process failed ({done.returncode}): {done.stderr[-2000:]}")
    played = json.loads(done.stdout)
    assert played["cpu"] == "generic", f"the child compiled for {played['cpu']!r}, not generic x86-64"
    return played["cases"]


def check(name: str, played: dict[str, object], recordings: dict[str, dict[str, dict[str, object]]],
          libraries: str | None = None) -> None:
    """Require ``played`` (case ``name``) to equal its recording for ``libraries`` (default:
    the installed ones); an AssertionError says what differs, or that these libraries have no
    recording and how to make one."""
    libraries = library_versions() if libraries is None else libraries
    assert libraries in recordings, (
        f"no fingerprints are recorded for {libraries!r} (recorded: {sorted(recordings)}); install the pinned "
        f"versions (pip install -e '.[test]') or record these with `{RECORD_COMMAND}`")
    expected = recordings[libraries][name]
    assert played == expected, (f"{name} differs from its recording ({libraries}): {played} != {expected}; "
                                f"if play changed on purpose, record again with `{RECORD_COMMAND}`")


def _main() -> None:
    parser = argparse.ArgumentParser(description="Play the fingerprint cases (portable: see the module docstring).")
    parser.add_argument("--play", help="play these comma-separated cases here and print their fingerprints as JSON")
    parser.add_argument("--ball-decay", type=float, help="with --play: replace PhysicsConfig.ball_decay")
    arguments = parser.parse_args()
    if arguments.play is None:  # the recordings file, played in the portable environment
        played = play_portable(list(ALL_CASES))
        print(json.dumps({library_versions(): played}, indent=1, sort_keys=True))
        return
    config = soccer_sim.MatchConfig()
    if arguments.ball_decay is not None:
        config = replace(config, physics=replace(config.physics, ball_decay=arguments.ball_decay))
    cases = {name: fingerprint(ALL_CASES[name], config) for name in arguments.play.split(",")}
    print(json.dumps({"cpu": cpu_name(), "cases": cases}))


if __name__ == "__main__":
    _main()
