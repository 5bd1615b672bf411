"""Record rcssserver 19 traces of the probe situations (development tooling; tests never run it).

usage: python3 record.py MODE RAW_OUT.json [PLAYER_PORT TRAINER_PORT]
MODE is one of (start the server first, options in README.md):
  clean      noise off: dashes, kicks, ball roll, two kicks, body-ball contact, tackles (push, freeze,
             success by place)
  kicknoise  only kick_rand on: kick speed and direction spread
  noisy      default noise: player drift, kicks, ball launched at a standing player, sprinter and
             walker into a still ball, a path 0.3 m from the ball
  referee    noise off, referee on in trainer mode: foul tackles, fouls called, cards
  keeper     noise off, referee on in trainer mode: the goalkeeper's catch, its free kick, moves,
             a dash and the kick that releases the ball; holding until the free kick times out
  foulrule   as referee: tackles with and without the foul flag on a ball holder, by place, the
             holder's body and whether (and when) it dashed: which are called
Every phase: one setup cycle (the trainer places players and ball, `(recover)`, play_on), then
`cycles` cycles in which a policy sends player commands; the trainer's see_global (exact
positions and velocities after each cycle) is recorded, state 0 being the one after the setup.
"""
from __future__ import annotations

import json
import re
import select
import socket
import sys
import time

# ---- a small synchronous-mode UDP client: players and the trainer in one process ----
# The server must run with server::synch_mode=true and server::coach=true; the trainer turns
# `(eye on)` so it receives (see_global ...) (exact positions and velocities) every cycle, and the
# server waits for every client's (done). Referee messages the players hear are kept once per
# cycle in Rig.heard; a player sent off by a red card is dropped from the rig. Team "A" must
# connect first (left side).


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

    def __init__(self, teams: dict[str, int], player_port: int, trainer_port: int,
                 goalies: tuple[str, ...] = ()) -> None:
        """`goalies`: teams whose first player connects as the goalkeeper (unum 1)."""
        self.trainer = Conn(trainer_port, "(init (version 19))")
        self.players: dict[str, Conn] = {}
        for team, n in teams.items():
            for i in range(n):
                goalie = " (goalie)" if team in goalies and i == 0 else ""
                c = Conn(player_port, f"(init {team} (version 19){goalie})")
                m = re.match(r"\(init ([lr]) (\d+)", c.init_reply)
                if not m:
                    raise RuntimeError(c.init_reply)
                self.players[f"{team}{int(m.group(2))}"] = c
        self.trainer.send("(eye on)")
        self.trainer.send("(ear on)")
        self.last_see = ""
        self.sense: dict[str, str] = {}
        self.heard: list[str] = []
        self.errors: list[str] = []   # "A1 (error too_many_moves)": what the server answered a player

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
                    elif msg.startswith(("(error", "(warning")) and key in names:
                        self.errors.append(f"{names[key]} {msg}")
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


# ---- the probe situations ----

TEAMS = {"A": 11, "B": 4}
TACKLERS = [f"A{i}" for i in range(1, 12)]


def park_all(rig: Rig, keep: tuple[str, ...]) -> None:
    """Move every player not in `keep` to the touchline area at rest, 4 m apart."""
    for i, name in enumerate(rig.players):
        if name not in keep:
            team, unum = name[0], name[1:]
            rig.trainer.send(f"(move (player {team} {unum}) {-45 + 4 * i} -32 0 0 0)")


def phase(rig: Rig, log: dict, name: str, keep: tuple[str, ...], cmds: list[str], policy, cycles: int,
          first: tuple[str, ...] = ()) -> list[dict]:
    """Run one phase and store its states under `name`; `first` players' commands go out first."""
    tr = rig.trainer
    tr.send("(recover)")
    park_all(rig, keep)
    for c in cmds:
        tr.send(c)
    tr.send("(change_mode play_on)")
    rig.heard.clear()
    rig.step()
    states = [snapshot(rig, keep)]
    for k in range(cycles):
        orders = policy(k, states[-1])
        for who in sorted(orders, key=lambda w: w not in first):
            (tr if who == "trainer" else rig.players[who]).send(orders[who])
            if who in first:
                time.sleep(0.005)
        rig.step()
        states.append(snapshot(rig, keep))
    log[name] = states
    return states


