"""What a team's players perceive under partial observation: :class:`PlayerViews`, one per team
per cycle, and :class:`PlayerObservation`, one player's share of it.

Under ``MatchConfig.observation.mode == "partial"`` a team's ``act`` receives a
:class:`PlayerViews` instead of the exact :class:`~soccer_sim.team.TeamView`. Row ``i`` of every
per-player array is what player ``i`` of the team perceives, and nothing in row ``i`` depends
on what another player perceives, so a team may decide per player (``views.player(i)``) or
vectorised over its players. Everything is in the team's own frame (attacking +x, own goal at
``x = -length / 2``; metres, m/cycle, degrees counter-clockwise from +x), as in the full view.

Three sources, as in rcssserver:

* the **referee** (heard by every player every cycle): cycle, half, play mode, score;
* **sense_body** (every cycle): stamina, effort, recovery capacity, frozen cycles, its card, the
  player's own velocity (quantised), body direction and neck angle, whether it holds the ball;
* the **see** (when one arrives: :attr:`PlayerViews.saw`; alternately after one and two cycles)
  with the ball and the players in view (:mod:`soccer_sim.perception.see`), and the
  **self-localisation** it allows (:mod:`soccer_sim.perception.localise`);
* the **hear**: the messages said last cycle that reached the player
  (:mod:`soccer_sim.perception.audio`).

The seen players are listed per observer nearest first (rows ``0 .. seen_count[i] - 1``;
the rest is padding: NaN positions, side 0, number -1); their order says nothing about who
they are. The arrays are overwritten every cycle: a team copies what it keeps.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from soccer_sim.state import PlayMode

TEAMMATE = 1
""":attr:`PlayerViews.seen_side` of a player seen as a team-mate."""
OPPONENT = -1
""":attr:`PlayerViews.seen_side` of a player seen as an opponent."""
UNKNOWN_SIDE = 0
""":attr:`PlayerViews.seen_side` of a player whose team was not seen (far away, or outside the
cone within ``visible_distance``), and of padding."""


@dataclass(frozen=True)
class PlayerObservation:
    """What one player perceives at one cycle (team frame; see :class:`PlayerViews` for each
    field's meaning). Arrays are copies: the player may keep them."""

    player: int
    """The player's index within its team."""
    cycle: int
    half: int
    play_mode: PlayMode
    mode_ours: bool
    score: tuple[int, int]
    stamina: float
    effort: float
    capacity: float
    frozen: int
    present: bool
    player_type: int
    holds_ball: bool
    position: np.ndarray
    """(2,) believed own position (m)."""
    velocity: np.ndarray
    """(2,) sensed own velocity (m/cycle)."""
    body_direction: float
    localised: bool
    saw: bool
    ball_seen: bool
    ball: np.ndarray
    """(2,) where the ball was seen (m; NaN unless ``ball_seen``)."""
    ball_distance: float
    ball_direction: float
    players: np.ndarray
    """(k, 2) the k players seen this cycle, nearest first (m)."""
    player_sides: np.ndarray
    """(k,) TEAMMATE, OPPONENT or UNKNOWN_SIDE."""
    player_numbers: np.ndarray
    """(k,) index within its team, -1 when not seen."""
    player_distances: np.ndarray
    player_directions: np.ndarray
    heard_mates: tuple[tuple[int, str], ...]
    """(team-mate index, message) pairs heard this cycle (said last cycle)."""
    heard_opponents: tuple[str, ...]
    """Opponents' messages heard this cycle (the speaker is not named)."""
    neck_angle: float = 0.0
    """The neck: the face's angle to the body (degrees); the player looks along
    ``body_direction + neck_angle``."""


class HeardLog(Sequence):
    """What each of a team's players heard from one side in one cycle, as
    :attr:`PlayerViews.heard_mates` (``named``: per listener its (team-mate index, message)
    pairs) or :attr:`PlayerViews.heard_opponents` (per listener the messages, speakers not
    named): a sequence of one tuple per listener, made on first use from the delivery's
    arrays (a team that decodes whole batches, :meth:`pairs`, never makes them).

    ``heard`` (listeners, speakers) bool: who heard whom, listeners the team's players in
    order, speakers the side's players in order; ``messages``: what each speaker said. Both
    are the match's and never change after the cycle."""

    __slots__ = ("_heard", "_messages", "_named", "_rows")

    def __init__(self, heard: np.ndarray, messages: Sequence[str | None], named: bool) -> None:
        self._heard, self._messages, self._named = heard, messages, named
        self._rows: tuple[tuple, ...] | None = None

    @property
    def heard(self) -> np.ndarray:
        """(listeners, speakers) bool: who heard whom (read only: the match's)."""
        return self._heard

    @property
    def messages(self) -> Sequence[str | None]:
        """What each speaker said (None: nothing)."""
        return self._messages

    def pairs(self) -> tuple[np.ndarray, np.ndarray, list[str]]:
        """Every message heard, one row each in listener then speaker order: (p,) listeners,
        (p,) speakers (the speaker's index within its side) and the p messages."""
        listeners, speakers = np.nonzero(self._heard)
        messages = self._messages
        return listeners, speakers, [messages[s] for s in speakers.tolist()]

    def _made(self) -> tuple[tuple, ...]:
        """The per-listener tuples, made once."""
        if self._rows is None:
            rows: list[tuple] = [()] * len(self._heard)
            listeners, speakers, texts = self.pairs()
            for listener, speaker, text in zip(listeners.tolist(), speakers.tolist(), texts):
                rows[listener] += ((speaker, text),) if self._named else (text,)
            self._rows = tuple(rows)
        return self._rows

    def __len__(self) -> int:
        return len(self._heard)

    def __getitem__(self, index):  # type: ignore[override]
        return self._made()[index]

    def __iter__(self) -> Iterator[tuple]:
        return iter(self._made())

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (HeardLog, tuple)):
            return self._made() == tuple(other)
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"HeardLog({self._made()!r})"


