"""Reading an rcssserver game log (``.rcg``, text version 6) back: its parameters, the
ball and players of every ``(show ...)`` line, the play modes and the team/score lines.

soccer-sim's own check of the files :class:`~soccer_sim.rcg.RcgRecorder` writes (and a way
to read the logs of real rcssserver matches). Strict: a line it does not understand is an
:class:`~soccer_sim.rcg.recorder.RcgError` naming the file and the line number.
``(team_graphic ...)`` lines, which carry nothing it reads, are skipped.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field

from soccer_sim.rcg.recorder import HEADER, RcgError

_NUMBER = r"(-?[\d.]+(?:e[-+]?\d+)?)"
_BALL = re.compile(r"\(\(b\) " + " ".join([_NUMBER] * 4) + r"\)")
_PLAYER = re.compile(
    r"\(\(([lr]) (\d+)\) (\d+) (0x[0-9a-f]+|0) " + " ".join([_NUMBER] * 6)
    + r"(?: [^()]+)? \(v ([hl]) " + _NUMBER + r"\)(?: \(fp [^()]*\))? \(s " + " ".join([_NUMBER] * 3)
    + r"(?: " + _NUMBER + r")?\)(?: \(f [lr] \d+\))? \(c ([\d ]+)\)\)")
_SHOW = re.compile(r"\(show (\d+) ")
_PLAY_MODE = re.compile(r"\(playmode (\d+) ([a-z_]+)\)$")
_TEAM = re.compile(r"\(team (\d+) (\S+) (\S+) (\d+) (\d+)(?: \d+ \d+ \d+ \d+)?\)$")
_PARAMS = re.compile(r"\(([a-z_0-9]+) ((?:\"[^\"]*\")|[^()]*)\)")
_MSG = re.compile(r'\(msg (\d+) (\d+) "(.*)"\)$')
_SKIPPED = ("(team_graphic ",)


@dataclass(frozen=True)
class PlayerFrame:
    """One player in one show line (rcssserver's frame and units)."""

    side: str
    unum: int
    type: int
    state: int
    x: float
    y: float
    vx: float
    vy: float
    body: float
    neck: float
    stamina: float
    effort: float
    recovery: float
    capacity: float | None
    counts: tuple[int, ...]

    @property
    def present(self) -> bool:
        """Whether the player is on the field (rcssserver's STAND flag; a player that never
        connected or was sent off is shown without it)."""
        return bool(self.state & 0x1)


@dataclass(frozen=True)
class Show:
    """One ``(show ...)`` line: the cycle, the ball (x, y, vx, vy) and the players."""

    cycle: int
    ball: tuple[float, float, float, float]
    players: tuple[PlayerFrame, ...]

    def player(self, side: str, unum: int) -> PlayerFrame:
        """The player of ``side`` (``l``/``r``) with shirt ``unum``; KeyError if absent."""
        for p in self.players:
            if p.side == side and p.unum == unum:
                return p
        raise KeyError(f"no player ({side} {unum}) in the show line of cycle {self.cycle}")


@dataclass
class GameLog:
    """What a game log holds, in file order."""

    server_params: dict[str, str] = field(default_factory=dict)
    player_params: dict[str, str] = field(default_factory=dict)
    player_types: list[dict[str, str]] = field(default_factory=list)
    shows: list[Show] = field(default_factory=list)
    play_modes: list[tuple[int, str]] = field(default_factory=list)
    """(cycle, mode name) of every ``(playmode ...)`` line."""
    teams: list[tuple[int, str, str, int, int]] = field(default_factory=list)
    """(cycle, left name, right name, left score, right score) of every ``(team ...)`` line."""
    messages: list[tuple[int, int, str]] = field(default_factory=list)
    """(cycle, board, text) of every ``(msg ...)`` line (rcssserver ends a log with its result)."""


def _float(text: str | None) -> float | None:
    return None if text is None else float(text)


def parse_show(line: str) -> Show:
    """One ``(show ...)`` line; ValueError if it is not one."""
    head = _SHOW.match(line)
    ball = _BALL.search(line)
    if head is None or ball is None or not line.endswith(")"):
        raise ValueError("not a show line with a ball")
    players = []
    rest = line[ball.end():-1]
    position = 0
    for m in _PLAYER.finditer(rest):
        if rest[position:m.start()].strip():
            raise ValueError(f"unreadable player text {rest[position:m.start()].strip()[:40]!r}")
        position = m.end()
        g = m.groups()
        players.append(PlayerFrame(g[0], int(g[1]), int(g[2]), int(g[3], 16) if g[3].startswith("0x") else int(g[3]),
                                   *(float(v) for v in g[4:10]), float(g[12]), float(g[13]), float(g[14]),
                                   _float(g[15]), tuple(int(v) for v in g[16].split())))
    if rest[position:].strip():
        raise ValueError(f"unreadable player text {rest[position:].strip()[:40]!r}")
    return Show(int(head.group(1)), tuple(float(v) for v in ball.groups()), tuple(players))


def read_rcg(path: str | os.PathLike) -> GameLog:
    """Parse the game log at ``path`` line by line; RcgError naming the file and line for
    anything that is not a version 6 text log."""
    path = os.fspath(path)
    log = GameLog()
    from formations.input_files import open_input  # the project's one rule for files it reads

    try:
        with open_input(path) as f:
            lines = f.read().decode("utf-8").split("\n")
    except (OSError, UnicodeDecodeError) as exc:
        raise RcgError(f"{path}: cannot read the game log ({getattr(exc, 'strerror', None) or exc})") from None
    if not lines or lines[0] != HEADER:
        raise RcgError(f"{path}: not a version 6 game log (the first line is not {HEADER})")
    for number, line in enumerate(lines[1:], start=2):
        try:
            _read_line(log, line)
        except ValueError as exc:
            raise RcgError(f"{path}, line {number}: {exc}: {line[:60]!r}") from None
    return log


def _read_line(log: GameLog, line: str) -> None:
    if not line or line.startswith(_SKIPPED):
        return
    if line.startswith("(show "):
        log.shows.append(parse_show(line))
    elif line.startswith("(playmode "):
        m = _PLAY_MODE.match(line)
        if m is None:
            raise ValueError("bad playmode line")
        log.play_modes.append((int(m.group(1)), m.group(2)))
    elif line.startswith("(msg "):
        m = _MSG.match(line)
        if m is None:
            raise ValueError("bad msg line")
        log.messages.append((int(m.group(1)), int(m.group(2)), m.group(3)))
    elif line.startswith("(team "):
        m = _TEAM.match(line)
        if m is None:
            raise ValueError("bad team line")
        log.teams.append((int(m.group(1)), m.group(2), m.group(3), int(m.group(4)), int(m.group(5))))
    elif line.startswith("(server_param "):
        log.server_params = dict(_PARAMS.findall(line[len("(server_param "):-1]))
    elif line.startswith("(player_param "):
        log.player_params = dict(_PARAMS.findall(line[len("(player_param "):-1]))
    elif line.startswith("(player_type "):
        log.player_types.append(dict(_PARAMS.findall(line[len("(player_type "):-1])))
    else:
        raise ValueError("unknown line")
