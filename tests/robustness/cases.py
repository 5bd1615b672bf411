"""Every case of the robustness audit: bad input, special files, limits and first contact.

One entry per input, grouped by the class of failure it was found in. Matches are tiny
(``idle`` v ``chaser``, 5 cycles) unless the case needs more. File names are relative to the
case's own temporary directory, which is also the command's working directory.

Not here (they cannot be checked by running one command in a few seconds): the first
compilation of the kernels on a cold cache, the README's length and wording, figures that
differ between machines.
"""

from __future__ import annotations

from tests.robustness.model import (
    Case, all_of, fails, line_at_most, never_says, new_png_in, no_escape, no_file, plain_tables, refused,
    refused_or_succeeds, result_is, says, stdout_has, stdout_is_json, stdout_lacks, succeeds, width_at_most,
)
from tests.robustness.steps import AgentDir, Copy, Device, Directory, Fifo, Link, Tamper, Teams, Text, Unwritable

PLAY = ("play", "idle", "chaser", "--cycles", "5")
TOURNAMENT = ("tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "5", "--workers", "1",
              "--no-progress")
RESULTS = Copy("results.sqlite", "r.sqlite")
RECORDING = Copy("match.rrd", "match.rrd")
DISTRIBUTED = ("experiment", "distributed", "--grid-sizes", "", "--etsp-sizes", "4", "--worst-sizes", "4",
               "--sweep-areas", "", "--trials", "1")
INCREMENTAL = ("experiment", "incremental", "--n", "8", "--trials", "1")
BENCH_FORMATION = ("bench", "formation", "--queries", "50", "--single", "50", "--batch", "25", "--repeats", "1",
                   "--set", "4-3-3")
TINY_MATCH = "from soccer_sim import MatchConfig, run_match\n"


def misbehaving(team: str, *options: str) -> tuple[str, ...]:
    """``play`` of the misbehaving team ``team`` against chaser."""
    return ("play", f"misbehaving:{team}", "chaser", "--cycles", "50", *options)


def match_with(config: str) -> str:
    """A snippet playing a 5-cycle match under the configuration expression ``config``."""
    return (f"from soccer_sim import FieldConfig, MatchConfig, PhysicsConfig, RuleConfig, run_match\n"
            f"config = MatchConfig({config}, max_cycles=5)\n"
            f"result = list(run_match('idle', 'chaser', config=config).score)")


def with_recorders(recorders: str) -> str:
    return TINY_MATCH + f"result = list(run_match('idle', 'chaser', config=MatchConfig(max_cycles=5), recorders={recorders}).score)"


INPUT_CHANGED = [
    Case("formation import onto its own input", "input changed", refused(),
         argv=("formation", "import", "helios", "hg.conf", "hg.conf"), setup=(Copy("agent2d.conf", "hg.conf"),)),
    Case("formation import onto a file of the imported directory", "input changed", refused(),
         argv=("formation", "import", "helios", "dt", "dt/normal-formation.conf"), setup=(AgentDir("dt"),)),
    Case("formation show --out onto the formation it draws", "input changed", refused(),
         argv=("formation", "show", "fs.png", "--out", "fs.png"), setup=(Copy("formation.json", "fs.png"),)),
    Case("replay --png onto the recording it reads", "input changed", refused(),
         argv=("replay", "in.png", "--png", "in.png"), setup=(Copy("match.rrd", "in.png"),)),
    Case("tournament --out on a damaged results file", "input changed", refused(),
         argv=(*TOURNAMENT, "--out", "r.sqlite"),
         setup=(RESULTS, Tamper("r.sqlite", "PRAGMA journal_mode=DELETE; DROP TABLE matches;"))),
    Case("tournament --out on an SQLite file that is no results file", "input changed", refused(),
         argv=(*TOURNAMENT, "--out", "other.sqlite"),
         setup=(Tamper("other.sqlite", "PRAGMA journal_mode=DELETE; CREATE TABLE notes (x); INSERT INTO notes VALUES (1);"),)),
]