def snapshot(rig: Rig, keep: tuple[str, ...]) -> dict:
    t, ball, players = rig.state()
    out = {"t": t, "ball": ball, "p": {k: players[k] for k in keep if k in players},
           "heard": list(rig.heard), "errors": list(rig.errors)}
    rig.heard.clear()
    rig.errors.clear()
    for k in keep:
        st = rig.stamina(k)
        if st is not None:
            out.setdefault("stamina", {})[k] = st
    return out


def move(name: str, x: float, y: float, body: float = 0.0, vx: float = 0.0, vy: float = 0.0) -> str:
    return f"(move (player {name[0]} {name[1:]}) {x} {y} {body} {vx} {vy})"


def ball(x: float, y: float, vx: float = 0.0, vy: float = 0.0) -> str:
    return f"(move (ball) {x} {y} 0 {vx} {vy})"


NEAR, MID, FAR = 0.3851, 0.735, 1.084   # ball centre distances: touching, mid, farthest kickable


def clean(rig: Rig, log: dict) -> None:
    def dash_lapping(k, s):
        c = {"A1": "(dash 100 0)"}
        if s["p"]["A1"][0] > 45.0:   # a move without velocity keeps velocity and stamina
            c["trainer"] = "(move (player A 1) -45 0 0)"
        return c
    phase(rig, log, "dash_forward", ("A1",), [move("A1", -45, 0), ball(0, 30)], dash_lapping, 500)
    for d in (90, -90, 180, 45):
        phase(rig, log, f"dash_dir{d}", ("A1",), [move("A1", 0, 0), ball(0, 30)],
              lambda k, s, d=d: {"A1": f"(dash 100 {d})"}, 20)
    import math
    for deg in (0, 45, 90, 135, 180):
        for label, r in (("near", NEAR), ("mid", MID), ("far", FAR)):
            if deg and label != "near":
                continue
            bx, by = r * math.cos(math.radians(deg)), r * math.sin(math.radians(deg))
            phase(rig, log, f"kick_{label}_at{deg}", ("A1",), [move("A1", -30, 0), ball(-30 + bx, by)],
                  lambda k, s: {"A1": "(kick 100 0)"} if k == 0 else {}, 80 if deg == 0 and label == "near" else 3)
    for d in (45, 90, 180):   # ball in front, sent at d degrees to the body
        phase(rig, log, f"kick_near_at0_dir{d}", ("A1",), [move("A1", -30, 0), ball(-30 + NEAR, 0)],
              lambda k, s, d=d: {"A1": f"(kick 100 {d})"} if k == 0 else {}, 3)
    two = [("same", "A1", "A2", move("A2", 0, -0.6, 90), "(kick 100 -90)"),
           ("orth", "A1", "A2", move("A2", 0, -0.6, 90), "(kick 100 0)"),
           ("opposed", "A1", "B1", move("B1", 0.6, 0, 180), "(kick 100 0)")]
    for label, p, q, mq, kq in two:
        phase(rig, log, f"two_kicks_{label}", (p, q), [move(p, -0.6, 0), mq, ball(0, 0)],
              lambda k, s, p=p, q=q, kq=kq: {p: "(kick 100 0)", q: kq} if k == 0 else {}, 3)
    for j in range(20):   # sprinter into a still ball: start 5.0 .. 5.95 m behind it
        phase(rig, log, f"sprint_into_ball_{j}", ("A1",), [move("A1", -5.0 - 0.05 * j, 0), ball(0, 0)],
              lambda k, s: {"A1": "(dash 100 0)"}, 15)
    for j in range(5):    # walker (dash 30) into the ball
        phase(rig, log, f"walk_into_ball_{j}", ("A1",), [move("A1", -3.0 - 0.06 * j, 0), ball(0, 0)],
              lambda k, s: {"A1": "(dash 30 0)"}, 40)
    for off in (0.15, 0.3):
        phase(rig, log, f"sprint_past_ball_{off}", ("A1",), [move("A1", -5, 0), ball(0, off)],
              lambda k, s: {"A1": "(dash 100 0)"}, 20)
    for speed in (2.7, 1.5, 0.8):
        for j in range(20):
            phase(rig, log, f"ball{speed}_at_player_{j}", ("A1",),
                  [move("A1", 0, 0, 180), ball(-3.0 * speed - speed * j / 20.0, 0, speed, 0)], lambda k, s: {}, 20)
    # tackle ball speed (success is certain close in front): ball at (x, y) from the tackler, direction d
    for bx, by, d in ((0.5, 0.0, 0), (0.5, 0.0, 90), (0.5, 0.0, 180), (0.5, 0.5, 0), (1.0, 0.0, -45), (0.5, 0.0, 45),
                      (0.5, 0.0, -90)):
        phase(rig, log, f"tackle_speed_{bx}_{by}_dir{d}", ("A1",), [move("A1", 0, 0), ball(bx, by)],
              lambda k, s, d=d: {"A1": f"(tackle {d} off)"} if k == 0 else {}, 12)  # > tackle_cycles
    # the freeze: (tackle 0) in the first cycle, then (dash 100 0) every cycle; ball won (0.5 m) or missed (3 m)
    for bx in (0.5, 3.0):
        phase(rig, log, f"tackle_freeze_{bx}", ("A1",), [move("A1", 0, 0), ball(bx, 0)],
              lambda k, s: {"A1": "(tackle 0 off)" if k == 0 else "(dash 100 0)"}, 13)
    # tackle success grid [(x, y, trials)], tacklers in turn (a tackler cannot act for tackle_cycles afterwards)
    grid = [(x, 0.0, 60) for x in (0.5, 1.0, 1.5, 1.75, 1.9, 2.05)] + \
           [(0.5, y, 60) for y in (0.6, 1.0, 1.15, 1.3)] + [(1.5, 0.8, 60), (1.7, 1.0, 60), (1.0, 1.1, 60)] + \
           [(-0.5, 0.0, 60), (-0.4, 0.3, 60), (0.0, 0.8, 60), (1.8, 0.0, 200)]
    n = 0
    for gx, gy, trials in grid:
        for j in range(trials):
            t = TACKLERS[n % len(TACKLERS)]
            n += 1
            phase(rig, log, f"tackle_grid_{gx}_{gy}_{j}", (t,), [move(t, 0, 0), ball(gx, gy)],
                  lambda k, s, t=t: {t: "(tackle 0 off)"}, 1)


