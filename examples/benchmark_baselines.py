"""The benchmark's baselines, trained and evaluated by one command: PPO with one policy shared by
the controlled players (Stable-Baselines3 + SuperSuit, the recipe of ``ppo_shared_policy.py``)
and MAPPO (``benchmark_mappo.py``) on the academy scenarios and on the full match at a fixed
budget of environment steps, 3 seeds each, every run checkpointed, resumable and evaluated by
``soccer-sim evaluate``; random actions evaluated the same way. The full match is trained
against one rung of a difficulty ladder of built-in teams (:data:`LADDER_TRAINING_OPPONENT`)
and evaluated against every rung (:data:`LADDER`). The protocol and the table:
docs/benchmark.md.

    pip install torch --index-url https://download.pytorch.org/whl/cpu
    pip install stable-baselines3 supersuit torchrl
    nohup nice -n 15 python examples/benchmark_baselines.py run --out runs/rl > runs/rl.log 2>&1 &
    python examples/benchmark_baselines.py status --out runs/rl
    python examples/benchmark_baselines.py report --out runs/rl --docs docs

``run`` evaluates the random-actions baseline on every scenario (on the full match against every
rung), then trains and evaluates the planned runs one at a time, in order (every seed of
``empty-goal``, then of ``run-to-score-with-keeper``, ``3-vs-1-with-keeper``,
``counter-attack``, PPO's runs before MAPPO's; then the full match's, PPO's before MAPPO's).
Re-running the same command skips finished runs and evaluations, continues an unfinished run
from its last checkpoint and an interrupted evaluation from its last stored episode; a larger
``--budget`` continues finished runs. Only one ``run`` works on an output folder at a time.
``status`` shows where every run is and the wall time left at the speeds measured so far;
``report`` writes the table of finished runs and the learning curves
(``examples/benchmark_report.py``).

One *environment step* is one cycle of one match, whatever the number of controlled players;
Stable-Baselines3 counts agent steps (environment steps times the players sharing the policy).
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import fcntl
import json
import os
import subprocess
import sys
from collections.abc import Iterator, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

CHECKOUT = Path(__file__).resolve().parents[1]
"""The checkout's root: ``soccer-sim evaluate`` runs there, so ``examples.*`` teams resolve."""

SCENARIOS = ("empty-goal", "run-to-score-with-keeper", "3-vs-1-with-keeper", "counter-attack")
"""The academy scenarios of the benchmark, in the order they are trained."""
FULL_MATCH = "full-match"
"""The regular match (11 a side, 6000 cycles), trained against :data:`LADDER_TRAINING_OPPONENT`
and evaluated against every rung of :data:`LADDER`; planned after the academy scenarios."""
PLANNED = (*SCENARIOS, FULL_MATCH)
"""Every scenario of the benchmark, in the order of the plan."""
PLAYERS = {"empty-goal": 1, "run-to-score-with-keeper": 1, "3-vs-1-with-keeper": 3, "counter-attack": 4,
           FULL_MATCH: 11}
"""Controlled players (the home side) of each scenario: agent steps per environment step."""
LADDER = ("idle", "chaser", "counter-442", "possession", "static", "press-433", "mmd+msd2")
"""The full match's opponents, weakest first: the order of their points in a round robin of the
seven, each rung beating the one below it head to head (docs/benchmark.md, "The difficulty
ladder", gives the commands and figures)."""
LADDER_TRAINING_OPPONENT = "chaser"
"""The away side the full-match runs train against: the lowest rung that plays the ball and
scores, so that both goal terms of the reward occur from the first episodes (docs/benchmark.md)."""
FULL_MATCH_EPISODES = 10
"""Episodes (full matches) of each evaluation against a rung (``--full-match-episodes``)."""
SEEDS = (0, 1, 2)
BUDGET = 500_000
"""Environment steps of a run (rounded up to whole PPO rollouts)."""
CHECKPOINT_EVERY = 50_000
"""Environment steps between checkpoints (each rounded up to a whole rollout)."""
EVALUATION_EPISODES = 100
"""Episodes of each evaluation (``soccer-sim evaluate --episodes``; seeds 2**32 + k)."""
OPPONENT = "static"
"""The away side in training and evaluation: the environment's and ``evaluate``'s default."""
RANDOM_TEAM = "examples.random_team:RandomTeam"
"""The random-actions baseline: uniform actions in the action box (``examples/random_team.py``)."""
PPO = "ppo-shared"
MAPPO = "mappo"
ALGORITHMS = (PPO, MAPPO)
"""The trained baselines, in the order their runs are planned."""
CHECKPOINT_SUFFIX = {PPO: ".zip", MAPPO: ".pt"}
"""A checkpoint's file type: a Stable-Baselines3 model, a torch file of the MAPPO run's state."""
RANDOM = "random-actions"
CHUNK_SEED_STRIDE = (1_000_000, 1_000)
"""Training seeds: chunk c of run seed s resets its matches with s * 1,000,000 + c * 1,000 (match
i gets that + i), so no two chunks or runs share a match seed while a run has under 1,000 chunks
and 1,000 matches; all of them lie below 2**32, under every evaluation seed."""
CURVE_FIELDS = ("env_steps", "agent_steps", "episodes", "mean_return", "goal_rate", "wall_s")
"""Columns of a run's ``curve.csv``: one row per PPO rollout, training episodes ended in it."""


