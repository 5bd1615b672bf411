"""The server's messages to a player, as typed records (rcssserver 19, client version 19).

Each step of synchronous mode brings a player ``(sense_body T ...)``, the ``(hear T ...)``
messages of the step, a ``(see T ...)`` on the steps it sees, and ``(think)``; now and then
also ``(change_player_type ...)``, ``(ok ...)``, ``(error ...)`` and ``(warning ...)``.
:func:`read_message` turns one text into its record; positions stay in the server's polar
form here (distances m, directions degrees relative to the player's face, the body plus the
neck; positive turns from the server's +x towards its +y). Making positions of them is
:mod:`rcss_bridge.views_builder`'s job.

Measured facts this relies on (``docs/bridge.md``): ``sense_body``'s ``speed`` is the amount
(m/cycle, to 0.01) and its direction relative to the face; ``head_angle`` is the neck angle
relative to the body; in a ``see`` a player is ``((p "TEAM" UNUM [goalie]) dist dir
[distchng dirchng body head [point]] [t|k|f ...])``, the team and the number missing when too
far, ``(P)`` / ``(B)`` / ``(F)`` / ``(G)`` anonymous when only close-by; a message said by a
team-mate is heard as ``(hear T DIR our UNUM "MSG")``, by an opponent as
``(hear T DIR opp "MSG")``, by oneself as ``(hear T self "MSG")``, and an unquoted say is
passed on as said (``(hear T self ABC)(done)``), so hears are read before tokenising.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from rcss_bridge.errors import ProtocolError
from rcss_bridge.sexpr import Expr, head, integer, number, parse, unquote


@dataclass(frozen=True)
class InitReply:
    """``(init SIDE UNUM PLAY_MODE)`` to a player, ``(init SIDE ok)`` to an online coach."""

    side: str
    """``"l"`` or ``"r"``."""
    unum: int | None
    """The shirt number the server gave the player (None for a coach)."""
    play_mode: str | None
    """The server's play mode at connection (None for a coach)."""


@dataclass(frozen=True)
class SenseBody:
    """``(sense_body T ...)``: the player's own state at server time ``time``."""

    time: int
    view_quality: str
    view_width: str
    stamina: float
    effort: float
    capacity: float
    speed: float
    """Amount of the player's velocity (m/cycle, quantised to 0.01)."""
    speed_direction: float
    """Direction of the velocity relative to the face (degrees, whole)."""
    head_angle: float
    """The neck: the face's direction relative to the body (degrees)."""
    counts: dict[str, int]
    """How many of each command the server has executed (``kick``, ``dash``, ``turn``,
    ``say``, ``turn_neck``, ``catch``, ``move``, ``change_view``, ...)."""
    tackle_expires: int
    """Steps the player still cannot act after a tackle."""
    foul_charged: int
    """Steps the player still cannot act after being fouled."""
    card: str
    """``none``, ``yellow`` or ``red``."""
    collision: tuple[str, ...]
    """What the player collided with this step (``ball``, ``player``, ``post``; empty: none)."""


@dataclass(frozen=True)
class SeenObject:
    """One object of a ``see``: its name tokens and the server's numbers for it."""

    name: tuple[str, ...]
    """The name tokens: ``("f", "c", "t")``, ``("b",)``, ``("p", '"TEAM"', "7", "goalie")``,
    ``("l", "r")``, ``("P",)``, ..."""
    distance: float
    direction: float
    """Degrees relative to the face."""
    extra: tuple[float, ...]
    """The numbers after distance and direction (change of distance and direction, then for a
    player its body and neck directions relative to the observer's face, and its arm)."""
    flags: tuple[str, ...]
    """Trailing symbols (a player tackling ``t``, kicking ``k``, fouled ``f``, ...)."""

    @property
    def kind(self) -> str:
        """The first name token: ``f`` flag, ``g`` goal, ``l`` line, ``b``/``B`` ball,
        ``p``/``P`` player, ``F``/``G`` an unnamed close flag or goal."""
        return self.name[0]


@dataclass(frozen=True)
class SeenPlayer:
    """A player in a ``see``."""

    team: str | None
    """The team's name (None when it could not be seen)."""
    unum: int | None
    """The shirt number (None when it could not be seen)."""
    goalie: bool
    distance: float
    direction: float
    """Degrees relative to the observer's face."""
    body: float | None
    """Its body direction relative to the observer's face (degrees; None when not told)."""


