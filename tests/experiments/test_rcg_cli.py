"""``play --rcg`` and the runners' ``--rcg-dir``: rcssserver game logs written whole or not at
all, their destination checked before the first match."""

from __future__ import annotations

import json

import pytest

from experiments.cli import main
from experiments.recording import rcg_recording
from soccer_sim import run_match
from soccer_sim.config import MatchConfig
from soccer_sim.rcg import RcgError, read_rcg


def test_play_writes_the_match_as_a_game_log(tmp_path, capsys) -> None:
    path = tmp_path / "m.rcg"
    assert main(["play", "chaser", "idle", "--seed", "1", "--cycles", "200", "--json", "--rcg", str(path)]) == 0
    report = json.loads(capsys.readouterr().out)
    log = read_rcg(path)
    assert log.shows[-1].cycle == 200 and log.play_modes[-1] == (200, "time_over")
    assert log.teams[-1] == (200, "chaser", "idle", report["score"]["home"], report["score"]["away"])
    kicks = [sum(p.counts[0] for p in log.shows[-1].players if p.side == side) for side in "lr"]
    assert kicks == [report["statistics"][team]["kicks"] for team in ("home", "away")]
    assert [p.name for p in tmp_path.iterdir()] == ["m.rcg"]          # no temporary file left


def test_play_refuses_a_bad_destination_before_the_match(tmp_path, capsys) -> None:
    assert main(["play", "chaser", "idle", "--cycles", "5", "--rcg", str(tmp_path / "x.rrd")]) == 2
    assert main(["play", "chaser", "idle", "--cycles", "5", "--rcg", str(tmp_path / "no" / "x.rcg")]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert len(lines) == 2                                     # one line per refused command
    assert "--rcg" in lines[0] and "x.rrd" in lines[0] and "must end in .rcg" in lines[0]
    assert "--rcg" in lines[1] and "does not exist" in lines[1]
    assert list(tmp_path.iterdir()) == []


def test_a_failed_match_leaves_an_earlier_log_as_it_was(tmp_path, capsys) -> None:
    path = tmp_path / "m.rcg"
    path.write_text("earlier")
    team = "tests.experiments.scripted_teams:RaisingTeam"
    assert main(["play", team, "idle", "--cycles", "30", "--rcg", str(path)]) == 1
    assert "error:" in capsys.readouterr().err
    assert path.read_text() == "earlier" and [p.name for p in tmp_path.iterdir()] == ["m.rcg"]


def test_the_recording_block_is_atomic(tmp_path) -> None:
    path = tmp_path / "m.rcg"
    with pytest.raises(KeyboardInterrupt):
        with rcg_recording(str(path), "--rcg") as recorders:
            recorders[0].on_start(_started())
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []
    with rcg_recording(str(path), "--rcg") as recorders:
        run_match("idle", "idle", config=MatchConfig(max_cycles=10), recorders=recorders)
        assert not path.exists()                               # written beside, renamed at the end
    assert read_rcg(path).shows[-1].cycle == 10
    with pytest.raises(RcgError, match="--rcg .*must end in .rcg"):
        with rcg_recording(str(tmp_path / "m.txt"), "--rcg"):
            pass
    with rcg_recording(None, "--rcg") as recorders:
        assert recorders == []


def _started():
    from soccer_sim import Match

    match = Match("idle", "idle", config=MatchConfig(max_cycles=5))
    match.start()
    return match


def test_the_runner_logs_every_kth_match(tmp_path, capsys) -> None:
    logs = tmp_path / "logs"
    base = ["tournament", "--teams", "chaser,idle", "--games", "4", "--cycles", "60", "--workers", "1",
            "--tables", str(tmp_path / "t"), "--no-progress"]
    assert main([*base, "--out", str(tmp_path / "a.sqlite"), "--rcg-dir", str(logs), "--record-every", "3"]) == 0
    files = sorted(p.name for p in logs.iterdir())
    assert len(files) == 2 and all(name.endswith(".rcg") and "-v-" in name and "seed" in name for name in files)
    assert read_rcg(logs / files[0]).shows[-1].cycle == 60
    capsys.readouterr()
    assert main([*base, "--out", str(tmp_path / "b.sqlite"), "--rcg-dir", str(tmp_path / "a.sqlite")]) == 2
    err = capsys.readouterr().err
    assert "--rcg-dir" in err and "a.sqlite" in err and len(err.splitlines()) == 1
    assert not (tmp_path / "b.sqlite").exists()                # refused before the first match


def test_the_game_logs_kernel_is_warmed_with_the_simulators_own(tmp_path) -> None:
    from experiments.warmup import kernels_for
    from soccer_sim.rcg import RcgRecorder
    from soccer_sim.rcg.bodies import facings

    engine = [k for k in kernels_for(["examples.my_team:MyTeam"]) if (k.module, k.function) ==
              ("soccer_sim.rcg.bodies", "facings")]
    assert len(engine) == 1                          # warmed for every match, whichever teams play
    run_match("idle", "idle", config=MatchConfig(max_cycles=3), recorders=[RcgRecorder(tmp_path / "m.rcg")])
    # the argument types the recorder calls it with
    assert engine[0].signature in [repr(tuple(signature)) for signature in facings.signatures]


def test_replay_of_a_game_log_says_which_tools_open_it(tmp_path, capsys) -> None:
    from experiments.cli import main

    log = tmp_path / "m.rcg"
    log.write_text("ULG6\n")
    before = log.read_bytes()
    assert main(["replay", str(log)]) == 2
    err = capsys.readouterr().err
    assert "rcssserver game log" in err and "rcssmonitor" in err and len(err.strip().splitlines()) == 1
    assert log.read_bytes() == before