SPECIAL_FILES = [
    Case("results export --csv FIFO", "special file", refused(), argv=("results", "export", "r.sqlite", "--csv", "pipe"),
         setup=(RESULTS, Fifo("pipe"))),
    Case("results export --csv null device", "special file", refused(),
         argv=("results", "export", "r.sqlite", "--csv", "null"), setup=(RESULTS, Device("null", "null"))),
    Case("results export --csv full device", "special file", refused(),
         argv=("results", "export", "r.sqlite", "--csv", "full"), setup=(RESULTS, Device("full", "full"))),
    Case("results export --csv link to a null device", "special file", refused(),
         argv=("results", "export", "r.sqlite", "--csv", "link.csv"),
         setup=(RESULTS, Device("nodes/null", "null"), Link("link.csv", "nodes/null"))),
    Case("play --record FIFO", "special file", refused(), argv=(*PLAY, "--record", "pipe.rrd"), setup=(Fifo("pipe.rrd"),)),
    Case("play --record null device", "special file", refused(), argv=(*PLAY, "--record", "null.rrd"),
         setup=(Device("null.rrd", "null"),)),
    Case("play --rcg null device", "special file", refused(), argv=(*PLAY, "--rcg", "null.rcg"),
         setup=(Device("null.rcg", "null"),)),
    Case("play --rcg FIFO", "special file", refused(), argv=(*PLAY, "--rcg", "pipe.rcg"), setup=(Fifo("pipe.rcg"),)),
    Case("replay --results --out FIFO", "special file", refused(),
         argv=("replay", "--results", "r.sqlite", "--row", "0", "--out", "pipe.rrd"), setup=(RESULTS, Fifo("pipe.rrd"))),
    Case("replay --results --out null device", "special file", refused(),
         argv=("replay", "--results", "r.sqlite", "--row", "0", "--out", "null.rrd"),
         setup=(RESULTS, Device("null.rrd", "null"))),
    Case("results show --tables with a FIFO inside", "special file", refused(),
         argv=("results", "show", "r.sqlite", "--tables", "t"), setup=(RESULTS, Fifo("t/league.csv"))),
    Case("tournament --tables with a null device inside", "special file", refused(),
         argv=(*TOURNAMENT, "--out", "n.sqlite", "--tables", "t"), setup=(Device("t/league.csv", "null"),),
         writes=("n.sqlite",), bound_factor=2),
]

HANGS = [
    Case("play --cycles 99999999999", "hang", refused(says=says("cycles")), argv=("play", "idle", "chaser", "--cycles", "99999999999")),
    Case("play --scenario FIFO", "hang", refused(says=never_says("no such")), argv=(*PLAY, "--scenario", "s.toml"),
         setup=(Fifo("s.toml"),)),
    Case("play --scenario zero device", "hang", refused(), argv=(*PLAY, "--scenario", "s.toml"),
         setup=(Device("s.toml", "zero"),)),
    Case("play --scenario urandom device", "hang", refused(), argv=(*PLAY, "--scenario", "s.json"),
         setup=(Device("s.json", "urandom"),)),
    Case("formation validate FIFO", "hang", refused(says=never_says("no such")), argv=("formation", "validate", "f.json"),
         setup=(Fifo("f.json"),)),
    Case("formation validate zero device", "hang", refused(), argv=("formation", "validate", "f.json"),
         setup=(Device("f.json", "zero"),)),
    Case("formation show urandom device", "hang", refused(), argv=("formation", "show", "f.conf", "--out", "out.png"),
         setup=(Device("f.conf", "urandom"),), writes=("out.png",)),
    Case("results export --csv link to stdout | head", "hang", refused_or_succeeds(stdout_has("home")),
         shell="set -o pipefail; {cli} results export r.sqlite --csv out.csv | head -c 100",
         setup=(RESULTS, Link("out.csv", "/proc/self/fd/1"))),
    Case("play --match-timeout against a team that disarms SIGALRM", "hang", fails(),
         argv=misbehaving("Deaf", "--match-timeout", "2"), setup=(Teams(),)),
    Case("tournament --backend ray --address 127.0.0.1:1", "hang", refused(1, 2),
         argv=(*TOURNAMENT, "--backend", "ray", "--address", "127.0.0.1:1", "--out", "ray.sqlite"),
         writes=("ray.sqlite",), memory_mb=None, bound_factor=1.5),
    Case("run_match with FieldConfig(length=1e308)", "hang", refused(says=says("length")),
         python=match_with("field=FieldConfig(length=1e308)")),
    Case("run_match with RuleConfig(set_play_clearance=1e308)", "hang", refused(says=says("set_play_clearance")),
         python=match_with("rules=RuleConfig(set_play_clearance=1e308)")),
]

