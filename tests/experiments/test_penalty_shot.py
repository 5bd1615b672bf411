"""The penalty-shot study: markers, chained trials, the uncoordinated team, the tests and the
command on a tiny trial count."""

from __future__ import annotations

import csv

import numpy as np
import pytest

import soccer_sim
from experiments.cli import main
from experiments.results.store import ResultStore
from experiments.studies import penalty_shot as ps
from soccer_sim import TeamCommand
from tests.experiments.helpers import SCRIPTED, outcome


def test_markers_are_fixed_alternate_halves_and_stay_off_the_lines_and_the_goal_area():
    a, b = ps.markers(40, seed=3), ps.markers(40, seed=3)
    assert np.array_equal(a, b) and not np.array_equal(a, ps.markers(40, seed=4))
    assert (a[0::2, 0] <= 0).all() and (a[1::2, 0] >= 0).all()
    assert (np.abs(a[:, 0]) <= 52.5 - ps.MARKER_INSET).all() and (np.abs(a[:, 1]) <= 34 - ps.MARKER_INSET).all()
    assert not ((a[:, 0] > 52.5 - 6.5) & (np.abs(a[:, 1]) < 10.16)).any()


@pytest.mark.parametrize("start", [
    [[53.5, 0.0], [53.4, 0.1], [0.0, 40.0]],
    [[51.09, -2.36], [51.9, -2.5], [51.2, -1.8]],  # pressed together against the goal line
    [[52.3, 34.0], [52.3, 34.0], [52.3, 34.0]],  # all in the corner on one point
])
def test_settle_keeps_attackers_on_the_field_and_apart(start):
    pos = ps.settle(np.array(start), 52.5, 34.0, 0.65)
    assert (np.abs(pos[:, 0]) <= 52.0).all() and (np.abs(pos[:, 1]) <= 33.5).all()
    gaps = [np.hypot(*(pos[i] - pos[j])) for i in range(3) for j in range(i + 1, 3)]
    assert min(gaps) >= 0.65 - 1e-9


@pytest.mark.parametrize("start", [
    [[52.0, 0.0086]],  # a scorer left on the goal line where the goalkeeper starts
    [[52.0, -0.1], [51.8, 0.2]],
    [[51.5, 0.0], [51.5, 0.0], [52.3, 0.4]],
])
def test_settle_keeps_attackers_off_the_goalkeepers_start(start):
    pos = ps.settle(np.array(start), 52.5, 34.0, 0.65, fixed=[ps.KEEPER_START])
    assert (np.abs(pos[:, 0]) <= 52.0).all()
    assert all(np.hypot(*(p - np.array(ps.KEEPER_START))) >= 0.65 - 1e-9 for p in pos)
    gaps = [np.hypot(*(pos[i] - pos[j])) for i in range(len(pos)) for j in range(i + 1, len(pos))]
    assert min(gaps, default=1.0) >= 0.65 - 1e-9


def test_a_goal_scored_from_the_goalkeepers_spot_does_not_stop_the_chain():
    # chaser scores its first trial from on the goal line beside the keeper's start (seed 0)
    trials = ps.run_chain("goalkeeper", "one", "chaser", "static", 1, ps.markers(3, 0), 1200, 0)
    assert [t.trial for t in trials] == [0, 1, 2]


def test_each_trial_starts_where_the_previous_goal_left_the_attackers(monkeypatch):
    played = []
    real = soccer_sim.run_match

    def recording(*args, **kwargs):
        result = real(*args, **kwargs)
        played.append((kwargs["scenario"], result))
        return result

    monkeypatch.setattr(soccer_sim, "run_match", recording)
    marker_list = ps.markers(3, seed=0)
    trials = ps.run_chain("empty goal", "coordinated", "chaser", "static", 2, marker_list, 600, 0)
    assert [t.trial for t in trials] == [0, 1, 2] and all(t.scored for t in trials)
    first = played[0][0]
    assert np.allclose(first.home.positions, ps.first_positions(2))
    for (_, before), (scenario, _), marker in zip(played, played[1:], marker_list[1:]):
        expected = ps.settle(before.state.pos[:2], 52.5, 34.0, 0.65)
        assert np.allclose(scenario.home.positions, expected)
        assert scenario.ball.position == tuple(marker) and scenario.away.players == 0
    assert all(t.seconds == pytest.approx(r.cycles * 0.1) for t, (_, r) in zip(trials, played))


