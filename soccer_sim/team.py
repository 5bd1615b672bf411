"""The interface between a team and the match: what a team sees and what it may command.

A team is any object with ``reset(side_info, config, rng)`` and ``act(view) -> TeamCommand``
(see :class:`Team`). Everything a team sees is in its *own* frame: it attacks towards +x
and its own goal line is at ``x = -field.length / 2``; the match converts the commands
back (see :mod:`soccer_sim.view`). Units: metres, cycles, metres per cycle (m/cycle) and
metres per cycle² for accelerations.
"""

from __future__ import annotations

from dataclasses import dataclass
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np

from soccer_sim.errors import SoccerSimError
from soccer_sim.state import NO_PLAYER, PlayMode

if TYPE_CHECKING:
    from soccer_sim.config import MatchConfig


class TeamError(SoccerSimError):
    """A team misbehaved: its ``act``/``reset`` raised, or it returned a malformed command.

    ``team_name`` names the team and ``player`` is the index (within the team) of the player
    whose command is wrong, or None when the whole command is at fault. The original
    exception, if any, is chained as ``__cause__``.
    """

    def __init__(self, team_name: str, message: str, player: int | None = None) -> None:
        where = f"team {team_name!r}" + (f", player {player}" if player is not None else "")
        super().__init__(f"{where}: {message}")
        self.team_name = team_name
        self.message = message
        self.player = player

    def __reduce__(self):
        """Pickle by the constructor's arguments, so the error crosses process boundaries
        (a process pool's worker to its parent) intact."""
        return type(self), (self.team_name, self.message, self.player)


def command_array(values: object, field_name: str, shape: tuple[int, ...],
                  fail: Callable[[str], Exception]) -> np.ndarray:
    """One field of a :class:`TeamCommand` (``command.<field_name>``) as a float64 array of
    ``shape``, or the exception ``fail(message)`` makes of what is wrong (None, not numeric,
    another shape): the one check of a command's arrays, for the match and the rcssserver bridge."""
    if values is None:
        raise fail(f"command.{field_name} is None; expected an array of shape {shape}")
    if isinstance(values, np.ndarray) and values.dtype.kind not in "fiu":
        raise fail(f"command.{field_name} must be numeric, got dtype {values.dtype}")
    try:
        array = np.asarray(values, dtype=np.float64)
    except (TypeError, ValueError, OverflowError) as exc:
        raise fail(f"command.{field_name} is not a numeric array ({exc})") from exc
    if array.shape != shape:
        raise fail(f"command.{field_name} must have shape {shape}, got {array.shape}")
    return array


def team_failure(name: str, method: str, exc: BaseException) -> TeamError:
    """The TeamError for an exception out of a team's ``method`` (``reset``, ``act``, ...).
    ``sys.exit()`` in a team's code is a failure of that team too: it must not end the program
    that plays the match (a tournament, an environment, ``soccer-sim play``) with its exit status."""
    if isinstance(exc, SystemExit):
        return TeamError(name, f"called sys.exit({exc.code!r}) in {method}()")
    return TeamError(name, f"{method}() raised {type(exc).__name__}: {exc}")


@dataclass(frozen=True)
class SideInfo:
    """Who a team is in this match (given to :meth:`Team.reset`)."""

    team: int
    """HOME (0) or AWAY (1): the team's index in scores, statistics and events."""
    name: str
    """The team's name in this match (the registry name, or the class name)."""
    opponent_name: str
    players_per_team: int
    """Players of this team (0 to 11; the rows of ``own_pos`` in its views)."""
    goalie_index: int
    """Index of the team's goalkeeper within the team (the only player whose catch counts);
    -1 (``NO_PLAYER``) when the team has no goalkeeper (a scenario may leave it out)."""
    opponents: int
    """Players of the opposing team (0 to 11; the rows of ``opp_pos``)."""
    opponent_goalie_index: int
    """Index of the opponents' goalkeeper among them, -1 (``NO_PLAYER``) if they have none."""
    player_types: tuple = ()
    """The match's heterogeneous player types (:class:`~soccer_sim.player_types.PlayerType`,
    index = type id, type 0 the default), the same for both teams; empty outside a match."""
    own_types: tuple[int, ...] = ()
    """Each own player's type id (row order); its parameters are ``player_types[id]``. Types
    are fixed for the whole match (no substitutions)."""
    opponent_types: tuple[int, ...] = ()
    """Each opponent's type id, as rcssserver's online coach sees them."""

    def own_type(self, player: int):
        """The :class:`~soccer_sim.player_types.PlayerType` of own player ``player``."""
        return self.player_types[self.own_types[player]]


