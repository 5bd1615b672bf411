"""A run's exit status tells the truth: 0 only when the tables are complete (a team's own
forfeit is a result), 1 with one line when matches could not be played for another reason; a
crash of the worker inside a team's code is that team's forfeit; the failure policy stops a
run that mostly fails, keeping what finished; the rate counts only matches played to the end."""

from __future__ import annotations

import re

import pytest

import experiments.runner.run as run
from experiments.cli import main
from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.results.store import ResultStore
from experiments.runner import MatchSpec, config_for, config_hash, run_matches
from experiments.runner.run import FAILURE_MIN_MATCHES, FAILURE_SHARE, FailurePolicy, RunStopped
from experiments.runner.spec import code_version
from experiments.runner.worker import failed_record
from tests.experiments.helpers import SCRIPTED
from tests.experiments.scripted_teams import CrashingFigures

CYCLES = 20
DIGEST = config_hash(config_for(CYCLES))
TOURNAMENT = ["tournament", "--teams", "chaser,idle", "--cycles", str(CYCLES), "--workers", "1", "--no-progress"]


class ScriptedPool:
    """Stands in for a backend (a lost Ray node, a broken machine): the k-th match it is given
    fails with no team at fault when ``fails(k)``, and is played 1-0 otherwise."""

    size = 1
    most_at_once = 1

    def __init__(self, fails) -> None:
        self.fails = fails

    def warm_up(self, specs) -> None:
        pass

    def run(self, specs):
        for k, spec in enumerate(specs):
            if self.fails(k):
                yield failed_record(spec, DIGEST, code_version(), 0.0, "NodeDied: the node running this match was lost")
            else:
                yield MatchRecord(spec.home, spec.away, spec.seed, DIGEST, code_version(), 1, 0, CYCLES, 0.01,
                                  {"goals": 1}, {"goals": 0})

    def close(self) -> None:
        pass


@pytest.fixture
def backend(monkeypatch):
    """``backend(fails)``: every run of this test plays on a ScriptedPool(fails)."""

    def use(fails) -> None:
        monkeypatch.setattr(run, "_pool", lambda *args, **kwargs: ScriptedPool(fails))

    return use


def error_lines(capsys) -> list[str]:
    return capsys.readouterr().err.splitlines()


def test_a_run_in_which_no_match_could_be_played_exits_1_with_the_count(tmp_path, capsys, backend) -> None:
    backend(lambda k: True)
    out = tmp_path / "t.sqlite"
    assert main([*TOURNAMENT, "--games", "2", "--out", str(out)]) == 1
    lines = error_lines(capsys)
    assert len(lines) == 1 and lines[0].startswith("error: 2 of the 2 matches could not be played"), lines
    assert str(out) in lines[0] and "again" in lines[0]


def test_one_unplayed_match_is_enough_for_status_1_and_a_complete_rerun_gives_0(tmp_path, capsys, backend) -> None:
    out = tmp_path / "t.sqlite"
    backend(lambda k: k == 3)
    assert main([*TOURNAMENT, "--games", "4", "--out", str(out)]) == 1
    assert error_lines(capsys)[0].startswith("error: 1 of the 4 matches could not be played")
    backend(lambda k: False)
    assert main([*TOURNAMENT, "--games", "4", "--out", str(out)]) == 0  # the failed match is played again
    assert error_lines(capsys) == []


def test_a_teams_own_forfeits_are_results_and_exit_0(tmp_path, capsys) -> None:
    raising = SCRIPTED + "RaisingTeam"
    code = main(["tournament", "--teams", f"idle,{raising}", "--games", "2", "--cycles", "30", "--workers", "1",
                 "--no-progress", "--out", str(tmp_path / "t.sqlite")])
    out, err = capsys.readouterr()
    assert code == 0 and err == "" and f"forfeited by {raising}" in out