@dataclass(frozen=True)
class See:
    """``(see T ...)``: what the player saw at server time ``time``."""

    time: int
    landmarks: tuple[SeenObject, ...]
    """Named flags and goals (``f ...``, ``g ...``), for self-localisation."""
    lines: tuple[SeenObject, ...]
    """Field lines (``l l``, ``l r``, ``l t``, ``l b``)."""
    ball: SeenObject | None
    """The ball (``b``, or ``B`` close behind); None when not seen."""
    players: tuple[SeenPlayer, ...]


@dataclass(frozen=True)
class Hear:
    """``(hear T SENDER MESSAGE)``."""

    time: int
    sender: str
    """``self``, ``our`` (a team-mate), ``opp`` (an opponent), ``referee``,
    ``online_coach_left`` / ``online_coach_right`` or ``coach`` (the trainer)."""
    message: str
    """The text (quotes removed; an unquoted say arrives as the server passed it on)."""
    direction: float | None = None
    """Direction of the speaker relative to the face (degrees; team-mates and opponents)."""
    unum: int | None = None
    """The team-mate's shirt number (``our`` only)."""


@dataclass(frozen=True)
class TypeChange:
    """``(change_player_type UNUM [TYPE])``: a team-mate's new type (``type`` given) or an
    opponent's change (``type`` None: opponents' types are never told)."""

    unum: int
    type: int | None


@dataclass(frozen=True)
class Reply:
    """``(ok ...)``, ``(error ...)`` or ``(warning ...)``: the server's answer to a command."""

    kind: str
    """``ok``, ``error`` or ``warning``."""
    text: str
    """The rest of the message (``synch_see``, ``illegal_command_form``, ...)."""


@dataclass(frozen=True)
class Parameters:
    """``(server_param ...)``, ``(player_param ...)`` or ``(player_type ...)``, kept as text
    (:mod:`rcss_bridge.params` reads them; every player receives them after ``init``)."""

    kind: str
    text: str


@dataclass(frozen=True)
class Think:
    """``(think)``: the step's messages are complete; the server waits for ``(done)``."""


Message = InitReply | SenseBody | See | Hear | TypeChange | Reply | Parameters | Think


_HEAR = re.compile(r"\(hear (\d+) (?:(self|referee|online_coach_left|online_coach_right|coach)"
                   r"|(-?[\d.]+) (?:(our) (\d+)|(opp))) (.*)\)\s*$", re.S)
"""A hear: time, then a named sender or a direction with ``our UNUM`` / ``opp``, then the text
(everything to the last ``)``: an unquoted say may contain spaces and parentheses)."""


def read_message(text: str) -> Message:
    """The record of one server message (a :class:`ProtocolError` quoting its head for one
    the bridge does not know or cannot read)."""
    kind = head(text)
    reader = _READERS.get(kind)
    if reader is None:
        raise ProtocolError(f"unknown server message ({kind} ...)")
    try:
        return reader(text)
    except (IndexError, TypeError) as exc:
        raise ProtocolError(f"malformed ({kind} ...) message: {text[:80]!r}") from exc


def read_hear(text: str) -> Hear:
    """A ``(hear ...)`` message (read with :data:`_HEAR`, not tokenised)."""
    match = _HEAR.match(text.rstrip("\0"))
    if match is None:
        raise ProtocolError(f"unreadable hear message: {text[:80]!r}")
    time, named, direction, our, unum, opp, body = match.groups()
    if named:
        return Hear(int(time), named, _said(body) if named != "referee" else body)
    return Hear(int(time), "our" if our else "opp", _said(body), float(direction), int(unum) if our else None)


def _said(body: str) -> str:
    """A player's message as said: the quotes of a quoted one removed."""
    return unquote(body) if len(body) >= 2 and body[0] == body[-1] == '"' else body


