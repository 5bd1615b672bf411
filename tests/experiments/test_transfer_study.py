"""``soccer-sim experiment transfer``: the report from stand-in results files of both engines
(written with the results store's API, no match played), the paired difference from the
baseline and the rank agreement checked against hand-computed figures, partial files, bad input
as one line with every file left as it was, and the command's plan and runs with the runner
replaced by a stand-in that stores made-up matches."""

from __future__ import annotations

import csv
import math
import shutil

import numpy as np
import pytest

from experiments.cli import main
from experiments.configuration import match_config
from experiments.results.record import MatchRecord
from experiments.results.store import ResultStore
from experiments.runner.spec import config_description, config_hash
from experiments.stats import rank_agreement, ranking
from experiments.studies.transfer import build_specs
from tests.experiments.test_play_rcss import kit

CYCLES = 200
TEAMS = ("mmdr", "static", "greedy")

SKILL = {"simulator": {"mmdr": 1, "static": 0, "greedy": -1},
         "rcssserver": {"mmdr": 0, "static": 1, "greedy": -1}}
"""Each team's goal difference against a reference opponent, before the seed's share: the
simulator ranks mmdr > static > greedy, the server static > mmdr > greedy."""


def home_gd(engine: str, home: str, away: str, seed: int) -> int:
    """The made-up goal difference of the home team: the skills' difference, a goal more on
    every third seed, and one more when mmdr is at home (so its differences vary by side)."""
    return SKILL[engine].get(home, 0) - SKILL[engine].get(away, 0) + (seed % 3 == 0) + (home == "mmdr")


def team_gd(engine: str, team: str, opponent: str, seed: int, side: int) -> int:
    """The made-up goal difference of ``team`` playing ``side`` (0 home) against ``opponent``."""
    return home_gd(engine, team, opponent, seed) if side == 0 else -home_gd(engine, opponent, team, seed)


def made_match(engine: str, home: str, away: str, seed: int, digest: str) -> MatchRecord:
    """A stored match whose score gives home its made-up goal difference, with statistics."""
    gd = home_gd(engine, home, away, seed)
    stats = {"goals": 0.0, "shots": 4.0 + seed, "passes": 100.0, "kicks": 150.0, "tackles": 3.0, "possession": 0.5,
             "distance_run": 40_000.0}
    home_stats, away_stats = dict(stats), dict(stats, shots=2.0)
    if engine == "rcssserver":
        for name, side_stats in ((home, home_stats), (away, away_stats)):
            if name != "helios-base":
                side_stats["missed_steps"] = float(seed)
    return MatchRecord(home, away, seed, digest, "test", max(gd, 0) + 1, max(-gd, 0) + 1, CYCLES, 1.0,
                       home_stats, away_stats)


def results_file(path, engine: str, pairs, seeds, kind: str = "transfer", observation: str = "partial",
                 cycles: int = CYCLES, params: dict | None = None):
    """A results file of ``engine`` holding each pair on each seed with both teams at home."""
    config = match_config(cycles, observation)
    digest = config_hash(config, None, engine)
    stored = {"teams": list(TEAMS), "opponents": ["counter-442"], "baseline": "static", "games": 2 * len(seeds),
              "seed": 0, "cycles": cycles, "observation": observation}
    if engine == "rcssserver":
        stored.update(engine="rcssserver", external={})
    with ResultStore.create(path, kind, digest, config_description(config, None, engine), params or stored) as store:
        for a, b in pairs:
            for seed in seeds:
                store.add(made_match(engine, a, b, seed, digest))
                store.add(made_match(engine, b, a, seed, digest))
    return path


DESIGN = [*(("--teams", ",".join(TEAMS))), "--opponents", "counter-442,helios-base", "--mirror", "mmdr,static",
          "--baseline", "static"]
SIM_PAIRS = [*((team, "counter-442") for team in TEAMS), ("mmdr", "static")]
REAL_PAIRS = [*SIM_PAIRS, *((team, "helios-base") for team in TEAMS)]


