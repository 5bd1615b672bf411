"""The match report as ``soccer-sim play`` prints it, for a match of the simulator and one of
rcssserver (``--engine rcssserver``) alike."""

from __future__ import annotations


def report_console():
    """A rich console for the report that lets a closed stdout raise BrokenPipeError (rich's
    own handling would exit with status 1 where ``--json`` exits with 0)."""
    from rich.console import Console

    class ReportConsole(Console):
        def on_broken_pipe(self) -> None:
            self.quiet = True
            raise BrokenPipeError

    return ReportConsole()


def print_report(console, report, elapsed: float) -> None:
    """The report as a person reads it: the score line, then the goals and the statistics as
    :class:`~experiments.reporting.Table` (drawn on a terminal, plain tab-separated text when
    piped, as every table of the command line; team names escaped in the score line: rich would
    take [..] for markup)."""
    from rich.markup import escape

    from experiments.match_report import SIDES
    from experiments.reporting import Table

    names = list(report.team_names)
    half = report.half_time_score
    half_text = f"half time {half[0]} - {half[1]}" if half is not None else "stopped before half time"
    console.print(f"[bold]{escape(names[0])} {report.score[0]} - {report.score[1]} {escape(names[1])}[/bold]  "
                  f"({half_text}; seed {report.seed}, {report.cycles} cycles, {elapsed:.2f} s)")
    if report.goals:
        goals = Table("Goals", ["cycle", "team", "scorer (shirt)", "score"], labels=0)
        score = [0, 0]
        for goal in report.goals:
            score[goal.team] += 1
            shirt = "-" if goal.shirt is None else f"#{goal.shirt}"
            if goal.own_goal:
                shirt = f"own goal by {SIDES[1 - goal.team]} {shirt}"
            goals.rows.append([str(goal.cycle), f"{names[goal.team]} ({SIDES[goal.team]})", shirt,
                               f"{score[0]} - {score[1]}"])
        goals.print(console)
    table = Table("Statistics", ["", f"{names[0]} (home)", f"{names[1]} (away)"])
    home, away = report.statistics
    for key in list(home) + [k for k in away if k not in home]:
        table.rows.append([key.replace("_", " "), _format(key, home.get(key)), _format(key, away.get(key))])
    for key in report.set_plays[0]:
        table.rows.append([key.replace("_", " ") + "s", str(report.set_plays[0][key]), str(report.set_plays[1][key])])
    table.rows.append(["offsides", str(report.offsides[0]), str(report.offsides[1])])
    table.print(console)
    if report.drop_balls:
        console.print(f"{report.drop_balls} set play(s) not taken in time: ball dropped")


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
