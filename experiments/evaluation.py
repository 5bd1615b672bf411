"""The evaluation protocol of a policy (or any team) on a scenario: fixed seeds disjoint from
training, a goal rate and a mean score difference with 95 % confidence intervals.

**Seeds.** Episode ``k`` (0, 1, ...) of an evaluation with offset ``s`` (``--seed``, default 0)
plays the match seed ``EVALUATION_SEED_BASE + s + k``, ``EVALUATION_SEED_BASE`` being 2**32.
Every match the environment plays in training takes its seed from NumPy's ``SeedSequence``
(:meth:`soccer_sim.env.SoccerParallelEnv.reset_arrays`), a 32-bit integer below 2**32, whatever
seed training was started with: so no evaluation episode ever repeats a training episode, and
two evaluations with the same offset play the same episodes.

**Sides.** The policy plays the home side (the environment's ``left`` agents, the side every
shipped scenario attacks with) against ``opponent`` on the away side.

**What is reported.** Over the episodes: the *goal rate*, the share of episodes in which the
policy's side scored at least once (with Wilson's 95 % interval, :func:`experiments.stats.proportion`),
and the *mean score difference*, goals for minus goals against per episode (with Student's t
95 % interval, :func:`experiments.stats.estimate`). An episode the policy forfeited (its code
raised or sent a malformed command) counts as one without a goal and has no score difference;
one the opponent forfeited, or that failed with no team at fault, is left out of both.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the simulator and numpy load only when an evaluation runs (``--help`` stays quick)
    from experiments.results.record import MatchRecord
    from experiments.stats import Estimate
    from experiments.runner.spec import MatchSpec
    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import Scenario

EVALUATION_SEED_BASE = 2 ** 32
"""The first evaluation seed: above every match seed the environment draws in training (32-bit)."""
DEFAULT_EPISODES = 100
"""Episodes of an evaluation by default: a goal rate's 95 % interval at most about ±0.1 wide."""
HOME = 0
DEFAULT_OPPONENT = "static"
"""The opponent by default: the environment's (``soccer_sim.env.options.DEFAULT_OPPONENT``, which a
test keeps equal; named here so that building the command's options imports no simulator)."""


def evaluation_seeds(episodes: int, offset: int = 0) -> range:
    """The match seeds of ``episodes`` evaluation episodes with ``offset`` (see the module docstring)."""
    first = EVALUATION_SEED_BASE + offset
    return range(first, first + episodes)


def evaluation_specs(policy: str, opponent: str, episodes: int, offset: int, scenario: Scenario | None,
                     config: MatchConfig | None = None) -> list[MatchSpec]:
    """The matches of an evaluation: ``policy`` at home against ``opponent``, one per seed of
    :func:`evaluation_seeds`, on ``scenario`` (None: the regular match) with ``config``."""
    from experiments.runner.spec import MatchSpec

    cycles = None if config is None else config.max_cycles
    return [MatchSpec(policy, opponent, seed, cycles, configuration=config, scenario=scenario)
            for seed in evaluation_seeds(episodes, offset)]


@dataclass(frozen=True)
class EvaluationSummary:
    """What an evaluation reports (see the module docstring)."""

    policy: str
    opponent: str
    episodes: int
    """Episodes counted: played ones and those the policy forfeited."""
    forfeits: int
    """Episodes the policy forfeited."""
    goals_for: int
    goals_against: int
    goal_rate: Estimate
    """Share of the counted episodes in which the policy scored, with Wilson's interval."""
    score_difference: Estimate
    """Goals for minus goals against per played episode, with Student's t interval."""


def summarise(records: Sequence[MatchRecord], policy: str, opponent: str) -> EvaluationSummary:
    """The :class:`EvaluationSummary` of ``policy``'s episodes at home against ``opponent`` in ``records``."""
    from experiments.stats import estimate, proportion

    mine = [r for r in records if r.names() == (policy, opponent)]
    played = [r for r in mine if r.played]
    forfeits = sum(1 for r in mine if not r.played and r.forfeit == HOME)
    scored = sum(1 for r in played if r.goals()[HOME] > 0)
    counted = len(played) + forfeits
    return EvaluationSummary(
        policy=policy, opponent=opponent, episodes=counted, forfeits=forfeits,
        goals_for=sum(r.goals()[HOME] for r in played), goals_against=sum(r.goals()[1 - HOME] for r in played),
        goal_rate=proportion(scored, counted),
        score_difference=estimate(r.goals()[HOME] - r.goals()[1 - HOME] for r in played))
