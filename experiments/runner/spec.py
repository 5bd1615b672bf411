"""What the runner plays: match specifications, the configuration they share and its hash.

A match is a pure function of (home, away, seed, configuration), so a specification plus the
configuration's hash is the key of a stored result: re-running a command plays only the keys
its results file does not hold yet.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, field
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # annotations only: importing the simulator is left to what plays matches
    from soccer_sim import MatchConfig


@dataclass(frozen=True, order=True)
class MatchSpec:
    """One match to play: team names (registered names, ``package.module:Attribute`` paths or
    mixed-team names, see :mod:`experiments.mixed_team`), the seed and the cycle limit."""

    home: str
    away: str
    seed: int
    cycles: int | None = None
    """``--cycles`` of the command (None: a regulation match); see :func:`config_for`."""
    record: str | None = field(default=None, compare=False)
    """A path to write the match's rerun replay to (``--record-dir``), or None; not part of
    the match's identity."""
    play: str | None = None
    """A ``package.module:function`` path that plays this spec instead of one match (a study's
    own unit of work, e.g. a chain of scenario trials), or None for a match between ``home`` and
    ``away``. The worker calls ``function(spec, record, watch)``: the function plays, wrapping
    every team object it plays with ``watch(team, name, side)`` (so a failure in that team's
    code forfeits the spec for ``side``), and fills ``record``'s goals, cycles and statistics.
    The run's ``figures`` recorder and ``record`` replay do not apply to it. Part of the identity;
    the names and the seed must still make the key unique in a results file."""
    play_args: tuple[tuple[str, object], ...] = ()
    """(name, value) pairs the ``play`` function reads (hashable, picklable); part of the identity."""
    plays_teams: tuple[str, ...] | None = field(default=None, compare=False)
    """The teams a ``play`` function plays (their kernels are warmed and a Ray node's
    pre-flight loads them); None: ``home`` and ``away``. Follows from ``play_args``, so it is
    not part of the identity."""

    @property
    def team_names(self) -> tuple[str, ...]:
        """The team names this spec plays: ``plays_teams``, else (home, away)."""
        return self.plays_teams if self.plays_teams is not None else (self.home, self.away)

    @property
    def key(self) -> tuple[str, str, int]:
        """(home, away, seed): unique within one results file (whose configuration is fixed)."""
        return (self.home, self.away, self.seed)

    def config(self) -> MatchConfig:
        return config_for(self.cycles)


def config_for(cycles: int | None) -> MatchConfig:
    """The MatchConfig of ``--cycles`` (the same rule as ``soccer-sim play``)."""
    from experiments.configuration import match_config

    return match_config(cycles)


def config_description(config: MatchConfig) -> str:
    """Every parameter of ``config`` as canonical JSON (sorted keys)."""
    return json.dumps(asdict(config), sort_keys=True, default=str)


def config_hash(config: MatchConfig) -> str:
    """A short stable hash of every parameter of ``config`` (16 hex digits of SHA-256)."""
    return hashlib.sha256(config_description(config).encode()).hexdigest()[:16]


def paired_specs(team: str, opponent: str, games: int, seed: int, cycles: int | None) -> list[MatchSpec]:
    """``games`` matches between two teams on paired seeds: seed ``seed + k`` is played once
    with each team at home, so ``games`` is rounded up to an even number. A team against itself
    plays ``games`` matches on distinct seeds (swapping sides would repeat the same match)."""
    if team == opponent:
        return [MatchSpec(team, team, s, cycles) for s in range(seed, seed + games)]
    return [spec for s in range(seed, seed + (games + 1) // 2)
            for spec in (MatchSpec(team, opponent, s, cycles), MatchSpec(opponent, team, s, cycles))]


def code_version() -> str:
    """The code version of this process: a hash of the project's source files as imported
    here (see :mod:`experiments.runner.fingerprint`), so a worker on another machine reports
    the code it really runs."""
    from experiments.runner.fingerprint import code_version as imported_code_version

    return imported_code_version()