class BenchmarkError(Exception):
    """A benchmark command that cannot do its job; the message says why, on one line."""


@dataclass(frozen=True)
class Settings:
    """Everything that makes a training run what it is (kept in its ``run.json``; a run is only
    ever continued with the same settings)."""

    scenario: str
    seed: int
    matches: int = 8
    n_steps: int = 256
    batch_size: int = 256
    learning_rate: float = 3e-4
    n_epochs: int = 10
    gamma: float = 0.99
    gae_lambda: float = 0.95
    checkpoint_every: int = CHECKPOINT_EVERY
    action_mode: str = "low_level"
    rewards: str = "dense"
    opponent: str = OPPONENT

    @property
    def players(self) -> int:
        return PLAYERS[self.scenario]

    @property
    def rollout_env_steps(self) -> int:
        """Environment steps of one PPO rollout (all matches together)."""
        return self.n_steps * self.matches


def training_opponent(scenario: str) -> str:
    """The away side a run on ``scenario`` trains against: the ladder's training rung on the full
    match, :data:`OPPONENT` on the academy scenarios."""
    return LADDER_TRAINING_OPPONENT if scenario == FULL_MATCH else OPPONENT


def scenario_label(scenario: str, opponent: str) -> str:
    """``scenario`` when the away side is the default :data:`OPPONENT` (the academy's folders and
    names), else ``scenario-v-opponent`` (``full-match-v-chaser``)."""
    return scenario if opponent == OPPONENT else f"{scenario}-v-{opponent}"


@dataclass(frozen=True)
class RunSpec:
    """One planned run: ``algorithm`` (:data:`PPO`) on ``scenario`` with ``seed``, trained
    against ``opponent``."""

    algorithm: str
    scenario: str
    seed: int
    opponent: str = OPPONENT

    def directory(self, out: Path) -> Path:
        """``OUT/ALGORITHM/SCENARIO/seed-S`` (``OUT/ALGORITHM/full-match-v-chaser/seed-S``)."""
        return out / self.algorithm / scenario_label(self.scenario, self.opponent) / f"seed-{self.seed}"

    @property
    def name(self) -> str:
        """The run's team name in evaluation tables."""
        return f"{self.algorithm}-{scenario_label(self.scenario, self.opponent)}-s{self.seed}"


def plan(scenarios: Sequence[str] = PLANNED, seeds: Sequence[int] = SEEDS,
         algorithms: Sequence[str] = ALGORITHMS) -> list[RunSpec]:
    """The runs in the order they are trained: the academy scenarios first, every run of an
    algorithm before the next algorithm's, every seed of a scenario before the next scenario;
    then the full match's runs in the same order."""
    stages = ([scenario for scenario in scenarios if scenario != FULL_MATCH],
              [scenario for scenario in scenarios if scenario == FULL_MATCH])
    return [RunSpec(algorithm, scenario, seed, training_opponent(scenario)) for stage in stages
            for algorithm in algorithms for scenario in stage for seed in seeds]