def kick_trials(rig: Rig, log: dict, trials: int) -> None:
    """(kick 100 0) of a ball at rest touching (near) and farthest (far) in front, `trials` each."""
    for j in range(trials):
        for label, r in (("near", NEAR), ("far", FAR)):
            phase(rig, log, f"kick_{label}_{j}", ("A1",), [move("A1", -30, 0), ball(-30 + r, 0)],
                  lambda k, s: {"A1": "(kick 100 0)"} if k == 0 else {}, 1)


def kicknoise(rig: Rig, log: dict) -> None:
    kick_trials(rig, log, 200)


def noisy(rig: Rig, log: dict) -> None:
    for j in range(200):
        phase(rig, log, f"sprint12_{j}", ("A1",), [move("A1", -30, 0), ball(0, 30)],
              lambda k, s: {"A1": "(dash 100 0)"}, 12)
    kick_trials(rig, log, 200)   # kick_rand and ball_rand together
    for speed in (2.7, 1.5, 0.8):
        for j in range(40):   # every start phase twice
            phase(rig, log, f"ball{speed}_at_player_{j}", ("A1",),
                  [move("A1", 0, 0, 180), ball(-3.0 * speed - speed * (j % 20) / 20.0, 0, speed, 0)],
                  lambda k, s: {}, 20)
    for j in range(20):   # the contact probes with noise, 20 start phases each
        phase(rig, log, f"sprint_into_ball_{j}", ("A1",), [move("A1", -5.0 - 0.05 * j, 0), ball(0, 0)],
              lambda k, s: {"A1": "(dash 100 0)"}, 15)
        phase(rig, log, f"walk_into_ball_{j}", ("A1",), [move("A1", -3.0 - 0.015 * j, 0), ball(0, 0)],
              lambda k, s: {"A1": "(dash 30 0)"}, 40)
        phase(rig, log, f"sprint_past_ball_0.3_{j}", ("A1",), [move("A1", -5.0 - 0.05 * j, 0), ball(0, 0.3)],
              lambda k, s: {"A1": "(dash 100 0)"}, 25)


