"""``bench soccer``'s figures: the per-cycle definitions, the game-log side, the pairings."""

from __future__ import annotations

import json

import numpy as np
import pytest

from experiments.benchmarks.soccer_cycles import CycleFigures, log_frame
from experiments.cli import main


def _cycle_figures() -> CycleFigures:
    # rows 0-2 home (0 the goalkeeper), rows 3-5 away (3 the goalkeeper)
    return CycleFigures(np.array([0, 0, 0, 1, 1, 1]), relocation=3.0, recovery_threshold=2400.0)


OUTFIELD = np.array([False, True, True, False, True, True])


def test_team_extent_counts_outfield_players_in_play_on_cycles_only() -> None:
    figures = _cycle_figures()
    pos = np.array([[-50.0, 0.0], [-20.0, -10.0], [10.0, 20.0], [50.0, 0.0], [5.0, 0.0], [25.0, 4.0]])
    figures.start(pos)
    stamina = np.full(6, 8000.0)
    figures.add(pos, np.array([0.0, 0.0]), stamina, OUTFIELD, play_on=True)          # ball in midfield
    figures.add(pos, np.array([40.0, 0.0]), stamina, OUTFIELD, play_on=True)         # ball in the final third
    figures.add(pos * 2.0, np.array([0.0, 0.0]), stamina, OUTFIELD, play_on=False)   # a stoppage: not counted
    out = figures.figures()
    # home: 30 x 30, away 20 x 4 (the goalkeepers left out)
    assert out["team length (m)"] == pytest.approx(25.0)
    assert out["team width (m)"] == pytest.approx(17.0)
    assert out["team length, ball in midfield (m)"] == pytest.approx(25.0)
    figures.add(pos + [[0, 0], [0, 0], [10.0, 0], [0, 0], [0, 0], [0, 0]], np.array([40.0, 0.0]), stamina,
                OUTFIELD, play_on=True)
    assert figures.figures()["team length (m)"] == pytest.approx((25.0 * 2 + 30.0) / 3)
    assert figures.figures()["team length, ball in midfield (m)"] == pytest.approx(25.0)


def test_distance_leaves_out_relocations_and_splits_by_role_label() -> None:
    figures = _cycle_figures()
    pos = np.zeros((6, 2))
    figures.start(pos)
    labels = ["goalkeeper", "defender", "forward", "goalkeeper", "defender", None]
    step = pos.copy()
    step[1] = (1.0, 0.0)   # runs 1 m
    step[4] = (0.0, 2.0)   # runs 2 m
    step[5] = (10.0, 0.0)  # placed 10 m away: not running
    figures.add(step, np.zeros(2), np.full(6, 8000.0), OUTFIELD, play_on=False, labels=labels)
    figures.add(step, np.zeros(2), np.full(6, 8000.0), OUTFIELD, play_on=False, labels=labels)
    assert figures.distance.tolist() == [1.0, 2.0]
    roles = figures.role_distances()
    # defenders: 3 m in 4 player-cycles of a 2-cycle match -> 1.5 m per player
    assert roles["defender"] == pytest.approx(1.5e-3)
    assert roles["forward"] == 0.0 and "None" not in roles and None not in roles


def test_places_by_role_label_face_each_teams_attack_in_play_on_cycles() -> None:
    figures = _cycle_figures()
    labels = ["goalkeeper", "centre-back", "winger", "goalkeeper", "centre-back", "winger"]
    # the home team attacks +x, the away team -x (the log frame)
    pos = np.array([[-50.0, 0.0], [-30.0, 5.0], [20.0, -25.0], [50.0, 0.0], [34.0, -3.0], [-10.0, 29.0]])
    figures.start(pos)
    stamina = np.full(6, 8000.0)
    figures.add(pos, np.zeros(2), stamina, OUTFIELD, play_on=True, labels=labels)
    figures.add(pos * 0.0, np.zeros(2), stamina, OUTFIELD, play_on=False, labels=labels)  # a stoppage
    places = figures.role_places()
    assert places["centre-back"] == pytest.approx((-32.0, 4.0))
    assert places["winger"] == pytest.approx((15.0, 27.0))
    assert places["goalkeeper"] == pytest.approx((-50.0, 0.0))
    grouped = figures.role_places({"centre-back": "defender", "winger": "forward"})
    assert set(grouped) == {"defender", "forward"} and grouped["defender"] == pytest.approx((-32.0, 4.0))


def test_stamina_shares_are_of_outfield_player_cycles() -> None:
    figures = _cycle_figures()
    pos = np.zeros((6, 2))
    figures.start(pos)
    stamina = np.array([50.0, 50.0, 2000.0, 50.0, 3000.0, 8000.0])  # goalkeepers' stamina is not counted
    figures.add(pos, np.zeros(2), stamina, OUTFIELD, play_on=True)
    out = figures.figures()
    assert out["outfield stamina below 100 (%)"] == pytest.approx(25.0)
    assert out["outfield stamina below recovery threshold (%)"] == pytest.approx(50.0)


