"""``soccer-sim experiment ablation``: each switch turns off the limit it names (and nothing
else turns it off under ``baseline``), the study runs end to end on short matches, resumes
from its results file, and refuses bad switches and team options before any match."""

from __future__ import annotations

import csv
from dataclasses import replace

import numpy as np
import pytest

from experiments.cli import main
from experiments.configuration import match_config
from experiments.studies.ablation import BASELINE, SWITCHES, Switch
from soccer_sim import TeamNotFoundError, resolve_team
from soccer_sim.match import Match
from soccer_sim.perception.params import SeeParams
from soccer_sim.perception.see import see
from soccer_sim.trivial_teams import ChaserTeam, IdleTeam


def switched(name: str, cycles: int):
    """The partial-observation configuration of ``cycles`` with switch ``name`` applied."""
    return SWITCHES[name].configured(match_config(cycles, "partial"))


def views_over(match: Match, cycles: int):
    """For each cycle: (the true player positions and ball before the step, the home views after it)."""
    match.start()
    while match.state.cycle < cycles:
        pos, ball = match.state.pos.copy(), match.state.ball.copy()
        match.step()
        yield pos, ball, match.observer.views[0]


class Retreat(IdleTeam):
    """Every player dashes flat out towards its own goal line, away from the ball at the centre
    spot, so its body turns away from the ball."""

    def reset(self, side_info, config, rng) -> None:
        super().reset(side_info, config, rng)
        self._command.dash[:, 0] = -100.0


class Talker(ChaserTeam):
    """A chaser whose players all speak every cycle and which records how many team-mates each
    player heard per cycle."""

    def reset(self, side_info, config, rng) -> None:
        super().reset(side_info, config, rng)
        self.most_heard = 0

    def act(self, view):
        command = super().act(view)
        self.most_heard = max(self.most_heard, max(len(mates) for mates in view.heard_mates))
        command.say = [f"p{i}" for i in range(view.n)]
        return command


def ball_seen_behind(name: str) -> int:
    """Sees of the ball outside the view cone and beyond ``visible_distance`` by players running
    away from it, over 40 cycles under switch ``name``."""
    config = switched(name, 40)
    see_params = config.observation.see
    count = 0
    for _, _, views in views_over(Match(Retreat(), IdleTeam(), seed=2, config=config), 40):
        behind = (views.saw & views.ball_seen & (np.abs(np.nan_to_num(views.ball_direction)) >= see_params.visible_angle / 2)
                  & (np.nan_to_num(views.ball_distance) > see_params.visible_distance))
        count += int(np.count_nonzero(behind))
    return count


def test_omni_lets_a_player_see_the_ball_behind_it():
    assert ball_seen_behind(BASELINE) == 0
    assert ball_seen_behind("omni") > 0


def most_team_mates_heard(name: str) -> int:
    talker = Talker()
    Match(talker, ChaserTeam(), seed=3, config=switched(name, 30)).run()
    return talker.most_heard


def test_all_heard_lets_a_listener_hear_more_than_one_team_mate_a_cycle():
    assert most_team_mates_heard(BASELINE) == 1       # hear_max: one team-mate a cycle
    assert most_team_mates_heard("all-heard") > 1
    assert switched("all-heard", 30).observation.audio.audio_cut_dist == match_config(30, "partial").observation.audio.audio_cut_dist


def distance_errors(name: str) -> np.ndarray:
    """|reported - true| distance of every ball and player sighting of the home team over 30
    cycles under switch ``name``."""
    match = Match(ChaserTeam(), ChaserTeam(), seed=5, config=switched(name, 30))
    errors = []
    for pos, ball, views in views_over(match, 30):
        rows = match.observer.seen_rows[:11]
        for i in np.flatnonzero(views.ball_seen):
            errors.append(abs(views.ball_distance[i] - np.hypot(*(ball - pos[i]))))
        for i in range(11):
            for k in range(int(views.seen_count[i])):
                errors.append(abs(views.seen_distance[i, k] - np.hypot(*(pos[rows[i, k]] - pos[i]))))
    return np.array(errors)


def test_no_noise_reports_seen_distances_exactly():
    baseline, noiseless = distance_errors(BASELINE), distance_errors("no-noise")
    assert len(baseline) > 50 and len(noiseless) > 50
    assert baseline.max() > 0.01                     # quantised as rcssserver does
    assert noiseless.max() < 1e-9


def test_without_noise_keeps_every_identity_and_exact_directions():
    rng = np.random.default_rng(0)
    players = np.array([[55.0, 3.0], [70.0, -4.0], [5.0, 0.7]])
    noisy = see(np.zeros((1, 2)), [0.0], (30.0, 1.234), players, rng, SeeParams())
    exact = see(np.zeros((1, 2)), [0.0], (30.0, 1.234), players, np.random.default_rng(0),
                SeeParams().without_noise())
    assert noisy.identity[0, 2] != 2              # 70 m away: the number (or team) is lost
    assert (exact.identity[0, 1:] == 2).all()     # every player in the cone seen with team and number
    np.testing.assert_allclose(exact.distance[0, 0], np.hypot(30.0, 1.234), rtol=0, atol=1e-12)
    np.testing.assert_allclose(exact.direction[0, 0], np.degrees(np.arctan2(1.234, 30.0)), rtol=0, atol=1e-12)
    assert noisy.direction[0, 0] == 2.0          # whole degrees
    # the view's limits stay: the cone, the ranges, the see timing
    kept = ("visible_angle", "visible_distance", "max_observation_length", "omnidirectional", "exact_self",
            "send_step", "simulator_step")
    assert all(getattr(SeeParams().without_noise(), f) == getattr(SeeParams(), f) for f in kept)


