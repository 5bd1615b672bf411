"""Rewrite the built-in formation sets (``formations/data/*.json``) from their design
(:mod:`formations.design`) on the simulator's default field:
``python -m tests.formations.write_builtin_sets [--out DIR]``.

The formations package is pure and takes the field from its caller; this is that caller for
the shipped data, and ``test_formation_builtins`` checks the files equal what it writes."""

from __future__ import annotations

import argparse
from pathlib import Path

from formations.design import data_directory, write_builtin_sets
from soccer_sim.config import STANDARD_FIELD


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Generate the built-in formation sets.")
    parser.add_argument("--out", type=Path, default=data_directory(), help="output directory")
    args = parser.parse_args(argv)
    for path in write_builtin_sets(args.out, STANDARD_FIELD):
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