class Probe:
    """A one-player team that remembers what it saw and dashes along +y."""

    seen: list = []

    def reset(self, side_info, config, rng):
        assert side_info.players_per_team == 1 and side_info.goalie_index == -1
        self.command = TeamCommand(dash=np.array([[0.0, 1.0]]), kick=np.zeros((1, 2)))

    def act(self, view):
        Probe.seen.append((id(self), view.own_pos.copy(), view.opp_pos.shape))
        return self.command


def test_the_uncoordinated_robots_each_see_only_themselves():
    Probe.seen = []
    team = ps.Uncoordinated(Probe, 3)
    scenario = ps.trial_scenario(np.array([10.0, 5.0]), ps.first_positions(3), keeper=True, limit=2)
    result = soccer_sim.run_match(team, "idle", scenario=scenario)
    assert result.cycles == 2 and len({who for who, _, _ in Probe.seen}) == 3
    first_cycle = Probe.seen[:3]
    for k, (_, own, opp_shape) in enumerate(first_cycle):
        assert np.allclose(own[0], ps.first_positions(3)[k]) and opp_shape == (1, 2)
    assert (result.state.pos[:3, 1] > ps.first_positions(3)[:, 1]).all()  # every robot followed its own copy


def test_signed_rank_p_values():
    a = np.arange(1.0, 21.0)
    assert ps.signed_rank_p(a, a) == 1.0
    assert ps.signed_rank_p(a, a + 5.0) < 0.001
    assert np.isnan(ps.signed_rank_p(a[:1], a[:1] + 1))


