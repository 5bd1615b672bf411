"""Each player's :class:`~soccer_sim.perception.views.PlayerViews` row from what the server
told that player, so that a team that plays under ``--observation partial`` reads the real
server the way it reads the simulator.

Per step and player (rows: shirt number - 1; a shirt not connected is a row with
``present`` False and NaN everywhere):

* ``sense_body``: stamina, effort, capacity; ``frozen`` = the longer of the tackle's and the
  foul's remaining steps; ``cards`` from its ``card``; ``present`` False once shown a red card; the sensed velocity (the
  speed's direction is relative to the face); ``neck_angle`` from its ``head_angle`` and
  ``view_width`` from its ``view_mode`` (both kept while a row hears no ``sense_body``).
* ``see`` (``saw``): the self-localisation of :mod:`rcss_bridge.localisation` (``localised``
  when it found a position); the ball and the players at the reported distance and direction
  from that position, nearest first, with their side (``TEAMMATE`` when the team name is ours,
  ``OPPONENT`` when another, ``UNKNOWN_SIDE`` when not given) and index (shirt - 1, or -1).
  Directions in the views are relative to the body (the server's, relative to the face, plus
  the neck angle). On steps without a see the position is dead-reckoned as the simulator's
  observer does (``pos += vel / player_decay`` of the player's type) and the body turned by
  the turns the player's own orders made (:meth:`ViewsBuilder.turned`; the face is the body
  plus ``sense_body``'s neck).
* ``hear``: team-mates' messages as (index, text), opponents' as text (one's own left out).
* the referee (:class:`~rcss_bridge.play_modes.RefereeState`): play mode, ``mode_ours``,
  half, score (ours, theirs); ``holds_ball`` for the goalkeeper's row while it holds the ball.
* ``change_player_type``: ``player_types`` of the team-mates whose type the server told.

Everything is in the team's frame (attacking +x): the left side's frame is the server's
absolute one, the right side's is it turned by 180° (``(x, y) -> (-x, -y)``, angles + 180°),
as the simulator's :class:`~soccer_sim.view.TeamFrame` does. ``cycle`` is the bridge's own
step counter (the server's clock stands still at times), given by the caller.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from soccer_sim.perception.view_width import NORMAL, VIEW_WIDTHS
from soccer_sim.perception.views import OPPONENT, TEAMMATE, UNKNOWN_SIDE, PlayerViews

from rcss_bridge.localisation import localise, wrap
from rcss_bridge.messages import Hear, Message, See, SenseBody, TypeChange

CARD_COUNTS = {"none": 0, "yellow": 1, "red": 2}
"""sense_body's ``card`` as :attr:`PlayerViews.cards` counts it (2: sent off, as the simulator counts)."""
from rcss_bridge.play_modes import RefereeState


