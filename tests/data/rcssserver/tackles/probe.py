"""Tackle probe on the real rcssserver 19 (synch mode, trainer, kick_rand 0); wrote tackles.json.

Run: run-server.sh NAME server::port=6200 server::coach_port=6201 server::olcoach_port=6202 \
       server::synch_mode=true server::coach=true server::kick_rand=0 server::player_rand=0 server::ball_rand=0 &
     RCSS_PROBES=<the reference kit's probes folder, holding rcclient.py> python3 probe.py OUT.json
tackles.json holds OUT.json's figures with their setup (the second push trial of each
direction, the freeze traces, the success count).
"""
import json, math, os, sys
sys.path.insert(0, os.environ["RCSS_PROBES"])
from rcclient import SynchRig

rig = SynchRig({"A": 1}, trainer_port=6201, player_port=6200)
rig.wait_think()
tr = rig.trainer
out = {}

def setup(ball_x, ball_y=0.0):
    tr.send("(recover)")
    tr.send("(move (player A 1) 0 0 0 0 0)")
    tr.send(f"(move (ball) {ball_x} {ball_y} 0 0 0)")
    tr.send("(change_mode play_on)")
    rig.done(); rig.wait_think()

def step(cmd=None):
    if cmd:
        rig.players[("A", 1)].send(cmd)
    rig.done(); rig.wait_think()
    return rig.state()

# push speed by direction (ball 0.5 m ahead: failure prob 0.25^6)
for d in (0, 90, -90, 180, 45):
    speeds = []
    for trial in range(2):
        setup(0.5)
        seq = []
        t, b, ps = step(f"(tackle {d})")
        seq.append((t, round(b[0], 4), round(b[2], 4), round(b[3], 4)))
        for k in range(10):
            t, b, ps = step()
            if k < 2:
                seq.append((t, round(b[0], 4), round(b[2], 4), round(b[3], 4)))
        speeds.append(seq)
    out[f"push_dir{d}"] = speeds
    print("push", d, speeds, flush=True)

# freeze: tackle then dash 100 every cycle; when does the player move?
for bx in (0.5, 3.0):
    setup(bx)
    xs = []
    t, b, ps = step("(tackle 0)")
    xs.append(ps[("A", 1)][0])
    for k in range(12):
        t, b, ps = step("(dash 100 0)")
        xs.append(ps[("A", 1)][0])
    out[f"freeze_ball{bx}"] = xs
    print("freeze", bx, [round(x, 3) for x in xs], flush=True)

# success rate at 1.8 m ahead (expected 1 - 0.9^6 = 0.4686)
won = 0
trials = 200
for trial in range(trials):
    setup(1.8)
    t, b, ps = step("(tackle 0)")
    if math.hypot(b[2], b[3]) > 0.5:
        won += 1
    # the tackler is frozen for 10 cycles; trainer moves reset nothing of that, so wait
    for k in range(10):
        step()
out["success_1.8"] = [won, trials]
print("success at 1.8:", won, "/", trials, flush=True)
json.dump(out, open(sys.argv[1], "w"), indent=1)
