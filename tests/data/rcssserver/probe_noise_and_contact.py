"""Probe of the real rcssserver 19.0.0 with its default noise (player_rand 0.1, ball_rand 0.05,
kick_rand 0.1): 200 sprints, 200 kicks of a touching and of a farthest ball, and the body-ball
contact probes (ball launched at a standing player, 40 trials per speed; sprinter and walker
into a still ball; a path 0.3 m from the ball, 20 each). Not run by the tests (they need no
server); its output, summarised by summarise_noise_and_contact.py, is noise_and_contact.json.

Run with the reference kit (RCSS_KIT: the kit's directory, holding probes/rcclient.py):
    <kit>/run-server.sh NAME server::synch_mode=true server::coach=true \
        server::port=6100 server::coach_port=6101 server::olcoach_port=6102 &
    python3 probe_noise_and_contact.py OUT.json
(the server listens on every interface: start both inside a loopback-only network
namespace, e.g. ``unshare -rn`` with ``ip link set lo up``)."""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.environ.get("RCSS_KIT", "/work/shared/reference/rcssserver"), "probes"))
from rcclient import SynchRig
import experiments_real as E

def main(out):
    rig = SynchRig({E.A: 3, E.B: 1}, trainer_port=6101, player_port=6100)
    rig.wait_think()
    log = {}
    for j in range(200):
        E.run_phase(rig, f"dash_{j}", {"keep": ("A1",), "cmds": ["(move (player A 1) -30 0 0 0 0)", "(move (ball) 0 30 0 0 0)"]},
                    lambda k, s: {"A1": "(dash 100 0)"}, 12, log)
    for j in range(200):
        E.run_phase(rig, f"kick_near_{j}", {"keep": ("A1",), "cmds": ["(move (player A 1) -30 0 0 0 0)", "(move (ball) -29.6151 0 0 0 0)"]},
                    lambda k, s: {"A1": "(kick 100 0)"} if k == 0 else {}, 2, log)
        E.run_phase(rig, f"kick_far_{j}", {"keep": ("A1",), "cmds": ["(move (player A 1) -30 0 0 0 0)", "(move (ball) -28.916 0 0 0 0)"]},
                    lambda k, s: {"A1": "(kick 100 0)"} if k == 0 else {}, 2, log)
    for speed in (2.7, 1.5, 0.8):
        for j in range(40):
            x0 = -10.0 - speed * (j % 20) / 20.0
            E.run_phase(rig, f"ball{speed}_at_player_{j}", {"keep": ("A1",), "cmds": [
                "(move (player A 1) 0 0 180 0 0)", f"(move (ball) {x0} 0 0 {speed} 0)"]}, lambda i, s: {}, 14, log)
    for k in range(20):
        E.run_phase(rig, f"run_into_ball_x{k}", {"keep": ("A1",), "cmds": [
            f"(move (player A 1) {-5.0 - 0.05 * k} 0 0 0 0)", "(move (ball) 0 0 0 0 0)"]},
            lambda i, s: {"A1": "(dash 100 0)"}, 15, log)
        E.run_phase(rig, f"walk_into_ball_x{k}", {"keep": ("A1",), "cmds": [
            f"(move (player A 1) {-3.0 - 0.015 * k} 0 0 0 0)", "(move (ball) 0 0 0 0 0)"]},
            lambda i, s: {"A1": "(dash 30 0)"}, 40, log)
        E.run_phase(rig, f"path03_{k}", {"keep": ("A1",), "cmds": [
            f"(move (player A 1) {-5.0 - 0.05 * k} 0 0 0 0)", "(move (ball) 0 0.3 0 0 0)"]},
            lambda i, s: {"A1": "(dash 100 0)"}, 25, log)
    json.dump(log, open(out, "w"))

main(sys.argv[1])