@pytest.fixture
def both(tmp_path):
    """Stand-in files of both engines: 6 games a pairing in the simulator, 4 in the server."""
    return (results_file(tmp_path / "sim.sqlite", "simulator", SIM_PAIRS, range(3)),
            results_file(tmp_path / "real.sqlite", "rcssserver", REAL_PAIRS, range(2)))


def read_csv(path) -> list[dict]:
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def report(tmp_path, sim, real, *extra) -> int:
    return main(["experiment", "transfer", "--report-only", *DESIGN, "--out-sim", str(sim), "--out-real", str(real),
                 "--tables", str(tmp_path / "tables"), *extra])


def expected_paired(engine: str, opponent: str, seeds) -> tuple[float, float, int]:
    """mmdr minus static on the same seed and side: mean, SE and pairs, computed by hand."""
    differences = [team_gd(engine, "mmdr", opponent, s, side) - team_gd(engine, "static", opponent, s, side)
                   for s in seeds for side in (0, 1)]
    n = len(differences)
    return float(np.mean(differences)), float(np.std(differences, ddof=1) / math.sqrt(n)), n


# ---------------------------------------------------------------------------------- the report
def test_the_report_from_both_engines_files(tmp_path, both, capsys):
    sim, real = both
    before = (sim.read_bytes(), real.read_bytes())
    assert report(tmp_path, sim, real) == 0
    out = capsys.readouterr().out
    assert "Kendall's tau-b" in out and "mmdr v counter-442" in out
    assert (sim.read_bytes(), real.read_bytes()) == before            # the report only reads them

    goals = {(r["engine"], r["team"], r["opponent"]): r for r in read_csv(tmp_path / "tables" / "transfer-goals.csv")}
    assert ("simulator", "mmdr", "helios-base") not in goals         # helios-base plays in the server only
    row = goals[("simulator", "mmdr", "counter-442")]
    values = [team_gd("simulator", "mmdr", "counter-442", s, side) for s in range(3) for side in (0, 1)]
    assert int(row["games"]) == 6 and float(row["mean_gd"]) == pytest.approx(np.mean(values))
    assert float(row["se"]) == pytest.approx(np.std(values, ddof=1) / math.sqrt(6))
    assert int(goals[("rcssserver", "greedy", "helios-base")]["games"]) == 4
    assert int(goals[("rcssserver", "mmdr", "static")]["games"]) == 4     # the mirror pairing, in both
    assert int(goals[("simulator", "mmdr", "static")]["games"]) == 6

    paired = {(r["engine"], r["team"], r["opponent"]): r for r in read_csv(tmp_path / "tables" / "transfer-paired.csv")}
    for engine, opponent, seeds in (("simulator", "counter-442", range(3)), ("rcssserver", "counter-442", range(2)),
                                    ("rcssserver", "helios-base", range(2))):
        mean, se, n = expected_paired(engine, opponent, seeds)
        row = paired[(engine, "mmdr", opponent)]
        assert (float(row["gd_difference"]), float(row["gd_difference_se"]), int(row["pairs"])) == (
            pytest.approx(mean), pytest.approx(se), n)
    assert ("simulator", "static", "counter-442") not in paired      # the baseline's own row

    agreement = read_csv(tmp_path / "tables" / "transfer-rank-agreement.csv")
    same = next(r for r in agreement if r["opponent"] == "counter-442")
    # simulator: mmdr > static > greedy; server: static > mmdr > greedy: 2 concordant, 1 discordant pair
    assert float(same["kendall_tau_b"]) == pytest.approx(1 / 3) and int(same["teams"]) == 3
    ranks = {(r["engine"], r["team"]): float(r["rank"]) for r in read_csv(tmp_path / "tables" / "transfer-ranks.csv")
             if r["opponent"] == "counter-442"}
    assert (ranks[("simulator", "mmdr")], ranks[("rcssserver", "static")], ranks[("rcssserver", "greedy")]) == (1, 1, 3)

    statistics = {(r["engine"], r["team"], r["against"]): r
                  for r in read_csv(tmp_path / "tables" / "transfer-statistics.csv")}
    ours, theirs = statistics[("rcssserver", "mmdr", "helios-base")], statistics[("rcssserver", "helios-base", "mmdr")]
    assert float(ours["missed_steps"]) == pytest.approx(0.5) and theirs["missed_steps"] == "nan"
    assert float(ours["distance_run"]) == pytest.approx(40.0) and int(theirs["games"]) == 4
    assert float(ours["shots"]) == pytest.approx(np.mean([4.0, 2.0, 5.0, 2.0]))
    assert ("simulator", "helios-base", "mmdr") not in statistics
    markdown = (tmp_path / "tables" / "transfer.md").read_text()
    assert "partial observation in both engines" in markdown and "missed steps" in markdown


