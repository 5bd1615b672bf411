"""The penalty-shot study: markers, chained trials, the uncoordinated team, the tests and the
command on a tiny trial count."""

from __future__ import annotations

import csv

import numpy as np
import pytest

import soccer_sim
from experiments.cli import main
from experiments.studies import penalty_shot as ps
from soccer_sim import TeamCommand


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
    assert main(["experiment", "penalty-shot", "--trials", "2", "--workers", "1", "--limit", "150",
                 "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "Time to score" in printed and "Wilcoxon" in printed and "12 trials in" in printed
    with open(out / "penalty_shot_trials.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 2 * len(ps.CONDITIONS) * len(ps.SETTINGS)
    assert {(r["setting"], r["condition"]) for r in rows} == {(s, c) for s in ps.SETTINGS for c in ps.CONDITIONS}
    assert all(0 < float(r["seconds"]) <= 15.0 for r in rows)
    assert all((r["scored"] == "True") == (float(r["seconds"]) < 15.0) for r in rows)
    with open(out / "penalty_shot_tests.csv") as handle:
        assert len(list(csv.DictReader(handle))) == len(ps.PAIRS) * len(ps.SETTINGS)
    assert (out / "penalty_shot.png").stat().st_size > 1000


def test_bad_options_are_reported_without_a_traceback(tmp_path, capsys):
    assert main(["experiment", "penalty-shot", "--trials", "2", "--team", "no-such-team", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "--team" in err and "Traceback" not in err
    assert main(["experiment", "penalty-shot", "--trials", "1", "--robots", "12", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "--robots must be at most 11" in err and "Traceback" not in err
    (tmp_path / "a-file").write_text("")
    assert main(["experiment", "penalty-shot", "--trials", "1", "--out", str(tmp_path / "a-file")]) == 2
    err = capsys.readouterr().err
    assert "--out" in err and "Traceback" not in err
