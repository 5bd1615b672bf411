"""The runner keeps going when teams fail: an erroring, a hanging, a deaf-hanging and a
crashing team are recorded as forfeits of the team at fault and the other matches are played."""

from __future__ import annotations

from experiments.runner import MatchSpec, run_matches
from experiments.stats import league_table
from tests.experiments.helpers import SCRIPTED


def test_failing_teams_are_recorded_and_the_run_completes(tmp_path, monkeypatch) -> None:
    import experiments.runner.local as local

    monkeypatch.setattr(local, "KILL_GRACE", 0.5)
    specs = [MatchSpec(SCRIPTED + "RaisingTeam", "chaser", 0, 100),
             MatchSpec("chaser", SCRIPTED + "NaNTeam", 0, 100),
             MatchSpec("idle", SCRIPTED + "HangingTeam", 0, 100),
             MatchSpec(SCRIPTED + "DeafHangingTeam", "idle", 0, 100),
             MatchSpec(SCRIPTED + "CrashingTeam", "idle", 0, 100),
             MatchSpec("chaser", "idle", 0, 100),
             MatchSpec("chaser", "idle", 1, 100)]
    summary = run_matches(specs, tmp_path / "r.sqlite", "tournament", {}, cycles=100, workers=2,
                          match_timeout=4.0, progress=False)  # generous: a loaded machine
    by_home = {(r.home, r.away, r.seed): r for r in summary.records}
    assert len(summary.records) == 7 and summary.errors == 5

    raised = by_home[(SCRIPTED + "RaisingTeam", "chaser", 0)]
    assert raised.forfeit == 0 and "scripted failure" in raised.error and "RuntimeError" in raised.traceback
    assert raised.home_goals is None

    nan = by_home[("chaser", SCRIPTED + "NaNTeam", 0)]
    assert nan.forfeit == 1 and "player 3" in nan.error and "TeamError" in nan.error

    hung = by_home[("idle", SCRIPTED + "HangingTeam", 0)]
    assert hung.forfeit == 1 and "MatchTimeout" in hung.error and "time.sleep" in hung.traceback

    deaf = by_home[(SCRIPTED + "DeafHangingTeam", "idle", 0)]
    assert deaf.forfeit == 0 and "killed" in deaf.error and "DeafHangingTeam" in deaf.error

    crashed = by_home[(SCRIPTED + "CrashingTeam", "idle", 0)]
    assert crashed.forfeit == 0 and "exit code 3" in crashed.error

    for seed in (0, 1):
        played = by_home[("chaser", "idle", seed)]
        assert played.played and played.cycles == 100 and "teammate_contacts" in played.home_stats

    # A forfeit is a loss for the team at fault and a win for the other, without goals.
    table = {row.team: row for row in league_table(summary.records, ["chaser", SCRIPTED + "RaisingTeam"])}
    raising = table[SCRIPTED + "RaisingTeam"]
    assert (raising.losses, raising.forfeits, raising.goal_difference.n) == (1, 1, 0)
    assert table["chaser"].wins >= 2


def test_rerun_keeps_forfeits_a_crash_inside_act_included(tmp_path) -> None:
    specs = [MatchSpec(SCRIPTED + "RaisingTeam", "idle", 0, 50), MatchSpec(SCRIPTED + "CrashingTeam", "idle", 0, 50)]
    path = tmp_path / "r.sqlite"
    first = run_matches(specs, path, "tournament", {}, cycles=50, workers=1, progress=False)
    assert first.played == 2
    again = run_matches(specs, path, "tournament", {}, cycles=50, workers=1, progress=False)
    assert (again.already_stored, again.played) == (2, 0)          # the crash was the team's: kept
    retried = run_matches(specs, path, "tournament", {}, cycles=50, workers=1, progress=False, retry_errors=True)
    assert (retried.already_stored, retried.played) == (0, 2)
    assert len(retried.records) == 2
