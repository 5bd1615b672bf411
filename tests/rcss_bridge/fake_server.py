"""A fake rcssserver on 127.0.0.1 that replays a recorded synchronous exchange.

It answers the ``init`` of the first players to connect with the recorded replies of
BRIDGE-1, BRIDGE-2, ... (and the online coach's with BRIDGE-coach's), each from a port of its
own as the real server does, and sends each the messages it received at connection. Then,
step by step over the recorded steps, it sends every player what that player received at the
step (ending with ``(think)``) and the coach what it received, and waits for every player's
``(done)`` as rcssserver reads datagrams (:func:`server_commands`: an unquoted ``say`` takes the
rest of the datagram); a step without every ``(done)`` within ``wait`` seconds is recorded as
missed and the next one follows, as the real server does after its 1.25 s.
"""

from __future__ import annotations

import select
import socket
import threading
import time

from tests.rcss_bridge.recorded import received

HOST = "127.0.0.1"


def server_commands(datagram: str) -> list[str]:
    """The commands rcssserver reads in one datagram of a player: each parenthesised command in
    turn (quoted text kept whole), except that a ``say`` whose message is not quoted takes
    everything to the datagram's end (measured: ``(say ABC)(done)`` is heard as ``ABC)(done``)."""
    text = datagram.rstrip("\0").strip()
    out: list[str] = []
    i = 0
    while i < len(text):
        if text[i] != "(":
            i += 1
            continue
        if text.startswith("(say ", i) and not text.startswith('(say "', i):
            out.append(text[i:])
            break
        j, quoted = i + 1, False
        while j < len(text) and (quoted or text[j] != ")"):
            quoted ^= text[j] == '"'
            j += 1
        out.append(text[i:j + 1])
        i = j + 1
    return out


class FakeServer:
    """The fake server (module docstring), run in a thread: ``with FakeServer() as server``.

    ``wait``: how long a step waits for the ``(done)`` s; ``connect_wait``: the same for the
    messages sent at connection (a (think) sent before the whole team is connected is never
    answered: the client's first step waits for every player's).

    ``players``: the recorded clients to play, in connection order; ``silent_after``: stop
    sending after this many steps (a server that hangs); ``refuse_after``: refuse inits beyond
    this many players as a full team is refused."""

    def __init__(self, players: tuple[str, ...] = ("BRIDGE-1", "BRIDGE-2"), coach: str = "BRIDGE-coach",
                 wait: float = 3.0, connect_wait: float = 0.3, silent_after: int | None = None,
                 refuse_after: int | None = None) -> None:
        self.recorded = {name: received(name) for name in players + (coach,)}
        self.player_names, self.coach_name = players, coach
        self.wait, self.connect_wait = wait, connect_wait
        self.silent_after, self.refuse_after = silent_after, refuse_after
        self.listen = self._bind()
        self.coach_listen = self._bind()
        self.port, self.coach_port = self.listen.getsockname()[1], self.coach_listen.getsockname()[1]
        self.datagrams: dict[str, list[str]] = {}
        """Every datagram each client sent after its init, by recorded client name."""
        self.missed: list[int] = []
        """The replayed steps (0-based; -1 the messages sent at connection) at which some
        player's ``(done)`` did not come."""
        self.byes: set[str] = set()
        self.steps = sorted(s for s in set().union(*(self.recorded[p] for p in players)) if s >= 0)
        self._clients: dict[str, tuple[socket.socket, tuple[str, int]]] = {}
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def __enter__(self) -> FakeServer:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join(5)
        for sock in [self.listen, self.coach_listen] + [s for s, _ in self._clients.values()]:
            sock.close()

    @staticmethod
    def _bind() -> socket.socket:
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sock.bind((HOST, 0))
        return sock

    # ------------------------------------------------------------------------------------
    def _run(self) -> None:
        wanted = len(self.player_names) + 1
        deadline = time.monotonic() + 10.0
        players = 0
        while len(self._clients) < wanted and not self._stop.is_set() and time.monotonic() < deadline:
            ready, _, _ = select.select([self.listen, self.coach_listen], [], [], 0.05)
            for sock in ready:
                data, address = sock.recvfrom(65536)
                if sock is self.coach_listen:
                    self._accept(self.coach_name, address)
                elif self.refuse_after is not None and players >= self.refuse_after:
                    sock.sendto(b"(error no_more_team_or_player_or_goalie)\0", address)
                else:
                    self._accept(self.player_names[players], address)
                    players += 1
        if len(self._clients) < wanted:
            return
        self._collect_dones(-1, self.connect_wait,
                            thinking={p for p in self.player_names if "(think)" in self.recorded[p].get(-1, [])})
        for index, step in enumerate(self.steps):
            if self._stop.is_set() or (self.silent_after is not None and index >= self.silent_after):
                break
            for name in (*self.player_names, self.coach_name):
                if name not in self.byes:
                    self._send(name, self.recorded[name].get(step, []))
            self._collect_dones(index, thinking=set(self.player_names))
        while not self._stop.is_set():  # keep listening (for the byes) until stopped
            self._collect_dones(None, 0.05)

    def _accept(self, name: str, address: tuple[str, int]) -> None:
        sock = self._bind()
        self._clients[name] = (sock, address)
        self.datagrams[name] = []
        self._send(name, self.recorded[name].get(-1, []))

    def _send(self, name: str, texts: list[str]) -> None:
        sock, address = self._clients[name]
        for text in texts:
            try:
                sock.sendto((text + "\0").encode("latin-1"), address)
            except OSError:  # the client's port is closed (it left): the real server sends on too
                return

    def _collect_dones(self, index: int | None, wait: float | None = None, thinking: set[str] = frozenset()) -> None:
        """Read the clients' datagrams until every player of ``thinking`` (those sent a
        ``(think)``) still connected has sent ``(done)`` (or ``wait`` seconds); a missing one
        marks step ``index`` missed."""
        pending = {name for name in thinking if name not in self.byes}
        socks = {self._clients[name][0]: name for name in self._clients}
        deadline = time.monotonic() + (self.wait if wait is None else wait)
        while (pending or index is None) and time.monotonic() < deadline:  # index None: listen the whole wait
            ready, _, _ = select.select(list(socks), [], [], max(deadline - time.monotonic(), 0.0))
            for sock in ready:
                name = socks[sock]
                try:
                    text = sock.recvfrom(65536)[0].decode("latin-1").rstrip("\0")
                except OSError:  # an error report for a datagram to a port closed since
                    continue
                self.datagrams[name].append(text)
                commands = server_commands(text)
                if "(bye)" in commands:
                    self.byes.add(name)
                    pending.discard(name)
                if "(done)" in commands:
                    pending.discard(name)
        if pending and index is not None:
            self.missed.append(index)