def test_the_command_on_two_trials_prints_the_tables_and_writes_the_files(tmp_path, capsys):
    out = tmp_path / "ps"
    assert main(["experiment", "penalty-shot", "--trials", "2", "--workers", "1", "--limit", "150", "--no-progress",
                 "--out", str(tmp_path / "ps.sqlite"), "--tables", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "Time to score" in printed and "Wilcoxon" in printed and "12 trials in 6 of 6 chains" in printed
    with open(out / "penalty_shot_trials.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 2 * len(ps.CONDITIONS) * len(ps.SETTINGS)
    assert {(r["setting"], r["condition"]) for r in rows} == {(s, c) for s in ps.SETTINGS for c in ps.CONDITIONS}
    assert all(0 < float(r["seconds"]) <= 15.0 for r in rows)
    assert all((r["scored"] == "True") == (float(r["seconds"]) < 15.0) for r in rows)
    with open(out / "penalty_shot_tests.csv") as handle:
        assert len(list(csv.DictReader(handle))) == len(ps.PAIRS) * len(ps.SETTINGS)
    assert (out / "penalty_shot.png").stat().st_size > 1000
    assert "Time to score" in (out / "penalty_shot.md").read_text()


def test_bad_options_are_reported_without_a_traceback(tmp_path, capsys):
    results = str(tmp_path / "ps.sqlite")
    assert main(["experiment", "penalty-shot", "--trials", "2", "--team", "no-such-team", "--out", results]) == 2
    err = capsys.readouterr().err
    assert "--team" in err and "Traceback" not in err
    with pytest.raises(SystemExit) as usage:           # more robots than a side has players: the option's range
        main(["experiment", "penalty-shot", "--trials", "1", "--robots", "12", "--out", results])
    err = capsys.readouterr().err
    assert usage.value.code == 2 and "--robots: must be a positive integer up to 11" in err and "Traceback" not in err
    (tmp_path / "a-file").write_text("")
    assert main(["experiment", "penalty-shot", "--trials", "1", "--out", results, "--tables",
                 str(tmp_path / "a-file")]) == 2
    err = capsys.readouterr().err
    assert "--tables" in err and "Traceback" not in err
    for option in (["--cycles", "100"], ["--record-dir", str(tmp_path / "replays")]):
        assert main(["experiment", "penalty-shot", "--trials", "1", "--out", results, *option]) == 2
        err = capsys.readouterr().err
        assert option[0] in err and "Traceback" not in err
    assert not (tmp_path / "ps.sqlite").exists() and not (tmp_path / "replays").exists()


# ------------------------------------------------------------------------------ on the runner
TINY = ["--trials", "2", "--limit", "120", "--robots", "2", "--team", "chaser", "--no-progress"]
PARAMS = {"trials": 2, "robots": 2, "team": "chaser", "keeper": "static", "limit": 120, "seed": 0, "cycles": None}


def _run(tmp_path, name: str, *extra: str) -> int:
    """Run the tiny study into ``name``.sqlite (tables in ``name``/); its exit status."""
    return main(["experiment", "penalty-shot", *TINY, "--out", str(tmp_path / f"{name}.sqlite"),
                 "--tables", str(tmp_path / name), *extra])


def _tables_printed(text: str) -> str:
    """The printed tables of a run (from the first table's title to the trial count)."""
    start = text.index("# Time to score")
    return text[start:text.index(" chains", start)]


def _records(path) -> list:
    with ResultStore.open(path) as store:
        return store.records()


def test_the_chain_keys_cover_every_parameter_that_changes_a_trial():
    specs = ps.build_specs(PARAMS)
    assert len({spec.key for spec in specs}) == 6 and all(spec.play == ps.PLAY for spec in specs)
    for name, value in (("trials", 3), ("robots", 3), ("team", "idle"), ("keeper", "idle"), ("limit", 121),
                        ("seed", 1)):
        other = {spec.key for spec in ps.build_specs({**PARAMS, name: value})}
        changed = {spec.key for spec in specs} - other
        # The empty goal ignores the keeper and a single robot ignores --robots: those chains are shared.
        assert len(changed) == {"keeper": 3, "robots": 4}.get(name, 6), name


def test_a_chain_played_by_a_worker_is_the_chain_of_run_chain():
    from experiments.runner.worker import play_spec

    spec = ps.build_specs(PARAMS)[5]  # goalkeeper, coordinated
    record = play_spec(spec, "hash", "version", timeout=None)
    trials = ps.run_chain("goalkeeper", "coordinated", "chaser", "static", 2, ps.markers(2, 0), 120, 0)
    assert record.error is None and record.cycles == sum(t.cycles for t in trials)
    assert record.home_goals == sum(t.scored for t in trials)
    assert ps.stored_trials([record], PARAMS) == trials


@pytest.mark.parametrize("side", [0, 1])
def test_a_chain_whose_team_raises_is_forfeited_by_that_team(side):
    from experiments.runner.worker import play_spec

    raising = SCRIPTED + "RaisingTeam"
    params = {**PARAMS, ("team", "keeper")[side]: raising}
    spec = ps.build_specs(params)[4]  # goalkeeper, uncoordinated: the keeper plays, the attackers are copies
    record = play_spec(spec, "hash", "version", timeout=None)
    assert record.forfeit == side and "scripted failure" in record.error and record.home_goals is None


def test_a_forfeited_chain_leaves_its_rows_empty_and_the_study_goes_on(tmp_path, capsys):
    status = _run(tmp_path, "ff", "--keeper", SCRIPTED + "RaisingTeam", "--workers", "1")
    printed = capsys.readouterr().out
    assert status == 0  # forfeits are results
    records = _records(tmp_path / "ff.sqlite")
    assert sorted((r.away.startswith(SCRIPTED), r.forfeit) for r in records) == [(False, -1)] * 3 + [(True, 1)] * 3
    assert "6 trials in 3 of 6 chains" in printed and "forfeited by " + SCRIPTED + "RaisingTeam goalkeeper" in printed
    with open(tmp_path / "ff" / "penalty_shot_summary.csv") as handle:
        summary = list(csv.DictReader(handle))
    assert [int(row["trials"]) for row in summary] == [2, 2, 2, 0, 0, 0]
    with open(tmp_path / "ff" / "penalty_shot_tests.csv") as handle:
        tests = list(csv.DictReader(handle))
    assert [row["p_value"] == "nan" for row in tests] == [False] * 3 + [True] * 3


@pytest.mark.slow  # slow: resuming stays in the default run through the runner's own resume tests
def test_a_resumed_run_equals_one_run_and_results_show_repeats_its_tables(tmp_path, capsys):
    from experiments.runner import run_matches

    assert _run(tmp_path, "whole", "--workers", "1") == 0
    whole = capsys.readouterr().out
    run_matches(ps.build_specs(PARAMS)[:2], tmp_path / "resumed.sqlite", ps.KIND, PARAMS, workers=1, progress=False)
    capsys.readouterr()
    assert _run(tmp_path, "resumed", "--workers", "1") == 0
    resumed = capsys.readouterr().out
    assert "(2 already stored): played 4" in resumed
    assert outcome(_records(tmp_path / "resumed.sqlite")) == outcome(_records(tmp_path / "whole.sqlite"))
    assert _tables_printed(resumed) == _tables_printed(whole)
    for name in ("trials", "summary", "tests"):
        assert ((tmp_path / "resumed" / f"penalty_shot_{name}.csv").read_text()
                == (tmp_path / "whole" / f"penalty_shot_{name}.csv").read_text())
    assert main(["results", "show", str(tmp_path / "whole.sqlite"), "--tables", str(tmp_path / "shown")]) == 0
    shown = capsys.readouterr().out
    assert "penalty-shot, 6 of 6 matches stored (0 failed)" in shown
    assert _tables_printed(shown) == _tables_printed(whole)
    assert ((tmp_path / "shown" / "penalty_shot_tests.csv").read_text()
            == (tmp_path / "whole" / "penalty_shot_tests.csv").read_text())


@pytest.mark.slow  # one and two workers give identical records: test_runner_resume keeps it in the default run
def test_the_tables_are_the_same_with_one_and_two_workers(tmp_path, capsys):
    assert _run(tmp_path, "one", "--workers", "1") == 0
    one = capsys.readouterr().out
    assert _run(tmp_path, "two", "--workers", "2") == 0
    two = capsys.readouterr().out
    assert "on 2 worker(s)" in two
    assert _tables_printed(one) == _tables_printed(two)
    assert outcome(_records(tmp_path / "one.sqlite")) == outcome(_records(tmp_path / "two.sqlite"))
    assert ((tmp_path / "one" / "penalty_shot_trials.csv").read_text()
            == (tmp_path / "two" / "penalty_shot_trials.csv").read_text())


def test_the_time_budget_covers_the_whole_chain():
    from experiments.runner.worker import play_spec

    ps.run_chain("goalkeeper", "one", "chaser", "static", 1, ps.markers(1, 0), 10, 0)  # imports done: only play is timed
    spec = ps.build_specs({**PARAMS, "trials": 200, "limit": 1200})[3]  # goalkeeper, one robot: minutes of play
    record = play_spec(spec, "hash", "version", timeout=1.0)
    # The timer strikes wherever the chain is: in the simulator (a bare MatchTimeout) or inside a
    # team's act (a TeamError carrying it, and that side forfeits).
    assert "MatchTimeout: match exceeded its time budget of 1 s" in record.error
    assert record.home_goals is None and record.wall_time < 60.0


def test_the_chains_name_the_teams_they_play_for_warm_up_and_ray_nodes() -> None:
    from experiments.studies.penalty_shot import chain_specs

    teams = {(setting, condition): spec.team_names for setting, condition, spec in chain_specs(PARAMS)}
    assert teams[("goalkeeper", "coordinated")] == ("chaser", "static")
    assert teams[("empty goal", "one")] == ("chaser", "idle")


@pytest.mark.slow  # Ray start-up: the default suite keeps one Ray run of each kind
def test_on_ray_the_study_gives_the_local_pools_tables(tmp_path, capsys) -> None:
    pytest.importorskip("ray")
    assert _run(tmp_path, "local", "--workers", "2") == 0
    local = [line for line in capsys.readouterr().out.splitlines() if " matches in " not in line]
    assert _run(tmp_path, "ray", "--workers", "2", "--backend", "ray") == 0
    on_ray = [line for line in capsys.readouterr().out.splitlines() if " matches in " not in line]
    strip = lambda lines: [line.replace(str(tmp_path / "ray"), "T").replace(str(tmp_path / "local"), "T")
                           for line in lines]
    assert strip(on_ray) == strip(local) and any("coordinated" in line for line in local)