class ViewsBuilder:
    """Builds one team's :class:`PlayerViews` step by step (module docstring).

    ``team_name``: the team's name as the server spells it; ``side``: ``"l"`` or ``"r"``;
    ``players``: the team's size; ``decay``: each player type's ``player_decay`` by type id;
    ``goalie``: the goalkeeper's row; ``mode``: the play mode of the init reply."""

    def __init__(self, team_name: str, side: str, players: int, decay: Sequence[float], goalie: int = 0,
                 mode: str = "before_kick_off") -> None:
        self.team_name = team_name
        self.side = side
        self.sign = 1.0 if side == "l" else -1.0
        """+1 for the left side (the server's frame is the team's), -1 for the right."""
        self.referee = RefereeState(side, mode)
        self._decay = np.asarray(decay, dtype=np.float64)
        self._goalie = goalie
        n, k = players, 2 * players - 1
        self._body = np.full(n, np.nan)
        """Each player's body direction (degrees, the server's frame; NaN before its first see
        with flags): from a see, the face less the neck; between sees, turned by the turns
        its orders made (:meth:`turned`)."""
        self._unseen = np.full(n, 1_000_000, dtype=np.int64)
        """Steps since each player last saw the ball (a large number before it ever did)."""
        self._turns = np.zeros(n)
        """The body turns (degrees) of the orders sent since the last :meth:`update`."""
        self._belief = np.full((n, 2), np.nan)
        self.views = PlayerViews(
            stamina=np.full(n, np.nan), effort=np.full(n, np.nan), capacity=np.full(n, np.nan),
            frozen=np.zeros(n, dtype=np.int64), present=np.zeros(n, dtype=bool),
            player_types=np.zeros(n, dtype=np.int64), holds_ball=np.zeros(n, dtype=bool),
            position=np.full((n, 2), np.nan), velocity=np.full((n, 2), np.nan), body_direction=np.full(n, np.nan),
            localised=np.zeros(n, dtype=bool), saw=np.zeros(n, dtype=bool), ball_seen=np.zeros(n, dtype=bool),
            ball=np.full((n, 2), np.nan), ball_distance=np.full(n, np.nan), ball_direction=np.full(n, np.nan),
            seen_count=np.zeros(n, dtype=np.int64), seen_position=np.full((n, k, 2), np.nan),
            seen_distance=np.full((n, k), np.nan), seen_direction=np.full((n, k), np.nan),
            seen_side=np.zeros((n, k), dtype=np.int8), seen_number=np.full((n, k), -1, dtype=np.int8),
            cards=np.zeros(n, dtype=np.int64), neck_angle=np.zeros(n), view_width=np.full(n, NORMAL, dtype=np.int64))
        """The views, overwritten by every :meth:`update` (as the simulator's are)."""

    @property
    def n(self) -> int:
        return self.views.n

    @property
    def ball_unseen(self) -> np.ndarray:
        """(n,) steps since each player last saw the ball itself (0: at this step; a copy)."""
        return self._unseen.copy()

    @property
    def necks(self) -> np.ndarray:
        """(n,) each player's neck as its last ``sense_body`` told it (``head_angle``: the
        face's angle to the body, degrees; a copy)."""
        return self.views.neck_angle.copy()

    def turned(self, angles: np.ndarray) -> None:
        """The body turns (degrees, by row; 0 for none) the orders just sent will make: the
        server tells no body direction between sees (``sense_body`` gives the neck, relative
        to the body), so the body kept since the last see is turned by what the player itself
        asked (:attr:`~rcss_bridge.commands.CommandTranslator.turns`)."""
        self._turns += np.nan_to_num(np.asarray(angles, dtype=np.float64))

    def update(self, step: int, inboxes: Mapping[int, Sequence[Message]]) -> PlayerViews:
        """The views after one step's messages: ``inboxes`` maps each connected player's row to
        the messages it received this step (parsed, in arrival order; when there are several
        ``sense_body`` or ``see``, from steps the server went on without the team, the last
        of each counts)."""
        views = self.views
        views.present[:] = False
        mates: list[tuple[tuple[int, str], ...]] = [()] * self.n
        opponents: list[tuple[str, ...]] = [()] * self.n
        referee_read = False
        for row in range(self.n):
            messages = inboxes.get(row)
            self._clear_sight(row)
            if messages is None:
                self._clear_senses(row)
                continue
            heard_mates: list[tuple[int, str]] = []
            heard_opponents: list[str] = []
            sense = next((m for m in reversed(messages) if isinstance(m, SenseBody)), None)
            see = next((m for m in reversed(messages) if isinstance(m, See)), None)
            for message in messages:
                if isinstance(message, Hear):
                    if message.sender == "referee":
                        if not referee_read:
                            self.referee.hear(message.message)
                    elif message.sender == "our" and message.unum is not None:
                        heard_mates.append((message.unum - 1, message.message))
                    elif message.sender == "opp":
                        heard_opponents.append(message.message)
                elif isinstance(message, TypeChange) and message.type is not None and 1 <= message.unum <= self.n:
                    views.player_types[message.unum - 1] = message.type
            referee_read = referee_read or any(isinstance(m, Hear) and m.sender == "referee" for m in messages)
            mates[row], opponents[row] = tuple(heard_mates), tuple(heard_opponents)
            if sense is None:
                self._clear_senses(row)
                continue
            self._sense(row, sense, see)
        views.cycle = step
        views.half = self.referee.half
        views.play_mode = self.referee.play_mode
        views.mode_ours = self.referee.mode_ours
        views.score = self.referee.score
        views.heard_mates = tuple(mates)
        views.heard_opponents = tuple(opponents)
        views.holds_ball[:] = False
        if self.referee.goalie_holds and views.present[self._goalie]:
            views.holds_ball[self._goalie] = True
        self._turns[:] = 0.0
        self._unseen = np.where(views.ball_seen, 0, np.minimum(self._unseen + 1, 1_000_000))
        return views

    # ------------------------------------------------------------------------------------
    def _sense(self, row: int, sense: SenseBody, see: See | None) -> None:
        views, s = self.views, self.sign
        views.present[row] = sense.card != "red"
        views.cards[row] = CARD_COUNTS.get(sense.card, 0)
        views.stamina[row], views.effort[row], views.capacity[row] = sense.stamina, sense.effort, sense.capacity
        views.frozen[row] = max(sense.tackle_expires, sense.foul_charged)
        views.neck_angle[row] = sense.head_angle
        if sense.view_width in VIEW_WIDTHS:
            views.view_width[row] = VIEW_WIDTHS.index(sense.view_width)
        position_found = False
        if math.isfinite(self._body[row]):
            self._body[row] = wrap(self._body[row] + self._turns[row])
        if see is not None:
            fix = localise(see)
            if math.isfinite(fix.face):
                self._body[row] = wrap(fix.face - sense.head_angle)
            if fix.flags > 0 and np.all(np.isfinite(fix.position)):
                self._belief[row] = fix.position
                position_found = True
        face = self._body[row] + sense.head_angle
        heading = math.radians(face + sense.speed_direction) if math.isfinite(face) else math.nan
        velocity = np.array([sense.speed * math.cos(heading), sense.speed * math.sin(heading)])
        if not position_found and np.all(np.isfinite(self._belief[row])) and np.all(np.isfinite(velocity)):
            decay = self._decay[int(views.player_types[row])]
            self._belief[row] = self._belief[row] + velocity / decay
        views.velocity[row] = velocity * s
        views.position[row] = self._belief[row] * s
        views.body_direction[row] = self._team_angle(self._body[row])
        views.saw[row] = see is not None
        views.localised[row] = position_found
        if see is not None and position_found and math.isfinite(face):
            self._sight(row, see, self._belief[row], face, sense.head_angle)

    def _sight(self, row: int, see: See, me: np.ndarray, face: float, neck: float) -> None:
        """The ball and the players of ``see`` as positions (team frame), nearest first."""
        views, s = self.views, self.sign
        if see.ball is not None and math.isfinite(see.ball.distance):
            views.ball_seen[row] = True
            views.ball_distance[row] = see.ball.distance
            views.ball_direction[row] = wrap(see.ball.direction + neck)
            views.ball[row] = _polar(me, see.ball.distance, face + see.ball.direction) * s
        seen = sorted((p for p in see.players if math.isfinite(p.distance)), key=lambda p: p.distance)
        seen = seen[: views.seen_distance.shape[1]]
        views.seen_count[row] = len(seen)
        for c, player in enumerate(seen):
            views.seen_distance[row, c] = player.distance
            views.seen_direction[row, c] = wrap(player.direction + neck)
            views.seen_position[row, c] = _polar(me, player.distance, face + player.direction) * s
            if player.team is not None:
                views.seen_side[row, c] = TEAMMATE if player.team == self.team_name else OPPONENT
            if player.unum is not None:
                views.seen_number[row, c] = player.unum - 1

    def _team_angle(self, angle: float) -> float:
        """An absolute direction (degrees) in the team's frame."""
        return wrap(angle if self.sign > 0 else angle + 180.0) if math.isfinite(angle) else math.nan

    def _clear_sight(self, row: int) -> None:
        views = self.views
        views.saw[row] = views.localised[row] = views.ball_seen[row] = False
        views.ball[row] = np.nan
        views.ball_distance[row] = views.ball_direction[row] = np.nan
        views.seen_count[row] = 0
        views.seen_position[row] = np.nan
        views.seen_distance[row] = views.seen_direction[row] = np.nan
        views.seen_side[row] = UNKNOWN_SIDE
        views.seen_number[row] = -1

    def _clear_senses(self, row: int) -> None:
        views = self.views
        views.stamina[row] = views.effort[row] = views.capacity[row] = np.nan
        views.frozen[row] = 0
        views.position[row] = views.velocity[row] = np.nan
        views.body_direction[row] = np.nan


def _polar(origin: np.ndarray, distance: float, direction: float) -> np.ndarray:
    """``origin`` plus ``distance`` m in the absolute ``direction`` (degrees)."""
    a = math.radians(direction)
    return np.array([origin[0] + distance * math.cos(a), origin[1] + distance * math.sin(a)])
