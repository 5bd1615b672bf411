"""Trim the raw traces of record.py into the small test data files in tests/data/rcssserver/.

usage: python3 make_data.py RAW_DIR OUT_DIR [FILE ...]   (RAW_DIR holds clean.json, kicknoise.json,
noisy.json, referee.json, keeper.json and foulrule.json from run_probe.sh; with FILEs, e.g. tackle.json, only those are written
and only the modes they read are needed). Numbers only: metres, metres per cycle, degrees.
"""
from __future__ import annotations

import collections
import datetime
import json
import math
import sys

SERVER = "rcssserver 19.0.0 (synch_mode, trainer mode, default server.conf and player.conf)"
NOISE_OFF = {"player_rand": 0.0, "ball_rand": 0.0, "kick_rand": 0.0}
PARAMS = {
    "clean": NOISE_OFF,
    "kicknoise": {"player_rand": 0.0, "ball_rand": 0.0, "kick_rand": 0.1},
    "noisy": {"player_rand": 0.1, "ball_rand": 0.05, "kick_rand": 0.1},
    "keeper": {**NOISE_OFF, "coach_w_referee": True, "goalie_max_moves": 2, "drop_ball_time": 100},
    "referee": {**NOISE_OFF, "coach_w_referee": True, "foul_detect_probability": 0.5, "foul_exponent": 10.0,
                "red_card_probability": 0.0},
}
PARAMS["foulrule"] = {**PARAMS["referee"], "tackle_dist": 2.0, "tackle_width": 1.25, "tackle_exponent": 6.0,
                      "foul_cycles": 5, "tackle_cycles": 10}


OPTIONS = ("server::synch_mode=true server::coach=true server::game_logging=false "
           "server::text_logging=false, and per mode: clean/referee server::player_rand=0 server::ball_rand=0 "
           "server::kick_rand=0; kicknoise server::player_rand=0 server::ball_rand=0; referee and keeper as "
           "clean and also server::coach_w_referee=true (see run_probe.sh)")


def meta(modes: list[str], what: str) -> dict:
    return {"server": SERVER, "recorded": datetime.date.today().isoformat(), "what": what,
            "server_options": OPTIONS, "server_parameters": {m: PARAMS[m] for m in modes},
            "script": "tests/data/rcssserver/probes/record.py " + "|".join(modes) + " (trimmed by make_data.py)",
            "frame": "x, y in metres, the tackler/kicker/runner at the origin or as given, facing +x "
                     "(body 0) unless given; 'state 0' is after the setup cycle"}


def r(v: float, n: int = 4) -> float:
    return round(float(v), n)


def disp(a: list[float], b: list[float]) -> list[float]:
    return [r(b[0] - a[0]), r(b[1] - a[1])]


def dash(c: dict) -> dict:
    run = c["dash_forward"]
    speed, heading, stamina = [], [], []
    for s0, s1 in zip(run, run[1:]):
        d = disp(s0["p"]["A1"], s1["p"]["A1"])
        lapped = abs(d[0]) > 2.0   # the trainer moved the runner back to x = -45
        speed.append(None if lapped else r(math.hypot(*d)))
        heading.append(None if lapped else r(math.degrees(math.atan2(d[1], d[0])), 2))
        stamina.append(r(s1["stamina"]["A1"][0], 2))
    side = {}
    for d in (90, -90, 180, 45):
        ph = c[f"dash_dir{d}"]
        side[str(d)] = [disp(a["p"]["A1"], b["p"]["A1"]) for a, b in zip(ph, ph[1:])]
    return {"meta": meta(["clean"], "dash 100 every cycle from rest at body 0: per-cycle displacement "
                                    "(speed, m/cycle; None where the trainer moved the runner back), its "
                                    "heading (deg) and the stamina sense_body reports after the cycle; "
                                    "side/back dashes: (dash 100 DIR) from rest, body fixed at 0, "
                                    "per-cycle displacement [dx, dy]"),
            "forward": {"speed": speed, "heading_deg": heading, "stamina": stamina,
                        "stamina_max": 8000.0, "extra_stamina": 50.0},
            "dash_dir": side}


