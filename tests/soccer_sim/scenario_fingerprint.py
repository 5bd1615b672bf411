"""Fingerprints of whole matches, to check that the default scenario reproduces the matches
played before scenarios existed, bit for bit.

A fingerprint hashes every cycle's world (player and ball positions and velocities, play
mode, score), the whole event log and both teams' statistics. It uses only the public API
that existed before scenarios (``run_match`` with recorders), so the same code recorded the
expected values on the older code base (commit d7c8672). Floating-point results depend on
the processor and on the numerical libraries' versions (numba compiles for the host CPU; numpy
and scipy pick vector kernels at run time), so the recordings are kept per
:func:`platform_key`. When play changes on purpose (a rule or a built-in team's behaviour),
the recordings are made again with this module on the new code, which prints the entry of
this platform to put into ``scenario_fingerprints.json``::

    python -m tests.soccer_sim.scenario_fingerprint

On a platform without a recording the tests do not pass silently: :func:`verdict` still plays
each match twice and requires the two to be identical, compares them with the recordings of
the same libraries on other processors (such recordings often carry over: see below), and
skips with a warning that names this processor and the command above when none matches.

(The goal-kick rule of rcssserver, ``proper_goal_kicks`` off, and the built-in teams' set plays
that never stall changed play; the recordings since then are of that code.)
Before that change the recordings on ``znver4`` and ``rocketlake`` processors were equal case
for case, so the trajectories did not depend on which of the two played them.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

import numpy as np

import soccer_sim

CASES: dict[str, tuple[str, str, int, int | None]] = {
    # name: (home, away, seed, max_cycles (None: a full match))
    "chaser-chaser-0": ("chaser", "chaser", 0, None),
    "chaser-chaser-1": ("chaser", "chaser", 1, None),
    "chaser-idle-2": ("chaser", "idle", 2, None),
    "mmdr-press433-3": ("mmdr", "press-433", 3, 700),
    "bidding-statues-4": ("bidding", "statues", 4, 700),
    "static-chaser-5": ("static", "chaser", 5, 700),
}
"""Fast cases: trivial teams over full matches, built-in teams over the first 700 cycles."""

SLOW_CASES: dict[str, tuple[str, str, int, int | None]] = {
    "mmdr-mmd+msd2-0": ("mmdr", "mmd+msd2", 0, None),
    "bidding-press433-1": ("bidding", "press-433", 1, None),
    "counter442-possession-2": ("counter-442", "possession", 2, None),
}
"""Full matches between built-in teams."""


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


RECORDINGS_PATH = Path(__file__).with_name("scenario_fingerprints.json")
RECORD_COMMAND = "python -m tests.soccer_sim.scenario_fingerprint"
"""Prints this platform's entry for :data:`RECORDINGS_PATH`."""


def cpu_name() -> str:
    """The processor numba compiles for: ``NUMBA_CPU_NAME`` when set (e.g. ``generic``), else the host's."""
    import llvmlite.binding
    import numba

    return numba.config.CPU_NAME or llvmlite.binding.get_host_cpu_name()


def library_versions() -> str:
    return " ".join(f"{name}-{metadata.version(name)}" for name in ("numpy", "scipy", "numba", "pymunk", "lap"))


def platform_key() -> str:
    """What the bits of a match depend on besides the code: the CPU and the numerical libraries."""
    return f"{cpu_name()} {library_versions()}"


def load_recordings() -> dict[str, dict[str, dict[str, object]]]:
    """Platform key -> case name -> recorded fingerprint."""
    return json.loads(RECORDINGS_PATH.read_text())


class UnrecordedPlatformWarning(UserWarning):
    """The fingerprints of this platform were never recorded, so bit-identity went unchecked."""


@dataclass(frozen=True)
class Verdict:
    """How a played case compares with the recordings."""

    checked: bool
    """True when the case was compared with a recording (of this platform or, identical, of another)."""
    message: str
    """What was compared, or why nothing could be (naming the processor and the recording command)."""


def verdict(name: str, play: Callable[[], dict[str, object]], recordings: dict[str, dict[str, dict[str, object]]],
            platform: str | None = None) -> Verdict:
    """Play case ``name`` with ``play`` and judge it against ``recordings``.

    With a recording for ``platform`` (default: this one), the fingerprint must equal it (an
    AssertionError otherwise). Without one, the case is played a second time and must come out
    identical (determinism is checked everywhere), and it is compared with the recordings of
    the same libraries on other processors: equal to one of them, it counts as checked;
    different from all (processors may differ in the last bits), it is reported unchecked, with
    the processor and :data:`RECORD_COMMAND` in the message.
    """
    platform = platform_key() if platform is None else platform
    played = play()
    if platform in recordings:
        expected = recordings[platform][name]
        assert played == expected, f"{name} differs from the recording of {platform!r}: {played} != {expected}"
        return Verdict(True, f"{name} equals the recording of {platform!r}")
    again = play()
    assert again == played, f"{name} played twice gave two different matches: {played} != {again}"
    cpu, _, versions = platform.partition(" ")
    others = {key.partition(" ")[0]: cases[name] for key, cases in recordings.items()
              if key.partition(" ")[2] == versions and name in cases}
    same = sorted(other for other, expected in others.items() if expected == played)
    if same:
        return Verdict(True, f"{name} equals the recording of processor {same[0]!r} (same libraries; "
                             f"none exists for {cpu!r})")
    compared = f"differs from the recordings of {sorted(others)}" if others else "no recording of these libraries exists"
    return Verdict(False, f"bit-identity of {name} unchecked on processor {cpu!r} ({versions}): {compared}; "
                          f"only checked that two runs are identical. Record this platform with "
                          f"`{RECORD_COMMAND}` and add its entry to {RECORDINGS_PATH.name}")


FIGURES_ADDED_LATER = ("tackles", "tackles_won", "fouls", "yellow_cards", "red_cards")
"""Statistics figures newer than the recorded fingerprints, left out of the statistics hash:
each counts events of the event log, which the events hash covers already."""


def recorded_figures(figures: dict[str, float]) -> dict[str, float]:
    """``figures`` without the :data:`FIGURES_ADDED_LATER`."""
    return {key: value for key, value in figures.items() if key not in FIGURES_ADDED_LATER}


def fingerprint(home: str, away: str, seed: int, max_cycles: int | None, **match_kwargs: object) -> dict[str, object]:
    """Play the match and return its score, cycles and hashes of trajectory, events and statistics."""
    config = soccer_sim.MatchConfig(max_cycles=max_cycles)
    trace = TrajectoryHash()
    result = soccer_sim.run_match(home, away, seed=seed, config=config, recorders=[trace], **match_kwargs)
    events = hashlib.sha256()
    for name, array in sorted(result.events.as_arrays().items()):
        events.update(name.encode())
        events.update(array.tobytes())
    stats = hashlib.sha256(repr([sorted(recorded_figures(s.as_dict()).items()) for s in result.statistics]).encode())
    return {
        "score": list(result.score), "cycles": result.cycles, "trajectory": trace.hexdigest()[:32],
        "events": events.hexdigest()[:32], "statistics": stats.hexdigest()[:32],
    }


if __name__ == "__main__":
    import json

    recorded = {name: fingerprint(*case) for name, case in {**CASES, **SLOW_CASES}.items()}
    print(json.dumps({platform_key(): recorded}, indent=1, sort_keys=True))
