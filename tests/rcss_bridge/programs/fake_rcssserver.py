#!/usr/bin/env python3
"""A stand-in for rcssserver in the match host's tests: it reads the ``server::key=value``
options the host gives, listens on 127.0.0.1 at ``server::port``, says ``A new (v19) player
(NAME N) connected.`` for every ``(init NAME ...)`` as rcssserver does (numbering each team's
players in order), and once two full teams are connected writes a game log and a text log
named as asked after ``FAKE_RCSS_SECONDS`` (1 s: the match) and exits (the game log is a copy
of ``FAKE_RCSS_RCG`` when set). ``FAKE_RCSS_MODE=hang`` never exits; ``FAKE_RCSS_MODE=crash`` exits
with status 3 at once. Its process id goes to ``fake-server.pid`` in the game log directory."""

import os
import re
import socket
import sys
import time

options = dict(re.match(r"server::([a-z_]+)=(.*)", a).groups() for a in sys.argv[1:] if a.startswith("server::"))
logs = options["game_log_dir"]
with open(os.path.join(logs, "fake-server.pid"), "w") as f:
    f.write(str(os.getpid()))
mode = os.environ.get("FAKE_RCSS_MODE", "match")
print("rcssserver-19.0.0 (a test's stand-in)", flush=True)
if mode == "crash":
    print("cannot bind", flush=True)
    sys.exit(3)
sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
sock.bind(("127.0.0.1", int(options["port"])))
teams: dict[str, int] = {}
while len(teams) < 2 or any(count < 11 for count in teams.values()):
    data, _ = sock.recvfrom(4096)
    found = re.match(r"\(init (\S+)", data.decode("latin-1"))
    if found:
        name = found.group(1)
        teams[name] = teams.get(name, 0) + 1
        print(f"A new (v19) player ({name} {teams[name]}) connected.", flush=True)
if mode == "hang":
    while True:
        time.sleep(1)
time.sleep(float(os.environ.get("FAKE_RCSS_SECONDS", "1.0")))  # the match
name = options["game_log_fixed_name"]
left, right = list(teams)
with open(os.path.join(logs, name + ".rcg"), "w") as f:
    recorded = os.environ.get("FAKE_RCSS_RCG")  # a game log to give as the match's
    f.write(open(recorded).read() if recorded else "ULG6\n")
with open(os.path.join(options["text_log_dir"], name + ".rcl"), "w") as f:
    f.write("")
print(f"Game Results:\n\t'{left}' vs '{right}'\n\tScore: {os.environ.get('FAKE_RCSS_SCORE', '0 - 0')}", flush=True)
