"""Record real rcssserver message transcripts for the bridge's tests (rcss_bridge).

Connects, from one process, a team of 11 players (the first as goalkeeper) and its online
coach ("BRIDGE", the left side), two players of a second team ("OTHERS", the right side) and
the trainer (with ``(eye on)``: its ``(see_global ...)`` every step is the truth the tests
compare the views with), all synchronous (``(synch_see)``, protocol version 19), and steps them together;
every datagram each client receives or sends is written as one JSON line
``{"client", "step", "dir": "in"|"out", "text"}`` (``step``: the recorder's own step counter;
``-1`` before the first ``(think)``). The trainer starts the match after a few steps, later
sends the ball into the right-hand goal, so the transcript has: the init replies,
server_param / player_param / player_type, before_kick_off, kick_off_l, play_on, a goal and the
kick-off after it. Every player of both teams says a quoted message each step; the second
team's player 1 also sends one unquoted say before its ``(done)`` in the same datagram at
one step (the server then never sees that ``(done)``: the step waits until its time-out).

usage: python3 record_transcripts.py OUT.jsonl PORT  (the server runs with
``server::synch_mode=true server::coach=true server::coach_w_referee=true`` on PORT, trainer
PORT+1, online coach PORT+2; see run_transcripts.sh)
"""
from __future__ import annotations

import json
import select
import socket
import sys
import time

HOST = "127.0.0.1"
STEPS = 140
START_AT = 8
"""The trainer's ``(start)`` (before kick-off until then)."""
GOAL_AT = 40
"""The trainer sends the ball towards the right-hand goal."""
UNQUOTED_AT = 20
"""OTHERS' player 1 sends ``(say ABC)(done)`` in one datagram at this step."""


class Client:
    def __init__(self, name: str, port: int, init: str, log) -> None:
        self.name, self.log = name, log
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind((HOST, 0))
        self.addr = (HOST, port)
        self.step = -1
        self.send(init)
        data, self.addr = self.sock.recvfrom(65536)
        self.record(data)

    def record(self, data: bytes) -> str:
        text = data.decode("latin-1").rstrip("\0")
        self.log.write(json.dumps({"client": self.name, "step": self.step, "dir": "in", "text": text}) + "\n")
        return text

    def send(self, text: str) -> None:
        self.log.write(json.dumps({"client": self.name, "step": self.step, "dir": "out", "text": text}) + "\n")
        self.sock.sendto((text + "\0").encode("latin-1"), self.addr)

    def drain(self, timeout: float) -> list[str]:
        got = []
        while True:
            ready, _, _ = select.select([self.sock], [], [], timeout)
            if not ready:
                return got
            data, _ = self.sock.recvfrom(65536)
            got.append(self.record(data))
            timeout = 0.0


def main(out: str, port: int) -> None:
    with open(out, "w") as log:
        players = []
        for i in range(11):
            players.append(Client(f"BRIDGE-{i + 1}", port, f"(init BRIDGE (version 19){' (goalie)' if i == 0 else ''})", log))
        coach = Client("BRIDGE-coach", port + 2, "(init BRIDGE (version 19))", log)
        others = [Client(f"OTHERS-{i + 1}", port, "(init OTHERS (version 19))", log) for i in range(2)]
        trainer = Client("trainer", port + 1, "(init (version 19))", log)
        everyone = players + others
        time.sleep(0.3)
        for c in everyone + [coach, trainer]:
            c.drain(0.05)
        for c in everyone:
            c.send("(synch_see)")
        trainer.send("(eye on)")
        coach.send("(change_player_type 2 5)")
        for step in range(STEPS):
            for c in everyone + [coach, trainer]:
                c.step = step
            waited = everyone + [trainer]
            pending = set(range(len(waited)))
            deadline = time.time() + 3.0
            while pending and time.time() < deadline:
                for k in list(pending):
                    if any(t.startswith("(think") for t in waited[k].drain(0.002)):
                        pending.discard(k)
            coach.drain(0.0)
            if step == START_AT:
                trainer.send("(start)")
            if step == GOAL_AT:
                trainer.send("(move (ball) 48 0 0 2.5 0)")
            for k, c in enumerate(everyone):
                said = f'"m{c.name[-2:].strip("-")}s{step % 100}"'
                if c.name == "OTHERS-1" and step == UNQUOTED_AT:
                    c.send("(turn 10)(say ABC)(done)")
                    continue
                body = "(turn 5)" if step % 3 == 0 else "(dash 20)"
                c.send(f"{body}(say {said})(done)")
            trainer.send("(done)")
        for c in everyone + [coach, trainer]:
            c.step = STEPS
            c.send("(bye)")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]))
