"""Summarise a trace of probe_noise_and_contact.py into the figures the tests compare with.

usage: python3 summarise_noise_and_contact.py TRACE.json > noise_and_contact.json"""
import json
import math
import sys

import numpy as np


def main(path: str) -> None:
    trace = json.load(open(path))
    out = {"server": "rcssserver 19.0.0", "parameters": "defaults (player_rand 0.1, ball_rand 0.05, kick_rand 0.1), "
           "synch_mode, trainer", "script": "probe_noise_and_contact.py"}
    ys = [trace[f"dash_{j}"][-1]["p"]["A1"][1] for j in range(200)]
    out["sprint_12_cycles_sideways_sd_m"] = {"trials": 200, "sd": round(float(np.std(ys)), 4)}
    for label in ("near", "far"):
        steps = [np.array(trace[f"kick_{label}_{j}"][1]["ball"][:2]) - np.array(trace[f"kick_{label}_{j}"][0]["ball"][:2])
                 for j in range(200)]
        speeds = [float(np.hypot(*d)) for d in steps]
        angles = [math.degrees(math.atan2(d[1], d[0])) for d in steps]
        out[f"kick_100_{label}_first_step"] = {"trials": 200, "mean_speed": round(float(np.mean(speeds)), 4),
                                                "speed_sd": round(float(np.std(speeds)), 4),
                                                "direction_sd_deg": round(float(np.std(angles)), 3)}
    for speed in (2.7, 1.5, 0.8):
        counts = {"through": 0, "stop": 0, "back": 0}
        for j in range(40):
            x = trace[f"ball{speed}_at_player_{j}"][-1]["ball"][0]
            counts["through" if x > 1 else "stop" if x > 0 else "back"] += 1
        out[f"ball_{speed}_at_standing_player"] = {"trials": 40, **counts}
    for name, key in (("sprinter_dash_100_into_still_ball", "run_into_ball_x"), ("walker_dash_30_into_still_ball", "walk_into_ball_x")):
        ends = [trace[f"{key}{k}"][-1] for k in range(20)]
        xs = [e["ball"][0] for e in ends]
        out[name] = {"trials": 20, "ran_past": sum(e["p"]["A1"][0] > e["ball"][0] for e in ends),
                     "ball_x_min": round(min(xs), 3), "ball_x_mean": round(float(np.mean(xs)), 3),
                     "ball_x_max": round(max(xs), 3)}
    moved = sum(any(abs(s["ball"][0]) > 1e-6 or abs(s["ball"][1] - 0.3) > 1e-6 for s in trace[f"path03_{k}"])
                for k in range(20))
    out["sprint_path_0.3_m_from_ball"] = {"trials": 20, "ball_moved": moved}
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main(sys.argv[1])
