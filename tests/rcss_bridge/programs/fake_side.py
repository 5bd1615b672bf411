#!/usr/bin/env python3
"""A stand-in for a team's program in the match host's tests: ``fake_side.py NAME PORT MODE``.
``ok`` connects 11 players (an ``(init NAME ...)`` from a socket each) and waits to be ended;
``fail`` connects them, then prints an error line naming a player and a step and exits 1;
``silent`` never connects. Its process id goes to ``NAME.pid`` in the working directory."""

import os
import socket
import sys
import time

name, port, mode = sys.argv[1], int(sys.argv[2]), sys.argv[3]
with open(f"{name}.pid", "w") as f:
    f.write(str(os.getpid()))
sockets = []
if mode != "silent":
    for unum in range(11):
        s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        s.sendto(f"(init {name} (version 19))\0".encode(), ("127.0.0.1", port))
        sockets.append(s)
if mode == "fail":
    time.sleep(0.3)
    print(f"error: team {name!r}, every player (one act() decides them all), step 7 (server time 5): "
          "act() raised ValueError: boom", file=sys.stderr, flush=True)
    sys.exit(1)
while True:
    time.sleep(1)