TRACEBACKS = [
    Case("play --match-timeout 1e308", "traceback", refused(says=says("match-timeout")), argv=(*PLAY, "--match-timeout", "1e308")),
    Case("play --match-timeout 1e-6", "traceback", refused(1, 2), argv=(*PLAY, "--match-timeout", "1e-6")),
    Case("tournament --match-timeout 1e308", "traceback", refused(says=says("match-timeout")),
         argv=(*TOURNAMENT, "--match-timeout", "1e308", "--out", "t.sqlite"), writes=("t.sqlite",)),
    Case("tournament --match-timeout 1e-6", "traceback", refused(1, 2),
         argv=(*TOURNAMENT, "--match-timeout", "1e-6", "--out", "t.sqlite"), writes=("t.sqlite",), bound_factor=2),
    Case("play --match-timeout 3 against a sleeping team", "traceback", fails(),
         argv=misbehaving("Sleeping", "--match-timeout", "3"), setup=(Teams(),)),
    Case("tournament --out ''", "traceback", refused(), argv=(*TOURNAMENT, "--out", "")),
    Case("results export --csv ''", "traceback", refused(), argv=("results", "export", "r.sqlite", "--csv", ""),
         setup=(RESULTS,)),
    Case("experiment distributed --seed -1", "traceback", refused(says=says("seed")), argv=(*DISTRIBUTED, "--seed", "-1")),
    Case("experiment incremental --seed -1", "traceback", refused(says=says("seed")), argv=(*INCREMENTAL, "--seed", "-1")),
    Case("bench formation --seed -1", "traceback", refused(says=says("seed")), argv=(*BENCH_FORMATION, "--seed", "-1")),
    Case("tournament --games 1000000000", "traceback", refused(says=says("games")),
         argv=("tournament", "--teams", "idle,chaser", "--games", "1000000000", "--cycles", "5", "--workers", "1",
               "--no-progress", "--out", "g.sqlite"), writes=("g.sqlite",), memory_mb=3072),
    Case("results show: params not JSON", "traceback", refused(), argv=("results", "show", "r.sqlite"),
         setup=(RESULTS, Tamper("r.sqlite", "UPDATE meta SET value = 'not json' WHERE key = 'params';"))),
    Case("results show: goals 'many'", "traceback", refused(), argv=("results", "show", "r.sqlite"),
         setup=(RESULTS, Tamper("r.sqlite", "UPDATE matches SET home_goals = 'many';"))),
    Case("results show: goals NULL", "traceback", refused(), argv=("results", "show", "r.sqlite"),
         setup=(RESULTS, Tamper("r.sqlite", "UPDATE matches SET home_goals = NULL;"))),
    Case("results export --csv into an unwritable directory", "traceback", refused(),
         argv=("results", "export", "r.sqlite", "--csv", "locked/x.csv"), setup=(RESULTS, Unwritable("locked"))),
    Case("results show --tables an unwritable directory", "traceback", refused(),
         argv=("results", "show", "r.sqlite", "--tables", "locked"), setup=(RESULTS, Unwritable("locked"))),
    Case("play --record on a full disk", "traceback", fails(), argv=(*PLAY, "--record", "disk/m.rrd"), disk="full"),
    Case("play --rcg on a full disk", "traceback", fails(), argv=(*PLAY, "--rcg", "disk/m.rcg"), disk="full"),
    Case("experiment incremental --out on a full disk", "traceback", fails(), argv=(*INCREMENTAL, "--out", "disk"),
         disk="full"),
    Case("play with stdout on a full disk", "traceback", fails(), argv=PLAY, stdout_device="full"),
    Case("play: a team raising BaseException", "traceback", fails(), argv=misbehaving("BaseRaising"), setup=(Teams(),)),
    Case("play: a team that SIGKILLs itself", "traceback", fails(), argv=misbehaving("SelfKilling"), setup=(Teams(),)),
    Case("tournament killed: its workers exit quietly", "traceback", succeeds(),
         argv=("tournament", "--teams", "idle,chaser", "--games", "8", "--cycles", "3000", "--workers", "2",
               "--no-progress", "--out", "k.sqlite"), writes=("k.sqlite",), kill_parent_after_workers=True,
         bound_factor=1.5),
    Case("run_match(recorders='x')", "traceback", refused(), python=with_recorders("'x'")),
    Case("run_match(recorders=[None])", "traceback", refused(), python=with_recorders("[None]")),
    Case("run_match(recorders=[object()])", "traceback", refused(), python=with_recorders("[object()]")),
    Case("run_match(recorders=5)", "traceback", refused(), python=with_recorders("5")),
    Case("load_scenario(None)", "traceback", refused(),
         python="from soccer_sim.scenarios import load_scenario\nresult = repr(load_scenario(None))"),
    Case("run_match with PhysicsConfig(ball_radius=1e308)", "traceback", refused(says=says("ball_radius")),
         python=match_with("physics=PhysicsConfig(ball_radius=1e308)")),
]