def read_sense_body(text: str) -> SenseBody:
    expr = parse(text)
    items = {item[0]: item[1:] for item in expr[2:] if isinstance(item, list) and item}
    view = items.get("view_mode", ["high", "normal"])
    stamina = items["stamina"]
    speed = items["speed"]
    counts = {name: integer(items[name][0], name) for name in
              ("kick", "dash", "turn", "say", "turn_neck", "catch", "move", "change_view", "change_focus")
              if name in items}
    tackle = _pairs(items.get("tackle", []))
    foul = _pairs(items.get("foul", []))
    collision = tuple(t for t in items.get("collision", ["none"]) if isinstance(t, str) and t != "none")
    return SenseBody(
        time=integer(expr[1], "sense_body time"), view_quality=str(view[0]), view_width=str(view[1]),
        stamina=number(stamina[0], "stamina"), effort=number(stamina[1], "effort"),
        capacity=number(stamina[2], "capacity") if len(stamina) > 2 else float("inf"),
        speed=number(speed[0], "speed"), speed_direction=number(speed[1], "speed direction"),
        head_angle=number(items["head_angle"][0], "head_angle"), counts=counts,
        tackle_expires=integer(tackle.get("expires", "0"), "tackle expires"),
        foul_charged=integer(foul.get("charged", "0"), "foul charged"), card=str(foul.get("card", "none")),
        collision=collision)


def _pairs(items: list) -> dict[str, str]:
    """``[["expires", "3"], ["count", "1"]]`` as ``{"expires": "3", "count": "1"}``."""
    return {item[0]: item[1] for item in items if isinstance(item, list) and len(item) == 2}


def read_see(text: str) -> See:
    expr = parse(text)
    landmarks: list[SeenObject] = []
    lines: list[SeenObject] = []
    players: list[SeenPlayer] = []
    ball: SeenObject | None = None
    for item in expr[2:]:
        seen = _seen_object(item)
        kind = seen.kind
        if kind in ("f", "g"):
            landmarks.append(seen)
        elif kind == "l":
            lines.append(seen)
        elif kind in ("b", "B"):
            ball = seen
        elif kind in ("p", "P"):
            players.append(_seen_player(seen))
    return See(integer(expr[1], "see time"), tuple(landmarks), tuple(lines), ball, tuple(players))


def _seen_object(item: Expr | str) -> SeenObject:
    if not isinstance(item, list) or not item or not isinstance(item[0], list):
        raise ProtocolError(f"see: malformed object {item!r}")
    numbers: list[float] = []
    flags: list[str] = []
    for token in item[1:]:
        try:
            numbers.append(float(token))  # type: ignore[arg-type]
        except (TypeError, ValueError):
            flags.append(str(token))
    if len(numbers) < 2 and item[0][0] not in ("l",):
        if len(numbers) == 1:  # a far object: its direction only (old protocols, low quality)
            numbers = [float("nan"), numbers[0]]
        else:
            raise ProtocolError(f"see: object {item!r} has no distance and direction")
    name = tuple(str(t) for t in item[0])
    return SeenObject(name, numbers[0], numbers[1], tuple(numbers[2:]), tuple(flags))


def _seen_player(seen: SeenObject) -> SeenPlayer:
    name = seen.name
    team = unquote(name[1]) if len(name) > 1 else None
    unum = int(name[2]) if len(name) > 2 else None
    goalie = "goalie" in name[3:]
    body = seen.extra[2] if len(seen.extra) >= 4 else None
    return SeenPlayer(team, unum, goalie, seen.distance, seen.direction, body)


def read_init(text: str) -> InitReply:
    expr = parse(text)
    if len(expr) == 2 and expr[1] == "ok":  # the trainer: (init ok)
        return InitReply("", None, None)
    side = str(expr[1])
    if side not in ("l", "r"):
        raise ProtocolError(f"init reply with side {side!r}: {text[:80]!r}")
    if expr[2] == "ok":
        return InitReply(side, None, None)
    return InitReply(side, integer(expr[2], "init unum"), str(expr[3]))


def read_type_change(text: str) -> TypeChange:
    expr = parse(text)
    unum = integer(expr[1], "change_player_type unum")
    return TypeChange(unum, integer(expr[2], "change_player_type type") if len(expr) > 2 else None)


def read_reply(text: str) -> Reply:
    kind = head(text)
    body = text.rstrip("\0").strip()[1 + len(kind):-1].strip()
    return Reply(kind, body)


_READERS = {
    "init": read_init, "sense_body": read_sense_body, "see": read_see, "hear": read_hear,
    "change_player_type": read_type_change, "ok": read_reply, "error": read_reply, "warning": read_reply,
    "think": lambda text: Think(),
    **{kind: (lambda text, kind=kind: Parameters(kind, text)) for kind in ("server_param", "player_param", "player_type")},
}