def checkpoint_targets(budget: int, every: int) -> list[int]:
    """The environment steps each checkpoint is due at: every ``every`` steps, then ``budget``."""
    if budget < 1 or every < 1:
        raise BenchmarkError(f"the budget and the checkpoint interval must be positive, got {budget} and {every}")
    return [*range(every, budget, every), budget]


def chunk_seed(run_seed: int, chunk: int) -> int:
    """The reset seed of chunk ``chunk`` of a run (see :data:`CHUNK_SEED_STRIDE`)."""
    return run_seed * CHUNK_SEED_STRIDE[0] + chunk * CHUNK_SEED_STRIDE[1]


# ----------------------------------------------------------------------------- a run's folder
CHECKPOINTS = "checkpoints"
CHECKPOINT_PREFIX = "steps-"


def checkpoint_path(run_dir: Path, env_steps: int, algorithm: str = PPO) -> Path:
    return run_dir / CHECKPOINTS / f"{CHECKPOINT_PREFIX}{env_steps:09d}{CHECKPOINT_SUFFIX[algorithm]}"


def checkpoints(run_dir: Path, algorithm: str = PPO) -> list[tuple[int, Path]]:
    """The run's saved checkpoints, (environment steps, file), fewest steps first."""
    found = []
    for path in (run_dir / CHECKPOINTS).glob(f"{CHECKPOINT_PREFIX}*{CHECKPOINT_SUFFIX[algorithm]}"):
        digits = path.stem[len(CHECKPOINT_PREFIX):]
        if digits.isdigit():
            found.append((int(digits), path))
    return sorted(found)


def evaluation_dir(run_dir: Path, env_steps: int | None = None, rung: str | None = None) -> Path:
    """Where the evaluation of the checkpoint at ``env_steps`` goes (None: the random baseline's),
    against the ladder's ``rung`` (``evaluation-N-v-RUNG``) or the academy's :data:`OPPONENT`
    (None: ``evaluation-N``)."""
    name = "evaluation" if env_steps is None else f"evaluation-{env_steps:09d}"
    return run_dir / (name if rung is None else f"{name}-v-{rung}")


def evaluations(scenario: str, run_dir: Path, env_steps: int | None = None) -> list[tuple[str, Path]]:
    """The evaluations a policy on ``scenario`` gets, (opponent, folder): one against
    :data:`OPPONENT` on an academy scenario, one against every rung of :data:`LADDER` on the full
    match. ``run_dir`` is a run's folder, or random actions' ``OUT/random-actions/SCENARIO``
    with ``env_steps`` None."""
    if scenario == FULL_MATCH:
        return [(rung, evaluation_dir(run_dir, env_steps, rung)) for rung in LADDER]
    return [(OPPONENT, evaluation_dir(run_dir, env_steps))]


def random_dir(out: Path, scenario: str) -> Path:
    """Random actions' folder on ``scenario`` (they do not train: their evaluations alone)."""
    return out / RANDOM / scenario


def evaluated(directory: Path) -> bool:
    """Whether ``soccer-sim evaluate`` finished there (it writes evaluation.csv once all episodes are in)."""
    return (directory / "evaluation.csv").is_file()


@dataclass(frozen=True)
class RunStatus:
    """Where a run stands: ``state`` one of pending, training, trained, finished."""

    spec: RunSpec
    state: str
    env_steps: int
    """Environment steps of the last checkpoint (0 without one)."""
    checkpoint: Path | None
    wall_s: float
    """Training wall time up to that checkpoint."""
    evaluations_done: int = 0
    """Evaluations of that checkpoint finished, of :func:`evaluations`' (at the budget only)."""


def run_status(spec: RunSpec, out: Path, budget: int) -> RunStatus:
    """The status of ``spec``'s run in ``out`` for ``budget``: pending (no checkpoint), training
    (its last checkpoint below the budget), trained (at the budget, not yet evaluated against
    every opponent of :func:`evaluations`) or finished (that checkpoint evaluated against all)."""
    run_dir = spec.directory(out)
    saved = checkpoints(run_dir, spec.algorithm)
    if not saved:
        return RunStatus(spec, "pending", 0, None, 0.0)
    steps, path = saved[-1]
    wall = read_curve(run_dir / "curve.csv", steps)
    wall_s = float(wall[-1]["wall_s"]) if wall else 0.0
    if steps < budget:
        return RunStatus(spec, "training", steps, path, wall_s)
    planned = evaluations(spec.scenario, run_dir, steps)
    done = sum(evaluated(directory) for _, directory in planned)
    return RunStatus(spec, "finished" if done == len(planned) else "trained", steps, path, wall_s, done)


