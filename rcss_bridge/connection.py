"""One UDP connection to rcssserver: a player or an online coach.

A client sends ``(init ...)`` to the server's well-known port (players 6000, online coaches
6002) and the reply comes from a port of the server's own for that client; everything after
goes there (:meth:`Connection.open`). Each server message is one datagram ending in a NUL
byte; each datagram sent is one or more commands (``(dash 80)(turn_neck 10)(done)``).
"""

from __future__ import annotations

import select
import socket
import time
from collections.abc import Callable

from rcss_bridge.errors import ServerError
from rcss_bridge.messages import InitReply, read_init
from rcss_bridge.sexpr import head

Recorder = Callable[[str, int, str, str], None]
"""Called with (client name, step, "in" | "out", text) for every datagram."""

DATAGRAM_BYTES = 65536
"""The largest datagram read (a ``see`` of 22 players and 55 flags is about 3 kB)."""


class Connection:
    """A connected client (use :meth:`open`). ``name`` names it in errors and transcripts."""

    def __init__(self, name: str, sock: socket.socket, address: tuple[str, int], reply: InitReply,
                 early: list[str], recorder: Recorder | None) -> None:
        self.name = name
        self.sock = sock
        self.address = address
        """The server's port for this client."""
        self.reply = reply
        self.early = early
        """Messages that arrived with the init reply's and before the first step
        (``server_param``, ``player_param``, the ``player_type`` messages)."""
        self.step = -1
        """The step counter datagrams are recorded with."""
        self._recorder = recorder
        self.closed = False

    @classmethod
    def open(cls, name: str, host: str, port: int, init: str, timeout: float,
             recorder: Recorder | None = None) -> Connection:
        """Send ``init`` to ``host:port`` and wait at most ``timeout`` s for the reply (a
        :class:`ServerError` for none, or for an ``(error ...)`` reply)."""
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        try:
            sock.bind((host, 0))
            if recorder is not None:
                recorder(name, -1, "out", init)
            sock.sendto((init + "\0").encode("latin-1"), (host, port))
            deadline = time.monotonic() + timeout
            while True:
                remaining = deadline - time.monotonic()
                ready, _, _ = select.select([sock], [], [], max(remaining, 0.0))
                if not ready:
                    raise ServerError(f"{name}: no reply to {init} from {host}:{port} within {timeout:g} s "
                                      "(is the server running there?)")
                data, address = sock.recvfrom(DATAGRAM_BYTES)
                text = _decode(data)
                if recorder is not None:
                    recorder(name, -1, "in", text)
                kind = head(text)
                if kind == "error":
                    raise ServerError(f"{name}: the server refused {init}: {text}")
                if kind == "init":
                    return cls(name, sock, address, read_init(text), [], recorder)
        except BaseException:
            sock.close()
            raise

    def send(self, text: str) -> None:
        """Send one datagram (a NUL byte is appended)."""
        if self._recorder is not None:
            self._recorder(self.name, self.step, "out", text)
        self.sock.sendto((text + "\0").encode("latin-1"), self.address)

    def receive(self) -> list[str]:
        """Every datagram waiting now (without blocking), decoded."""
        got: list[str] = []
        while True:
            ready, _, _ = select.select([self.sock], [], [], 0.0)
            if not ready:
                return got
            data, _ = self.sock.recvfrom(DATAGRAM_BYTES)
            text = _decode(data)
            if self._recorder is not None:
                self._recorder(self.name, self.step, "in", text)
            got.append(text)

    def close(self) -> None:
        """Say ``(bye)`` (the server then frees the player's place) and close the socket."""
        if self.closed:
            return
        self.closed = True
        try:
            self.send("(bye)")
        except OSError:
            pass
        finally:
            self.sock.close()


def _decode(data: bytes) -> str:
    """A datagram's text without its trailing NUL (latin-1: every byte stands for itself)."""
    return data.decode("latin-1").rstrip("\0")
