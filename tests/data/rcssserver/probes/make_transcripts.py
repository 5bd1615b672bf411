"""Trim a raw transcript of record_transcripts.py into the bridge's test data.

usage: python3 make_transcripts.py RAW.jsonl OUT_DIR
Writes OUT_DIR/exchange.jsonl.gz: every datagram of the clients KEPT at the steps STEPS (the
init exchange, step -1, always), and OUT_DIR/truth.jsonl.gz: the trainer's see_global of
those steps (the exact positions, for checking the views). One JSON line per datagram
({"client", "step", "dir", "text"}; rcss_bridge.transcripts reads them).
"""
from __future__ import annotations

import gzip
import json
import sys
from pathlib import Path

KEPT = ("BRIDGE-1", "BRIDGE-2", "BRIDGE-coach", "OTHERS-1")
STEPS = set(range(-1, 3)) | set(range(8, 12)) | set(range(19, 23)) | set(range(40, 45)) | set(range(92, 96))
"""Before kick-off (0-2), the kick-off (8-11: the trainer's start at 8, kick_off_l heard at 9),
OTHERS-1's unquoted say (20; its echo at 21), play on and the goal (40-44: the ball sent at
40, play_on at 41, goal_l_1 at 42) and the kick-off after it (92-95: kick_off_r at 93)."""


def main(raw: str, out_dir: str) -> None:
    rows = [json.loads(line) for line in open(raw)]
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    kept = [r for r in rows if r["client"] in KEPT and r["step"] in STEPS]
    truth = [r for r in rows if r["client"] == "trainer" and r["step"] in STEPS and r["text"].startswith("(see_global")]
    for name, chosen in (("exchange.jsonl.gz", kept), ("truth.jsonl.gz", truth)):
        with gzip.open(out / name, "wt", encoding="utf-8", compresslevel=9) as stream:
            for r in chosen:
                stream.write(json.dumps(r) + "\n")
        print(name, len(chosen), (out / name).stat().st_size, "bytes")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