def read_curve(path: Path, up_to: int | None = None) -> list[dict]:
    """The rows of a ``curve.csv`` (numbers parsed), those past ``up_to`` environment steps left
    out (a chunk whose checkpoint was never saved); [] when there is no file."""
    if not path.is_file():
        return []
    with open(path, newline="") as handle:
        rows = [{key: float(value) if key in ("mean_return", "goal_rate", "wall_s") else int(value)
                 for key, value in row.items()} for row in csv.DictReader(handle)]
    return [row for row in rows if up_to is None or row["env_steps"] <= up_to]


def write_curve(path: Path, rows: Sequence[dict]) -> None:
    """``curve.csv``, written whole or not at all."""
    from experiments.results.files import text_output

    with text_output(path, newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=CURVE_FIELDS)
        writer.writeheader()
        writer.writerows(rows)


def check_settings(run_dir: Path, settings: Settings) -> None:
    """Write ``run.json`` for a new run; for an existing one, refuse settings that differ from it."""
    from experiments.results.files import text_output

    path = run_dir / "run.json"
    wanted = asdict(settings)
    if path.is_file():
        stored = json.loads(path.read_text())
        changed = sorted(key for key in set(stored) | set(wanted) if stored.get(key) != wanted.get(key))
        if changed:
            raise BenchmarkError(f"{run_dir} was trained with other settings ({', '.join(changed)} differ): "
                                 "continue it with the same ones, or use another --out")
        return
    run_dir.mkdir(parents=True, exist_ok=True)
    with text_output(path) as handle:
        handle.write(json.dumps(wanted, indent=2) + "\n")


# ----------------------------------------------------------------------------- evaluation
def policy_file(spec: RunSpec, run_dir: Path, env_steps: int) -> Path:
    """The file of the run's policy at ``env_steps`` that the evaluation loads: the PPO checkpoint
    itself; MAPPO's actor saved whole beside its training state."""
    if spec.algorithm == MAPPO:
        return run_dir / "policies" / f"{CHECKPOINT_PREFIX}{env_steps:09d}.pt"
    return checkpoint_path(run_dir, env_steps, spec.algorithm)


def checkpoint_team(spec: RunSpec, policy: Path) -> str:
    """The checkpoint team name ``soccer-sim evaluate`` loads the run's policy by (docs/env.md):
    ``sb3`` for PPO, ``torchrl`` for MAPPO's actor."""
    kind = "torchrl" if spec.algorithm == MAPPO else "sb3"
    return f"checkpoint:{kind}:{policy.resolve()}?scenario={spec.scenario}&name={spec.name}"


def evaluation_command(team: str, scenario: str, directory: Path, episodes: int,
                       opponent: str = OPPONENT) -> list[str]:
    """``soccer-sim evaluate`` of ``team`` on ``scenario`` against ``opponent``, results and
    tables in ``directory`` (one worker: the benchmark runs one job at a time)."""
    return [sys.executable, "-m", "experiments.cli", "evaluate", team, "--scenario", scenario,
            "--episodes", str(episodes), "--opponent", opponent, "--workers", "1", "--no-progress",
            "--out", str(directory / "evaluation.sqlite"), "--tables", str(directory)]


def evaluate(team: str, scenario: str, directory: Path, episodes: int, opponent: str = OPPONENT) -> None:
    """Run the evaluation command (from the checkout, so that ``examples.*`` resolves); a
    :class:`BenchmarkError` when it fails."""
    directory.mkdir(parents=True, exist_ok=True)
    environment = {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, [str(CHECKOUT),
                                                                              os.environ.get("PYTHONPATH")]))}
    print(f"evaluate {team} on {scenario} against {opponent} ({episodes} episodes) -> {directory}", flush=True)
    finished = subprocess.run(evaluation_command(team, scenario, directory, episodes, opponent), cwd=CHECKOUT,
                              env=environment, check=False)
    if finished.returncode != 0 or not evaluated(directory):
        raise BenchmarkError(f"soccer-sim evaluate of {team} on {scenario} against {opponent} failed (exit status "
                             f"{finished.returncode}); its output is above")


