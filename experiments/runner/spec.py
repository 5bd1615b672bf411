"""What the runner plays: match specifications, the configuration they share and its hash.

A match is a pure function of (home, away, seed, configuration, scenario), so a
specification's :attr:`MatchSpec.identity` covers all of them, and a results file, which holds
the matches of one configuration and scenario (their :func:`config_hash`), keys each match by
(home, away, seed): re-running a command plays only the keys its results file does not hold yet.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, field
from typing import TYPE_CHECKING

from experiments.errors import ParameterError

SIMULATOR = "simulator"
"""The engine of a match played by this project's simulator (:attr:`MatchSpec.engine`)."""

if TYPE_CHECKING:  # annotations only: importing the simulator is left to what plays matches
    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import Scenario


@dataclass(frozen=True, order=True)
class MatchSpec:
    """One match to play: team names (registered names, ``package.module:Attribute`` paths or
    mixed-team names, see :mod:`experiments.mixed_team`), the seed, the cycle limit, and
    optionally a whole configuration and a scenario. Equal specs play the same match; see
    :attr:`identity` for one digest of everything that changes play."""

    home: str
    away: str
    seed: int
    cycles: int | None = None
    """The cycle limit (None: a regulation match); the configuration is :func:`config_for` it
    unless ``configuration`` is given (then it is that configuration's ``max_cycles``)."""
    record: str | None = field(default=None, compare=False)
    """A path to write the match's rerun replay to (``--record-dir``), or None; not part of
    the match's identity."""
    rcg: str | None = field(default=None, compare=False)
    """A path to write the match's rcssserver game log to (``--rcg-dir``), or None; not part of
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

    configuration: MatchConfig | None = None
    """The whole match configuration (physics, rules, stamina, field), or None for the one of
    ``cycles`` (:func:`config_for`)."""
    scenario: Scenario | None = None
    """A scenario to play instead of the regular match from the kick-off, or None."""
    engine: str = SIMULATOR
    """Where the match is played: :data:`SIMULATOR`, or another engine's name (``"rcssserver"``,
    :mod:`experiments.rcss_runs`) whose ``play`` function plays it there. Part of the
    configuration's hash (:func:`config_description`), so one results file never mixes engines."""

    def __post_init__(self) -> None:
        if self.engine != SIMULATOR and self.play is None:
            raise ParameterError("engine", f"{self.engine!r} needs the play function that plays the match there")
        if self.configuration is not None:
            if self.cycles is None:
                object.__setattr__(self, "cycles", self.configuration.max_cycles)
            elif self.cycles != self.configuration.max_cycles:
                raise ParameterError("cycles", f"{self.cycles} differs from the configuration's max_cycles "
                                               f"{self.configuration.max_cycles}")
            if self.configuration == config_for(self.cycles):
                object.__setattr__(self, "configuration", None)   # one form of each spec: equal specs compare equal

    @property
    def identity(self) -> str:
        """A short stable digest (16 hex digits of SHA-256) of everything that changes play: the
        teams, the seed, the whole resolved configuration, the scenario's content (not only its
        name), and a study's ``play`` function and arguments. Equal specs have equal identities;
        the replay and game-log paths and ``plays_teams`` are not part of it."""
        described = {"home": self.home, "away": self.away, "seed": self.seed, "play": self.play,
                     "play_args": [list(pair) for pair in self.play_args],
                     "setting": json.loads(config_description(self.config(), self.scenario, self.engine))}
        return _digest(json.dumps(described, sort_keys=True, default=str))

    @property
    def team_names(self) -> tuple[str, ...]:
        """The team names this spec plays: ``plays_teams``, else (home, away)."""
        return self.plays_teams if self.plays_teams is not None else (self.home, self.away)

    @property
    def key(self) -> tuple[str, str, int]:
        """(home, away, seed): unique within one results file (whose configuration is fixed)."""
        return (self.home, self.away, self.seed)

    def config(self) -> MatchConfig:
        """The configuration this spec plays with: ``configuration``, else that of ``cycles``."""
        return self.configuration if self.configuration is not None else config_for(self.cycles)


def config_for(cycles: int | None) -> MatchConfig:
    """The MatchConfig of a cycle limit (the same rule as ``soccer-sim play``, see
    :func:`experiments.configuration.match_config`)."""
    from experiments.configuration import match_config

    return match_config(cycles)


def config_description(config: MatchConfig, scenario: Scenario | None = None, engine: str = SIMULATOR) -> str:
    """Every parameter of ``config`` as canonical JSON (sorted keys), with the whole content of
    ``scenario`` under the key ``scenario`` when one is played, and ``engine`` under the key
    ``engine`` when it is not the simulator (the simulator's descriptions, and hashes, stay as
    results files have always stored them)."""
    described = asdict(config)
    from soccer_sim.perception.config import ObservationConfig

    if config.observation == ObservationConfig():
        del described["observation"]  # full observation keeps the hash its results files always had
    if scenario is not None:
        from soccer_sim.scenarios import scenario_to_dict

        described["scenario"] = scenario_to_dict(scenario)
    if engine != SIMULATOR:
        described["engine"] = engine
    return json.dumps(described, sort_keys=True, default=str)


def config_hash(config: MatchConfig, scenario: Scenario | None = None, engine: str = SIMULATOR) -> str:
    """A short stable hash (16 hex digits of SHA-256) of every parameter of ``config``, the
    content of ``scenario`` and the ``engine``: the configuration a results file holds matches
    of. Without a scenario, in the simulator, it is the hash of the configuration alone, as
    results files have always stored."""
    return _digest(config_description(config, scenario, engine))


def _digest(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def paired_specs(team: str, opponent: str, games: int, seed: int, cycles: int | None,
                 observation: str = "full", scenario: Scenario | None = None) -> list[MatchSpec]:
    """``games`` matches between two teams on paired seeds: seed ``seed + k`` is played once
    with each team at home, so ``games`` is rounded up to an even number. A team against itself
    plays ``games`` matches on distinct seeds (swapping sides would repeat the same match).
    ``observation``: ``"full"`` or ``"partial"`` (the configuration's observation mode);
    ``scenario``: played instead of the regular match (None)."""
    config = None
    if observation != "full":
        from experiments.configuration import match_config

        config = match_config(cycles, observation)

    def spec(home: str, away: str, s: int) -> MatchSpec:
        return MatchSpec(home, away, s, cycles, configuration=config, scenario=scenario)

    if team == opponent:
        return [spec(team, team, s) for s in range(seed, seed + games)]
    return [one for s in range(seed, seed + (games + 1) // 2)
            for one in (spec(team, opponent, s), spec(opponent, team, s))]


def code_version() -> str:
    """The code version of this process: a hash of the project's source files as imported
    here (see :mod:`experiments.runner.fingerprint`), so a worker on another machine reports
    the code it really runs."""
    from experiments.runner.fingerprint import code_version as imported_code_version

    return imported_code_version()
