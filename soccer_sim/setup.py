"""What a match is set up as, resolved once from the configuration and the scenario.

A :class:`~soccer_sim.config.MatchConfig` says how the game is played in general (the field,
the physics, the rules, the length); a :class:`~soccer_sim.scenarios.Scenario` says what this
match is (the sides' sizes and goalkeepers, the start, the rules it switches, the end
conditions). :meth:`MatchSetup.resolve` combines the two into one :class:`MatchSetup` that
the match loop, the referee and its rules, the environment and the teams' :class:`SideInfo`
are built from, so no component reads parts of both on its own.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from soccer_sim.config import MatchConfig
from soccer_sim.ending import MatchEnd
from soccer_sim.errors import SoccerSimError
from soccer_sim.scenarios.library import get_scenario
from soccer_sim.scenarios.scenario import Scenario, ScenarioError
from soccer_sim.state import NO_PLAYER, PlayMode
from soccer_sim.team import SideInfo


class SetupTypeError(SoccerSimError, TypeError):
    """A match's configuration or setup given as something else (a TypeError too)."""


@dataclass(frozen=True)
class MatchSetup:
    """One match's sides, rules on/off, start and end (see the module docstring).

    Build it with :meth:`resolve`; ``MatchSetup.resolve()`` is the regular match.
    """

    config: MatchConfig
    """The configuration played: the one given, with the scenario's offside switch applied."""
    scenario: Scenario
    """The scenario played (the regular match by default)."""
    sizes: tuple[int, int]
    """(home, away) players; player rows ``0..home-1`` are home's, the rest away's."""
    goalies: tuple[int, int]
    """Each side's goalkeeper index within the side, ``NO_PLAYER`` (-1) for none."""
    set_plays: bool
    """Whether restarts are set plays; False: every restart but the opening one is a dropped
    ball on its spot."""
    half_time: bool
    """Whether the match has a half-time break at ``config.rules.half_cycles`` (away kicks off the
    second half; the ends stay); False: one period."""
    start_mode: PlayMode
    """The play mode play opens in."""
    start_side: int
    """The side the opening set play belongs to."""
    attacking_side: int
    """The side with the ball's initiative (``"scored"`` and ``"lost"`` end conditions)."""
    end: MatchEnd
    """When the match ends (:mod:`soccer_sim.ending`)."""

    @classmethod
    def resolve(cls, config: MatchConfig | None = None, scenario: Scenario | str | None = None) -> MatchSetup:
        """The setup of a match played with ``config`` (None: the defaults) and ``scenario`` (a
        :class:`Scenario`, the name of one in the library, or None for the regular match).
        TypeError for a config that is not a MatchConfig; ScenarioError for a scenario that
        does not fit the configuration."""
        if config is None:
            config = MatchConfig()
        if not isinstance(config, MatchConfig):
            raise SetupTypeError(f"config must be a MatchConfig, got {type(config).__name__}")
        scenario = resolve_scenario(scenario)
        scenario.check(config)
        if scenario.offside is not None and scenario.offside != config.rules.offside:
            config = replace(config, rules=replace(config.rules, offside=scenario.offside))
        half_time = scenario.half_time
        end_cycle = config.total_cycles if scenario.cycle_limit is None else min(config.total_cycles,
                                                                                  scenario.cycle_limit)
        end = MatchEnd(end_cycle=end_cycle, full_cycles=config.total_cycles,
                       half_end=config.rules.half_cycles if half_time else -1,
                       conditions=scenario.end_on, defender=1 - scenario.attacking_side)
        return cls(config=config, scenario=scenario, sizes=scenario.sizes(config), goalies=scenario.goalies(config),
                   set_plays=scenario.set_plays, half_time=half_time, start_mode=scenario.start_play_mode,
                   start_side=scenario.start_side, attacking_side=scenario.attacking_side, end=end)

    # ------------------------------------------------------------------ derived values
    @property
    def offside(self) -> bool:
        """Whether offside is called (the configuration's rule, or the scenario's switch)."""
        return self.config.rules.offside

    @property
    def end_cycle(self) -> int:
        """Cycles the match lasts at most."""
        return self.end.end_cycle

    @property
    def players(self) -> int:
        """Player rows of the match (both sides)."""
        return self.sizes[0] + self.sizes[1]

    @property
    def goalie_rows(self) -> tuple[int, int]:
        """Each side's goalkeeper as a player row, ``NO_PLAYER`` for none."""
        first = (0, self.sizes[0])
        return tuple(NO_PLAYER if g < 0 else first[t] + g for t, g in enumerate(self.goalies))  # type: ignore[return-value]

    def side_info(self, team: int, names: tuple[str, str]) -> SideInfo:
        """What ``team`` (HOME or AWAY) is told about itself and its opponents at ``reset``;
        ``names``: the (home, away) team names."""
        other = 1 - team
        return SideInfo(team=team, name=names[team], opponent_name=names[other],
                        players_per_team=self.sizes[team], goalie_index=self.goalies[team],
                        opponents=self.sizes[other], opponent_goalie_index=self.goalies[other])


def resolve_scenario(scenario: Scenario | str | None) -> Scenario:
    """A :class:`Scenario` from a Scenario, a library name or None (the regular match)."""
    if scenario is None:
        return _REGULAR
    if isinstance(scenario, Scenario):
        return scenario
    if isinstance(scenario, str):
        return get_scenario(scenario)
    raise ScenarioError("Scenario", f"expected a Scenario, a library name or None, got {type(scenario).__name__}")


_REGULAR = Scenario()
