"""A small synchronous-mode UDP client for rcssserver 19: players and the trainer in one process.

Development tooling only (tests never import it). The server must run with
server::synch_mode=true and server::coach=true; the trainer turns `(eye on)` so it receives
`(see_global ...)` (exact positions and velocities) every cycle, and the server waits for
every client's `(done)`. Referee messages the players hear are kept (once per cycle) in `Rig.heard`; a player sent off
by a red card is dropped from the rig (the server stops talking to it). Team "A" must be
the first to connect (left side).
"""
from __future__ import annotations

import re
import select
import socket
import time

HOST = "127.0.0.1"

_NUM = r"([-\d.e+]+)"
_BALL = re.compile(r"\(\(b\) " + " ".join([_NUM] * 4) + r"\)")
_PLAYER = re.compile(r'\(\(p "([^"]+)" (\d+)(?: goalie)?\) ' + " ".join([_NUM] * 6))
_STAMINA = re.compile(r"\(stamina " + " ".join([_NUM] * 3) + r"\)")
_HEAR_REFEREE = re.compile(r"\(hear \d+ referee ([^)]+)\)")


class Conn:
    """One UDP client; after the init reply it talks to the server's per-client port."""

    def __init__(self, port: int, init: str) -> None:
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((HOST, 0))
        self.addr = (HOST, port)
        self.sock.sendto((init + "\0").encode(), self.addr)
        self.inbox: list[str] = []
        self.init_reply = ""
        while not self.init_reply:
            data, addr = self.sock.recvfrom(65536)
            msg = data.decode(errors="replace").rstrip("\0")
            self.addr = addr
            if msg.startswith(("(init", "(ok init", "(error")):
                self.init_reply = msg
            else:
                self.inbox.append(msg)

    def send(self, msg: str) -> None:
        self.sock.sendto((msg + "\0").encode(), self.addr)

    def poll(self) -> None:
        while select.select([self.sock], [], [], 0)[0]:
            data, _ = self.sock.recvfrom(65536)
            self.inbox.append(data.decode(errors="replace").rstrip("\0"))


class Rig:
    """Players {team: count} and a trainer, stepped together cycle by cycle."""

    def __init__(self, teams: dict[str, int], player_port: int, trainer_port: int) -> None:
        self.trainer = Conn(trainer_port, "(init (version 19))")
        self.players: dict[str, Conn] = {}
        for team, n in teams.items():
            for _ in range(n):
                c = Conn(player_port, f"(init {team} (version 19))")
                m = re.match(r"\(init ([lr]) (\d+)", c.init_reply)
                if not m:
                    raise RuntimeError(c.init_reply)
                self.players[f"{team}{int(m.group(2))}"] = c
        self.trainer.send("(eye on)")
        self.trainer.send("(ear on)")
        self.last_see = ""
        self.sense: dict[str, str] = {}
        self.heard: list[str] = []

    def step(self, timeout: float = 10.0) -> None:
        """Send (done) from every client, then wait until each has received (think)."""
        for c in [self.trainer, *self.players.values()]:
            c.send("(done)")
        self.wait_think(timeout)

    def wait_think(self, timeout: float = 10.0) -> None:
        """Block until every client has received (think); keep the latest see_global, sense_body
        and the referee's messages."""
        names = {id(c): k for k, c in self.players.items()}
        pending = {id(c): c for c in [self.trainer, *self.players.values()]}
        heard_now: list[str] = []
        t0 = time.time()
        while pending:
            ready = select.select([c.sock for c in pending.values()], [], [], 0.5)[0]
            for key, c in list(pending.items()):
                if c.sock in ready:
                    c.poll()
                think = False
                for msg in c.inbox:
                    if msg.startswith("(see_global"):
                        self.last_see = msg
                    elif msg.startswith("(sense_body") and key in names:
                        self.sense[names[key]] = msg
                    elif msg.startswith("(think"):
                        think = True
                    elif msg.startswith("(hear"):
                        m = _HEAR_REFEREE.match(msg)
                        if m and m.group(1) not in heard_now:
                            heard_now.append(m.group(1))
                c.inbox.clear()
                if think:
                    del pending[key]
            for h in heard_now:   # a red card disables the player: it gets no (think) any more
                m = re.match(r"red_card_([lr])_(\d+)", h)
                if m:
                    gone = self.players.pop(("A" if m.group(1) == "l" else "B") + m.group(2), None)
                    if gone is not None:
                        pending.pop(id(gone), None)
            if time.time() - t0 > timeout:
                who = ["trainer" if c is self.trainer else names[k] for k, c in pending.items()]
                raise TimeoutError(f"no (think) from the server for {who} at {self.last_see[:20]}")
        self.heard.extend(heard_now)

    def state(self) -> tuple[int, list[float], dict[str, list[float]]]:
        """(time, ball [x, y, vx, vy], {"A1": [x, y, vx, vy, body, neck]}) from the last see_global."""
        s = self.last_see
        ball = [float(v) for v in _BALL.search(s).groups()]
        players = {f"{m.group(1)}{m.group(2)}": [float(v) for v in m.groups()[2:]]
                   for m in _PLAYER.finditer(s)}
        return int(s.split()[1]), ball, players

    def stamina(self, name: str) -> list[float] | None:
        m = _STAMINA.search(self.sense.get(name, ""))
        return [float(v) for v in m.groups()] if m else None
