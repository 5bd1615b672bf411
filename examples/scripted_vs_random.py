"""The scripted team, controlling the left side of the environment, against the random team.

Run: python examples/scripted_vs_random.py [cycles]
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the checkout, for `examples.*`

from examples.random_team import RandomTeam  # noqa: E402
from examples.scripted_team import scripted_policy  # noqa: E402
from soccer_sim.env import parallel_env  # noqa: E402


def main(cycles: int = 1000) -> None:
    env = parallel_env(controlled="left", opponent=RandomTeam(), max_cycles=cycles)
    observations, infos = env.reset(seed=0)
    totals = dict.fromkeys(env.agents, 0.0)
    while env.agents:
        actions = {agent: scripted_policy(observations[agent]) for agent in env.agents}
        observations, rewards, terminations, truncations, infos = env.step(actions)
        for agent, reward in rewards.items():
            totals[agent] += reward
    score = tuple(infos["left_0"]["score"].tolist())
    print(f"after {cycles} cycles: score {score}, reward of left_0 {totals['left_0']:+.0f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1000)