@dataclass(eq=False)
class TeamView:
    """What a team sees at one cycle, in its own frame (attacking +x, own goal at -x).

    The match owns these arrays and overwrites them every cycle, so a team must copy
    anything it wants to keep across cycles. Positions in metres, velocities in m/cycle.
    """

    own_pos: np.ndarray
    """(n, 2) positions of the team's players; row i is player i (row goalie_index is the goalkeeper)."""
    own_vel: np.ndarray
    """(n, 2) velocities of the team's players."""
    opp_pos: np.ndarray
    """(n, 2) positions of the opponents."""
    opp_vel: np.ndarray
    """(n, 2) velocities of the opponents."""
    ball: np.ndarray
    """(2,) ball position."""
    ball_vel: np.ndarray
    """(2,) ball velocity."""
    stamina: np.ndarray
    """(n,) stamina of the team's players (see config.StaminaConfig)."""
    play_mode: PlayMode = PlayMode.KICK_OFF
    mode_ours: bool = False
    """True when the current set play (or the goalkeeper's hold) belongs to this team."""
    score: tuple[int, int] = (0, 0)
    """(ours, theirs)."""
    cycle: int = 0
    half: int = 0
    """0 for the first half, 1 for the second (the teams keep their ends, as in rcssserver 19)."""
    ball_holder: int = NO_PLAYER
    """Index (within this team) of our goalkeeper if it holds the ball, else NO_PLAYER (-1)."""
    effort: np.ndarray | None = None
    """(n,) effort of the team's players: the fraction of dash power that becomes acceleration
    (1 when fresh, down to ``StaminaConfig.effort_min`` when tired). A view built by hand
    without it gets fresh players (ones)."""
    capacity: np.ndarray | None = None
    """(n,) stamina each player can still recover in this half (inf: unlimited; the default
    of a view built by hand)."""
    present: np.ndarray | None = None
    """(n,) bool: False for a player sent off (red card). It stays in every array (its row
    keeps its place), parked off the pitch, and its commands are ignored. A view built by
    hand without it has everybody present."""
    opp_present: np.ndarray | None = None
    """(m,) bool: the same for the opponents."""
    frozen: np.ndarray | None = None
    """(n,) int: cycles during which each player still cannot act (after a tackle,
    ``TackleConfig.tackle_cycles``, or after being fouled, ``foul_cycles``); its commands are
    ignored while above zero. Zeros in a view built by hand."""
    cards: np.ndarray | None = None
    """(n,) int: each of our players' yellow cards (rcssserver's sense_body ``card``: 0 or 1;
    2 once a second one sent the player off). None in a view built by hand: nobody is carded."""
    own_types: np.ndarray | None = None
    """(n,) int: each of our players' heterogeneous player type, an index into
    ``SideInfo.player_types`` (0: the default type; fixed for the match). Zeros in a view
    built by hand."""
    opp_types: np.ndarray | None = None
    """(m,) int: the opponents' player types, as rcssserver's online coach sees them."""

    def __post_init__(self) -> None:
        n = len(self.stamina)
        if self.effort is None:
            self.effort = np.ones(n)
        if self.capacity is None:
            self.capacity = np.full(n, np.inf)
        if self.present is None:
            self.present = np.ones(n, dtype=bool)
        if self.opp_present is None:
            self.opp_present = np.ones(len(self.opp_pos), dtype=bool)
        if self.frozen is None:
            self.frozen = np.zeros(n, dtype=np.int64)
        if self.own_types is None:
            self.own_types = np.zeros(n, dtype=np.intp)
        if self.opp_types is None:
            self.opp_types = np.zeros(len(self.opp_pos), dtype=np.intp)