def referee(rig: Rig, log: dict) -> None:
    # victim B holds the ball 0.5 m in front; the tackler 1.0 m behind the victim, 1.5 m from the ball
    n = 0
    for label, trials in (("standing", 100), ("dashing", 20)):
        for j in range(trials):
            alive = [a for a in TACKLERS if a in rig.players]   # red-carded tacklers are gone
            t, v = alive[n % len(alive)], f"B{1 + n % 4}"
            n += 1
            def pol(k, s, t=t, v=v, label=label):
                if k:
                    return {}
                return {t: "(tackle 0 on)", v: "(dash 100 0)"} if label == "dashing" else {t: "(tackle 0 on)"}
            phase(rig, log, f"foul_{label}_{j}", (t, v), [move(v, 0, 0), ball(0.5, 0), move(t, -1.0, 0)],
                  pol, 2, first=(v,))
    for j in range(10):   # what follows a called foul: 35 cycles
        alive = [a for a in TACKLERS if a in rig.players]
        t, v = alive[(n + j) % len(alive)], "B1"
        states = phase(rig, log, f"foul_followup_{j}", (t, v), [move(v, 0, 0), ball(0.5, 0), move(t, -1.0, 0)],
                       lambda k, s, t=t: {t: "(tackle 0 on)"} if k == 0 else {}, 36)
        if any("foul_charge" in h for s in states for h in s["heard"]):
            break


KEEPER_TEAMS = {"A": 2, "B": 1}
KEEPER_ORDERS = ["(catch 0)", "", "(move -45 5)", "(move -44 -6)", "(move -46 0)", "(dash 100 0)", "(dash 100 0)",
                 "(dash 100 0)", "(turn 90)", "(kick 50 0)", "", ""]
"""The goalkeeper A1's command in each cycle of the hold probe ("" none): the catch, an idle cycle, three
moves (the third beyond goalie_max_moves 2), three dashes, a turn, the kick that releases the ball."""


def keeper(rig: Rig, log: dict) -> None:
    # the goalkeeper at (-48, 0) facing +x, the ball at rest 1 m in front (inside catchable_area_l 1.2);
    # a team-mate and an opponent parked on the touchline. Each phase's setup passes through drop_ball
    # first: a mode change forgets the last kicker, so the goalkeeper's own kick of the phase before
    # does not make its next catch a back pass.
    forget = "(change_mode drop_ball)"
    setup = [forget, move("A1", -48, 0), ball(-47, 0)]
    phase(rig, log, "keeper_hold", ("A1", "B1"), setup,
          lambda k, s: {"A1": KEEPER_ORDERS[k]} if KEEPER_ORDERS[k] else {}, len(KEEPER_ORDERS))
    # catch, then hold without a kick until the referee ends the free kick
    phase(rig, log, "keeper_timeout", ("A1", "B1"), setup,
          lambda k, s: {"A1": "(catch 0)"} if k == 0 else {}, 110)
    # catch 2.5 m inside the penalty area's front line (x = -36), then dash out of the area with the ball
    phase(rig, log, "keeper_leaves_area", ("A1", "B1"), [forget, move("A1", -40.5, 0), ball(-39.5, 0)],
          lambda k, s: {"A1": "(catch 0)" if k == 0 else "(dash 100 0)"} if k < 8 else {}, 45)