def test_case_study_files_of_both_engines_are_read_as_they_are(tmp_path, capsys):
    """Files of ``experiment case-study --observation partial`` and ``--engine rcssserver``
    (rows keyed by the teams and seed, the case study's parameters), helios-base's in a second
    server file read with --read-real."""
    sim = results_file(tmp_path / "cs-sim.sqlite", "simulator", SIM_PAIRS, range(2), kind="case-study")
    real = results_file(tmp_path / "cs-real.sqlite", "rcssserver", SIM_PAIRS, range(2), kind="case-study")
    helios = results_file(tmp_path / "cs-helios.sqlite", "rcssserver", [(t, "helios-base") for t in TEAMS], range(1),
                          kind="case-study")
    assert report(tmp_path, sim, real, "--read-real", str(helios)) == 0
    goals = {(r["engine"], r["team"], r["opponent"]): int(r["games"])
             for r in read_csv(tmp_path / "tables" / "transfer-goals.csv")}
    assert goals[("rcssserver", "mmdr", "counter-442")] == 4 and goals[("rcssserver", "static", "helios-base")] == 2
    assert "cs-helios.sqlite" in (tmp_path / "tables" / "transfer.md").read_text()


def test_a_partial_file_reports_what_it_holds_and_says_how_many_games_each_row_has(tmp_path, capsys):
    sim = results_file(tmp_path / "sim.sqlite", "simulator", SIM_PAIRS, range(3))
    # a run stopped early: two of the pairings against counter-442, one against helios-base
    real = results_file(tmp_path / "real.sqlite", "rcssserver", [*REAL_PAIRS[:2], ("mmdr", "helios-base")], range(1))
    assert report(tmp_path, sim, real, "--games-real", "6") == 0
    out = capsys.readouterr().out
    assert "fewer games than asked: mmdr v counter-442 in rcssserver (2 of 6)" in out
    assert "greedy v helios-base in rcssserver (0 of 6)" in out
    goals = {(r["engine"], r["team"], r["opponent"]): r for r in read_csv(tmp_path / "tables" / "transfer-goals.csv")}
    assert int(goals[("rcssserver", "static", "counter-442")]["games"]) == 2
    assert goals[("rcssserver", "greedy", "counter-442")]["mean_gd"] == "nan"
    agreement = read_csv(tmp_path / "tables" / "transfer-rank-agreement.csv")
    assert int(next(r for r in agreement if r["opponent"] == "counter-442")["teams"]) == 2   # greedy unranked there
    assert "fewer games than asked" in (tmp_path / "tables" / "transfer.md").read_text()
    assert report(tmp_path, sim, real) == 0          # without --games-real: the games the file's run asked for
    assert "greedy v helios-base in rcssserver (0 of 2)" in capsys.readouterr().out


