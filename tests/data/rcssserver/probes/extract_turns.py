"""Cut one player's recorded exchange and the game log's body directions out of a match played
with ``play --engine rcssserver`` and the team process's ``--transcript`` (the data of
``tests/rcss_bridge/test_turns_between_sees.py``).

python3 extract_turns.py WORKDIR TEAM UNUM FIRST_TIME LAST_TIME OUT.jsonl.gz OUT_TRUTH.json

WORKDIR holds ``match.rcg`` and ``TEAM.jsonl.gz`` (the left team's transcript); the steps kept
are those whose ``sense_body`` time lies in [FIRST_TIME, LAST_TIME]; the truth is each
``(show T)``'s body direction of the player (the last show of a time), from FIRST_TIME - 1 on.
"""

import collections
import gzip
import json
import sys

from rcss_bridge.transcripts import read_transcript
from soccer_sim.rcg import read_rcg


def main(work: str, team: str, unum: int, first: int, last: int, out: str, truth_out: str) -> None:
    shows = {show.cycle: show for show in read_rcg(f"{work}/match.rcg").shows}
    client = f"{team}-{unum}"
    steps = collections.defaultdict(list)
    for datagram in read_transcript(f"{work}/{team}.jsonl.gz"):
        if datagram.client == client:
            steps[datagram.step].append(datagram)
    kept = []
    for step in sorted(steps):
        times = [int(d.text.split()[1]) for d in steps[step] if d.direction == "in" and d.text.startswith("(sense_body")]
        if times and first <= times[-1] <= last:
            kept.append(step)
    with gzip.open(out, "wt") as stream:
        for step in kept:
            for d in steps[step]:
                stream.write(json.dumps({"client": d.client, "step": d.step, "dir": d.direction, "text": d.text}) + "\n")
    truth = {str(t): shows[t].player("l", unum).body for t in range(first - 1, last + 2) if t in shows}
    with open(truth_out, "w") as stream:
        json.dump({"client": client, "source": "rcssserver 19.0.0 game log, (show T) body direction of the player, "
                   "degrees", "body_by_time": truth}, stream, indent=0)


if __name__ == "__main__":
    work, team, unum, first, last, out, truth_out = sys.argv[1:8]
    main(work, team, int(unum), int(first), int(last), out, truth_out)