SILENT = [
    Case("replay --png an existing directory", "silent",
         refused_or_succeeds(all_of(no_file("shots.png"), new_png_in("shots"))),
         argv=("replay", "match.rrd", "--png", "shots"), setup=(RECORDING, Directory("shots"))),
    Case("replay --png ''", "silent", refused(always=no_file(".png")), argv=("replay", "match.rrd", "--png", ""),
         setup=(RECORDING,)),
    Case("play: a team calling os._exit(0)", "silent", fails(), argv=misbehaving("Quitting"), setup=(Teams(),)),
    Case("play --json: a team that prints", "silent", succeeds(stdout_is_json),
         argv=("play", "misbehaving:Printing", "chaser", "--cycles", "5", "--json"), setup=(Teams(),)),
    Case("assign_costs with every cost 1e308", "silent",
         refused_or_succeeds(result_is(lambda v: isinstance(v, float) and v < float("inf"), "a finite total")),
         python="import numpy as np\nfrom agents.assignment import assign_costs\n"
                "result = float(assign_costs(np.full((3, 3), 1e308)).total)"),
    Case("assign with complex coordinates", "silent", refused(),
         python="import numpy as np\nfrom agents.assignment import assign\n"
                "result = assign(np.array([[1 + 1j, 2], [3, 4]]), np.array([[0, 0], [1, 1j]])).target_of.tolist()"),
    Case("tournament --workers 50", "silent", refused_or_succeeds(stdout_lacks(r"\b50 worker")),
         argv=(*TOURNAMENT, "--workers", "50", "--out", "w.sqlite"), writes=("w.sqlite",), bound_factor=2),
    Case("play --scenario an empty TOML file", "silent", refused(), argv=(*PLAY, "--scenario", "empty.toml"),
         setup=(Text("empty.toml", ""),)),
    Case("results export --csv -", "silent", refused_or_succeeds(all_of(no_file("-"), stdout_has("home"))),
         argv=("results", "export", "r.sqlite", "--csv", "-"), setup=(RESULTS,)),
]

