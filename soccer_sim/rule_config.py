"""The referee's parameters (:class:`RuleConfig`) and rcssserver's tackles, fouls and cards
(:class:`TackleConfig`); part of :class:`soccer_sim.config.MatchConfig`, importable from
:mod:`soccer_sim.config` like every configuration."""

from __future__ import annotations

import math
from dataclasses import dataclass

from soccer_sim.config_checks import ConfigError
from soccer_sim.config_ranges import check_ranges


@dataclass(frozen=True)
class RuleConfig:
    """The referee's rules and time limits (cycles)."""

    half_cycles: int = 3000
    """Length of one half; a match is two halves, the teams keeping their ends (as rcssserver 19)."""
    offside: bool = True
    """Whether the offside rule is enforced."""
    offside_active_distance: float | None = None
    """None (rcssserver since 2011): a player in an offside position is penalised only when it
    plays the ball (kick, body touch or catch). A distance (m; the simulator's rule before
    0.2 used 2.5): also when it comes that close to the ball."""
    set_play_clearance: float = 9.15
    """Opponents are kept at least this far from the ball at set plays (m)."""
    set_play_timeout: int = 100
    """A set play not taken within this many cycles is restarted by dropping the ball
    (rcssserver ``drop_ball_time``)."""
    catch_length: float = 1.2
    """Length of the goalkeeper's catchable area, measured from the goalkeeper towards the ball (m)."""
    catch_width: float = 1.0
    """Width of the goalkeeper's catchable area (m)."""
    catch_ban_cycles: int = 5
    """Cycles after a catch attempt during which the goalkeeper cannot try again."""
    goalie_max_moves: int = 2
    """How many times a goalkeeper holding a caught ball may place itself with
    ``TeamCommand.move`` (rcssserver ``goalie_max_moves``); further moves are refused (they
    still take the cycle's body command). Negative: no limit. How long it may hold the ball is
    ``set_play_timeout``, the free kick's limit."""
    goalie_index: int = 0
    """Index (within its team, 0-based) of each team's goalkeeper; shirt number 1."""
    back_pass_rule: bool = True
    """A goalkeeper may not catch a ball kicked to it by a team-mate (the last touch was that
    team-mate's kick): the attempt gives the opponents an indirect free kick (rcssserver
    ``back_passes``)."""
    goal_pause_cycles: int = 50
    """Cycles of pause (play mode AFTER_GOAL) between a goal and the next kick-off, in which
    nobody may kick and teams may place their players with ``TeamCommand.move`` (rcssserver
    waits 50 cycles after a goal). 0: the kick-off follows at once."""
    corner_inset: float = 1.0
    """A corner kick is taken this far inside the corner along both lines (m; rcssserver
    ``corner_kick_margin``)."""
    stuck_ball_radius: float = 3.0
    """The ball counts as stuck while it stays within this distance of where it was when it
    last moved away further (m; rcssserver ``ball_stuck_area``)."""
    stuck_ball_cycles: int | None = 100
    """A ball stuck for this many cycles of play on is dropped where it lies (both teams may
    play it at once). None: never."""
    goal_kick_leaves_area: bool = True
    """A goal kick must leave the penalty area before it is in play (rcssserver): the
    opponents wait outside the area, and one of them playing the ball before it has left
    retakes the goal kick. What a team-mate of the taker may do is ``proper_goal_kicks``."""
    proper_goal_kicks: bool = False
    """Also a team-mate of the taker playing the ball before it has left the penalty area
    retakes the goal kick (rcssserver ``proper_goal_kicks``, off by default: then the ball is
    in play once a team-mate plays it). The taker itself may play it again (no double touch)."""
    max_goal_kicks: int = 3
    """With ``proper_goal_kicks``: once a goal kick has been retaken this many times in a row
    for its own team's fault, the next such fault gives the opponents an indirect free kick
    on the penalty area's edge (rcssserver ``max_goal_kicks``)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`);
        how the distances fit the field is :class:`~soccer_sim.config.MatchConfig`'s check."""
        check_ranges(self)
        for name in ("offside", "back_pass_rule", "goal_kick_leaves_area", "proper_goal_kicks"):
            if not isinstance(getattr(self, name), bool):
                raise ConfigError(f"RuleConfig.{name} must be a bool, got {getattr(self, name)!r}")


