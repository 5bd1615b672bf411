"""``soccer-sim play [HOME] [AWAY] --seed N [--cycles N]``: play one match, print the score and
both teams' statistics."""

from __future__ import annotations

import argparse


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "play", help="play one match and print the score and statistics",
        description="Play one match between two teams (registered names or package.module:Attribute "
                    "paths) and print the score and per-team statistics.")
    parser.add_argument("home", nargs="?", default="chaser", help="home team (default: chaser)")
    parser.add_argument("away", nargs="?", default="chaser", help="away team (default: chaser)")
    parser.add_argument("--seed", type=int, default=0, help="match seed (default: 0)")
    parser.add_argument("--cycles", type=positive_int, default=None,
                        help="stop after this many cycles (default: the full two halves)")
    parser.set_defaults(func=run)


def positive_int(text: str) -> int:
    """argparse type: a positive integer (shared by the commands and benchmarks that play matches)."""
    value = int(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {text}")
    return value


def run(args: argparse.Namespace) -> int:
    import time

    from rich.console import Console
    from rich.table import Table

    from soccer_sim import ConfigError, MatchConfig, TeamError, TeamNotFoundError, run_match

    console = Console()
    try:
        config = MatchConfig(max_cycles=args.cycles)
        start = time.perf_counter()
        result = run_match(args.home, args.away, seed=args.seed, config=config)
        elapsed = time.perf_counter() - start
    except (TeamNotFoundError, TeamError, ConfigError, ValueError) as exc:
        console.print(f"[red]error:[/red] {exc}")
        return 2
    home_name, away_name = result.team_names
    console.print(f"[bold]{home_name} {result.score[0]} - {result.score[1]} {away_name}[/bold]  "
                  f"(seed {result.seed}, {result.cycles} cycles, {elapsed:.2f} s)")
    table = Table(title="Statistics")
    table.add_column("")
    table.add_column(f"{home_name} (home)", justify="right")
    table.add_column(f"{away_name} (away)", justify="right")
    home, away = (stats.as_dict() for stats in result.statistics)
    for key in list(home) + [k for k in away if k not in home]:
        table.add_row(key.replace("_", " "), _format(key, home.get(key)), _format(key, away.get(key)))
    console.print(table)
    return 0


def _format(key: str, value: float | None) -> str:
    if value is None:
        return "-"
    if key == "possession":
        return f"{100 * value:.1f} %"
    if key == "distance_run":
        return f"{value / 1000:.2f} km"
    if float(value).is_integer():
        return str(int(value))
    return f"{value:.3g}"