def kicks(c: dict) -> dict:
    out = {}
    for name, ph in c.items():
        if name.startswith(("kick_", "two_kicks_")):
            b0, b1, p = ph[0]["ball"], ph[1]["ball"], ph[0]["p"]
            kicker = p.get("A1", next(iter(p.values())))
            out[name] = {"ball_rel": [r(b0[0] - kicker[0]), r(b0[1] - kicker[1])],
                         "first_cycle": disp(b0, b1)}
    roll = c["kick_near_at0"]
    return {"meta": meta(["clean"], "(kick 100 DIR) of a ball at rest: kick_<dist>_at<A>[_dirD] is a ball "
                                    "at distance near (0.3851, touching) / mid (0.735) / far (1.084) at angle A "
                                    "from the body, kicked at D deg to the body (0 if absent); first_cycle is "
                                    "the ball's displacement in the kick's cycle (= its speed after the "
                                    "kick). two_kicks_*: two players kick the ball at (0, 0) in one cycle "
                                    "(same: both towards +x; orth: +x and +y; opposed: +x and -x). "
                                    "roll_x: ball x after each cycle of kick_near_at0, from x0"),
            "kicks": out,
            "roll": {"x0": r(roll[0]["ball"][0]), "x": [r(s["ball"][0]) for s in roll[1:]]}}


def contact(c: dict) -> dict:
    def trace(ph, with_y=False, who="A1"):
        """x (and y) of the player and the ball per state; without y, both stay on y = 0 (checked)."""
        out = {"player_x": [r(s["p"][who][0], 3) for s in ph], "ball_x": [r(s["ball"][0], 3) for s in ph]}
        if with_y:
            out.update(player_y=[r(s["p"][who][1], 3) for s in ph], ball_y=[r(s["ball"][1], 3) for s in ph])
        else:
            assert all(abs(s["p"][who][1]) < 1e-9 and abs(s["ball"][1]) < 1e-9 for s in ph)
        return out
    at_player = {}
    for sp in (2.7, 1.5, 0.8):
        at_player[str(sp)] = [{"player0": [r(v) for v in c[f"ball{sp}_at_player_{j}"][0]["p"]["A1"][:2]],
                               "ball_x0": r(c[f"ball{sp}_at_player_{j}"][0]["ball"][0]),
                               "ball_vx0": r(c[f"ball{sp}_at_player_{j}"][0]["ball"][2]),
                               "end_ball": [r(v) for v in c[f"ball{sp}_at_player_{j}"][-1]["ball"]],
                               "end_player": [r(v) for v in c[f"ball{sp}_at_player_{j}"][-1]["p"]["A1"][:4]]}
                              for j in range(20)]
    return {"meta": meta(["clean"], "body-ball contact, states 0..n (positions after each cycle): "
                                    "sprint: dash 100 at body 0 from x0 towards a still ball at (0, 0), 20 "
                                    "start phases; walk: dash 30; past: dash 100 along y = 0 with the ball "
                                    "at (0, off); x only (y stays 0) except for past; at_player: a ball launched "
                                    "along +x at a player standing at (0, 0) (body 180), state 0 = player0 [x, y] (the "
                                    "trainer's move puts the player at (0, 0), but where the previous phase left the "
                                    "ball may push it off before this ball is placed) / ball_x0 / ball_vx0, 20 "
                                    "cycles on: "
                                    "end_ball = [x, y, vx, vy], end_player = [x, y, vx, vy]"),
            "sprint": [trace(c[f"sprint_into_ball_{j}"]) for j in range(20)],
            "walk": [trace(c[f"walk_into_ball_{j}"]) for j in range(5)],
            "past": {str(off): trace(c[f"sprint_past_ball_{off}"], with_y=True) for off in (0.15, 0.3)},
            "ball_at_player": at_player}