def test_one_engine_alone(tmp_path, both, capsys):
    sim, _ = both
    assert main(["experiment", "transfer", "--report-only", "--engine-only", "simulator", *DESIGN,
                 "--out-sim", str(sim), "--out-real", str(tmp_path / "absent.sqlite"),
                 "--tables", str(tmp_path / "tables")]) == 0
    assert "rcssserver" not in {r["engine"] for r in read_csv(tmp_path / "tables" / "transfer-goals.csv")}
    assert read_csv(tmp_path / "tables" / "transfer-rank-agreement.csv") == []
    assert not (tmp_path / "absent.sqlite").exists()


def test_results_show_reports_one_engines_half(tmp_path, both, capsys):
    _, real = both
    assert main(["results", "show", str(real)]) == 0
    out = capsys.readouterr().out
    assert "transfer" in out and "static v counter-442" in out and "goal difference minus static's" in out


# ---------------------------------------------------------------------------------- bad input
def one_line(capsys) -> str:
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: ") and "Traceback" not in err, err
    return err


@pytest.mark.parametrize("case, words", [
    ("missing", "--out-real {real_missing}: no such results file"),
    ("swapped", "holds matches played in the simulator, not in rcssserver"),
    ("absent team", "no match of 'bidding'"),
    ("full observation", "holds matches under full observation"),
    ("other lengths", "different lengths"),
    ("twice", "is also in --out-real"),
    ("other kind", "holds the results of 'ablation'"),
])
def test_bad_input_is_one_line_and_leaves_every_file_as_it_was(tmp_path, both, capsys, case, words):
    sim, real = both
    args = {"sim": sim, "real": real, "extra": []}
    if case == "missing":
        args["real"] = tmp_path / "nothing.sqlite"
    elif case == "swapped":
        args["real"] = sim
        args["sim"] = results_file(tmp_path / "sim2.sqlite", "simulator", SIM_PAIRS, range(1))
    elif case == "absent team":
        args["extra"] = ["--teams", "mmdr,static,bidding"]
    elif case == "full observation":
        args["sim"] = results_file(tmp_path / "full.sqlite", "simulator", SIM_PAIRS, range(1), observation="full")
    elif case == "other lengths":
        args["sim"] = results_file(tmp_path / "long.sqlite", "simulator", SIM_PAIRS, range(1), cycles=400)
    elif case == "twice":
        args["extra"] = ["--read-real", str(results_file(tmp_path / "copy.sqlite", "rcssserver", REAL_PAIRS[:1], [0]))]
    elif case == "other kind":
        args["real"] = results_file(tmp_path / "ablation.sqlite", "rcssserver", REAL_PAIRS, [0], kind="ablation")
    files = sorted(tmp_path.glob("*.sqlite"))
    before = [path.read_bytes() for path in files]
    status = report(tmp_path, args["sim"], args["real"], *args["extra"])
    assert status == 2
    assert words.format(real_missing=tmp_path / "nothing.sqlite") in one_line(capsys)
    assert [path.read_bytes() for path in files] == before
    assert not (tmp_path / "tables").exists()
    assert not (tmp_path / "nothing.sqlite").exists()