def test_log_frame_turns_the_second_half() -> None:
    assert log_frame(np.array([3.0, 4.0]), 1).tolist() == [3.0, -4.0]
    assert log_frame(np.array([3.0, 4.0]), -1).tolist() == [-3.0, 4.0]


def test_a_game_log_gives_the_same_figures_as_the_match_it_records(tmp_path) -> None:
    from experiments.benchmarks.soccer_match import match_figures
    from experiments.benchmarks.soccer_rcg import NOT_IN_A_LOG, rcg_figures
    from soccer_sim.rcg import RcgRecorder, read_rcg

    path = tmp_path / "match.rcg"
    live = match_figures("mmdr", "counter-442", 11, 3000, recorders=(RcgRecorder(path),))  # (a half with goal kicks and fouls)
    logged = rcg_figures(read_rcg(path))
    assert live["kicks"] > 50 and live["kick-ins"] > 0 and live["goalkeeper catches"] > 0 and live["goal kicks"] > 0
    assert live["passes (kick to kick)"] > 10
    compared = [name for name in live if logged.get(name) is not None]
    assert len(compared) >= 20
    for name in compared:
        # positions are logged to 0.1 mm
        assert logged[name] == pytest.approx(live[name], rel=1e-6, abs=1e-4), name
    for name in NOT_IN_A_LOG:
        assert logged[name] is None
    assert not any(name.startswith("distance run by") for name in logged)  # a log names no roles


def test_set_plays_from_play_mode_changes() -> None:
    from experiments.benchmarks.soccer_match import COUNTED
    from experiments.benchmarks.soccer_rcg import _count_modes

    counts = dict.fromkeys(COUNTED, 0.0)
    modes = [(10, "play_on"), (20, "free_kick_l"), (25, "play_on"), (40, "foul_charge_r"), (40, "free_kick_l"),
             (45, "play_on"), (50, "offside_l"), (50, "free_kick_r"), (55, "play_on"), (60, "kick_in_r"),
             (60, "kick_in_r"), (70, "indirect_free_kick_r"), (80, "drop_ball"), (81, "corner_kick_l")]
    _count_modes(modes, {("l", 19)}, counts)   # the free kick at 20 follows the catch at 19
    assert counts["free kicks"] == 3 and counts["fouls"] == 1 and counts["offside calls"] == 1
    assert counts["kick-ins"] == 1 and counts["dropped balls"] == 1 and counts["corners"] == 1


def test_helios_labels_map_role_names(tmp_path) -> None:
    from experiments.benchmarks.helios_roles import helios_labels

    names = ["Goalie", "CenterBack", "CenterBack", "SideBack", "SideBack", "DefensiveHalf", "OffensiveHalf",
             "OffensiveHalf", "SideForward", "SideForward", "CenterForward"]
    path = tmp_path / "normal-formation.conf"
    path.write_text(json.dumps({"role": [{"number": i + 1, "name": n} for i, n in enumerate(names)]}))
    labels = helios_labels(path)
    assert labels[0] == "goalkeeper" and labels[1] == "centre-back" and labels[3] == "full-back"
    assert labels[5] == "holding-midfielder" and labels[8] == "winger" and labels[10] == "centre-forward"
    path.write_text(json.dumps({"role": [{"number": 1, "name": "Goalie"}]}))
    with pytest.raises(ValueError, match="1..11"):
        helios_labels(path)


def test_default_pairings_play_both_sides_on_the_same_seeds() -> None:
    from experiments.benchmarks.soccer import matches_to_play
    from experiments.benchmarks.soccer_pairings import PAIRINGS
    from agents.teams.builtin import ASSIGNER_VARIANTS as ASSIGNERS

    tasks = matches_to_play(None, None, 3, seed=10)
    assert len(tasks) == 48 and len(PAIRINGS) == 8
    assert ("mmdr", "counter-442", 12) in tasks and ("counter-442", "mmdr", 12) in tasks
    teams = {team for pairing in PAIRINGS for team in pairing}
    assert set(ASSIGNERS) <= teams and {"counter-442", "press-433", "possession"} <= teams
    assert matches_to_play("a", "b", 2) == [("a", "b", 0), ("a", "b", 1)]
    with pytest.raises(ValueError, match="both"):
        matches_to_play("a", None, 2)


def test_bench_soccer_reads_game_logs_and_shows_what_they_lack(tmp_path, capsys) -> None:
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.rcg import RcgRecorder

    path = tmp_path / "short.rcg"
    run_match("chaser", "chaser", seed=1, config=MatchConfig(max_cycles=200), recorders=[RcgRecorder(path)])
    assert main(["bench", "soccer", "--rcg", str(path), "--json"]) == 0
    rows = {row[0]: row for row in json.loads(capsys.readouterr().out)["tables"][0]["rows"]}
    assert rows["passes"][1] in ("-", None) and rows["kicks"][1] not in ("-", None)
    assert main(["bench", "soccer", "--rcg", str(tmp_path / "missing.rcg")]) == 2
    assert "missing.rcg" in capsys.readouterr().err


