"""The root of the bridge's errors.

Every error :mod:`rcss_bridge` raises on purpose derives from :class:`BridgeError`, so a
caller can catch the whole package's complaints with one ``except``; each also keeps a
built-in base (``ValueError`` for a message the bridge cannot read, ``TimeoutError`` for a
server or a team that took too long), as the project's other error roots do.
"""

from __future__ import annotations


class BridgeError(Exception):
    """Something the bridge to rcssserver refuses or could not do."""


class ProtocolError(BridgeError, ValueError):
    """A server message the bridge cannot read (malformed, or not what the protocol says)."""


class ServerError(BridgeError, RuntimeError):
    """The server refused a client (an ``(error ...)`` reply to ``init``), went silent, or left."""


class TeamFailure(BridgeError, RuntimeError):
    """A team's decision raised, or took longer than the server waits for a step.

    ``player`` is the index (0-based, within the team) of the player being decided (None for a
    team whose one ``act()`` decides every player), ``step``
    the bridge's own step counter and ``server_time`` the server's clock at that step (which
    stands still before kick-off, after goals and at some stoppages, so both are given)."""

    def __init__(self, team_name: str, player: int | None, step: int, server_time: int, message: str) -> None:
        who = "every player (one act() decides them all)" if player is None else f"player {player} (shirt {player + 1})"
        super().__init__(f"team {team_name!r}, {who}, step {step} (server time {server_time}): {message}")
        self.team_name = team_name
        self.player = player
        self.step = step
        self.server_time = server_time
        self.message = message

    def __reduce__(self):
        """Pickle by the constructor's arguments (the error may cross a process boundary)."""
        return type(self), (self.team_name, self.player, self.step, self.server_time, self.message)


class TeamTooSlow(TeamFailure, TimeoutError):
    """A team's decision for one step took longer than the server waits (its ``(done)`` would
    come after the server had moved on)."""


class CommandError(BridgeError, ValueError):
    """A team's command the bridge cannot translate for the server (a malformed
    ``TeamCommand``, a player type choice the server would refuse). ``player`` is the row of
    the player at fault (shirt number - 1), or None when the whole command is."""

    def __init__(self, team_name: str, message: str, player: int | None = None) -> None:
        where = f"team {team_name!r}" + (f", player {player} (shirt {player + 1})" if player is not None else "")
        super().__init__(f"{where}: {message}")
        self.team_name = team_name
        self.message = message
        self.player = player

    def __reduce__(self):
        """Pickle by the constructor's arguments (the error may cross a process boundary)."""
        return type(self), (self.team_name, self.message, self.player)