@pytest.mark.parametrize("argv, words", [
    (["--teams", "mmdr,helios-base", "--baseline", "mmdr"], "plays in rcssserver only"),
    (["--baseline", "bidding", "--teams", "mmdr,static"], "--baseline 'bidding' must be one of --teams"),
    (["--mirror", "mmdr"], "--mirror: needs at least 2"),
    (["--mirror", "mmdr,static,greedy"], "give two teams"),
    (["--no-mirror", "--mirror", "mmdr,static"], "contradict"),
    (["--out-sim", "same.sqlite", "--out-real", "same.sqlite"], "never mixes engines"),
    (["--opponents", "", "--no-mirror"], "nothing to compare"),
    (["--opponents", "nobody"], "unknown team 'nobody'"),
])
def test_bad_options_are_one_line_before_anything_runs(tmp_path, capsys, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    assert main(["experiment", "transfer", "--plan", "--engine-only", "simulator", *argv]) == 2
    assert words in one_line(capsys)
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------------- the plan and the runs
def test_each_engine_plays_the_pairings_it_can():
    params = {"teams": ["mmdr", "static"], "opponents": ["counter-442"], "mirror": [["mmdr", "static"]],
              "baseline": "static", "games": 3, "seed": 5, "cycles": CYCLES, "observation": "partial"}
    specs = build_specs(params)
    pairs = {tuple(sorted((s.home, s.away))) for s in specs}
    assert pairs == {("counter-442", "mmdr"), ("counter-442", "static"), ("mmdr", "static")}
    assert len(specs) == 3 * 4                     # 3 games rounded up to 4: seeds 5 and 6, each side at home
    assert {s.seed for s in specs} == {5, 6}
    assert all(s.config().observation.mode == "partial" for s in specs)


def needs_unshare():
    if shutil.which("unshare") is None:
        pytest.skip("the server's pre-flight needs the unshare command")


def test_the_plan_names_each_engines_matches_and_what_is_stored(tmp_path, capsys, monkeypatch):
    needs_unshare()
    monkeypatch.chdir(tmp_path)
    home = kit(tmp_path / "kit")
    real = results_file(tmp_path / "real.sqlite", "rcssserver", [("mmdr", "helios-base")], [0])
    before = real.read_bytes()
    assert main(["experiment", "transfer", "--plan", *DESIGN, "--games-sim", "4", "--games-real", "2",
                 "--cycles", str(CYCLES), "--rcss-home", str(home), "--out-sim", "sim.sqlite",
                 "--out-real", str(real)]) == 0
    out = capsys.readouterr().out
    lines = {line.split("\t")[0]: line.split("\t")[1:] for line in out.splitlines() if "\t" in line}
    assert lines["helios-base v mmdr"] == ["-", "2 / 2"]
    assert lines["counter-442 v greedy"] == ["0 / 4", "0 / 2"]
    assert lines["mmdr v static"] == ["0 / 4", "0 / 2"]                # the mirror pairing, in both
    assert "simulator: 16 matches in sim.sqlite, 0 stored, 16 to play" in out
    assert f"rcssserver: 14 matches in {real}, 2 stored, 12 to play" in out
    assert real.read_bytes() == before and not (tmp_path / "sim.sqlite").exists()
    assert not (tmp_path / "transfer-tables").exists()


def test_the_plan_refuses_a_file_the_run_would_refuse(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = results_file(tmp_path / "sim.sqlite", "simulator", SIM_PAIRS, [0], kind="case-study")
    assert main(["experiment", "transfer", "--plan", "--engine-only", "simulator", *DESIGN, "--cycles", str(CYCLES),
                 "--out-sim", str(sim)]) == 2
    assert "give this one to --read-sim" in one_line(capsys)


def test_a_missing_server_build_stops_the_run_before_the_simulators_half(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["experiment", "transfer", *DESIGN, "--games-sim", "2", "--games-real", "2", "--cycles", str(CYCLES),
                 "--rcss-home", str(tmp_path / "none"), "--no-progress"]) == 2
    assert "build.sh" in one_line(capsys)
    assert list(tmp_path.iterdir()) == []


@pytest.fixture
def stand_in_runner(monkeypatch):
    """The runner replaced: every spec handed to it is stored as a made-up match of its engine
    in the run's file; the calls are kept."""
    from experiments.commands import run_options
    from experiments.runner.run import RunSummary

    calls = []

    def execute(args, kind, specs, params, figures=None):
        engine = specs[0].engine
        digest = config_hash(specs[0].config(), None, engine)
        calls.append((args.out, kind, engine, list(specs), params))
        with ResultStore.create(args.out, kind, digest, config_description(specs[0].config(), None, engine),
                                params) as store:
            for spec in specs:
                store.add(made_match(engine, spec.home, spec.away, spec.seed, digest))
            records = store.records()
        return RunSummary(args.out, len(specs), 0, len(specs), 0, 1.0, 1, records, len(specs))

    monkeypatch.setattr(run_options, "execute", execute)
    return calls


def test_a_run_plays_each_half_into_its_file_and_reports_both(tmp_path, capsys, monkeypatch, stand_in_runner):
    needs_unshare()
    monkeypatch.chdir(tmp_path)
    home = kit(tmp_path / "kit")
    assert main(["experiment", "transfer", *DESIGN, "--games-sim", "4", "--games-real", "2", "--cycles", str(CYCLES),
                 "--rcss-home", str(home), "--no-progress"]) == 0
    (sim_out, kind, sim_engine, sim_specs, sim_params), (real_out, _, real_engine, real_specs, real_params) = \
        stand_in_runner
    assert (sim_out, real_out, kind, sim_engine, real_engine) == (
        "transfer-sim.sqlite", "transfer-real.sqlite", "transfer", "simulator", "rcssserver")
    assert all(s.config().observation.mode == "partial" for s in sim_specs + real_specs)
    assert not any("helios-base" in (s.home, s.away) for s in sim_specs) and len(sim_specs) == 16
    assert sum("helios-base" in (s.home, s.away) for s in real_specs) == 6 and len(real_specs) == 14
    assert [s.seed for s in real_specs] == sorted(s.seed for s in real_specs)     # the server's seed order
    assert real_params["engine"] == "rcssserver" and "engine" not in sim_params
    assert sim_params["mirror"] == [["mmdr", "static"]] and sim_params["observation"] == "partial"
    goals = read_csv(tmp_path / "transfer-tables" / "transfer-goals.csv")
    assert {r["engine"] for r in goals} == {"simulator", "rcssserver"}
    assert "fewer games than asked" not in capsys.readouterr().out


def test_one_engines_half_is_played_alone_and_the_others_file_read_when_it_exists(tmp_path, capsys, monkeypatch,
                                                                                  stand_in_runner):
    monkeypatch.chdir(tmp_path)
    results_file(tmp_path / "transfer-real.sqlite", "rcssserver", REAL_PAIRS, range(1))
    assert main(["experiment", "transfer", "--engine-only", "simulator", *DESIGN, "--games-sim", "2",
                 "--cycles", str(CYCLES), "--no-progress"]) == 0
    assert [call[2] for call in stand_in_runner] == ["simulator"]
    goals = read_csv(tmp_path / "transfer-tables" / "transfer-goals.csv")
    assert {r["engine"] for r in goals} == {"simulator", "rcssserver"}


# ---------------------------------------------------------------------------------- statistics helpers
def test_rank_agreement_is_kendalls_tau_b_over_the_teams_both_rank():
    assert rank_agreement([3, 2, 1], [3, 2, 1]).tau == pytest.approx(1.0)
    assert rank_agreement([3, 2, 1], [1, 2, 3]).tau == pytest.approx(-1.0)
    result = rank_agreement([0.5, 0.1, -0.2, math.nan], [0.1, 0.4, -0.3, 0.9])
    assert result.n == 3 and result.tau == pytest.approx(1 / 3)
    tied = rank_agreement([1.0, 1.0, 0.0], [2.0, 1.0, 0.0])      # tau-b: 2 concordant, 0 discordant, one tie
    assert tied.tau == pytest.approx(2 / math.sqrt(2 * 3))
    assert math.isnan(rank_agreement([1.0, 1.0], [2.0, 1.0]).tau)
    assert math.isnan(rank_agreement([1.0], [2.0]).tau) and rank_agreement([1.0], [2.0]).n == 1


def test_ranking_puts_the_highest_first_and_shares_ties():
    assert ranking([0.2, math.nan, 0.9, 0.2]) == [2.5, pytest.approx(math.nan, nan_ok=True), 1.0, 2.5]
