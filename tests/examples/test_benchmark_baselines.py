"""The benchmark driver (examples/benchmark_baselines.py): its plan, where a run stands from its
files, what a re-run does with each state, and the table and curves of the report, on small
stand-in folders (no torch); one slow test trains for real where torch is installed."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from examples import benchmark_baselines as bb
from examples import benchmark_report as br
from experiments.stats import estimate

BUDGET = 500_000


def write_evaluation(directory: Path, goal_rate: float, low: float, high: float, diff: float,
                     episodes: int = 100) -> None:
    """An evaluation.csv as ``soccer-sim evaluate --tables`` writes it."""
    directory.mkdir(parents=True, exist_ok=True)
    header = ["policy_name", "policy", "opponent", "scenario", "episodes", "first_seed", "goal_rate", "goal_rate_low",
              "goal_rate_high", "mean_score_diff", "score_diff_se", "score_diff_low", "score_diff_high", "goals_for",
              "goals_against", "forfeits"]
    row = ["p", "p", "static", "s", episodes, 2 ** 32, goal_rate, low, high, diff, 0.01, diff - 0.02, diff + 0.02,
           round(goal_rate * episodes), 0, 0]
    with open(directory / "evaluation.csv", "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerow(row)


def write_run(out: Path, scenario: str, seed: int, steps: list[int], wall_per_step: float = 0.01,
              algorithm: str = bb.PPO) -> Path:
    """A run folder with checkpoints at ``steps`` and a curve with one row per checkpoint."""
    run_dir = bb.RunSpec(algorithm, scenario, seed, bb.training_opponent(scenario)).directory(out)
    (run_dir / bb.CHECKPOINTS).mkdir(parents=True, exist_ok=True)
    for step in steps:
        bb.checkpoint_path(run_dir, step, algorithm).write_bytes(b"stand-in")
    bb.write_curve(run_dir / "curve.csv", [
        {"env_steps": step, "agent_steps": step * bb.PLAYERS[scenario], "episodes": 10, "mean_return": 0.1 * k,
         "goal_rate": min(1.0, 0.2 * k), "wall_s": round(step * wall_per_step, 1)} for k, step in enumerate(steps)])
    return run_dir


# ----------------------------------------------------------------------------- plan and states
def test_the_plan_trains_every_seed_of_a_scenario_before_the_next_and_ppo_first() -> None:
    runs = bb.plan()
    assert [(r.scenario, r.seed) for r in runs[:4]] == [("empty-goal", 0), ("empty-goal", 1), ("empty-goal", 2),
                                                         ("run-to-score-with-keeper", 0)]
    per_algorithm = len(bb.SCENARIOS) * len(bb.SEEDS)
    seeds = len(bb.SEEDS)
    assert [r.algorithm for r in runs] == ([bb.PPO] * per_algorithm + [bb.MAPPO] * per_algorithm
                                           + [bb.PPO] * seeds + [bb.MAPPO] * seeds)  # the full match last
    assert runs[0].directory(Path("o")) == Path("o/ppo-shared/empty-goal/seed-0")
    assert runs[per_algorithm].directory(Path("o")) == Path("o/mappo/empty-goal/seed-0")
    assert all(r.opponent == bb.OPPONENT for r in runs[:2 * per_algorithm])  # the academy's folders and names as ever


def test_checkpoints_fall_every_interval_and_on_the_budget() -> None:
    assert bb.checkpoint_targets(500_000, 50_000) == [50_000 * k for k in range(1, 11)]
    assert bb.checkpoint_targets(120_000, 50_000) == [50_000, 100_000, 120_000]
    with pytest.raises(bb.BenchmarkError, match="must be positive"):
        bb.checkpoint_targets(0, 50_000)


def test_no_two_chunks_share_a_match_seed_and_all_lie_below_the_evaluation_seeds() -> None:
    matches = 8
    seeds = [bb.chunk_seed(s, c) + i for s in (0, 1, 2, 3_999) for c in range(11) for i in range(matches)]
    assert len(set(seeds)) == len(seeds) and max(seeds) < 2 ** 32


def test_a_runs_state_follows_its_files(tmp_path) -> None:
    spec = bb.RunSpec(bb.PPO, "empty-goal", 1)
    assert bb.run_status(spec, tmp_path, BUDGET).state == "pending"
    run_dir = write_run(tmp_path, "empty-goal", 1, [51_200, 102_400])
    status = bb.run_status(spec, tmp_path, BUDGET)
    assert (status.state, status.env_steps, status.wall_s) == ("training", 102_400, 1024.0)
    assert status.checkpoint == bb.checkpoint_path(run_dir, 102_400)
    write_run(tmp_path, "empty-goal", 1, [51_200, 102_400, 501_760])
    assert bb.run_status(spec, tmp_path, BUDGET).state == "trained"
    write_evaluation(bb.evaluation_dir(run_dir, 501_760), 0.9, 0.8, 0.95, 0.9)
    assert bb.run_status(spec, tmp_path, BUDGET).state == "finished"
    assert bb.run_status(spec, tmp_path, 1_000_000).state == "training"  # a larger budget continues it


def test_a_mappo_run_is_found_by_its_own_checkpoints_and_evaluated_through_torchrl(tmp_path) -> None:
    spec = bb.RunSpec(bb.MAPPO, "3-vs-1-with-keeper", 0)
    run_dir = spec.directory(tmp_path)
    write_run(tmp_path, "empty-goal", 0, [51_200])  # a PPO run's .zip beside it changes nothing
    (run_dir / bb.CHECKPOINTS).mkdir(parents=True)
    bb.checkpoint_path(run_dir, 501_760).with_suffix(".zip").write_bytes(b"not mappo's")
    assert bb.run_status(spec, tmp_path, BUDGET).state == "pending"
    bb.checkpoint_path(run_dir, 501_760, bb.MAPPO).write_bytes(b"stand-in")
    status = bb.run_status(spec, tmp_path, BUDGET)
    assert (status.state, status.checkpoint.name) == ("trained", "steps-000501760.pt")
    policy = bb.policy_file(spec, run_dir, 501_760)
    assert policy == run_dir / "policies" / "steps-000501760.pt"
    assert bb.checkpoint_team(spec, policy).startswith(f"checkpoint:torchrl:{policy}?scenario=3-vs-1-with-keeper&")


def test_the_curve_ends_at_the_last_checkpoint(tmp_path) -> None:
    run_dir = write_run(tmp_path, "empty-goal", 0, [2_048, 4_096, 6_144])
    assert [row["env_steps"] for row in bb.read_curve(run_dir / "curve.csv", 4_096)] == [2_048, 4_096]
    assert bb.read_curve(tmp_path / "none.csv") == []


def test_a_run_continues_only_with_the_settings_it_was_started_with(tmp_path) -> None:
    settings = bb.Settings("3-vs-1-with-keeper", seed=2)
    bb.check_settings(tmp_path / "run", settings)
    bb.check_settings(tmp_path / "run", settings)  # the same again: fine
    assert settings.players == 3 and settings.rollout_env_steps == 2_048
    with pytest.raises(bb.BenchmarkError, match="learning_rate, matches differ"):
        bb.check_settings(tmp_path / "run", bb.Settings("3-vs-1-with-keeper", seed=2, matches=4, learning_rate=1e-3))


def test_the_evaluation_is_soccer_sim_evaluate_of_the_checkpoint(tmp_path) -> None:
    spec = bb.RunSpec(bb.PPO, "counter-attack", 2)
    team = bb.checkpoint_team(spec, tmp_path / "steps-000501760.zip")
    assert team == f"checkpoint:sb3:{tmp_path}/steps-000501760.zip?scenario=counter-attack&name={spec.name}"
    command = bb.evaluation_command(team, "counter-attack", tmp_path / "e", 100)
    assert command[1:5] == ["-m", "experiments.cli", "evaluate", team]
    from experiments.cli import build_parser

    parsed = build_parser().parse_args(command[3:])
    assert (parsed.scenario, parsed.episodes, parsed.opponent, parsed.seed, parsed.workers) == \
        ("counter-attack", 100, "static", 0, 1)
    assert parsed.out == str(tmp_path / "e" / "evaluation.sqlite")


def test_a_second_driver_on_the_same_folder_is_refused(tmp_path) -> None:
    with bb.exclusive(tmp_path):
        with pytest.raises(bb.BenchmarkError, match="another benchmark run is working on"):
            with bb.exclusive(tmp_path):
                pass
    with bb.exclusive(tmp_path):  # released
        pass


def test_a_rerun_skips_finished_runs_evaluates_trained_ones_and_continues_the_rest(tmp_path, monkeypatch,
                                                                                     capsys) -> None:
    scenario = "run-to-score-with-keeper"
    out = tmp_path / "runs"
    write_evaluation(bb.evaluation_dir(out / bb.RANDOM / scenario), 0.05, 0.02, 0.11, 0.05)
    finished = write_run(out, scenario, 0, [51_200, 501_760])
    write_evaluation(bb.evaluation_dir(finished, 501_760), 0.7, 0.6, 0.8, 0.7)
    write_run(out, scenario, 1, [51_200, 501_760])    # trained, not evaluated
    write_run(out, scenario, 2, [51_200])             # interrupted
    evaluated, trained = [], []

    def stand_in_evaluate(team, scenario_name, directory, episodes, opponent):
        assert opponent == bb.OPPONENT
        evaluated.append((team, directory.name))
        write_evaluation(directory, 0.5, 0.4, 0.6, 0.5, episodes)

    def stand_in_train(settings, run_dir, budget):
        trained.append((settings.seed, budget, bb.checkpoints(run_dir)[-1][0]))
        bb.checkpoint_path(run_dir, 501_760).write_bytes(b"stand-in")

    monkeypatch.setattr(bb, "evaluate", stand_in_evaluate)
    monkeypatch.setattr(bb, "trainer", lambda algorithm: stand_in_train)
    args = bb.parse_args(["run", "--out", str(out), "--scenarios", scenario, "--algorithms", bb.PPO])
    assert bb.run(args) == 0
    assert trained == [(2, BUDGET, 51_200)]                 # only the interrupted run trains, from its checkpoint
    assert [name for _, name in evaluated] == ["evaluation-000501760"] * 2   # seeds 1 and 2, not the random one
    assert "ppo-shared-run-to-score-with-keeper-s1" in evaluated[0][0]
    assert "finished at 501760 steps" in capsys.readouterr().out
    evaluated.clear()
    assert bb.run(args) == 0 and evaluated == []            # everything done: nothing again


def test_a_failed_evaluation_is_reported_and_the_others_still_run(tmp_path, monkeypatch, capsys) -> None:
    out = tmp_path / "runs"
    calls = []

    def failing(team, scenario, directory, episodes, opponent):
        calls.append(scenario)
        raise bb.BenchmarkError(f"soccer-sim evaluate of {team} on {scenario} failed (exit status 2)")

    monkeypatch.setattr(bb, "evaluate", failing)
    monkeypatch.setattr(bb, "trainer", lambda algorithm: pytest.fail("no run is planned"))
    args = bb.parse_args(["run", "--out", str(out), "--scenarios", "empty-goal", "counter-attack"])
    args.seeds = []  # the random baselines alone
    assert bb.run(args) == 1
    assert calls == ["empty-goal", "counter-attack"]
    assert "not done: random-actions on empty-goal, random-actions on counter-attack" in capsys.readouterr().out


def test_status_shows_each_run_and_the_time_left_at_the_measured_speed(tmp_path, capsys) -> None:
    write_run(tmp_path, "empty-goal", 0, [250_000], wall_per_step=0.001)  # 250 s for 250,000 steps
    assert bb.main(["status", "--out", str(tmp_path), "--scenarios", "empty-goal", "counter-attack",
                    "--algorithms", bb.PPO]) == 0
    printed = capsys.readouterr().out
    assert "ppo-shared-empty-goal-s0" in printed and "training" in printed and "1000" in printed
    # 250,000 + 2 x 500,000 steps left at 1,000 steps/s; counter-attack not measured yet
    assert "training left: 0.3 h at the measured speeds, plus 3 runs of scenarios not measured yet" in printed


@pytest.mark.parametrize("argv, message", [
    (["run", "--out", "x", "--budget", "0"], "--budget must be positive"),
    (["run", "--out", "x", "--seeds", "5000"], "--seeds must lie in 0..3999"),
    (["run", "--out", "x", "--scenarios", "corner"], "invalid choice"),
])
def test_bad_options_are_refused_on_one_line(argv, message, capsys) -> None:
    with pytest.raises(SystemExit) as refused:
        bb.parse_args(argv)
    assert refused.value.code == 2 and message in capsys.readouterr().err


# ----------------------------------------------------------------------------- the full match's ladder
def test_the_full_match_is_planned_last_trained_against_one_rung_in_folders_of_its_own() -> None:
    ladder = [spec for spec in bb.plan() if spec.scenario == bb.FULL_MATCH]
    assert [(spec.algorithm, spec.seed) for spec in ladder] == [(bb.PPO, 0), (bb.PPO, 1), (bb.PPO, 2),
                                                                 (bb.MAPPO, 0), (bb.MAPPO, 1), (bb.MAPPO, 2)]
    assert bb.plan()[-6:] == ladder
    assert {spec.opponent for spec in ladder} == {bb.LADDER_TRAINING_OPPONENT} == {"chaser"}
    assert ladder[1].directory(Path("o")) == Path("o/ppo-shared/full-match-v-chaser/seed-1")
    assert ladder[3].name == "mappo-full-match-v-chaser-s0"
    assert bb.PLAYERS[bb.FULL_MATCH] == 11
    args = bb.parse_args(["run", "--out", "o"])
    assert bb.settings_for(ladder[0], args).opponent == "chaser"
    academy = bb.settings_for(bb.plan()[0], args)  # the academy's run.json stays what it was
    assert academy == bb.Settings("empty-goal", seed=0) and academy.opponent == "static"


def test_the_ladder_runs_from_idle_and_chaser_to_the_best_built_in_team() -> None:
    from soccer_sim.registry import available_teams

    assert bb.LADDER[:2] == ("idle", "chaser") and len(set(bb.LADDER)) == len(bb.LADDER)
    assert {"counter-442", "press-433", "possession", "static", "mmd+msd2"} == set(bb.LADDER[2:])
    assert set(bb.LADDER) <= set(available_teams())
    assert bb.LADDER_TRAINING_OPPONENT in bb.LADDER


def test_the_documented_ladder_is_the_one_the_driver_evaluates_against() -> None:
    import re

    text = (Path(__file__).resolve().parents[2] / "docs" / "benchmark.md").read_text()
    rows = re.findall(r"^\| (\d+) \| `([^`]+)` \|", text, flags=re.MULTILINE)
    assert rows == [(str(k), rung) for k, rung in enumerate(bb.LADDER, start=1)]
    assert f"trained against `{bb.LADDER_TRAINING_OPPONENT}`" in text


def test_a_full_match_policy_is_evaluated_against_every_rung_in_its_own_folder(tmp_path) -> None:
    run_dir = tmp_path / "run"
    planned = bb.evaluations(bb.FULL_MATCH, run_dir, 501_760)
    assert [opponent for opponent, _ in planned] == list(bb.LADDER)
    assert planned[0][1] == run_dir / "evaluation-000501760-v-idle"
    assert bb.evaluations("empty-goal", run_dir, 501_760) == [("static", run_dir / "evaluation-000501760")]
    assert bb.evaluations(bb.FULL_MATCH, run_dir)[-1][1] == run_dir / f"evaluation-v-{bb.LADDER[-1]}"
    from experiments.cli import build_parser

    for opponent, directory in planned:
        command = bb.evaluation_command("some-team", bb.FULL_MATCH, directory, bb.FULL_MATCH_EPISODES, opponent)
        parsed = build_parser().parse_args(command[3:])
        assert (parsed.scenario, parsed.opponent, parsed.episodes, parsed.workers) == \
            ("full-match", opponent, bb.FULL_MATCH_EPISODES, 1)
        assert parsed.out == str(directory / "evaluation.sqlite") and parsed.tables == str(directory)


def test_a_full_match_run_is_finished_only_once_evaluated_against_every_rung(tmp_path) -> None:
    spec = next(spec for spec in bb.plan() if spec.scenario == bb.FULL_MATCH)
    run_dir = write_run(tmp_path, bb.FULL_MATCH, 0, [51_200, 501_760])
    assert run_dir == spec.directory(tmp_path)
    for opponent, directory in bb.evaluations(bb.FULL_MATCH, run_dir, 501_760)[:-1]:
        write_evaluation(directory, 0.5, 0.2, 0.8, 1.0, episodes=10)
    status = bb.run_status(spec, tmp_path, BUDGET)
    assert (status.state, status.evaluations_done) == ("trained", len(bb.LADDER) - 1)
    write_evaluation(bb.evaluation_dir(run_dir, 501_760), 0.5, 0.2, 0.8, 1.0)  # the academy's name counts not
    assert bb.run_status(spec, tmp_path, BUDGET).state == "trained"
    write_evaluation(bb.evaluation_dir(run_dir, 501_760, bb.LADDER[-1]), 0.5, 0.2, 0.8, 1.0, episodes=10)
    assert bb.run_status(spec, tmp_path, BUDGET).state == "finished"


def test_run_trains_the_full_match_against_its_rung_and_evaluates_the_missing_rungs(tmp_path, monkeypatch,
                                                                                     capsys) -> None:
    out = tmp_path / "runs"
    random_done = bb.evaluations(bb.FULL_MATCH, bb.random_dir(out, bb.FULL_MATCH))[0][1]
    write_evaluation(random_done, 0.0, 0.0, 0.3, -20.0, episodes=4)          # random v idle already evaluated
    trained_dir = write_run(out, bb.FULL_MATCH, 0, [51_200, 501_760])         # seed 0: trained,
    write_evaluation(bb.evaluation_dir(trained_dir, 501_760, "idle"), 0.9, 0.6, 1.0, 3.0, episodes=4)  # 1 rung done
    evaluated, trained = [], []

    def stand_in_evaluate(team, scenario, directory, episodes, opponent):
        evaluated.append((team.split("?")[-1] if team.startswith("checkpoint:") else team, opponent, episodes,
                          directory.relative_to(out).as_posix()))
        if opponent == "press-433" and "s1" in team:
            raise bb.BenchmarkError("soccer-sim evaluate of it failed (exit status 1)")
        write_evaluation(directory, 0.1, 0.0, 0.4, -1.0, episodes)

    def stand_in_train(settings, run_dir, budget):
        trained.append((settings.scenario, settings.seed, settings.opponent, run_dir.relative_to(out).as_posix()))
        (run_dir / bb.CHECKPOINTS).mkdir(parents=True, exist_ok=True)
        bb.checkpoint_path(run_dir, 501_760).write_bytes(b"stand-in")

    monkeypatch.setattr(bb, "evaluate", stand_in_evaluate)
    monkeypatch.setattr(bb, "trainer", lambda algorithm: stand_in_train)
    args = bb.parse_args(["run", "--out", str(out), "--scenarios", bb.FULL_MATCH, "--algorithms", bb.PPO,
                          "--seeds", "0", "1", "--full-match-episodes", "4"])
    assert bb.run(args) == 1
    assert trained == [("full-match", 1, "chaser", "ppo-shared/full-match-v-chaser/seed-1")]
    rungs = list(bb.LADDER)
    assert [(team, opponent) for team, opponent, _, _ in evaluated] == \
        [(bb.RANDOM_TEAM, rung) for rung in rungs[1:]] + \
        [("scenario=full-match&name=ppo-shared-full-match-v-chaser-s0", rung) for rung in rungs[1:]] + \
        [("scenario=full-match&name=ppo-shared-full-match-v-chaser-s1", rung) for rung in rungs]
    assert {episodes for _, _, episodes, _ in evaluated} == {4}
    assert evaluated[0][3] == "random-actions/full-match/evaluation-v-chaser"
    assert evaluated[-1][3] == f"ppo-shared/full-match-v-chaser/seed-1/evaluation-000501760-v-{rungs[-1]}"
    assert "not done: ppo-shared-full-match-v-chaser-s1 vs press-433" in capsys.readouterr().out
    evaluated.clear()
    assert bb.run(args) == 1 and [(team, opponent) for team, opponent, _, _ in evaluated] == \
        [("scenario=full-match&name=ppo-shared-full-match-v-chaser-s1", "press-433")]   # only the one that failed, again


def test_status_lists_the_full_match_runs_with_their_evaluations(tmp_path, capsys) -> None:
    run_dir = write_run(tmp_path, bb.FULL_MATCH, 2, [51_200, 501_760], wall_per_step=0.005, algorithm=bb.MAPPO)
    write_evaluation(bb.evaluation_dir(run_dir, 501_760, "idle"), 0.9, 0.6, 1.0, 3.0, episodes=10)
    assert bb.main(["status", "--out", str(tmp_path), "--scenarios", bb.FULL_MATCH]) == 0
    lines = capsys.readouterr().out.splitlines()
    row = next(line for line in lines if line.startswith("mappo-full-match-v-chaser-s2"))
    assert "trained" in row and "501760" in row and row.endswith(f"1/{len(bb.LADDER)}")
    assert sum(line.startswith(("ppo-shared-full-match-v-chaser-s", "mappo-full-match-v-chaser-s"))
               for line in lines) == 6


# ----------------------------------------------------------------------------- report
def finished_folder(out: Path) -> None:
    """empty-goal: random and 3 finished seeds; run-to-score: random, 1 finished seed, 1 training, 1 pending."""
    write_evaluation(bb.evaluation_dir(out / bb.RANDOM / "empty-goal"), 0.03, 0.01, 0.08, 0.03)
    for seed, rate in zip(bb.SEEDS, (0.9, 0.8, 1.0)):
        run_dir = write_run(out, "empty-goal", seed, [51_200, 501_760])
        write_evaluation(bb.evaluation_dir(run_dir, 501_760), rate, rate - 0.1, min(1.0, rate + 0.05), rate)
    write_evaluation(bb.evaluation_dir(out / bb.RANDOM / "run-to-score-with-keeper"), 0.1, 0.05, 0.17, -0.2)
    run_dir = write_run(out, "run-to-score-with-keeper", 0, [51_200, 501_760])
    write_evaluation(bb.evaluation_dir(run_dir, 501_760), 0.12, 0.07, 0.2, -0.1)
    write_run(out, "run-to-score-with-keeper", 1, [51_200, 102_400])


def test_the_table_averages_the_finished_seeds_and_lists_the_others(tmp_path) -> None:
    finished_folder(tmp_path)
    scenarios = ["empty-goal", "run-to-score-with-keeper"]
    baselines = br.aggregate(tmp_path, scenarios, bb.SEEDS, BUDGET, [bb.PPO])
    rows = {(row.scenario, row.policy): row for row in baselines.rows}
    ppo = rows[("empty-goal", bb.PPO)]
    assert ppo.runs == 3 and ppo.per_seed == (0.9, 0.8, 1.0)
    assert math.isclose(ppo.goal_rate.mean - ppo.goal_rate.low, 4.302653 * 0.1 / math.sqrt(3), rel_tol=1e-5)
    assert ppo.goal_rate.high == 1.0  # cut where a share lies; the score difference's is not
    assert ppo.score_difference == estimate([0.9, 0.8, 1.0]) and ppo.score_difference.high > 1.0
    assert rows[("empty-goal", bb.RANDOM)].goal_rate.high == 0.08
    single = rows[("run-to-score-with-keeper", bb.PPO)]
    assert single.runs == 1 and math.isnan(single.goal_rate.low)
    assert [(s.spec.seed, s.state) for s in baselines.unfinished] == [(1, "training"), (2, "pending")]
    table = br.markdown(baselines, BUDGET)
    lines = table.splitlines()
    assert "| empty-goal | ppo-shared | 500,000 | 3 | 0.90 [0.65, 1.00] | +0.90 [+0.65, +1.15] | 0.90, 0.80, 1.00 |" \
           " yes |" in lines  # t with 2 degrees of freedom: wide, yet above random's 0.08
    assert "| run-to-score-with-keeper | ppo-shared | 500,000 | 1 | 0.12 | -0.10 | 0.12 | - |" in lines
    assert "| empty-goal | random-actions | - | 1 (100 episodes) | 0.03 [0.01, 0.08] | +0.03 [+0.01, +0.05] | - | - |" \
           in lines
    assert "- ppo-shared-run-to-score-with-keeper-s1: training, 102,400 of 500,000 environment steps" in lines


def ladder_folder(out: Path) -> None:
    """The full match: random actions against every rung; PPO's 3 seeds finished (goal rates 0.9,
    0.8, 1.0 against idle, falling by 0.1 a rung up the ladder); MAPPO's seed 0 trained and
    evaluated against one rung only."""
    for k, (rung, directory) in enumerate(bb.evaluations(bb.FULL_MATCH, bb.random_dir(out, bb.FULL_MATCH))):
        write_evaluation(directory, 0.0, 0.0, 0.28, float(-2 * k), episodes=10)
    for seed, rate in zip(bb.SEEDS, (0.9, 0.8, 1.0)):
        run_dir = write_run(out, bb.FULL_MATCH, seed, [51_200, 501_760])
        for k, (rung, directory) in enumerate(bb.evaluations(bb.FULL_MATCH, run_dir, 501_760)):
            write_evaluation(directory, round(max(0.0, rate - 0.1 * k), 2), 0.0, 1.0, 3.0 - k, episodes=10)
    run_dir = write_run(out, bb.FULL_MATCH, 0, [51_200, 501_760], algorithm=bb.MAPPO)
    write_evaluation(bb.evaluation_dir(run_dir, 501_760, "idle"), 0.5, 0.2, 0.8, 1.0, episodes=10)


def test_the_table_has_a_row_per_rung_and_policy_on_the_full_match(tmp_path) -> None:
    ladder_folder(tmp_path)
    baselines = br.aggregate(tmp_path, [bb.FULL_MATCH], bb.SEEDS, BUDGET)
    assert [(row.opponent, row.policy) for row in baselines.rows] == \
        [(rung, policy) for rung in bb.LADDER for policy in (bb.RANDOM, bb.PPO)]   # MAPPO: nothing finished
    rows = {(row.opponent, row.policy): row for row in baselines.rows}
    second = rows[(bb.LADDER[1], bb.PPO)]
    assert second.runs == 3 and second.per_seed == (0.8, 0.7, 0.9) and second.situation == "full-match v chaser"
    assert second.score_difference == estimate([2.0, 2.0, 2.0])
    assert math.isclose(second.goal_rate.mean - second.goal_rate.low, 4.302653 * 0.1 / math.sqrt(3), rel_tol=1e-5)
    assert [(s.spec.name, s.state, s.evaluations_done) for s in baselines.unfinished] == \
        [("mappo-full-match-v-chaser-s0", "trained", 1), ("mappo-full-match-v-chaser-s1", "pending", 0),
         ("mappo-full-match-v-chaser-s2", "pending", 0)]                       # a run once, not once a rung
    lines = br.markdown(baselines, BUDGET).splitlines()
    assert "| full-match v idle | random-actions | - | 1 (10 episodes) | 0.00 [0.00, 0.28] | +0.00 [-0.02, +0.02] " \
           "| - | - |" in lines
    assert "| full-match v idle | ppo-shared | 500,000 | 3 | 0.90 [0.65, 1.00] | +3.00 [+3.00, +3.00] | " \
           "0.90, 0.80, 1.00 | yes |" in lines
    assert f"| full-match v {bb.LADDER[-1]} | ppo-shared | 500,000 | 3 | 0.30 [0.05, 0.55] | -3.00 [-3.00, -3.00] | " \
           "0.30, 0.20, 0.40 | no (intervals overlap) |" in lines
    assert f"- mappo-full-match-v-chaser-s0: trained, 501,760 of 500,000 environment steps, evaluated against 1 of " \
           f"{len(bb.LADDER)} opponents" in lines


def test_the_report_writes_the_ladder_rows_and_each_evaluation_with_its_opponent(tmp_path) -> None:
    ladder_folder(tmp_path / "runs")
    finished_folder(tmp_path / "runs")
    docs = tmp_path / "docs"
    (docs / "figures").mkdir(parents=True)
    (docs / "benchmark.md").write_text(f"{br.BEGIN}\n{br.END}\n")
    assert bb.main(["report", "--out", str(tmp_path / "runs"), "--docs", str(docs)]) == 0
    text = (docs / "benchmark.md").read_text()
    assert text.index("| empty-goal | ppo-shared |") < text.index("| full-match v idle | random-actions |") \
        < text.index("| full-match v idle | ppo-shared |") < text.index("| full-match v chaser | random-actions |")
    assert sum(line.startswith("| full-match v ") for line in text.splitlines()) == 2 * len(bb.LADDER)
    with open(docs / "figures" / "benchmark_evaluations.csv") as handle:
        evaluations = [row for row in csv.DictReader(handle) if row["scenario"] == bb.FULL_MATCH]
    assert [(row["policy"], row["seed"], row["opponent"]) for row in evaluations] == \
        [(bb.RANDOM, "", rung) for rung in bb.LADDER] + \
        [(bb.PPO, str(seed), rung) for seed in bb.SEEDS for rung in bb.LADDER]
    with open(docs / "figures" / "benchmark_curves.csv") as handle:
        curves = [row for row in csv.DictReader(handle) if row["scenario"] == bb.FULL_MATCH]
    assert {(row["algorithm"], row["seed"]) for row in curves} == {(bb.PPO, "0"), (bb.PPO, "1"), (bb.PPO, "2"),
                                                                  (bb.MAPPO, "0")}


def test_the_sanity_bar_needs_disjoint_intervals() -> None:
    random = br.TableRow("s", bb.RANDOM, None, 1, br.Estimate(100, 0.03, math.nan, 0.01, 0.08), estimate([0.0]))
    high = br.TableRow("s", bb.PPO, BUDGET, 3, estimate([0.9, 0.92, 0.94]), estimate([0.9]))
    low = br.TableRow("s", bb.PPO, BUDGET, 3, estimate([0.0, 0.0, 0.0]), estimate([0.0]))
    assert br.above_random(high, random) == "yes"
    assert br.above_random(low, random) == "below"
    assert br.above_random(high, None) == "-"


def test_the_report_rewrites_only_the_marked_part_of_benchmark_md(tmp_path) -> None:
    finished_folder(tmp_path / "runs")
    docs = tmp_path / "docs"
    (docs / "figures").mkdir(parents=True)
    (docs / "benchmark.md").write_text(f"# Benchmark\n\nbefore\n\n{br.BEGIN}\nold table\n{br.END}\n\nafter\n")
    assert bb.main(["report", "--out", str(tmp_path / "runs"), "--docs", str(docs)]) == 0
    text = (docs / "benchmark.md").read_text()
    assert text.startswith("# Benchmark\n\nbefore\n\n" + br.BEGIN + "\n| scenario |") and text.endswith(
        br.END + "\n\nafter\n")
    assert "old table" not in text and "- ppo-shared-counter-attack-s2: pending, 0 of 500,000" in text
    assert "- mappo-empty-goal-s0: pending, 0 of 500,000" in text
    with open(docs / "figures" / "benchmark_curves.csv") as handle:
        curves = list(csv.DictReader(handle))
    assert {(row["scenario"], row["seed"]) for row in curves} == {("empty-goal", "0"), ("empty-goal", "1"),
                                                                  ("empty-goal", "2"),
                                                                  ("run-to-score-with-keeper", "0"),
                                                                  ("run-to-score-with-keeper", "1")}
    with open(docs / "figures" / "benchmark_evaluations.csv") as handle:
        evaluations = list(csv.DictReader(handle))
    assert [(row["policy"], row["scenario"], row["seed"]) for row in evaluations] == [
        ("random-actions", "empty-goal", ""), ("ppo-shared", "empty-goal", "0"), ("ppo-shared", "empty-goal", "1"),
        ("ppo-shared", "empty-goal", "2"), ("random-actions", "run-to-score-with-keeper", ""),
        ("ppo-shared", "run-to-score-with-keeper", "0")]
    assert (docs / "figures" / "benchmark_curves.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_report_refuses_a_document_without_markers(tmp_path, capsys) -> None:
    (tmp_path / "benchmark.md").write_text("# Benchmark\n")
    (tmp_path / "runs").mkdir()
    assert bb.main(["report", "--out", str(tmp_path / "runs"), "--docs", str(tmp_path)]) == 1
    assert "has no table markers" in capsys.readouterr().err
    assert (tmp_path / "benchmark.md").read_text() == "# Benchmark\n"


def test_curves_are_averaged_over_rollouts_by_their_episodes() -> None:
    xs, ys = br.smoothed([1, 2, 3, 4], [0.0, 1.0, math.nan, 0.5], [1, 3, 0, 2], window=2)
    assert xs == [2, 4] and ys == [0.75, 0.5]


def test_the_documented_table_is_the_report_of_its_own_kind() -> None:
    text = (Path(__file__).resolve().parents[2] / "docs" / "benchmark.md").read_text()
    assert text.count(br.BEGIN) == 1 and text.count(br.END) == 1 and text.index(br.BEGIN) < text.index(br.END)


# ----------------------------------------------------------------------------- real training
@pytest.mark.slow
def test_a_resumed_run_trains_exactly_as_an_uninterrupted_one(tmp_path) -> None:
    pytest.importorskip("torch")
    pytest.importorskip("stable_baselines3")
    pytest.importorskip("supersuit")
    import zipfile

    from examples.benchmark_training import train

    settings = bb.Settings("empty-goal", seed=0, matches=2, n_steps=64, batch_size=64, checkpoint_every=128)
    assert train(settings, tmp_path / "whole", 256) == 256
    assert train(settings, tmp_path / "parts", 128) == 128
    assert train(settings, tmp_path / "parts", 256) == 256
    for name in ("policy.pth", "policy.optimizer.pth"):
        whole = zipfile.ZipFile(bb.checkpoint_path(tmp_path / "whole", 256)).read(name)
        assert whole == zipfile.ZipFile(bb.checkpoint_path(tmp_path / "parts", 256)).read(name)
    strip = [{k: v for k, v in row.items() if k != "wall_s"} for row in bb.read_curve(tmp_path / "whole/curve.csv")]
    assert strip == [{k: v for k, v in row.items() if k != "wall_s"}
                     for row in bb.read_curve(tmp_path / "parts/curve.csv")]
    assert [row["env_steps"] for row in bb.read_curve(tmp_path / "whole/curve.csv")] == [128, 256]


@pytest.mark.slow
def test_a_resumed_mappo_run_trains_exactly_as_an_uninterrupted_one(tmp_path) -> None:
    pytest.importorskip("torchrl")
    import torch

    from examples.benchmark_mappo import policy_path, train
    from soccer_sim.env.checkpoints import load_policy

    settings = bb.Settings("3-vs-1-with-keeper", seed=1, matches=2, n_steps=64, batch_size=64, checkpoint_every=128)
    assert train(settings, tmp_path / "whole", 256) == 256
    assert train(settings, tmp_path / "parts", 128) == 128
    assert train(settings, tmp_path / "parts", 256) == 256
    whole, parts = (torch.load(bb.checkpoint_path(tmp_path / run, 256, bb.MAPPO), weights_only=True)
                    for run in ("whole", "parts"))
    for part in ("actor", "critic"):
        assert all(torch.equal(whole[part][key], parts[part][key]) for key in whole[part])
    strip = [{k: v for k, v in row.items() if k != "wall_s"} for row in bb.read_curve(tmp_path / "whole/curve.csv")]
    assert strip == [{k: v for k, v in row.items() if k != "wall_s"}
                     for row in bb.read_curve(tmp_path / "parts/curve.csv")]
    policy = load_policy("torchrl", policy_path(tmp_path / "whole", 256))  # as soccer-sim evaluate loads it
    from soccer_sim.env import parallel_env

    size = parallel_env(scenario="3-vs-1-with-keeper", controlled="left").observation_space("left_0").shape[0]
    actions = policy.act_batch(np.zeros((3, size), dtype=np.float32))
    assert actions.shape == (3, 5) and np.all(np.abs(actions) <= 1.0)


@pytest.mark.slow
@pytest.mark.parametrize("algorithm", [bb.PPO, bb.MAPPO])
def test_a_full_match_run_trains_its_eleven_players_against_the_training_rung(tmp_path, algorithm) -> None:
    pytest.importorskip("torchrl" if algorithm == bb.MAPPO else "stable_baselines3")
    pytest.importorskip("supersuit")
    import json
    from dataclasses import replace

    spec = next(spec for spec in bb.plan() if spec.scenario == bb.FULL_MATCH and spec.algorithm == algorithm)
    args = bb.parse_args(["run", "--out", str(tmp_path), "--matches", "1", "--checkpoint-every", "64"])
    settings = replace(bb.settings_for(spec, args), n_steps=64, batch_size=64)
    assert bb.trainer(algorithm)(settings, spec.directory(tmp_path), 64) == 64
    assert json.loads((spec.directory(tmp_path) / "run.json").read_text())["opponent"] == "chaser"
    assert [(row["env_steps"], row["agent_steps"]) for row in bb.read_curve(spec.directory(tmp_path) / "curve.csv")] \
        == [(64, 64 * 11)]
    status = bb.run_status(spec, tmp_path, 64)
    assert (status.state, status.evaluations_done) == ("trained", 0)
    assert bb.policy_file(spec, spec.directory(tmp_path), 64).is_file()
