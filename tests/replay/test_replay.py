"""Replays: what a recording holds, read back with rerun's own reader, and the commands."""

from __future__ import annotations

import numpy as np
import pytest

from experiments.cli import main
from soccer_sim import MatchConfig, run_match
from soccer_sim.replay import ReplayError, RerunRecorder, read_replay
from soccer_sim.state import EventKind


class Trajectory:
    """The simulator's own record of every cycle, to compare a replay with."""

    def on_start(self, match) -> None:
        self.cycles, self.pos, self.ball, self.score = [], [], [], []
        self.on_cycle(match)

    def on_cycle(self, match) -> None:
        state = match.state
        self.cycles.append(state.cycle)
        self.pos.append(state.pos.copy())
        self.ball.append(state.ball.copy())
        self.score.append(state.score.copy())

    def on_end(self, match) -> None:
        pass


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    """A 700-cycle match between built-in teams, recorded in blocks of 250 cycles."""
    path = tmp_path_factory.mktemp("replay") / "match.rrd"
    trajectory = Trajectory()
    result = run_match("mmdr", "chaser", seed=4, config=MatchConfig(max_cycles=700),
                       recorders=[trajectory, RerunRecorder(path, flush_every=250)])
    return path, trajectory, result, read_replay(path)


def test_positions_are_the_simulators_at_every_cycle(recorded) -> None:
    _, trajectory, _, replay = recorded
    assert replay.cycles.tolist() == trajectory.cycles
    pos = np.asarray(trajectory.pos, dtype=np.float32)
    for k in (0, 1, 249, 250, 251, 499, 500, len(pos) - 1):
        np.testing.assert_array_equal(replay.players["home"][k], pos[k, :11])
        np.testing.assert_array_equal(replay.players["away"][k], pos[k, 11:])
        np.testing.assert_array_equal(replay.ball[k], np.asarray(trajectory.ball[k], dtype=np.float32))
    np.testing.assert_array_equal(replay.score, np.asarray(trajectory.score, dtype=float))


def test_field_is_static_and_blueprint_stored(recorded) -> None:
    replay = recorded[3]
    assert {"/world/field/lines", "/world/field/goals"} <= replay.static_paths
    assert replay.has_blueprint


def test_events_and_role_drawings_are_present(recorded) -> None:
    _, _, result, replay = recorded
    kinds = result.events.as_arrays()["kind"]
    assert len(replay.events) == len(kinds) > 0
    kicks = sum(text.startswith(("kick mmdr #", "kick chaser #")) for _, text in replay.events)
    assert kicks == int(np.sum(kinds == EventKind.KICK))
    assert sum(text.startswith("kick off") for _, text in replay.events) >= 1
    # The built-in team draws its role targets every cycle; the chaser draws nothing.
    assert len(replay.targets["home"]) == len(replay.cycles) and "away" not in replay.targets
    assert all(len(lines) == 10 for lines in replay.lines["home"][1:])
    assert {"/world/home/roles/triangulation", "/world/ball/trail", "/stats/possession/home", "/stats/stamina/away",
            "/events"} <= replay.temporal_paths


def test_recorder_needs_a_destination_and_reader_refuses_other_files(tmp_path) -> None:
    with pytest.raises(ValueError, match="needs a path"):
        RerunRecorder()
    with pytest.raises(ReplayError, match="no such replay file"):
        read_replay(tmp_path / "missing.rrd")
    junk = tmp_path / "junk.rrd"
    junk.write_bytes(b"not a recording")
    with pytest.raises(ReplayError, match="junk.rrd"):
        read_replay(junk)


def test_play_record_then_replay_png(tmp_path, capsys) -> None:
    path = tmp_path / "m.rrd"
    assert main(["play", "static", "chaser", "--seed", "1", "--cycles", "200", "--record", str(path)]) == 0
    assert "replay written to" in capsys.readouterr().out
    png = tmp_path / "m.png"
    assert main(["replay", str(path), "--png", str(png), "--cycle", "150"]) == 0
    assert png.stat().st_size > 10_000
    assert main(["replay", str(path), "--png", str(png), "--cycle", "5000"]) == 2
    assert "cycle 5000 is not in the replay" in capsys.readouterr().err
    assert main(["replay", str(path), "--png", str(tmp_path / "no" / "m.png")]) == 2
    assert "--png" in capsys.readouterr().err
    assert main(["replay", str(path), "--png", str(tmp_path / "m.txt")]) == 2
    assert "not supported" in capsys.readouterr().err