@dataclass(eq=False)
class PlayerViews:
    """What each of a team's ``n`` players perceives at one cycle (module docstring). Arrays
    have the team's players along their first axis; ``K`` = the players of both teams minus one
    (the most another player can see).

    The match owns these arrays and overwrites them every cycle (like a ``TeamView``'s), so a
    team must copy what it keeps; :meth:`player` returns copies."""

    stamina: np.ndarray
    """(n,) stamina (sense_body)."""
    effort: np.ndarray
    """(n,) effort: the fraction of dash power that becomes acceleration."""
    capacity: np.ndarray
    """(n,) stamina each player can still recover in this half."""
    frozen: np.ndarray
    """(n,) cycles each player still cannot act (after a tackle or a foul)."""
    present: np.ndarray
    """(n,) False for a player sent off (its row stays, it perceives nothing)."""
    player_types: np.ndarray
    """(n,) each player's heterogeneous type id (``SideInfo.player_types``)."""
    holds_ball: np.ndarray
    """(n,) True for the goalkeeper while it holds the ball."""
    position: np.ndarray
    """(n, 2) each player's belief about its own position (m): the self-localisation model on
    cycles with a see, advanced by the sensed velocity in between (NaN never after the first
    see; exact with ``SeeParams.exact_self``)."""
    velocity: np.ndarray
    """(n, 2) each player's sensed own velocity (m/cycle; speed to 0.01, direction to 1°)."""
    body_direction: np.ndarray
    """(n,) each player's body direction (degrees, team frame). A player looks along its face,
    ``body_direction + neck_angle``."""
    localised: np.ndarray
    """(n,) True when this cycle's see showed at least one flag (False on cycles without a see)."""
    saw: np.ndarray
    """(n,) True when a see arrived this cycle; otherwise nothing below is filled in."""
    ball_seen: np.ndarray
    """(n,) True when the player sees the ball this cycle."""
    ball: np.ndarray
    """(n, 2) where each player sees the ball (m): its believed position plus the reported
    distance and direction; NaN where not seen. The ball's velocity is not observed."""
    ball_distance: np.ndarray
    """(n,) the reported distance to the ball (m; NaN where not seen)."""
    ball_direction: np.ndarray
    """(n,) the reported direction of the ball from the body (degrees; NaN where not seen):
    rcssserver's direction from the face plus the neck angle."""
    seen_count: np.ndarray
    """(n,) how many players each player sees (the valid rows of the seen_* arrays)."""
    seen_position: np.ndarray
    """(n, K, 2) where each seen player is (m), nearest first; NaN padding."""
    seen_distance: np.ndarray
    """(n, K) reported distances (m); NaN padding."""
    seen_direction: np.ndarray
    """(n, K) reported directions from the body (degrees); NaN padding."""
    seen_side: np.ndarray
    """(n, K) int8: TEAMMATE, OPPONENT or UNKNOWN_SIDE."""
    seen_number: np.ndarray
    """(n, K) int8: the seen player's index within its team, -1 when its number was not seen."""
    cycle: int = 0
    half: int = 0
    """0 for the first half, 1 for the second (the frame never changes side)."""
    play_mode: PlayMode = PlayMode.KICK_OFF
    mode_ours: bool = False
    """True when the current set play (or the goalkeeper's hold) belongs to this team."""
    score: tuple[int, int] = (0, 0)
    """(ours, theirs)."""
    heard_mates: Sequence[tuple[tuple[int, str], ...]] = ()
    """Per player, the (team-mate index, message) pairs heard this cycle (said last cycle): a
    tuple per player (a match gives a :class:`HeardLog`, which makes them on first use)."""
    heard_opponents: Sequence[tuple[str, ...]] = ()
    """Per player, the opponents' messages heard this cycle (speakers not named; a
    :class:`HeardLog` too)."""
    cards: np.ndarray | None = None
    """(n,) each player's yellow cards (sense_body's ``card``: 0 or 1; 2 once sent off); None:
    nobody is carded."""
    view_width: np.ndarray | None = None
    """(n,) each player's view width (sense_body's ``view_mode``): ``NARROW`` 0, ``NORMAL`` 1 or
    ``WIDE`` 2 (:mod:`soccer_sim.perception.view_width`: a cone of half, once or twice
    ``visible_angle``, sees every 75, 150 or 300 ms), which only the player's own
    ``TeamCommand.change_view`` changes. None in views built by hand: all ``NORMAL``."""
    neck_angle: np.ndarray | None = None
    """(n,) each player's neck (sense_body's ``head_angle``): the face's angle to the body
    (degrees, ``SeeParams.min_neck_angle`` .. ``max_neck_angle``), which only the player's own
    ``TeamCommand.turn_neck`` changes (:mod:`soccer_sim.perception.neck`); the view cone is
    centred on ``body_direction + neck_angle``. rcssserver reports it in whole degrees (towards
    zero), the simulator as it is. None in views built by hand: zeros."""

    def __post_init__(self) -> None:
        n = len(self.stamina)
        if self.neck_angle is None:
            self.neck_angle = np.zeros(n)
        if self.view_width is None:
            self.view_width = np.ones(n, dtype=np.int64)
        if not self.heard_mates:
            self.heard_mates = ((),) * n
        if not self.heard_opponents:
            self.heard_opponents = ((),) * n

    @property
    def n(self) -> int:
        """Players of the team."""
        return len(self.stamina)

    def player(self, i: int) -> PlayerObservation:
        """Player ``i``'s own observation (copies of its rows)."""
        if not 0 <= i < self.n:
            raise IndexError(f"player {i} is not a player of this team (0..{self.n - 1})")
        k = int(self.seen_count[i])
        return PlayerObservation(
            player=i, cycle=self.cycle, half=self.half, play_mode=self.play_mode, mode_ours=self.mode_ours,
            score=self.score, stamina=float(self.stamina[i]), effort=float(self.effort[i]),
            capacity=float(self.capacity[i]), frozen=int(self.frozen[i]), present=bool(self.present[i]),
            player_type=int(self.player_types[i]), holds_ball=bool(self.holds_ball[i]),
            position=self.position[i].copy(), velocity=self.velocity[i].copy(),
            body_direction=float(self.body_direction[i]), localised=bool(self.localised[i]),
            saw=bool(self.saw[i]), ball_seen=bool(self.ball_seen[i]), ball=self.ball[i].copy(),
            ball_distance=float(self.ball_distance[i]), ball_direction=float(self.ball_direction[i]),
            players=self.seen_position[i, :k].copy(), player_sides=self.seen_side[i, :k].copy(),
            player_numbers=self.seen_number[i, :k].copy(), player_distances=self.seen_distance[i, :k].copy(),
            player_directions=self.seen_direction[i, :k].copy(), heard_mates=self.heard_mates[i],
            heard_opponents=self.heard_opponents[i], neck_angle=float(self.neck_angle[i]))
