"""``soccer-sim scenarios [NAME|FILE]``: list the shipped scenarios, or print one as JSON.

Without an argument it prints a table of the library (name, sides, start, end conditions,
cycle limit, what is drawn from the seed, description). With a library name or a ``.json`` /
``.toml`` file it checks the scenario against the default configuration and prints its file
form (JSON), a starting point for a scenario of one's own. A bad scenario is reported in one
line, without a traceback (exit status 2).
"""

from __future__ import annotations

import argparse

from experiments.commands import doc_summary


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("scenarios", help="list the shipped scenarios, or print one as JSON",
                                   description=doc_summary(__doc__))
    parser.add_argument("scenario", nargs="?", default=None, metavar="NAME|FILE",
                        help="a library name or a .json/.toml file: check it and print it as JSON")
    parser.add_argument("--json", action="store_true",
                        help="the library listing as one JSON object (a named scenario is printed as JSON anyway)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import json
    import sys

    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import ScenarioError, get_scenario, library, load_scenario, scenario_to_dict

    try:
        if args.scenario is None:
            if args.json:
                from experiments.reporting import json_output

                return json_output(lambda: _print_library(library(), MatchConfig()) or 0)
            _print_library(library(), MatchConfig())
            return 0
        text = args.scenario
        scenario = load_scenario(text) if text.lower().endswith((".json", ".toml")) else get_scenario(text)
        scenario.check(MatchConfig())
    except ScenarioError as exc:
        from experiments.commands.errors import fail

        return fail(str(exc))
    try:
        print(_compact_points(json.dumps(scenario_to_dict(scenario), indent=2)))
        sys.stdout.flush()
    except BrokenPipeError:  # the reader went away (``| head``): not an error
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return 0


def _compact_points(text: str) -> str:
    """Indented JSON with each [x, y] pair on one line."""
    import re

    number = r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?"
    return re.sub(rf"\[\s*({number}),\s*({number})\s*\]", r"[\1, \2]", text)


def _sides(scenario, config) -> str:
    parts = []
    for n, goalie in zip(scenario.sizes(config), scenario.goalies(config)):
        parts.append(f"{n}" + (" (GK)" if goalie >= 0 else ""))
    return " v ".join(parts)


def _print_library(scenarios: dict, config) -> None:
    """The library as one table (drawn on a terminal, tab-separated when piped, see
    :class:`experiments.reporting.Table`), then each scenario's description on its own line."""
    from experiments.reporting import Table

    header = ["name", "home v away", "start", "ends on", "cycle limit", "drawn from the seed"]
    table = Table("Scenarios (soccer-sim play HOME AWAY --scenario NAME)", header, labels=len(header))
    for name, s in scenarios.items():
        drawn = [what for what, on in (("ball", s.ball.area is not None), ("home", s.home.jitter > 0),
                                       ("away", s.away.jitter > 0)) if on]
        start = s.start_mode.replace("_", " ") + ("" if s.start_mode == "play_on" else f" ({s.start_team})")
        limit = s.cycle_limit if s.cycle_limit is not None else config.total_cycles
        table.rows.append([name, _sides(s, config), start, ", ".join(s.end_on) or "time", str(limit),
                           ", ".join(drawn) or "-"])
    table.print()
    for name, s in scenarios.items():
        print(f"{name}: {' '.join(s.description.split())}")