@pytest.mark.slow  # test_runner_failures keeps a crash inside act as a forfeit in the default suite
def test_a_worker_crash_inside_act_is_the_teams_forfeit(tmp_path) -> None:
    specs = [MatchSpec("idle", SCRIPTED + "CrashingTeam", 0, 50), MatchSpec(SCRIPTED + "ExitingTeam", "idle", 0, 50)]
    summary = run_matches(specs, tmp_path / "r.sqlite", "tournament", {}, cycles=50, workers=1, progress=False)
    crashed, exited = (next(r for r in summary.records if r.key == spec.key) for spec in specs)
    assert crashed.forfeit == 1 and "WorkerDied" in crashed.error and "exit code 3" in crashed.error
    assert SCRIPTED + "CrashingTeam" in crashed.error
    assert exited.forfeit == 0 and "sys.exit(1)" in exited.error
    assert summary.unplayed == 0
    again = run_matches(specs, tmp_path / "r.sqlite", "tournament", {}, cycles=50, workers=1, progress=False)
    assert (again.already_stored, again.played) == (2, 0)  # a forfeit is a result: not played again


def test_a_worker_crash_outside_team_code_is_nobodys_fault_and_is_played_again(tmp_path) -> None:
    specs = [MatchSpec("chaser", "idle", 0, 30)]
    path = tmp_path / "r.sqlite"
    broken = run_matches(specs, path, "tournament", {}, cycles=30, workers=1, progress=False,
                         figures=CrashingFigures)
    (record,) = broken.records
    assert record.forfeit == FORFEIT_NONE and "exit code 1" in record.error and broken.unplayed == 1
    assert "no team at fault" in broken.line()
    healed = run_matches(specs, path, "tournament", {}, cycles=30, workers=1, progress=False)
    assert (healed.played, healed.unplayed) == (1, 0) and healed.records[0].played


def test_the_failure_policy_stops_a_mostly_failing_run_and_keeps_what_finished(tmp_path, capsys, backend) -> None:
    assert (FAILURE_SHARE, FAILURE_MIN_MATCHES) == (0.2, 20)  # the documented defaults
    out = tmp_path / "t.sqlite"
    backend(lambda k: k % 3 == 2)                               # a third of the matches are lost
    assert main([*TOURNAMENT, "--games", "40", "--out", str(out)]) == 1
    lines = error_lines(capsys)
    assert len(lines) == 1 and lines[0].startswith("error: run stopped: 6 of the 20 matches finished so far"), lines
    assert "NodeDied" in lines[0] and str(out) in lines[0] and "run the same command again to resume" in lines[0]
    with ResultStore.open(out) as store:
        assert len(store.keys()) == 20                           # every finished match stays stored
    backend(lambda k: False)
    assert main([*TOURNAMENT, "--games", "40", "--out", str(out)]) == 0
    assert "40 matches in" in capsys.readouterr().out


def test_the_policy_waits_for_enough_matches_and_a_share_above_its_limit(tmp_path, backend) -> None:
    specs = [MatchSpec("chaser", "idle", seed, CYCLES) for seed in range(30)]
    backend(lambda k: k % 5 == 4)                               # exactly 20 %: not more than the limit
    summary = run_matches(specs, tmp_path / "a.sqlite", "tournament", {}, cycles=CYCLES, progress=False)
    assert (summary.played, summary.unplayed) == (30, 6)
    backend(lambda k: k < 19)                                   # 19 of 19 lost: too few to judge yet ...
    with pytest.raises(RunStopped, match="19 of the 20 matches"):  # ... the 20th decides
        run_matches(specs, tmp_path / "b.sqlite", "tournament", {}, cycles=CYCLES, progress=False)
    backend(lambda k: k in (0, 1))
    with pytest.raises(RunStopped, match="2 of the 2 matches"):  # a stricter policy, given as an option
        run_matches(specs, tmp_path / "c.sqlite", "tournament", {}, cycles=CYCLES, progress=False,
                    policy=FailurePolicy(max_share=0.5, min_matches=2))


def test_the_rate_counts_only_matches_played_to_their_end(tmp_path, backend) -> None:
    specs = [MatchSpec("chaser", "idle", seed, CYCLES) for seed in range(4)]
    backend(lambda k: True)
    lost = run_matches(specs, tmp_path / "a.sqlite", "tournament", {}, cycles=CYCLES, progress=False)
    assert lost.completed == 0 and "(0 matches/hour)" in lost.line()
    backend(lambda k: k % 2 == 0)
    half = run_matches(specs, tmp_path / "b.sqlite", "tournament", {}, cycles=CYCLES, progress=False)
    assert (half.played, half.completed) == (4, 2)
    rate = float(re.search(r"\(([\d,]+) matches/hour\)", half.line()).group(1).replace(",", ""))
    assert rate == pytest.approx(2 / half.seconds * 3600, rel=0.01)
