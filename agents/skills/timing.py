"""Timing of every skill call for one team of 11 (``python -m agents.skills.timing``).

The situations are reproducible random mid-game views (players spread over the field, the
ball rolling near one of our players, who can kick it). Each call is timed with
:mod:`timeit` after one warm-up call (which compiles the numba kernels); the figure is the
median over views of the best of ``repeat`` runs, in microseconds per call.
"""

from __future__ import annotations

import argparse
import statistics
import timeit
from collections.abc import Callable

import numpy as np

from agents.skills.decision import decide_on_ball
from agents.skills.dribbling import dribble
from agents.skills.goalkeeping import distribute, guard_position, should_catch
from agents.skills.context import SkillContext
from agents.skills.interception import ball_race, intercept
from agents.skills.kicking import kick_for_velocity
from agents.skills.model import MotionModel
from agents.skills.movement import dash_to_points, paced_dashes, speed_caps
from agents.skills.passing import best_pass
from agents.skills.shooting import best_shot
from soccer_sim.config import MatchConfig
from soccer_sim.state import PlayMode
from soccer_sim.team import TeamView


def random_view(config: MatchConfig, rng: np.random.Generator, carrier: int = 9,
                carrier_at: tuple[float, float] | None = None) -> TeamView:
    """A mid-game view: both teams spread over the field, our ``carrier`` (at ``carrier_at``
    if given) next to a slow ball."""
    n = config.players_per_team
    hl, hw = config.field.half_length, config.field.half_width
    own = np.column_stack([rng.uniform(-hl + 5, hl - 5, n), rng.uniform(-hw + 3, hw - 3, n)])
    opp = np.column_stack([rng.uniform(-hl + 5, hl - 5, n), rng.uniform(-hw + 3, hw - 3, n)])
    own[0] = (-hl + 2.0, 0.0)
    opp[0] = (hl - 2.0, 0.0)
    if carrier_at is not None:
        own[carrier] = carrier_at
    ball = own[carrier] + (0.6, 0.0)
    return TeamView(own_pos=own, own_vel=rng.uniform(-0.3, 0.3, (n, 2)), opp_pos=opp,
                    opp_vel=rng.uniform(-0.3, 0.3, (n, 2)), ball=ball, ball_vel=np.array([0.3, 0.1]),
                    stamina=np.full(n, config.stamina.maximum), play_mode=PlayMode.PLAY_ON,
                    effort=np.full(n, 1.0))


def skill_calls(ctx: SkillContext, view: TeamView, carrier: int,
                attack: TeamView) -> dict[str, Callable[[], object]]:
    """The calls timed, by name (each for a whole team of players where the skill allows);
    ``attack`` is a view with the carrier 18 m from the opponents' goal (shots in range)."""
    model = ctx.model
    n = model.players_per_team
    targets = view.own_pos + 5.0
    urgent = np.zeros(n, dtype=bool)
    urgent[carrier] = True
    out = np.empty((n, 2))
    wanted = np.array([2.0, 0.5])
    return {
        "intercept (11 players, 60 cycles)": lambda: intercept(ctx, view.ball, view.ball_vel,
                                                               ctx.arrays(view).ours),
        "ball_race (both teams)": lambda: ball_race(ctx, view),
        "dash_to_points (11 players)": lambda: dash_to_points(model, ctx.arrays(view).ours, targets,
                                                              out=out),
        "speed_caps (11 players)": lambda: speed_caps(ctx, view, urgent),
        "paced_dashes (11 players)": lambda: paced_dashes(ctx, view, targets, urgent, out),
        "kick_for_velocity": lambda: kick_for_velocity(model, view.own_pos[carrier], view.ball, view.ball_vel, wanted),
        "best_pass": lambda: best_pass(ctx, view, carrier),
        "best_shot (out of range)": lambda: best_shot(ctx, view, carrier),
        "best_shot (in range)": lambda: best_shot(ctx, attack, carrier),
        "dribble": lambda: dribble(ctx, view, carrier),
        "guard_position": lambda: guard_position(model, view.ball),
        "should_catch": lambda: should_catch(ctx, view),
        "distribute (goalkeeper)": lambda: distribute(ctx, view),
        "decide_on_ball (midfield)": lambda: decide_on_ball(ctx, view, carrier),
        "decide_on_ball (18 m from goal)": lambda: decide_on_ball(ctx, attack, carrier),
    }


def time_skills(views: int = 20, repeat: int = 5, number: int = 200, seed: int = 0) -> dict[str, float]:
    """Median microseconds per call of every skill over ``views`` random views."""
    config = MatchConfig()
    ctx = SkillContext(MotionModel.even_sides(config))
    rng = np.random.default_rng(seed)
    results: dict[str, list[float]] = {}
    for _ in range(views):
        carrier = 9
        view = random_view(config, rng, carrier)
        attack = random_view(config, rng, carrier, (config.field.half_length - 18.6, float(rng.uniform(-8, 8))))
        for name, call in skill_calls(ctx, view, carrier, attack).items():
            call()
            best = min(timeit.repeat(call, number=number, repeat=repeat)) / number
            results.setdefault(name, []).append(best * 1e6)
    return {name: statistics.median(values) for name, values in results.items()}


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--views", type=int, default=20, help="random situations (default 20)")
    parser.add_argument("--number", type=int, default=200, help="calls per timing run (default 200)")
    args = parser.parse_args(argv)
    if args.views < 1 or args.number < 1:
        parser.error("--views and --number must be positive")
    for name, micro in time_skills(args.views, number=args.number).items():
        print(f"{name:40s} {micro:9.1f} µs")


if __name__ == "__main__":
    main()
