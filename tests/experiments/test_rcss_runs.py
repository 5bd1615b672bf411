"""``--engine rcssserver`` on ``tournament`` and ``experiment case-study``: matches played in
the server through the runner and stored in the results store (the tests' stand-in server and
teams, in a private network namespace), the engine in the configuration's hash, a resume with
the other engine refused in one line, helios-base refused under the simulator, and bad input
as one line before anything runs."""

from __future__ import annotations

import sqlite3
import subprocess
import sys

import pytest

from experiments.cli import main
from experiments.configuration import match_config
from experiments.rcss_engine import external_argv
from experiments.rcss_runs import in_seed_order, server_spec
from experiments.results.store import ResultStore
from experiments.runner.spec import MatchSpec, config_description, config_hash, paired_specs
from soccer_sim import run_match
from soccer_sim.config import MatchConfig
from soccer_sim.rcg import RcgRecorder
from tests.experiments.test_play_rcss import PROGRAMS, kit

STAND_IN = f"{sys.executable} {PROGRAMS / 'fake_side.py'} {{team}} {{port}}"
"""An external team's command: the tests' stand-in team program (its mode appended)."""


def _namespace_works() -> bool:
    try:
        return subprocess.run(["unshare", "-rn", "true"], capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


needs_namespace = pytest.mark.skipif(not _namespace_works(), reason="no private network namespace here (unshare -rn)")


# ---------------------------------------------------------------------------------- the identity
def test_the_engine_is_part_of_the_configuration_hash_and_the_simulators_hash_is_unchanged():
    config = match_config(400, "partial")
    assert config_hash(config) == config_hash(config, None, "simulator")
    assert "engine" not in config_description(config)
    assert '"engine": "rcssserver"' in config_description(config, None, "rcssserver")
    assert config_hash(config, None, "rcssserver") != config_hash(config)
    simulator = paired_specs("static", "helios-base", 2, 0, 400, "partial")[0]
    server = server_spec(simulator, "/nowhere", {})
    assert server.engine == "rcssserver" and server.key == simulator.key
    assert server.identity != simulator.identity
    assert server.plays_teams == ("static",)                 # helios-base has no kernels to warm
    assert dict(server.play_args)["rcss_home"] == "/nowhere"


def test_a_spec_of_another_engine_needs_its_play_function():
    with pytest.raises(ValueError, match="play function"):
        MatchSpec("static", "chaser", 0, 40, engine="rcssserver")


def test_specs_are_played_in_seed_order_so_an_interrupted_run_stays_paired():
    specs = [spec for team in ("mmdr", "static") for spec in paired_specs(team, "helios-base", 4, 0, 400)]
    ordered = in_seed_order(specs)
    assert [spec.seed for spec in ordered] == [0, 0, 0, 0, 1, 1, 1, 1]
    assert [(spec.home, spec.away) for spec in ordered[:4]] == [
        ("mmdr", "helios-base"), ("helios-base", "mmdr"), ("static", "helios-base"), ("helios-base", "static")]


def test_an_external_command_is_given_the_host_the_ports_and_the_team_name():
    assert external_argv("./team --host {host} -p {port} -P {coach_port} -t '{team}'", "alpha", port=6100) == (
        "./team", "--host", "127.0.0.1", "-p", "6100", "-P", "6102", "-t", "alpha")
    with pytest.raises(ValueError):
        external_argv("'unclosed", "alpha")


# ---------------------------------------------------------------------------------- bad input
def _one_line(capsys) -> str:
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    return err


@pytest.mark.parametrize("command", [
    ["tournament", "--teams", "static,helios-base"],
    ["experiment", "case-study", "--teams", "static", "--opponents", "helios-base", "--baseline", "static"],
])
def test_helios_base_is_refused_under_the_simulator(tmp_path, capsys, command):
    out = tmp_path / "r.sqlite"
    assert main([*command, "--games", "2", "--cycles", "40", "--out", str(out)]) == 2
    err = _one_line(capsys)
    assert "helios-base plays only in the real server" in err and "--engine rcssserver" in err
    assert not out.exists()


def test_a_missing_build_is_one_line_saying_how_to_build_it(tmp_path, capsys):
    out = tmp_path / "r.sqlite"
    assert main(["tournament", "--engine", "rcssserver", "--teams", "static,helios-base", "--games", "2",
                 "--cycles", "40", "--rcss-home", str(tmp_path / "none"), "--out", str(out)]) == 2
    assert "build.sh --server-only" in _one_line(capsys)
    kit(tmp_path / "server-only", helios=False)
    assert main(["tournament", "--engine", "rcssserver", "--teams", "static,helios-base", "--games", "2",
                 "--cycles", "40", "--rcss-home", str(tmp_path / "server-only"), "--out", str(out)]) == 2
    assert "helios-base is not built" in _one_line(capsys)
    assert not out.exists()


@pytest.mark.parametrize("extra, words", [
    (["--backend", "ray"], "local pool only"),
    (["--record-dir", "replays"], "--record-dir is not available"),
    (["--cycles", "30"], "multiple of 20"),
    (["--external", "alpha"], "NAME=COMMAND"),
    (["--external", "static=./x"], "already a team's name"),
    (["--scenario", "kick-off"], "--scenario is not available"),
])
def test_options_the_server_cannot_honour_are_one_line(tmp_path, capsys, extra, words):
    home = kit(tmp_path / "kit")
    args = ["tournament", "--engine", "rcssserver", "--teams", "static,helios-base", "--games", "2",
            "--cycles", "40", "--rcss-home", str(home), "--out", str(tmp_path / "r.sqlite")]
    for option in ("--cycles",):
        if option in extra:
            del args[args.index(option):args.index(option) + 2]
    assert main([*args, *extra]) == 2
    assert words in _one_line(capsys)
    assert not (tmp_path / "r.sqlite").exists()


def test_external_teams_need_the_server(tmp_path, capsys):
    assert main(["tournament", "--teams", "static,chaser", "--external", "alpha=./x", "--games", "2",
                 "--out", str(tmp_path / "r.sqlite")]) == 2
    assert "--external needs --engine rcssserver" in _one_line(capsys)


def test_a_resume_with_the_other_engine_is_one_line_and_leaves_the_file_as_it_was(tmp_path, capsys):
    """A file of the simulator's matches refuses a run in the server (and the other way round,
    in the stored-and-resumed test below)."""
    out = tmp_path / "r.sqlite"
    config = match_config(40, "partial")
    with ResultStore.create(out, "tournament", config_hash(config), config_description(config), {}):
        pass
    before = out.read_bytes()
    home = kit(tmp_path / "kit")
    assert main(["tournament", "--engine", "rcssserver", "--teams", "static,helios-base", "--games", "2",
                 "--cycles", "40", "--rcss-home", str(home), "--out", str(out), "--no-progress"]) == 2
    err = _one_line(capsys)
    assert "holds matches played in the simulator, and this run plays in rcssserver" in err
    assert "never mixes engines" in err and "--engine simulator" in err
    assert out.read_bytes() == before


# ---------------------------------------------------------------------------------- matches stored
@pytest.fixture
def recorded_match(tmp_path, monkeypatch):
    """The stand-in server's game log: a 400-cycle match of the simulator; its score."""
    log = tmp_path / "recorded.rcg"
    result = run_match("static", "chaser", seed=2, config=MatchConfig(max_cycles=400), recorders=[RcgRecorder(log)])
    monkeypatch.setenv("FAKE_RCSS_RCG", str(log))
    monkeypatch.setenv("FAKE_RCSS_SCORE", f"{result.score[0]} - {result.score[1]}")
    monkeypatch.setenv("FAKE_RCSS_SECONDS", "0.2")
    monkeypatch.chdir(tmp_path)
    return tuple(int(goals) for goals in result.score)


@needs_namespace
def test_a_two_match_tournament_is_stored_and_resumed(tmp_path, capsys, recorded_match):
    home, out = kit(tmp_path / "kit"), tmp_path / "real.sqlite"
    args = ["tournament", "--engine", "rcssserver", "--teams", "helios-base,alpha", "--external",
            f"alpha={STAND_IN} ok", "--games", "2", "--cycles", "400", "--rcss-home", str(home), "--out", str(out),
            "--no-progress", "--rcg-dir", str(tmp_path / "logs"), "--record-every", "1"]
    assert main(args) == 0
    captured = capsys.readouterr()
    assert "2 matches in" in captured.out and "played 2" in captured.out and "0 failed" in captured.out
    assert "1 match at a time" in captured.err                # the default number of workers, said
    with ResultStore.open(out) as store:
        records = store.records()
        assert '"engine": "rcssserver"' in store.meta()["config"]
        assert store.params["engine"] == "rcssserver" and store.params["external"] == {"alpha": f"{STAND_IN} ok"}
    assert sorted(r.key for r in records) == [("alpha", "helios-base", 0), ("helios-base", "alpha", 0)]
    for record in records:
        assert record.error is None and (record.home_goals, record.away_goals) == recorded_match
        assert record.cycles == 400
        assert record.home_stats["kicks"] > 0 and "teammate_contacts" not in record.home_stats
    assert len(list((tmp_path / "logs").glob("*.rcg"))) == 2

    with sqlite3.connect(out) as db:                         # as if the run had stopped after one match
        db.execute("DELETE FROM matches WHERE home = 'alpha'")
    assert main(args) == 0
    line = capsys.readouterr().out
    assert "(1 already stored): played 1" in line
    with ResultStore.open(out) as store:
        assert sorted(r.key for r in store.records()) == [("alpha", "helios-base", 0), ("helios-base", "alpha", 0)]

    assert main(["tournament", "--teams", "static,chaser", "--games", "2", "--cycles", "400", "--out", str(out),
                 "--no-progress"]) == 2                      # the simulator into the server's file
    err = _one_line(capsys)
    assert "holds matches played in rcssserver, and this run plays in the simulator" in err


@needs_namespace
def test_a_side_whose_program_fails_forfeits_the_match(tmp_path, capsys, recorded_match, monkeypatch):
    monkeypatch.setenv("FAKE_RCSS_SECONDS", "30")        # the stand-in fails 0.3 s after connecting, long before
    home, out = kit(tmp_path / "kit"), tmp_path / "real.sqlite"
    assert main(["experiment", "case-study", "--engine", "rcssserver", "--teams", "alpha", "--opponents",
                 "helios-base", "--baseline", "alpha", "--external", f"alpha={STAND_IN} fail", "--games", "2",
                 "--cycles", "400", "--rcss-home", str(home), "--out", str(out), "--no-progress"]) == 0
    with ResultStore.open(out) as store:
        records = store.records()
    assert len(records) == 2
    for record in records:
        assert record.error is not None and "act() raised ValueError: boom" in record.error
        assert record.forfeit == (record.home, record.away).index("alpha")