FIRST_CONTACT = [
    Case("play piped: plain tables", "first contact", succeeds(plain_tables), argv=PLAY),
    Case("tournament --help is quick", "first contact", succeeds(within=1.0), argv=("tournament", "--help")),
    Case("experiment case-study --help is quick", "first contact", succeeds(within=1.0),
         argv=("experiment", "case-study", "--help")),
    Case("play --help is quick", "first contact", succeeds(within=1.0), argv=("play", "--help")),
    Case("tournament --tables X --out X is refused before playing", "first contact", refused(always=no_file("X")),
         argv=(*TOURNAMENT, "--out", "X", "--tables", "X")),
    Case("results show on an 80-column terminal", "first contact", succeeds(width_at_most(80)),
         argv=("results", "show", "r.sqlite"), setup=(RESULTS,), tty_columns=80),
    Case("play with an unknown team: a short error", "first contact", refused(says=line_at_most(200)),
         argv=("play", "nobody", "chaser", "--cycles", "5")),
    Case("play: a bad say is named, not echoed", "first contact", fails(says=all_of(line_at_most(300), no_escape)),
         argv=("play", "misbehaving:Shouting", "chaser", "--cycles", "5"), setup=(Teams(),)),
    Case("results show FIFO: not 'no such file'", "first contact", refused(says=never_says("no such")),
         argv=("results", "show", "pipe.sqlite"), setup=(Fifo("pipe.sqlite"),)),
    Case("results show link to a null device: not 'no such file'", "first contact", refused(says=never_says("no such")),
         argv=("results", "show", "link.sqlite"), setup=(Device("nodes/null", "null"), Link("link.sqlite", "nodes/null"))),
    Case("results export --csv on a read-only file system", "first contact",
         refused(1, 2, says=all_of(says("read-only"), never_says("permission denied"))),
         argv=("results", "export", "r.sqlite", "--csv", "disk/x.csv"), setup=(RESULTS,), disk="read-only"),
    Case("formation show on a full disk: exit 1", "first contact", fails(),
         argv=("formation", "show", "4-4-2", "--out", "disk/f.png"), disk="full"),
    Case("replay --png on a full disk: exit 1", "first contact", fails(),
         argv=("replay", "match.rrd", "--png", "disk/x.png"), setup=(RECORDING,), disk="full"),
    Case("results export --csv on a full disk: exit 1", "first contact", fails(),
         argv=("results", "export", "r.sqlite", "--csv", "disk/x.csv"), setup=(RESULTS,), disk="full"),
]

CONTROL = [
    Case("play --json (valid)", "control", succeeds(stdout_is_json), argv=(*PLAY, "--json")),
    Case("results export --csv (valid)", "control", succeeds(lambda run: None if (run.dir / "out.csv").is_file()
                                                             else "out.csv not written"),
         argv=("results", "export", "r.sqlite", "--csv", "out.csv"), setup=(RESULTS,), writes=("out.csv",)),
    Case("formation import helios (valid)", "control", succeeds(),
         argv=("formation", "import", "helios", "hg.conf", "out.json"), setup=(Copy("agent2d.conf", "hg.conf"),)),
    Case("run_match (valid)", "control", succeeds(result_is(lambda v: isinstance(v, list) and len(v) == 2, "a score")),
         python=TINY_MATCH + "result = list(run_match('idle', 'chaser', config=MatchConfig(max_cycles=5)).score)"),
    Case("results show --tables (valid)", "control", succeeds(), argv=("results", "show", "r.sqlite", "--tables", "t"),
         setup=(RESULTS,)),
]

CASES: list[Case] = [*INPUT_CHANGED, *SPECIAL_FILES, *HANGS, *TRACEBACKS, *SILENT, *FIRST_CONTACT, *CONTROL]
"""Every case, in the order they are run and listed."""