def evaluate_missing(team: str, scenario: str, run_dir: Path, env_steps: int | None, episodes: int,
                     label: str) -> list[str]:
    """Every evaluation of :func:`evaluations` not finished yet, in turn; returns the failed ones
    (``label``, or ``label vs RUNG`` on the ladder), each reported on its line while the others
    still run."""
    failed = []
    planned = evaluations(scenario, run_dir, env_steps)
    for opponent, directory in planned:
        if evaluated(directory):
            continue
        try:
            evaluate(team, scenario, directory, episodes, opponent)
        except BenchmarkError as exc:
            print(f"error: {exc}", flush=True)
            failed.append(label if len(planned) == 1 else f"{label} vs {opponent}")
    return failed


def episodes_for(scenario: str, args: argparse.Namespace) -> int:
    """Evaluation episodes on ``scenario``: ``--full-match-episodes`` on the full match, else ``--episodes``."""
    return args.full_match_episodes if scenario == FULL_MATCH else args.episodes


# ----------------------------------------------------------------------------- driving
@contextlib.contextmanager
def exclusive(out: Path) -> Iterator[None]:
    """Hold ``out/driver.lock`` while a ``run`` works on ``out``: a second one is refused."""
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "driver.lock", "a") as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise BenchmarkError(f"another benchmark run is working on {out} (it holds {out / 'driver.lock'}); "
                                 "wait for it or stop it first") from None
        handle.seek(0)
        handle.truncate()
        handle.write(f"{os.getpid()}\n")
        handle.flush()
        yield


def settings_for(spec: RunSpec, args: argparse.Namespace) -> Settings:
    return Settings(scenario=spec.scenario, seed=spec.seed, matches=args.matches,
                    checkpoint_every=args.checkpoint_every, opponent=spec.opponent)


def trainer(algorithm: str):
    """The ``train(settings, run_dir, budget)`` of ``algorithm``, imported only when a run trains
    (torch, and TorchRL for MAPPO)."""
    if algorithm == MAPPO:
        from examples.benchmark_mappo import train
    else:
        from examples.benchmark_training import train
    return train


def run(args: argparse.Namespace) -> int:
    """Random baselines, then every planned run to the budget and its evaluation (module docstring)."""
    failed = []
    with exclusive(args.out):
        for scenario in args.scenarios:
            failed += evaluate_missing(RANDOM_TEAM, scenario, random_dir(args.out, scenario), None,
                                       episodes_for(scenario, args), f"{RANDOM} on {scenario}")
        for spec in plan(args.scenarios, args.seeds, args.algorithms):
            status = run_status(spec, args.out, args.budget)
            if status.state == "finished":
                print(f"{spec.name}: finished at {status.env_steps} steps", flush=True)
                continue
            run_dir = spec.directory(args.out)
            try:
                if status.state in ("pending", "training"):
                    trainer(spec.algorithm)(settings_for(spec, args), run_dir, args.budget)
                    status = run_status(spec, args.out, args.budget)
            except BenchmarkError as exc:
                print(f"error: {exc}", flush=True)
                failed.append(spec.name)
                continue
            failed += evaluate_missing(checkpoint_team(spec, policy_file(spec, run_dir, status.env_steps)),
                                       spec.scenario, run_dir, status.env_steps, episodes_for(spec.scenario, args),
                                       spec.name)
    if failed:
        print(f"not done: {', '.join(failed)}", flush=True)
        return 1
    print("every planned run is trained and evaluated", flush=True)
    return 0


def rates(statuses: Sequence[RunStatus]) -> dict[str, float]:
    """Environment steps per second of training measured so far, per algorithm and scenario
    (over their runs' checkpoints)."""
    steps: dict[tuple[str, str], float] = {}
    seconds: dict[tuple[str, str], float] = {}
    for status in statuses:
        if status.env_steps and status.wall_s > 0:
            key = (status.spec.algorithm, status.spec.scenario)
            steps[key] = steps.get(key, 0) + status.env_steps
            seconds[key] = seconds.get(key, 0.0) + status.wall_s
    return {key: steps[key] / seconds[key] for key in steps}