def test_play_record_refuses_bad_paths(tmp_path, capsys) -> None:
    assert main(["play", "chaser", "idle", "--cycles", "5", "--record", str(tmp_path / "x.txt")]) == 2
    assert main(["play", "chaser", "idle", "--cycles", "5", "--record", str(tmp_path / "no" / "x.rrd")]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert len(lines) == 2  # one line per refused command, on stderr
    assert "must end in .rrd" in lines[0] and "does not exist" in lines[1]


def test_a_stored_match_is_recreated_by_its_row(tmp_path, capsys) -> None:
    results = tmp_path / "r.sqlite"
    assert main(["tournament", "--teams", "chaser,idle", "--games", "2", "--cycles", "300", "--workers", "1",
                 "--out", str(results), "--tables", str(tmp_path / "t"), "--no-progress"]) == 0
    capsys.readouterr()
    out = tmp_path / "again.rrd"
    assert main(["replay", "--results", str(results), "--row", "1", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "replay written to" in printed and "note:" not in printed  # same score as stored
    assert read_replay(out).cycles[-1] == 300
    assert main(["replay", "--results", str(results), "--row", "9", "--out", str(out)]) == 2
    assert "holds rows 0 to 1" in capsys.readouterr().err
    assert main(["replay", "--results", str(results), "--row", "1", "--out", str(tmp_path / "no" / "x.rrd")]) == 2
    err = capsys.readouterr().err
    assert "--out" in err and "does not exist" in err
    assert main(["replay", "--results", str(results), "--row", "1", "--out", str(tmp_path / "x.txt")]) == 2
    assert "must end in .rrd" in capsys.readouterr().err


@pytest.mark.slow  # test_rcg_cli keeps the runner recording every k-th match in the default suite
def test_the_runner_records_every_kth_match(tmp_path, capsys) -> None:
    replays = tmp_path / "replays"
    base = ["tournament", "--teams", "chaser,idle", "--games", "4", "--cycles", "120", "--workers", "2",
            "--tables", str(tmp_path / "t"), "--no-progress"]
    assert main([*base, "--out", str(tmp_path / "a.sqlite"), "--record-dir", str(replays),
                 "--record-every", "3"]) == 0
    files = sorted(p.name for p in replays.iterdir())
    assert len(files) == 2  # matches 0 and 3 of the 4 played
    assert all(name.endswith(".rrd") and "-v-" in name and "seed" in name for name in files)
    assert read_replay(replays / files[0]).cycles[-1] == 120
    assert main([*base, "--out", str(tmp_path / "b.sqlite")]) == 0  # recording changes no result
    capsys.readouterr()
    from experiments.results.store import ResultStore

    with ResultStore.open(tmp_path / "a.sqlite") as a, ResultStore.open(tmp_path / "b.sqlite") as b:
        assert [(r.home, r.seed, r.home_goals, r.away_goals) for r in a.records()] == \
               [(r.home, r.seed, r.home_goals, r.away_goals) for r in b.records()]
    assert main([*base, "--out", str(tmp_path / "c.sqlite"), "--record-dir", str(tmp_path / "a.sqlite")]) == 2


def test_recording_into_a_callers_stream(tmp_path) -> None:
    """What a live viewer gets (spawn=True streams the same data): a caller's stream, here saved."""
    import rerun as rr

    stream = rr.RecordingStream("soccer-sim-test")
    stream.save(tmp_path / "stream.rrd")
    run_match("chaser", "idle", seed=1, config=MatchConfig(max_cycles=60), recorders=[RerunRecorder(recording=stream)])
    stream.flush()
    stream.disconnect()
    replay = read_replay(tmp_path / "stream.rrd")
    assert replay.cycles.tolist() == list(range(61)) and replay.players["home"].shape == (61, 11, 2)


class LastTouches:
    """Every cycle's last toucher and play mode (the match's start state left out)."""

    def on_start(self, match) -> None:
        self.n = match.state.sizes[0]
        self.touchers, self.modes = [], []

    def on_cycle(self, match) -> None:
        self.touchers.append(int(match.state.last_touch))
        self.modes.append(int(match.state.play_mode))

    def on_end(self, match) -> None:
        pass


def test_the_replays_possession_is_the_statistics_possession_at_every_cycle(tmp_path) -> None:
    from soccer_sim.state import PlayMode

    touches = LastTouches()
    result = run_match("chaser", "chaser", seed=5, config=MatchConfig(max_cycles=400),
                       recorders=[touches, RerunRecorder(tmp_path / "p.rrd", flush_every=150, drawings=False)])
    replay = read_replay(tmp_path / "p.rrd")
    touchers = np.asarray(touches.touchers)
    home = np.cumsum((touchers >= 0) & (touchers < touches.n))
    away = np.cumsum(touchers >= touches.n)
    expected = np.where(home + away > 0, home / np.maximum(home + away, 1), 0.0)
    assert replay.possession.shape == (401,) and replay.possession[0] == 0.0  # the start: nobody had the ball
    np.testing.assert_array_equal(replay.possession[1:], expected)
    assert replay.possession[-1] == result.statistics[0].possession
    # counted in every play mode, not only in play on (the match had restarts with a last toucher)
    assert any(t >= 0 and m != PlayMode.PLAY_ON for t, m in zip(touches.touchers, touches.modes))


def test_the_replay_logs_events_with_the_shared_event_text() -> None:
    import soccer_sim.replay
    import soccer_sim.replay.recorder
    from soccer_sim.analysis.events import describe_event

    assert soccer_sim.replay.describe_event is describe_event  # still importable from the replay package
    assert soccer_sim.replay.recorder.describe_event is describe_event


def test_the_environments_human_mode_streams_through_the_recorder(tmp_path, monkeypatch) -> None:
    """render_mode="human" spawns a viewer; here the spawned stream is saved to a file instead."""
    import rerun as rr

    from soccer_sim.env import parallel_env

    saved = tmp_path / "human.rrd"

    def spawn(self, *args, default_blueprint=None, **kwargs):
        self.save(saved, default_blueprint=default_blueprint)

    monkeypatch.setenv("DISPLAY", ":0")
    monkeypatch.setattr(rr.RecordingStream, "spawn", spawn)
    environment = parallel_env(render_mode="human", max_cycles=25)
    environment.reset(seed=0)
    (recorder,) = [r for r in environment._match.recorders if isinstance(r, RerunRecorder)]
    while environment.agents:
        environment.step({a: environment.action_space(a).sample() for a in environment.agents})
    recorder.recording.flush()
    recorder.recording.disconnect()  # a viewer's stream stays open; the file is finished here
    replay = read_replay(saved)
    assert replay.cycles.tolist() == list(range(26)) and replay.players["home"].shape == (26, 11, 2)
    assert replay.has_blueprint and {"/world/field/lines"} <= replay.static_paths
