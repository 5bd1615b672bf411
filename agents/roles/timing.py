"""Timing of every role assigner (``python -m agents.roles.timing``).

The situations are reproducible random ones: k outfield players and k role targets spread
uniformly over the field, the ball anywhere, attacking or defending in turn. For each
assigner and situation, ``assign`` and then ``steer`` (with that answer) are timed with
:mod:`timeit` after one warm-up call (which compiles the numba kernels); the figure is the
median over situations of the best of ``repeat`` runs, in microseconds per call.
:func:`offensive_order`, which the team computes once per cycle for any assigner, is timed
the same way.
"""

from __future__ import annotations

import argparse
import statistics
import timeit

import numpy as np

from agents.roles import assigner_names, make_assigner
from agents.roles.base import RoleContext, offensive_order
from agents.roles.errors import RoleError
from soccer_sim.config import STANDARD_FIELD

_HALF_LENGTH, _HALF_WIDTH = STANDARD_FIELD.half_length, STANDARD_FIELD.half_width


def _points(rng: np.random.Generator, k: int) -> np.ndarray:
    return np.column_stack((rng.uniform(-_HALF_LENGTH + 1, _HALF_LENGTH - 1, k),
                            rng.uniform(-_HALF_WIDTH + 1, _HALF_WIDTH - 1, k)))


def time_assigners(k: int = 10, situations: int = 20, repeat: int = 5, number: int = 500,
                   seed: int = 0) -> dict[str, dict[str, float]]:
    """Median microseconds per call, ``{assigner name: {"assign": ..., "steer": ...,
    "assign+steer": ...}}``, plus ``"offensive_order"`` (its ``"assign"`` entry only)."""
    if k < 1 or situations < 1 or repeat < 1 or number < 1:
        raise RoleError(f"k, situations, repeat and number must be positive, got {k}, {situations}, {repeat}, {number}")
    rng = np.random.default_rng(seed)
    cases = []
    for s in range(situations):
        ctx = RoleContext(ball=_points(rng, 1)[0], own_goal=np.array([-_HALF_LENGTH, 0.0]),
                          opp_goal=np.array([_HALF_LENGTH, 0.0]), opponents=_points(rng, 11),
                          field_half_length=_HALF_LENGTH, field_half_width=_HALF_WIDTH, cycle=s,
                          attacking=bool(s % 2))
        targets = _points(rng, k)
        cases.append((_points(rng, k), targets, offensive_order(targets), ctx))
    results: dict[str, dict[str, list[float]]] = {}

    def best(call) -> float:
        call()
        return min(timeit.repeat(call, number=number, repeat=repeat)) / number * 1e6

    for name in assigner_names():
        assigner = make_assigner(name)
        assigner.reset(k, np.random.default_rng(seed))
        times = results.setdefault(name, {"assign": [], "steer": [], "assign+steer": []})
        previous = None
        for players, targets, order, ctx in cases:
            roles = assigner.assign(players, targets, order, previous, ctx)
            times["assign"].append(best(lambda: assigner.assign(players, targets, order, roles, ctx)))
            times["steer"].append(best(lambda: assigner.steer(players, targets, roles, ctx)))
            times["assign+steer"].append(best(lambda: assigner.steer(
                players, targets, assigner.assign(players, targets, order, roles, ctx), ctx)))
            previous = roles
    results["offensive_order"] = {"assign": [best(lambda: offensive_order(targets)) for _, targets, _, _ in cases]}
    return {name: {part: statistics.median(values) for part, values in parts.items()}
            for name, parts in results.items()}


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--players", type=int, default=10, help="outfield players k (default 10)")
    parser.add_argument("--situations", type=int, default=20, help="random situations (default 20)")
    parser.add_argument("--number", type=int, default=500, help="calls per timing run (default 500)")
    args = parser.parse_args(argv)
    if args.players < 1 or args.situations < 1 or args.number < 1:
        parser.error("--players, --situations and --number must be positive")
    table = time_assigners(args.players, args.situations, number=args.number)
    print(f"µs per call, k = {args.players}, median over {args.situations} situations")
    print(f"{'assigner':16s} {'assign':>8s} {'steer':>8s} {'both':>8s}")
    for name, parts in table.items():
        cells = [f"{parts[p]:8.1f}" if p in parts else f"{'':8s}" for p in ("assign", "steer", "assign+steer")]
        print(f"{name:16s} {' '.join(cells)}")


if __name__ == "__main__":
    main()
