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
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import json
    import sys

    from rich.console import Console

    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import ScenarioError, get_scenario, library, load_scenario, scenario_to_dict

    console = Console()
    try:
        if args.scenario is None:
            _print_library(console, library(), MatchConfig())
            return 0
        text = args.scenario
        scenario = load_scenario(text) if text.lower().endswith((".json", ".toml")) else get_scenario(text)
        scenario.check(MatchConfig())
    except ScenarioError as exc:  # one plain line (a rich console would wrap a long message)
        print(f"error: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
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


def _print_library(console, scenarios: dict, config) -> None:
    from rich.markup import escape
    from rich.table import Table

    table = Table(title="Scenarios (soccer-sim play HOME AWAY --scenario NAME)")
    # Names in full (they are what --scenario takes); the other columns wrap instead.
    table.add_column("name", no_wrap=True, min_width=max(map(len, scenarios), default=4))
    for column in ("home v away", "start", "ends on", "cycle limit", "drawn from the seed"):
        table.add_column(column)
    for name, s in scenarios.items():
        drawn = [what for what, on in (("ball", s.ball.area is not None), ("home", s.home.jitter > 0),
                                       ("away", s.away.jitter > 0)) if on]
        start = s.start_mode.replace("_", " ") + ("" if s.start_mode == "play_on" else f" ({s.start_team})")
        limit = s.cycle_limit if s.cycle_limit is not None else config.total_cycles
        table.add_row(escape(name), _sides(s, config), start, ", ".join(s.end_on) or "time", str(limit),
                      ", ".join(drawn) or "-")
    console.print(table)
    for name, s in scenarios.items():
        console.print(f"[bold]{escape(name)}[/bold]: {escape(s.description)}")