def noise(kn: dict, noisy: dict) -> dict:
    def kick(raw: dict) -> dict:
        n = sum(name.startswith("kick_near_") for name in raw)
        return {lab: [disp(raw[f"kick_{lab}_{j}"][0]["ball"], raw[f"kick_{lab}_{j}"][1]["ball"]) for j in range(n)]
                for lab in ("near", "far")}
    sprint = [disp(noisy[f"sprint12_{j}"][0]["p"]["A1"], noisy[f"sprint12_{j}"][-1]["p"]["A1"])
              for j in range(sum(name.startswith("sprint12_") for name in noisy))]
    at_player = {str(sp): [{"player0": [r(v) for v in noisy[f"ball{sp}_at_player_{j}"][0]["p"]["A1"][:2]],
                            "ball_x0": r(noisy[f"ball{sp}_at_player_{j}"][0]["ball"][0]),
                            "ball_vx0": r(noisy[f"ball{sp}_at_player_{j}"][0]["ball"][2]),
                            "end_ball": [r(v) for v in noisy[f"ball{sp}_at_player_{j}"][-1]["ball"]]}
                           for j in range(40)] for sp in (2.7, 1.5, 0.8)}

    def ends(prefix: str) -> list[list[float]]:
        """[ball x, player x] at the end of each start phase."""
        return [[r(noisy[f"{prefix}_{j}"][-1]["ball"][0]), r(noisy[f"{prefix}_{j}"][-1]["p"]["A1"][0])]
                for j in range(20)]
    past = [any(abs(s["ball"][0]) > 1e-6 or abs(s["ball"][1] - 0.3) > 1e-6 for s in noisy[f"sprint_past_ball_0.3_{j}"])
            for j in range(20)]
    return {"meta": meta(["kicknoise", "noisy"],
                         "kick: (kick 100 0) of a ball at rest in front (near 0.3851 / far 1.084), only kick_rand "
                         "on (kicknoise), ball displacement [dx, dy] in the kick's cycle, 200 trials each; "
                         "kick_default_noise: the same with the default noise (kick_rand and ball_rand); "
                         "sprint12: displacement [dx, dy] after 12 cycles of dash 100 from rest at body 0, default "
                         "noise, 200 trials; ball_at_player: as in contact.json with default noise, every start "
                         "phase twice (40 trials per speed), 20 cycles; contact: the contact probes with default "
                         "noise, 20 start phases each: sprint (dash 100 from x = -5 - 0.05 j, 15 cycles) and walk "
                         "(dash 30 from -3 - 0.015 j, 40 cycles) into a still ball at (0, 0), [ball x, player x] "
                         "at the end; past_0.3_moved: dash 100 from -5 - 0.05 j for 25 cycles past a ball at "
                         "(0, 0.3), whether the ball moved"),
            "kick": kick(kn), "kick_default_noise": kick(noisy), "sprint12": sprint, "ball_at_player": at_player,
            "contact": {"sprint": ends("sprint_into_ball"), "walk": ends("walk_into_ball"), "past_0.3_moved": past}}