@dataclass(frozen=True)
class TackleConfig:
    """Tackles, fouls and cards, as rcssserver 19 models them (its parameter names in each
    docstring; :mod:`soccer_sim.tackles` and :mod:`soccer_sim.rules.fouls` apply them).

    A tackle fails with probability ``(x / tackle_dist)^e + (|y| / tackle_width)^e`` where
    (x, y) is the ball's centre relative to the tackler's centre in the frame of its body
    (x ahead; :func:`soccer_sim.body.facing`) and ``e`` is ``tackle_exponent`` (``foul_exponent``
    for a foul tackle while an opponent can kick the ball); a ball behind (x <= 0) is reached
    only up to ``tackle_back_dist``.
    """

    enabled: bool = True
    """Whether tackle commands are obeyed (False: ignored, as if never given)."""
    tackle_dist: float = 2.0
    """How far ahead of the body a tackle reaches (m; rcssserver ``tackle_dist``)."""
    tackle_back_dist: float = 0.0
    """How far behind the body a tackle reaches (m; rcssserver ``tackle_back_dist``; 0: never)."""
    tackle_width: float = 1.25
    """How far to either side of the body a tackle reaches (m; rcssserver ``tackle_width``)."""
    tackle_exponent: float = 6.0
    """Exponent of the failure probability (rcssserver ``tackle_exponent``)."""
    tackle_cycles: int = 10
    """A tackler (successful or not, unless a successful foul tackle) cannot dash, kick or tackle
    in the cycle of its tackle and the ``tackle_cycles - 1`` cycles after it (rcssserver
    ``tackle_cycles``)."""
    tackle_power_rate: float = 0.027
    """Ball acceleration (m/cycle²) per unit of tackle power (rcssserver ``tackle_power_rate``)."""
    max_tackle_power: float = 100.0
    """Tackle power when pushing the ball straight ahead of the body (rcssserver ``max_tackle_power``)."""
    max_back_tackle_power: float = 0.0
    """Tackle power when pushing the ball straight back; in between the power falls linearly
    with the angle (rcssserver ``max_back_tackle_power``)."""
    tackle_rand_factor: float = 2.0
    """Tackle noise as a multiple of the tackler's kick noise :attr:`PhysicsConfig.kick_rand`
    (rcssserver ``tackle_rand_factor``; rcssserver scales the player type's ``kick_rand``): a
    random push of up to ``kick_rand * tackle_rand_factor * (pos_rate + speed_rate)`` m/cycle
    in a uniform direction, the rates within [0.5, 1] growing with the success probability and
    the ball's speed."""
    foul_exponent: float = 10.0
    """Exponent of the failure probability of a foul tackle (rcssserver ``foul_exponent``)."""
    foul_detect_probability: float = 0.5
    """Chance the referee sees a foul (rcssserver ``foul_detect_probability``)."""
    foul_cycles: int = 5
    """A player fouled by a foul tackle cannot act for this many cycles (rcssserver ``foul_cycles``)."""
    red_card_probability: float = 0.0
    """Chance that a carded foul is a straight red card (rcssserver ``red_card_probability``;
    a second yellow card is always a red one)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`)."""
        if not isinstance(self.enabled, bool):
            raise ConfigError(f"TackleConfig.enabled must be a bool, got {self.enabled!r}")
        check_ranges(self)

    @property
    def tackle_reach(self) -> float:
        """No tackle succeeds with the ball's centre further than this from the tackler's (m)."""
        return math.hypot(max(self.tackle_dist, self.tackle_back_dist), self.tackle_width)