FOUL_RULE_PLACES = {
    # tackler (x, y) and the push's absolute direction (deg, away from the holder): the ball holder
    # stands at (0, 0), the ball at (0.5, 0); the tackler faces the ball
    "behind": (-1.0, 0.0, 0.0),       # the holder between tackler and ball, on the tackle's line
    "behind_diag": (-0.7, -0.7, 0.0), # the holder between them, 0.25 m off the line
    "side": (0.0, -1.0, 0.0),         # the holder nearer than the ball, 0.45 m off the line
    "side_ahead": (0.5, -1.0, 0.0),   # the holder further than the ball: never charged
    "front": (1.5, 0.0, -90.0),       # the ball between tackler and holder: never charged
}
FOUL_RULE_CASES = [
    # (label, place, holder's body (deg), flag, holder's action, trials); the holder's actions:
    #   stand: nothing; dash_first: (dash 100 0) sent before the tackle in the tackle's cycle;
    #   dash_after: (dash 100 0) sent after the tackle in the tackle's cycle;
    #   dashed_before: (dash 20 0) in the cycle before the tackle, nothing in the tackle's cycle
    ("off_behind_stand", "behind", 0, "off", "stand", 40),
    ("off_behind_dash_first", "behind", 0, "off", "dash_first", 100),
    ("off_behind_dash_after", "behind", 0, "off", "dash_after", 40),
    ("off_behind_dashed_before", "behind", 0, "off", "dashed_before", 120),
    ("off_behind_facing_tackler_dash_first", "behind", 180, "off", "dash_first", 40),
    ("off_behind_diag_dash_first", "behind_diag", 0, "off", "dash_first", 40),
    ("off_side_dash_first", "side", 0, "off", "dash_first", 40),
    ("off_side_ahead_dash_first", "side_ahead", 0, "off", "dash_first", 40),
    ("off_front_dash_first", "front", 0, "off", "dash_first", 40),
    ("on_front_stand", "front", 0, "on", "stand", 40),
    ("on_side_stand", "side", 0, "on", "stand", 40),
    ("on_side_dashed_before", "side", 0, "on", "dashed_before", 16),
]
"""The foul rule's situations (mode foulrule): when a tackle on a ball holder is called."""


def foul_rule(rig: Rig, log: dict) -> None:
    """Tackles on a right-team ball holder (B1..B4 in turn) by left players (in turn, those not
    sent off), each with the tackler placed as FOUL_RULE_PLACES says, facing the ball and pushing
    it away from the holder (so a tackle that reached the ball moves it more than 0.8 m)."""
    import math
    log["cases"] = {label: {"tackler": list(FOUL_RULE_PLACES[place][:2]), "push_dir": FOUL_RULE_PLACES[place][2],
                            "holder_body": float(body), "flag": flag, "holder": action}
                    for label, place, body, flag, action, _ in FOUL_RULE_CASES}   # for make_data.py
    n = 0
    for label, place, body, flag, action, trials in FOUL_RULE_CASES:
        tx, ty, push = FOUL_RULE_PLACES[place]
        facing = math.degrees(math.atan2(0.0 - ty, 0.5 - tx))
        direction = round((push - facing + 180.0) % 360.0 - 180.0, 3)   # relative to the body
        for j in range(trials):
            alive = [a for a in TACKLERS if a in rig.players]
            t, v = alive[n % len(alive)], f"B{1 + n % 4}"
            n += 1
            tackle_at = 1 if action == "dashed_before" else 0

            def pol(k, s, t=t, v=v):
                orders = {}
                if k == tackle_at:
                    orders[t] = f"(tackle {direction} {flag})"
                if action in ("dash_first", "dash_after") and k == 0:
                    orders[v] = "(dash 100 0)"
                if action == "dashed_before" and k == 0:
                    orders[v] = "(dash 20 0)"
                return orders
            first = (t,) if action == "dash_after" else (v,)
            phase(rig, log, f"foulrule_{label}_{j}", (t, v),
                  [move(v, 0, 0, body), ball(0.5, 0), move(t, tx, ty, round(facing, 3))],
                  pol, tackle_at + 2, first=first)


def main() -> None:
    mode, out = sys.argv[1], sys.argv[2]
    player_port = int(sys.argv[3]) if len(sys.argv) > 3 else 6000
    trainer_port = int(sys.argv[4]) if len(sys.argv) > 4 else 6001
    rig = Rig(KEEPER_TEAMS, player_port, trainer_port, goalies=("A",)) if mode == "keeper" \
        else Rig(TEAMS, player_port, trainer_port)
    rig.wait_think()
    log: dict = {}
    try:
        {"clean": clean, "kicknoise": kicknoise, "noisy": noisy, "referee": referee, "keeper": keeper,
         "foulrule": foul_rule}[mode](rig, log)
    finally:
        with open(out, "w") as f:
            json.dump(log, f)
    print(mode, "phases", len(log), "last cycle", rig.state()[0])


if __name__ == "__main__":
    main()