def tackles(c: dict, ref: dict) -> dict:
    speed = {}
    for name, ph in c.items():
        if name.startswith("tackle_speed_"):
            _, _, x, y, d = name.split("_")
            speed[name] = {"ball_rel": [float(x), float(y)], "dir": float(d[3:]),
                           "first_cycle": disp(ph[0]["ball"], ph[1]["ball"])}
    grid = collections.defaultdict(lambda: [0, 0])
    for name, ph in c.items():
        if name.startswith("tackle_grid_"):
            _, _, x, y, _ = name.split("_")
            cell = grid[(float(x), float(y))]
            cell[0] += math.hypot(*ph[1]["ball"][2:]) > 1e-6   # the ball moved: the tackle succeeded
            cell[1] += 1
    freeze = {label: [r(s["p"]["A1"][0]) for s in c[f"tackle_freeze_{bx}"][1:]]
              for label, bx in (("won", 0.5), ("missed", 3.0))}
    fouls = {}
    for lab in ("standing", "dashing"):
        counts = collections.Counter()
        for name, ph in ref.items():
            if name.startswith(f"foul_{lab}_"):
                heard = [h for s in ph[1:] for h in s["heard"]]
                if "foul_charge_l" in heard:
                    counts["foul_called"] += 1
                elif ph[1]["ball"][0] > 1.0:
                    counts["tackled_no_call"] += 1
                else:
                    counts["tackle_failed"] += 1
                counts["yellow_card"] += any(h.startswith("yellow_card") for h in heard)
                counts["red_card"] += any(h.startswith("red_card") for h in heard)
                counts["trials"] += 1
        fouls[lab] = dict(counts)
    follow = [ph for name, ph in ref.items() if name.startswith("foul_followup")][-1]
    sequence = [[s["t"], h] for s in follow for h in s["heard"]]
    called = next(i for i, s in enumerate(follow) if "foul_charge_l" in s["heard"])
    return {"meta": meta(["clean", "referee"],
                         "tackle_speed: (tackle DIR off) with the ball at rest at ball_rel from the tackler (body "
                         "0), ball displacement in the tackle's cycle. grid: [x, y, successes, trials] of (tackle 0 "
                         "off) with the ball at rest at (x, y) from the tackler. freeze: (tackle 0 off) in the "
                         "first cycle, then (dash 100 0) every cycle, the tackler's x after each of the 13 cycles, "
                         "the ball 0.5 m ahead (won) or 3.0 m (missed). fouls: (tackle 0 on) by a left player at "
                         "(-1, 0) on a right player at (0, 0) (body 0) holding the ball at (0.5, 0); "
                         "'standing': the ball holder does nothing, 'dashing': it dashes in the tackle's cycle. "
                         "followup: referee messages [time, message] after a called foul"),
            "tackle_speed": speed,
            "grid": [[x, y, s, n] for (x, y), (s, n) in grid.items()],
            "freeze": freeze,
            "fouls": fouls,
            "followup": {"messages": sequence, "ball_after_call": [r(v) for v in follow[called]["ball"]],
                         "tackler_at": [-1.0, 0.0]}}


def goalkeeper(k: dict) -> dict:
    def trace(ph: list[dict], orders: list[str] | None) -> list[dict]:
        out = []
        for i, st in enumerate(ph):
            row = {"t": st["t"], "ball": [r(v) for v in st["ball"][:2]], "keeper": [r(v) for v in st["p"]["A1"][:2]],
                   "heard": st["heard"], "errors": [e.split(" ", 1)[1] for e in st["errors"]]}
            if orders is not None and i < len(orders):
                row["order"] = orders[i]   # sent after this state, acted on in the next
            out.append(row)
        return out
    hold = k["keeper_hold"]
    orders = ["(catch 0)", "", "(move -45 5)", "(move -44 -6)", "(move -46 0)", "(dash 100 0)", "(dash 100 0)",
              "(dash 100 0)", "(turn 90)", "(kick 50 0)", "", ""]
    timeout = k["keeper_timeout"]
    changes = [i for i, st in enumerate(timeout) if st["heard"]]
    leaves = k["keeper_leaves_area"]
    return {"meta": meta(["keeper"],
                         "the goalkeeper A1 (left, unum 1, type 0) and the ball, cycle by cycle, from the trainer's "
                         "see_global: 'hold': the ball at rest 1 m in front of the keeper, then each state's "
                         "'order' (the keeper's command sent after it): catch, an idle cycle, three moves (the "
                         "third beyond goalie_max_moves), three dashes, a turn, the kick. 'timeout': catch, then "
                         "no command until the free kick's drop_ball_time ends it (only the states around the "
                         "play mode changes; i: index from the setup state). 'leaves_area': catch 2.5 m inside "
                         "the penalty area's front line (x = -36), then (dash 100 0) until the catch fault. "
                         "heard: the referee's messages heard in the cycle that led to the state; errors: the "
                         "server's replies to the keeper"),
            "hold": trace(hold, orders),
            "timeout": [dict(trace([timeout[i]], None)[0], i=i) for i in sorted(
                {j for c in changes for j in (c - 1, c) if j >= 0})],
            "leaves_area": trace(leaves[:8], None) + [dict(trace([leaves[i]], None)[0], i=i)
                                                      for i, st in enumerate(leaves) if i >= 8 and st["heard"]]}


