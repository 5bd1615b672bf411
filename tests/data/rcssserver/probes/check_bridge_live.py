"""Play a team of the bridge's client layer (rcss_bridge.TeamClient) against nobody in the real
server for STEPS steps, with the trainer watching (``(eye on)``: exact positions), and print
how far the views are from the truth and how the steps went; then check that a decision
slower than the server waits ends with TeamTooSlow naming the player and the step.

usage (inside a private network namespace with the server running as in run_transcripts.sh,
trainer on PORT+1): python3 check_bridge_live.py PORT STEPS
"""
from __future__ import annotations

import math
import re
import socket
import sys
import threading
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[4]))

from rcss_bridge import ClientSettings, PlayerOrder, TeamClient, TeamTooSlow  # noqa: E402

_PLAYER = re.compile(r'\(\(p "BRIDGE" (\d+)(?: goalie)?\) ([-\d.e]+) ([-\d.e]+) [-\d.e]+ [-\d.e]+ ([-\d.e]+)')


def main(port: int, steps: int) -> None:
    trainer = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    trainer.bind(("127.0.0.1", 0))
    trainer.sendto(b"(init (version 19))\0", ("127.0.0.1", port + 1))
    trainer.settimeout(5)
    _, taddr = trainer.recvfrom(65536)
    truth: dict[int, str] = {}
    stop = threading.Event()

    def watch() -> None:  # the trainer's see_global, answered with (done)
        trainer.settimeout(0.2)
        while not stop.is_set():
            try:
                data, _ = trainer.recvfrom(65536)
            except socket.timeout:
                continue
            text = data.decode("latin-1").rstrip("\0")
            if text.startswith("(see_global"):
                truth[int(text.split()[1])] = text
            elif text.startswith("(think"):
                trainer.sendto(b"(done)\0", taddr)

    settings = ClientSettings(port=port, coach_port=port + 2, step_timeout=5.0)
    errors = {"position": [], "body": []}
    cpu = []
    with TeamClient("BRIDGE", settings) as team:
        team.connect()
        trainer.sendto(b"(eye on)\0", taddr)
        threading.Thread(target=watch, daemon=True).start()
        started = [False]

        def decide(step, row):
            if row == 0 and step.step == 5 and not started[0]:
                trainer.sendto(b"(start)\0", taddr)
                started[0] = True
            return PlayerOrder("(dash 60)" if (step.step + row) % 4 else "(turn 30)", f"s{row}")

        def on_step(step):
            t0 = time.process_time()
            seen = truth.get(step.server_time)
            if seen and step.step > 2:
                exact = {int(m.group(1)) - 1: (float(m.group(2)), float(m.group(3)), float(m.group(4)))
                         for m in _PLAYER.finditer(seen)}
                v = step.views
                for row, (x, y, body) in exact.items():
                    if v.localised[row]:
                        errors["position"].append(math.hypot(v.position[row, 0] - x, v.position[row, 1] - y))
                        errors["body"].append(abs((v.body_direction[row] - body + 180) % 360 - 180))
            cpu.append(time.process_time() - t0)

        t0 = time.time()
        played = team.play(decide, steps=steps, on_step=on_step)
        wall = time.time() - t0
    for key, values in errors.items():
        values.sort()
        print(f"{key} error over {len(values)} localised player-steps: median {values[len(values) // 2]:.3f}, "
              f"95% {values[int(len(values) * 0.95)]:.3f}, max {values[-1]:.3f}")
    print(f"{played} steps in {wall:.1f} s")
    slow = TeamClient("SLOW", ClientSettings(port=port, coach_port=None, connect=2, decision_budget=0.5))
    try:
        slow.connect()
        slow.play(lambda step, row: (time.sleep(2.0) if row == 1 and step.step == 3 else None) or PlayerOrder())
    except TeamTooSlow as exc:
        print("slow team:", exc)
    stop.set()


if __name__ == "__main__":
    main(int(sys.argv[1]), int(sys.argv[2]))