def test_exact_self_gives_each_player_its_true_position():
    def largest_error(name: str) -> float:
        match = Match(ChaserTeam(), ChaserTeam(), seed=6, config=switched(name, 30))
        sign = None
        worst = 0.0
        for pos, _, views in views_over(match, 30):
            sign = match.state.attack_direction(0)
            worst = max(worst, float(np.abs(views.position * sign - pos[:11]).max()))
        return worst

    assert largest_error(BASELINE) > 0.01
    assert largest_error("exact-self") == 0.0


def test_every_switch_changes_only_what_it_names():
    base = match_config(100, "partial")
    assert SWITCHES[BASELINE].configured(base) == base
    changed = {name: SWITCHES[name].configured(base).observation for name in SWITCHES}
    assert changed["exact-self"] == replace(base.observation, see=replace(base.observation.see, exact_self=True))
    assert changed["omni"] == replace(base.observation, see=replace(base.observation.see, omnidirectional=True))
    assert changed["all-heard"] == replace(base.observation, audio=replace(base.observation.audio, hear_decay=0))
    assert changed["no-noise"] == replace(base.observation, see=base.observation.see.without_noise())
    for name in SWITCHES:
        assert SWITCHES[name].configured(base).physics == base.physics


def study(tmp_path, *extra: str) -> list[str]:
    return ["experiment", "ablation", "--teams", "chaser", "--opponents", "idle", "--games", "2", "--cycles", "40",
            "--out", str(tmp_path / "ab.sqlite"), "--tables", str(tmp_path / "tables"), "--no-progress",
            "--workers", "1", *extra]


def assert_baseline_is_the_partial_match(path) -> None:
    """The baseline's matches in ``path`` are the partial-observation matches themselves (the
    case study's with ``--observation partial``: same configuration hash, same play)."""
    from experiments.results.store import ResultStore
    from experiments.runner.spec import config_hash
    from soccer_sim import run_match

    config = match_config(40, "partial")
    with ResultStore.open(path) as store:
        assert store.config_hash == config_hash(config)
        records = [r for r in store.records() if BASELINE in r.home + r.away]
    assert len(records) == 2
    for record in records:
        home, away = ("chaser", "idle") if record.home == "chaser [baseline]" else ("idle", "chaser")
        result = run_match(home, away, seed=record.seed, config=config)
        assert record.goals() == tuple(int(g) for g in result.score) and record.cycles == result.cycles
        assert (record.home_stats, record.away_stats) == tuple(s.as_dict() for s in result.statistics)


def test_the_study_runs_resumes_and_reports_one_row_per_team_and_switch(tmp_path, capsys):
    switches = "baseline,omni,no-noise"
    assert main(study(tmp_path, "--switches", switches)) == 0
    first = capsys.readouterr().out
    assert "played 6 in" in first
    with open(tmp_path / "tables" / "ablation.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["team"], r["switch"]) for r in rows] == [("chaser", s) for s in switches.split(",")]
    assert all(r["games"] == "2" for r in rows)
    assert rows[0]["gd_minus_baseline"] == "nan" and rows[1]["gd_minus_baseline"] != "nan"
    assert "role conflicts (share)" in (tmp_path / "tables" / "ablation.md").read_text()
    assert_baseline_is_the_partial_match(tmp_path / "ab.sqlite")
    # the same command again plays nothing: every match is stored
    assert main(study(tmp_path, "--switches", switches)) == 0
    assert "(6 already stored): played 0 in" in capsys.readouterr().out
    # one more switch plays only its own matches
    assert main(study(tmp_path, "--switches", switches + ",all-heard")) == 0
    assert "(6 already stored): played 2 in" in capsys.readouterr().out
    assert main(["results", "show", str(tmp_path / "ab.sqlite")]) == 0
    shown = capsys.readouterr().out
    assert "8 of 8 matches stored" in shown and "all-heard" in shown


@pytest.mark.parametrize("switches, words", [("baseline,omnii", "unknown switch 'omnii'; known switches: baseline, "
                                                                 "exact-self, omni, all-heard, no-noise, agreement"),
                                             ("omni", "must include baseline"),
                                             ("baseline,omni,omni", "named twice")])
def test_bad_switches_fail_in_one_line_before_any_match(tmp_path, capsys, switches, words):
    assert main(study(tmp_path, "--switches", switches)) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "ab.sqlite").exists()


def keyword_team(careful: bool = False) -> ChaserTeam:
    """A factory taking a team option: a chaser that records it."""
    team = ChaserTeam()
    team.careful = careful
    return team


def test_team_options_reach_the_factory_or_are_refused_by_name():
    team, _ = resolve_team(f"{__name__}:keyword_team", {"careful": True})
    assert team.careful is True
    with pytest.raises(TeamNotFoundError, match=r"calling .* with shared_assignment=True failed"):
        resolve_team("chaser", {"shared_assignment": True})
    with pytest.raises(TeamNotFoundError, match="takes no options"):
        resolve_team(ChaserTeam(), {"careful": True})


def test_a_switch_whose_team_options_a_team_does_not_take_is_refused_before_any_match(tmp_path, capsys, monkeypatch):
    options = Switch("careful", "care", team_options=(("careful", True),))
    monkeypatch.setitem(SWITCHES, "careful", options)
    argv = study(tmp_path, "--switches", "baseline,careful")
    argv[argv.index("chaser")] = f"{__name__}:keyword_team"
    assert main(argv) == 2                              # idle, the opponent, takes no options
    err = capsys.readouterr().err
    assert "switch 'careful'" in err and "careful=True" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "ab.sqlite").exists()