def status(args: argparse.Namespace) -> int:
    """One line per planned run, and the training wall time left at the speeds measured so far."""
    statuses = [run_status(spec, args.out, args.budget) for spec in plan(args.scenarios, args.seeds, args.algorithms)]
    measured = rates(statuses)
    left, unknown = 0.0, []
    print(f"{'run':<40} {'state':<9} {'env steps':>10} {'wall':>8}  {'steps/s':>7}  evaluated")
    for item in statuses:
        rate = measured.get((item.spec.algorithm, item.spec.scenario))
        planned = len(evaluations(item.spec.scenario, item.spec.directory(args.out)))
        print(f"{item.spec.name:<40} {item.state:<9} {item.env_steps:>10} {item.wall_s / 60:>6.1f} m  "
              f"{'-' if rate is None else f'{rate:.0f}':>7}  {item.evaluations_done}/{planned}")
        remaining = max(0, args.budget - item.env_steps)
        if remaining and rate:
            left += remaining / rate
        elif remaining:
            unknown.append(item.spec.name)
    print(f"training left: {left / 3600:.1f} h at the measured speeds"
          + (f", plus {len(unknown)} runs of scenarios not measured yet" if unknown else ""))
    return 0


def report(args: argparse.Namespace) -> int:
    from examples.benchmark_report import write_report

    for path in write_report(args.out, args.docs, args.scenarios, args.seeds, args.budget, args.algorithms):
        print(f"wrote {path}")
    return 0


def parse_args(argv: Sequence[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=("run", "status", "report"), help="train and evaluate; show; tabulate")
    parser.add_argument("--out", type=Path, required=True, help="the runs' folder (keep it outside the checkout)")
    parser.add_argument("--scenarios", nargs="+", default=list(PLANNED), choices=PLANNED, metavar="NAME",
                        help=f"scenarios (default: {' '.join(PLANNED)}; {FULL_MATCH} is trained against "
                             f"{LADDER_TRAINING_OPPONENT} and evaluated against {', '.join(LADDER)})")
    parser.add_argument("--algorithms", nargs="+", default=list(ALGORITHMS), choices=ALGORITHMS, metavar="NAME",
                        help=f"trained baselines (default: {' '.join(ALGORITHMS)})")
    parser.add_argument("--seeds", nargs="+", type=int, default=list(SEEDS), help="run seeds (default: 0 1 2)")
    parser.add_argument("--budget", type=int, default=BUDGET, help="environment steps per run (default: %(default)s)")
    parser.add_argument("--checkpoint-every", type=int, default=CHECKPOINT_EVERY,
                        help="environment steps between checkpoints (default: %(default)s)")
    parser.add_argument("--matches", type=int, default=8, help="matches played at once in training (default: 8)")
    parser.add_argument("--episodes", type=int, default=EVALUATION_EPISODES,
                        help="evaluation episodes on an academy scenario (default: %(default)s)")
    parser.add_argument("--full-match-episodes", type=int, default=FULL_MATCH_EPISODES,
                        help="evaluation episodes (full matches) against each rung of the ladder (default: %(default)s)")
    parser.add_argument("--docs", type=Path, default=CHECKOUT / "docs",
                        help="report: the docs folder holding benchmark.md and figures/ (default: the checkout's)")
    args = parser.parse_args(argv)
    for option in ("budget", "checkpoint_every", "matches", "episodes", "full_match_episodes"):
        if getattr(args, option) < 1:
            parser.error(f"--{option.replace('_', '-')} must be positive, got {getattr(args, option)}")
    if any(seed < 0 or seed >= 4_000 for seed in args.seeds):
        parser.error("--seeds must lie in 0..3999 (their training seeds stay below 2**32)")
    return args


def main(argv: Sequence[str] | None = None) -> int:
    args = parse_args(argv)
    command = {"run": run, "status": status, "report": report}[args.command]
    try:
        return command(args)
    except BenchmarkError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    if str(CHECKOUT) not in sys.path:  # ``python examples/benchmark_baselines.py`` from anywhere
        sys.path.insert(0, str(CHECKOUT))
    sys.exit(main())