@dataclass(slots=True)
class TeamCommand:
    """What a team asks its players to do this cycle (own frame, like the view).

    The match clips every request to the physical limits (config.PhysicsConfig and the
    stamina model), so a team may simply ask for "as much as possible". Only the fields below
    exist: setting any other attribute (a misspelt ``command.kik``) raises AttributeError.
    """

    dash: np.ndarray
    """(n, 2) requested acceleration per player (m/cycle²)."""
    kick: np.ndarray
    """(n, 2) requested change of the ball's velocity per player (m/cycle); applied only for
    players that can kick (ball within the kickable distance, set-play rules permitting).
    An all-zero row means "do not kick"."""
    catch: bool = False
    """The goalkeeper tries to catch the ball this cycle (a bool, Python or numpy; 0 and 1 are
    accepted too, anything else is a TeamError)."""
    move: np.ndarray | None = None
    """(n, 2) placement targets, honoured before a kick-off and in the pause after a goal
    (play modes KICK_OFF and AFTER_GOAL; the referee clamps them into the team's own half),
    and, for the goalkeeper's row alone, while it holds the ball (GOALIE_HOLDS: at most
    ``RuleConfig.goalie_max_moves`` moves, further ones refused; rcssserver's ``move``)."""
    tackle: np.ndarray | None = None
    """(n,) tackle directions in degrees, own frame (0: towards +x, the opponents' goal; 90:
    towards +y), NaN for players that do not tackle; None: nobody tackles. rcssserver's
    ``(tackle DIR)``: a tackle reaches ``TackleConfig.tackle_dist`` ahead of the player's body
    (:func:`soccer_sim.body.facing`; at rest a player faces the ball) and succeeds with a
    probability that falls with the ball's distance and offset; a successful one pushes the
    ball in this direction, hardest straight ahead of the body. A tackling player neither
    dashes nor kicks this cycle and cannot act for ``tackle_cycles`` cycles in all."""
    foul: np.ndarray | None = None
    """(n,) bool: the tackle of that player is a foul tackle (rcssserver's ``(tackle DIR on)``):
    while an opponent can kick the ball it succeeds more easily (``foul_exponent``), does not
    freeze the tackler, stops the opponents that can kick the ball for ``foul_cycles``, and is
    carded when the referee sees it. None: no foul tackles."""
    say: Sequence[str | None] | None = None
    """One message per player (a str of at most ``AudioParams.say_msg_size`` characters from
    rcssserver's set, :data:`soccer_sim.perception.SAY_CHARACTERS`) or None for a player that
    says nothing; None: nobody speaks. rcssserver's ``(say MSG)``: under partial observation a
    message said now is heard next cycle by the players within ``audio_cut_dist``
    (:class:`~soccer_sim.perception.views.PlayerViews` ``heard_mates`` / ``heard_opponents``).
    Under full observation messages are checked but reach nobody. A bad message is a TeamError
    naming the player. Messages of one width may come as a
    :class:`~soccer_sim.perception.coded.CodedMessages` (their characters as codes)."""
    turn_neck: np.ndarray | None = None
    """(n,) neck turns in degrees (positive counter-clockwise), NaN or 0 for players that keep
    their neck; None: nobody turns it. rcssserver's ``(turn_neck MOMENT)``, which goes with any
    body command: the moment is clipped to ``SeeParams.min_neck_moment`` / ``max_neck_moment``
    and the neck angle (the face's angle to the body, 0 at the start) to ``min_neck_angle`` /
    ``max_neck_angle`` (:mod:`soccer_sim.perception.neck`). Under partial observation the view
    cone of every later see is centred on the body direction plus the neck angle, which the
    views report (:attr:`~soccer_sim.perception.views.PlayerViews.neck_angle`); under full
    observation the turns are checked and change nothing. An infinite or non-numeric turn, or
    an array of another shape, is a TeamError naming the player."""
    change_view: np.ndarray | None = None
    """(n,) integer view width codes, one per player: ``NARROW`` 0, ``NORMAL`` 1, ``WIDE`` 2
    (:mod:`soccer_sim.perception.view_width`) or ``KEEP`` -1; None: nobody changes. rcssserver's
    ``(change_view WIDTH)``, which goes with any body command: a cone of half, once or twice
    ``SeeParams.visible_angle`` with a see every 75, 150 or 300 ms (``send_step`` / 2, 1, 2);
    every player starts ``NORMAL``. Under partial observation the change holds from the next
    cycle (:attr:`~soccer_sim.perception.views.PlayerViews.view_width`); under full observation
    it is checked and changes nothing. Any other value or shape is a TeamError."""


@runtime_checkable
class Team(Protocol):
    """A team: called once before the match, then once per cycle.

    Optionally a team may define ``statistics() -> dict[str, float]``: figures it reports
    (role switches, ...) that are merged into its match statistics.
    """

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        """Prepare for a new match. ``rng`` is the team's own seeded generator: use it (and no
        other source of randomness) so that matches stay reproducible."""
        ...

    def act(self, view: TeamView) -> TeamCommand:
        """Decide this cycle's command from the team-relative view."""
        ...
