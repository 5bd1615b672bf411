"""Send ten robots to ten goals with every assignment method and compare the outcomes.

Run: python examples/assign_robots.py
"""

import numpy as np

from agents.assignment import METHODS, assign


def main() -> None:
    rng = np.random.default_rng(7)
    robots = rng.integers(0, 100, size=(10, 2)).astype(float)
    targets = rng.integers(0, 100, size=(10, 2)).astype(float)
    print(f"{'method':<10} {'makespan':>9} {'total':>8} {'sum of squares':>15}  targets")
    for method in METHODS:
        result = assign(robots, targets, method=method, rng=np.random.default_rng(0)) if method == "random" \
            else assign(robots, targets, method=method)
        print(f"{method:<10} {result.makespan:9.2f} {result.total:8.2f} {result.total_squared:15.1f}  "
              f"{result.target_of.tolist()}")


if __name__ == "__main__":
    main()