def test_role_distances_by_group_pool_the_labels_of_a_group() -> None:
    figures = _cycle_figures()
    figures.start(np.zeros((6, 2)))
    step = np.zeros((6, 2))
    step[1] = (1.0, 0.0)   # the centre-back runs 1 m, the full-back 3 m
    step[2] = (3.0, 0.0)
    labels = ["goalkeeper", "centre-back", "full-back", "goalkeeper", "centre-back", "full-back"]
    figures.add(step, np.zeros(2), np.full(6, 8000.0), OUTFIELD, play_on=False, labels=labels)
    kinds = figures.role_distances({"centre-back": "defender", "full-back": "defender"})
    assert kinds == {"defender": pytest.approx(1e-3)}   # 4 m over 4 player-cycles of one cycle
    assert figures.role_distances()["full-back"] == pytest.approx(1.5e-3)


def test_compare_sets_the_stored_real_server_figures_beside_ours(tmp_path, capsys) -> None:
    from experiments.benchmarks.soccer import REAL_SERVER_FIGURES, real_server_rows
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.rcg import RcgRecorder

    stored = real_server_rows()
    assert len(stored) >= 6 and all(match["goals"] is not None and match["passes"] is None for match in stored)
    path = tmp_path / "short.rcg"
    run_match("chaser", "chaser", seed=1, config=MatchConfig(max_cycles=100), recorders=[RcgRecorder(path)])
    assert main(["bench", "soccer", "--rcg", str(path), "--compare", "--json"]) == 0
    table = json.loads(capsys.readouterr().out)["tables"][0]
    assert len(table["columns"]) == 5
    rows = {row[0]: row for row in table["rows"]}
    goals = np.mean([match["goals"] for match in stored])
    assert rows["goals"][3] == pytest.approx(goals, abs=0.006)
    assert "distance run by centre-back (km per player)" in rows  # helios-base's positions
    bad = tmp_path / "bad.json"
    bad.write_text("{}")
    with pytest.raises(ValueError, match="bad.json"):
        real_server_rows(bad)
    assert REAL_SERVER_FIGURES.name == "helios_matches.json"


def _plays():
    from experiments.benchmarks.soccer_plays import PlayFigures

    return PlayFigures(np.array([0, 0, 0, 1, 1, 1]), half_length=52.5, goal_width=14.02, ball_radius=0.085,
                       ball_decay=0.94)


NONE = np.array([], dtype=np.intp)
STILL = np.array([0.0, 0.0, 0.0, 0.0])


def test_passes_kick_to_kick_are_broken_by_opponents_catches_and_stoppages() -> None:
    plays = _plays()
    plays.add(np.array([1]), NONE, NONE, NONE, STILL, True)
    plays.add(NONE, NONE, NONE, np.array([2]), STILL, True)   # a team-mate's body: the pass goes on
    plays.add(np.array([2]), NONE, NONE, NONE, STILL, True)   # 1 -> 2
    plays.add(np.array([1]), NONE, NONE, NONE, STILL, True)   # 2 -> 1
    assert plays.passes == 2
    plays.add(NONE, NONE, NONE, np.array([4]), STILL, True)   # off an opponent: no pass
    plays.add(np.array([2]), NONE, NONE, NONE, STILL, True)
    plays.add(NONE, NONE, NONE, NONE, STILL, False)           # a stoppage: no pass
    plays.add(np.array([1]), NONE, NONE, NONE, STILL, True)
    plays.add(NONE, np.array([0]), NONE, NONE, STILL, True)   # 1 -> the keeper's catch is a pass ...
    plays.add(np.array([2]), NONE, NONE, NONE, STILL, True)   # ... but the catch ends the chain
    plays.add(np.array([3]), NONE, NONE, NONE, STILL, True)   # to an opponent: no pass
    plays.add(np.array([4, 5]), NONE, NONE, NONE, STILL, True)  # two players at once: no pass
    plays.add(np.array([4]), NONE, NONE, NONE, STILL, True)
    assert plays.passes == 3


def test_shots_follow_the_ball_path_to_the_goal_the_kicker_attacks() -> None:
    plays = _plays()
    toward_away_goal = np.array([40.0, 0.0, 2.0, 0.1])     # reaches x = 52.585 at y = 0.6
    plays.add(np.array([1]), NONE, NONE, NONE, toward_away_goal, True)
    assert plays.shots == 1
    plays.add(np.array([4]), NONE, NONE, NONE, toward_away_goal, True)  # away attacks -x: not a shot
    plays.add(np.array([1]), NONE, NONE, NONE, np.array([40.0, 0.0, 0.5, 0.0]), True)  # rolls 8.3 m: short
    plays.add(np.array([1]), NONE, NONE, NONE, np.array([40.0, 0.0, 2.0, 1.5]), True)  # wide of the post
    assert plays.shots == 1
    plays.add(np.array([4]), NONE, NONE, NONE, np.array([-40.0, 3.0, -2.0, 0.0]), True)
    assert plays.shots == 2


def test_workers_play_the_same_matches() -> None:
    from experiments.benchmarks.soccer import play_all

    tasks = [("chaser", "idle", 0), ("idle", "chaser", 1)]
    alone = play_all(tasks, 60, workers=1)   # (first: the forked workers inherit what it loaded)
    assert play_all(tasks, 60, workers=2) == alone