FOUL_RULE_TRACED = ("off_behind_dash_first", "off_behind_dashed_before", "off_behind_dash_after", "on_front_stand")
"""The cases whose first trial foul_rule.json keeps as a trace."""


def foul_rule(ref: dict) -> dict:
    """foul_rule.json from the foulrule mode's raw traces (what it holds: its meta)."""
    cases = {label: {**case, "trials": 0, "tackled": 0, "foul_called": 0, "yellow_card": 0, "red_card": 0}
             for label, case in ref["cases"].items()}   # the situations as record.py wrote them
    traces = {}
    for name, ph in ref.items():
        if not name.startswith("foulrule_"):
            continue
        label, j = name[len("foulrule_"):].rsplit("_", 1)
        case = cases[label]
        at = 2 if case["holder"] == "dashed_before" else 1   # the state after the tackle's cycle
        heard = [h for s in ph[1:] for h in s["heard"]]
        called = "foul_charge_l" in heard
        case["trials"] += 1
        # a tackle that reached the ball pushed it more than 0.8 m away, or the foul put it at the tackler
        case["tackled"] += called or math.dist(ph[at]["ball"][:2], ph[at - 1]["ball"][:2]) > 0.8
        case["foul_called"] += called
        case["yellow_card"] += any(h.startswith("yellow_card") for h in heard)
        case["red_card"] += any(h.startswith("red_card") for h in heard)
        if label in FOUL_RULE_TRACED and j == "0":
            traces[label] = [{"t": s["t"], "ball": [r(v) for v in s["ball"]],
                              "players": {k: [r(v) for v in p] for k, p in s["p"].items()}, "heard": s["heard"]}
                             for s in ph]
    return {"meta": meta(["foulrule"],
                         "foul calls after tackles on a ball holder: a right player (B1..B4 in turn) at (0, 0) "
                         "with body holder_body (deg) and the ball at (0.5, 0) within its kickable area; a left "
                         "player (A1..A11 in turn) at 'tackler', its body facing the ball, sends (tackle DIR "
                         "flag) pushing towards push_dir (absolute, deg: away from the holder). The holder: "
                         "'stand' does nothing; 'dash_first' sends (dash 100 0) in the tackle's cycle, received "
                         "before the tackle; 'dash_after' the same, received after the tackle; 'dashed_before' "
                         "sends (dash 20 0) in the cycle before the tackle and nothing in its cycle. Counts per "
                         "case: trials, tackled (the tackle reached the ball: it moved more than 0.8 m in the "
                         "tackle's cycle, or a foul was called), foul_called (the referee said foul_charge_l), "
                         "yellow_card, red_card (a second yellow card; red_card_probability is 0). traces: the "
                         "first trial of some cases, states after the setup cycle and each cycle after it, "
                         "players [x, y, vx, vy, body, neck], the referee's messages heard"),
            "cases": cases, "traces": traces}


FILES = {"dash.json": (dash, ("clean",)), "kick.json": (kicks, ("clean",)), "contact.json": (contact, ("clean",)),
         "noise.json": (noise, ("kicknoise", "noisy")), "tackle.json": (tackles, ("clean", "referee")),
         "goalkeeper.json": (goalkeeper, ("keeper",)),
         "foul_rule.json": (foul_rule, ("foulrule",))}
"""Each data file: the function that trims it and the raw modes it reads."""


def main() -> None:
    raw, out = sys.argv[1], sys.argv[2]
    names = sys.argv[3:] or list(FILES)   # only these data files (their modes' raw traces suffice)
    loaded: dict[str, dict] = {}
    for name in names:
        make, modes = FILES[name]
        for m in modes:
            if m not in loaded:
                with open(f"{raw}/{m}.json") as f:
                    loaded[m] = json.load(f)
        with open(f"{out}/{name}", "w") as f:
            json.dump(make(*(loaded[m] for m in modes)), f, separators=(",", ":"))
            f.write("\n")


if __name__ == "__main__":
    main()
