"""Team-relative views and the conversion of team commands back to the absolute frame.

Every team sees the world as if it attacked towards +x. When a team attacks towards -x in
the absolute frame (the away team; the teams keep their ends at half time), its
frame is the absolute one turned by 180° about the centre spot: ``(x, y) -> (-x, -y)`` for
positions and vectors alike. A rotation (not a reflection) keeps left and right as the
players see them, and it is its own inverse, so commands go back with the same sign.

Each team has a :class:`TeamFrame` that owns its view's arrays and overwrites them every
cycle (one numpy call for all positions and velocities); teams must copy what they keep.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from soccer_sim.kernels import mirror_bodies, store_command
from soccer_sim.perception.audio import AudioParams, check_coded_messages, check_team_messages
from soccer_sim.perception.coded import CodedMessages
from soccer_sim.perception.view_width import KEEP, check_view_widths
from soccer_sim.state import NO_PLAYER, StateError, WorldState
from soccer_sim.team import TeamCommand, TeamError, TeamView, command_array


def _read_only(view: np.ndarray) -> np.ndarray:
    """A read-only window on ``view`` (the state keeps writing into the array behind it)."""
    window = view.view()
    window.flags.writeable = False
    return window


class TeamFrame:
    """One team's window on the world: builds its :class:`TeamView` and reads its commands.

    ``state`` is the match's world state: the frame reads its arrays (which the state owns and
    never replaces) every cycle, and the sides' sizes from its ``sizes``. ``commands`` is the
    match's (P, 4) absolute command buffer (``[dash_x, dash_y, kick_x, kick_y]`` per player
    row, P players of both sides); this team writes its own rows. ``type_ids``: the match's (P,)
    player type per row, written once the teams have chosen (the view shows windows onto it;
    None: everyone the default type, for frames built without a match).
    """

    def __init__(self, team: int, name: str, state: WorldState, commands: np.ndarray,
                 type_ids: np.ndarray | None = None, audio: AudioParams = AudioParams()) -> None:
        home, away = state.sizes
        n = home if team == 0 else away
        total = home + away
        self.team = team
        self.name = name
        self.n = n
        self._offset = 0 if team == 0 else home
        self.rows = slice(self._offset, self._offset + n)
        self._state = state
        self._bodies = state.bodies
        self._stamina, self._effort, self._capacity = state.stamina, state.effort, state.capacity
        self._score = state.score
        # Positions and velocities in two (P + 1, 2) blocks (players, then the ball), so that
        # every array of the view is C-contiguous (teams and compiled kernels take them as they are).
        self._pos = np.empty((total + 1, 2))
        self._vel = np.empty((total + 1, 2))
        own, opp = self.rows, (slice(home, total) if team == 0 else slice(0, home))
        self.view = TeamView(
            own_pos=self._pos[own], own_vel=self._vel[own], opp_pos=self._pos[opp], opp_vel=self._vel[opp],
            ball=self._pos[total], ball_vel=self._vel[total], stamina=np.empty(n), effort=np.empty(n),
            capacity=np.empty(n), present=_read_only(state.present[own]), opp_present=_read_only(state.present[opp]),
            frozen=_read_only(state.frozen[own]), cards=_read_only(state.cards[own]),
            own_types=None if type_ids is None else _read_only(type_ids[own]),
            opp_types=None if type_ids is None else _read_only(type_ids[opp]),
        )
        self.tackling = False
        """Whether the last command read asked any player to tackle (then :attr:`tackle` and
        :attr:`foul` hold it)."""
        self.tackle = np.full(n, np.nan)
        """(n,) the last command's tackle directions, absolute frame, radians (NaN: none)."""
        self.foul = np.zeros(n, dtype=bool)
        """(n,) the last command's foul flags."""
        self.turns_neck = False
        """Whether the last command read turned any player's neck (then :attr:`neck_turn` holds it)."""
        self.neck_turn = np.zeros(n)
        """(n,) the last command's neck turns (degrees; 0: none). A neck angle is relative to the
        body, so it is the same in every frame."""
        self.changes_view = False
        """Whether the last command read asked any player to change its view width (then
        :attr:`view_width` holds it)."""
        self.view_width = np.full(n, KEEP, dtype=np.int64)
        """(n,) the last command's view width codes (``KEEP``: none)."""
        self.said: Sequence[str | None] | None = None
        """The last command's messages (one per player, None: silent; a tuple, or the team's
        :class:`~soccer_sim.perception.coded.CodedMessages`), or None if nobody spoke."""
        self._audio = audio
        self._allowed = frozenset(audio.characters)
        self._commands = commands[self.rows]
        self._dash = self._commands[:, 0:2]
        self._kick = self._commands[:, 2:4]
        self._shape = (n, 2)

    def update_view(self, state: WorldState, sign: int) -> TeamView:
        """Refresh and return the team's view of ``state`` (arrays overwritten in place).
        ``state``: the state the frame was made for; ``sign``: the team's attack direction,
        ``state.attack_direction(team)``."""
        if state is not self._state:
            raise StateError(f"the TeamFrame of {self.name!r} was made for another WorldState")
        view = self.view
        team = self.team
        mirror_bodies(self._bodies, float(sign), self._pos, self._vel, self._offset, self._stamina, self._effort,
                      self._capacity, view.stamina, view.effort, view.capacity)
        view.play_mode = state.play_mode
        view.mode_ours = state.mode_team == team
        score = self._score.tolist()
        view.score = (score[team], score[1 - team])
        view.cycle = state.cycle
        view.half = state.half
        holder = state.ball_holder - self._offset
        view.ball_holder = holder if 0 <= holder < self.n else NO_PLAYER
        return view

    def read_command(self, command: object, sign: int) -> tuple[bool, np.ndarray | None]:
        """Validate ``command`` and write its dash and kick, in the absolute frame, into this
        team's rows of the command buffer; return (catch request, absolute move targets or None).
        ``sign``: the team's attack direction, as for :meth:`update_view`.

        Raises :class:`TeamError` naming the team (and player) for a malformed command.
        """
        if not isinstance(command, TeamCommand):
            raise TeamError(self.name, f"act() must return a TeamCommand, got {type(command).__name__}")
        dash, kick = command.dash, command.kick
        # Fast path: float arrays of the right shape (anything else is converted or rejected).
        if type(dash) is not np.ndarray or dash.shape != self._shape or dash.dtype != np.float64:
            dash = self._as_array(dash, "dash")
        if type(kick) is not np.ndarray or kick.shape != self._shape or kick.dtype != np.float64:
            kick = self._as_array(kick, "kick")
        bad = store_command(dash, kick, float(sign), self._commands)
        if bad >= 0:
            field_name, values = ("dash", dash) if bad < self.n else ("kick", kick)
            self._check_finite(values, field_name)
        move = command.move
        if move is not None:
            move = self._as_array(move, "move") * sign
            self._check_finite(move, "move")
        catch = command.catch
        if type(catch) is not bool:
            catch = self._as_flag(catch, "catch")
        if command.tackle is not None:
            self.tackling = self._read_tackle(command.tackle, command.foul, sign)
        elif self.tackling:
            self.tackling = False
        if command.turn_neck is not None:
            self.turns_neck = self._read_turn_neck(command.turn_neck)
        elif self.turns_neck:
            self.turns_neck = False
        if command.change_view is not None:
            self.changes_view = self._read_change_view(command.change_view)
        elif self.changes_view:
            self.changes_view = False
        said = command.say
        self.said = None if said is None else self._read_say(said)
        return catch, move

    def _read_change_view(self, widths: object) -> bool:
        """Validate ``command.change_view`` into :attr:`view_width`; whether anybody asks for a width."""
        codes = check_view_widths(widths, self.n)
        if isinstance(codes, str):
            raise TeamError(self.name, codes)
        self.view_width[:] = codes
        return bool((codes != KEEP).any())

    def _read_turn_neck(self, turns: object) -> bool:
        """Validate ``command.turn_neck`` (degrees, NaN for none) into :attr:`neck_turn` (NaN as
        0); whether any player turns its neck."""
        degrees = self._angles(turns, "turn_neck")
        np.copyto(self.neck_turn, degrees)
        self.neck_turn[np.isnan(degrees)] = 0.0
        return bool(self.neck_turn.any())

    def _read_say(self, said: object) -> Sequence[str | None]:
        """The messages of ``command.say`` (one per player, str or None), each checked against
        the channel's rules (:func:`~soccer_sim.perception.audio.check_team_messages`); messages
        held as codes are kept as they are (a ``CodedMessages``), others as a tuple."""
        if type(said) is CodedMessages:
            check_coded_messages(said, self.n, self._audio, self.name)
            return said
        if isinstance(said, (str, bytes)) or not hasattr(said, "__len__") or not hasattr(said, "__iter__"):
            raise TeamError(self.name, f"command.say must be a sequence of {self.n} messages (str or None), "
                                       f"got {type(said).__name__}")
        messages = tuple(said)  # type: ignore[arg-type]
        check_team_messages(messages, self.n, self._audio, self.name, self._allowed)
        return messages

    def _read_tackle(self, tackle: object, foul: object, sign: int) -> bool:
        """Validate the tackle directions (degrees, own frame, NaN for none) and foul flags
        into :attr:`tackle` (radians, absolute frame) and :attr:`foul`; whether anybody tackles."""
        n = self.n
        degrees = self._angles(tackle, "tackle")
        if foul is None:
            self.foul[:] = False
        else:
            flags = np.asarray(foul)
            if flags.shape != (n,) or flags.dtype.kind not in "bi":
                raise TeamError(self.name, f"command.foul must be a bool array of shape {(n,)}, "
                                           f"got {flags.dtype} of shape {flags.shape}")
            self.foul[:] = flags != 0
        np.radians(degrees, out=self.tackle)
        if sign < 0:
            self.tackle += np.pi
        return bool(np.isfinite(self.tackle).any())

    def _as_flag(self, value: object, field_name: str) -> bool:
        """``value`` as a bool if it is one (Python or numpy) or the integer 0 or 1, else a TeamError."""
        if isinstance(value, np.bool_):
            return bool(value)
        if isinstance(value, (int, np.integer)) and value in (0, 1):
            return bool(value)
        raise TeamError(self.name, f"command.{field_name} must be a bool, got {value!r} ({type(value).__name__})")

    def _angles(self, values: object, field_name: str) -> np.ndarray:
        """``values`` as one angle per player (an (n,) float64 array, degrees, NaN allowed), or a
        TeamError saying why it cannot be one (:func:`~soccer_sim.team.command_array`; an
        infinite angle names its player)."""
        degrees = command_array(values, field_name, (self.n,), lambda message: TeamError(self.name, message))
        bad = np.flatnonzero(np.isinf(degrees))
        if bad.size:
            raise TeamError(self.name, f"command.{field_name} is infinite: {degrees[bad[0]]}", player=int(bad[0]))
        return degrees

    def _as_array(self, values: object, field_name: str) -> np.ndarray:
        """``values`` as an (n, 2) float64 array, or a TeamError saying why it cannot be one."""
        return command_array(values, field_name, self._shape, lambda message: TeamError(self.name, message))

    def _check_finite(self, values: np.ndarray, field_name: str) -> None:
        bad = np.flatnonzero(~np.isfinite(values).all(axis=1))
        if bad.size:
            raise TeamError(self.name, f"command.{field_name} is not finite: {values[bad[0]].tolist()}",
                            player=int(bad[0]))

