"""Turn helios-base v helios-base game logs (made by play_helios_matches.sh) into
``tests/data/rcssserver/helios_matches.json``: the figures of ``bench soccer`` per match,
computed by its game-log path (:func:`experiments.benchmarks.soccer_rcg.rcg_figures`) with
helios-base's role labels (:mod:`experiments.benchmarks.helios_roles`).

usage (from the repository root):
    python tests/data/rcssserver/probes/helios_figures.py FORMATION.conf LOG.rcg [LOG.rcg ...]
FORMATION.conf: helios-base's src/formations-dt/normal-formation.conf. Matches already in
the file whose log is not given again are kept (so logs can be added a few at a time).
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[4]))

from experiments.benchmarks.helios_roles import KINDS, helios_labels  # noqa: E402
from experiments.benchmarks.soccer_rcg import rcg_figures  # noqa: E402
from soccer_sim.rcg import read_rcg  # noqa: E402

OUT = Path(__file__).resolve().parents[1] / "helios_matches.json"


def main(formation: str, logs: list[str]) -> None:
    shirts = helios_labels(formation)
    names = {os.path.basename(path) for path in logs}
    kept = json.loads(OUT.read_text())["matches"] if OUT.exists() else []
    matches = [match for match in kept if match["log"] not in names]
    params: dict[str, str] = {}
    for path in logs:
        log = read_rcg(path)
        params = params or log.server_params
        figures = rcg_figures(log, {"l": shirts, "r": shirts}, KINDS)
        _, left, right, left_goals, right_goals = log.teams[-1]
        matches.append({"log": os.path.basename(path), "teams": [left, right], "score": [left_goals, right_goals],
                        "cycles": log.shows[-1].cycle,
                        "figures": {k: (None if v is None else round(v, 4)) for k, v in figures.items()}})
        print(os.path.basename(path), left_goals, right_goals, flush=True)
    matches.sort(key=lambda match: match["log"])
    OUT.write_text(json.dumps({
        "source": "rcssserver 19.0.0, helios-base v helios-base, full matches (2 x 3000 cycles, synchronous mode), "
                  "played one at a time by probes/play_helios_matches.sh; figures by bench soccer --rcg "
                  "(probes/helios_figures.py)",
        "server": {key: params.get(key) for key in ("version", "synch_mode", "half_time", "proper_goal_kicks",
                                                   "drop_ball_time", "stamina_max", "recover_dec_thr")},
        "role_labels": shirts,
        "matches": matches}, indent=1) + "\n")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
