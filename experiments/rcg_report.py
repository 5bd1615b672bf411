"""The match report of ``soccer-sim play`` (:class:`~experiments.match_report.MatchReport`)
read from an rcssserver game log (``.rcg``, :func:`soccer_sim.rcg.read_rcg`): how a match
played in the real server (``--engine rcssserver``) is reported.

The left team of the log is home (it attacks +x; teams keep their ends in rcssserver 19).
From the log:

* **score**, **goals**: the ``(team ...)`` lines and the changes to ``goal_l`` / ``goal_r``;
  a goal's scorer is the last player who played the ball (kick, catch, tackle or the ball
  bouncing off it) before it, an own goal when that player is of the other team;
  **half-time score**: the score at the end of the first half (``half_time`` seconds of the
  log's ``server_param`` in cycles);
* **set plays** from the changes of play mode (:data:`rcss_bridge.play_modes.MODE_MAP`, the
  bridge's one table): ``kick_off_X``, ``kick_in_X``, ``corner_kick_X``, ``goal_kick_X`` are
  X's; ``free_kick_X`` and ``indirect_free_kick_X`` are X's free kicks except the one the
  server gives X right after its goalkeeper caught the ball (the simulator's keeper's hold,
  not a set play); an ``offside_X``, a foul by X, a back pass ... is a free kick of X's
  opponents; **offsides** against X: ``offside_X``; **drop balls**: changes to ``drop_ball``;
* **statistics** per team: ``kicks``, ``tackles`` from the rise of each player's counters
  in its ``(c ...)`` (the server counts a kick when it reaches the ball, every tackle tried),
  ``tackles_won`` those whose show line has the tackle flag without the fault flag;
  ``passes`` and ``shots`` as ``bench soccer`` defines them for a log
  (:class:`~experiments.benchmarks.soccer_plays.PlayFigures`: kick to kick, and a kick whose
  ball path crosses the goal line between the posts); ``possession`` the share of the cycles
  whose last player on the ball was the team's (:class:`~soccer_sim.analysis.possession.Possession`,
  a kick-off forgetting him; a ball that bounced off a body counts in play on only, as the
  simulator's referee hears touches then); ``distance_run`` as ``bench soccer`` (relocations left out);
  ``fouls`` the play-mode changes to a foul by the team; ``yellow_cards`` / ``red_cards`` the
  players shown with the card flag. ``teammate_contacts`` and ``ignored_commands`` are not
  in a log: None (shown as ``-``).
"""

from __future__ import annotations

import numpy as np

from experiments.benchmarks.rcg_walk import (CATCH, KEYS, KICK, TACKLE_COUNT, TEAM, log_figures, mode_changes,
                                             walk_shows)
from experiments.match_report import SET_PLAY_KINDS, Goal, MatchReport
from rcss_bridge.play_modes import MODE_MAP, other
from soccer_sim.analysis.possession import Possession
from soccer_sim.config import STANDARD_FIELD
from soccer_sim.rcg import GameLog
from soccer_sim.rcg.mapping import MAX_PLAYER, RED_CARD, YELLOW_CARD
from soccer_sim.state import SET_PLAYS, PlayMode

SIDE_TEAM = {"l": 0, "r": 1}
"""A side's letter -> the report's team (home is the left)."""

FOULS = frozenset({"foul_charge", "foul_push", "foul_multiple_attack", "foul_ballout", "back_pass",
                   "free_kick_fault", "catch_fault", "illegal_defense"})
"""Play modes (without the side) that call a foul or a fault on the side they name."""


NOT_IN_A_LOG = ("teammate_contacts", "ignored_commands")
"""Statistics of the simulator's report that a game log cannot give."""


_NOBODY = np.zeros(0, dtype=np.intp)
"""No rows (a show line's touches outside play on)."""


def rcg_match_report(log: GameLog, team_names: tuple[str, str], seed: int) -> MatchReport:
    """The report of the match in ``log``; ``team_names``: (left, right) as the report names
    them. A ValueError for a log without show lines or the server parameters it needs."""
    cycles, plays = log_figures(log, STANDARD_FIELD.half_length)
    params = log.server_params
    try:
        half_cycles = int(round(float(params["half_time"]) * 1000.0 / float(params.get("simulator_step", 100))))
    except (KeyError, ValueError) as exc:
        raise ValueError(f"the game log's server_param line lacks a number for {exc}") from None
    possession = Possession(MAX_PLAYER)
    kicks, tackles, won = [0, 0], [0, 0], [0, 0]
    catches: set[tuple[str, int]] = set()
    cards: dict[int, set[int]] = {YELLOW_CARD: set(), RED_CARD: set()}
    last_on_ball = -1
    last_before: list[tuple[int, int]] = []  # (cycle, row of the last player on the ball after it)
    for step in walk_shows(log):
        if any(mode.startswith(("kick_off_", "before_kick_off")) for mode in step.entered):
            last_on_ball = -1  # a kick-off forgets who had the ball
        for flag, shown in cards.items():
            shown.update(np.flatnonzero(step.states & flag).tolist())
        if step.number == 0:
            cycles.start(step.pos)
            continue
        rise = step.rise
        for t in (0, 1):
            rows = slice(t * MAX_PLAYER, (t + 1) * MAX_PLAYER)
            kicks[t] += int(rise[rows, KICK].sum())
            tackles[t] += int(rise[rows, TACKLE_COUNT].sum())
        for i in step.won:
            won[int(TEAM[i])] += 1
        kicked, caught = np.flatnonzero(rise[:, KICK] > 0), np.flatnonzero(rise[:, CATCH] > 0)
        catches.update((KEYS[int(i)][0], step.cycle) for i in caught)
        touched = step.touched if step.mode == "play_on" else _NOBODY  # the simulator's referee: in play on
        played = np.unique(np.concatenate([kicked, caught, step.won, touched]))
        if played.size:
            last_on_ball = int(played[-1]) if played.size == 1 else int(played[0])
        possession.add(last_on_ball)
        last_before.append((step.cycle, last_on_ball))
        play_on = step.mode == "play_on"
        cycles.add(step.pos, step.ball[:2], step.stamina, step.outfield, play_on)
        plays.add(kicked, caught, step.won, step.touched, step.ball, play_on)
    modes = sorted(log.play_modes, key=lambda m: m[0])
    set_plays, offsides, fouls, drop_balls, goal_cycles = _read_modes(modes, catches)
    score = (log.teams[-1][3], log.teams[-1][4]) if log.teams else (0, 0)
    goals = _goals(goal_cycles, last_before, KEYS)
    end = log.shows[-1].cycle
    half_time = None
    if end >= half_cycles:
        half_time = (sum(1 for g in goals if g.team == 0 and g.cycle <= half_cycles),
                     sum(1 for g in goals if g.team == 1 and g.cycle <= half_cycles))
    statistics = []
    for t in (0, 1):
        figures: dict[str, float | None] = {
            "goals": score[t], "shots": plays.team_shots[t], "kicks": kicks[t], "passes": plays.team_passes[t],
            "possession": possession.share(t), "teammate_contacts": None, "distance_run": float(cycles.distance[t]),
            "tackles": tackles[t], "tackles_won": won[t], "fouls": fouls[t],
            "yellow_cards": sum(1 for i in cards[YELLOW_CARD] if TEAM[i] == t),
            "red_cards": sum(1 for i in cards[RED_CARD] if TEAM[i] == t), "ignored_commands": None,
        }
        statistics.append(figures)
    return MatchReport(team_names=tuple(team_names), seed=seed, cycles=end, score=(int(score[0]), int(score[1])),
                       half_time_score=half_time, goals=goals, set_plays=set_plays, offsides=tuple(offsides),
                       drop_balls=drop_balls, statistics=(statistics[0], statistics[1]))


def _read_modes(modes: list[tuple[int, str]], catches: set[tuple[str, int]]):
    """Set plays, offsides and fouls per team, dropped balls and the goals' (cycle, side)
    from the changes of play mode (module docstring)."""
    set_plays = tuple({**{k: 0 for k in SET_PLAY_KINDS}, "goal_kick_retake": 0} for _ in (0, 1))
    offsides, fouls, drop_balls = [0, 0], [0, 0], 0
    goals: list[tuple[int, str]] = []
    for cycle, name in mode_changes(modes):
        if name == "drop_ball":
            drop_balls += 1
            continue
        base, _, side = name.rpartition("_")
        if side not in SIDE_TEAM or base not in MODE_MAP:
            continue
        if base == "goal":
            goals.append((cycle, side))
            continue
        if base == "offside":
            offsides[SIDE_TEAM[side]] += 1
        if base in FOULS:
            fouls[SIDE_TEAM[side]] += 1
        play_mode, rule = MODE_MAP[base]
        owner = side if rule == "same" else other(side)
        if play_mode not in SET_PLAYS:
            continue
        if play_mode == PlayMode.FREE_KICK and base in ("free_kick", "indirect_free_kick") and \
                ((side, cycle) in catches or (side, cycle - 1) in catches):
            continue  # the restart after the keeper's catch: the keeper's hold
        set_plays[SIDE_TEAM[owner]][play_mode.name.lower()] += 1
    return set_plays, offsides, fouls, drop_balls, goals


def _goals(goal_cycles: list[tuple[int, str]], last_before: list[tuple[int, int]], keys) -> list[Goal]:
    """Each goal with the last player on the ball before it."""
    goals = []
    for cycle, side in goal_cycles:
        scorer = next((row for c, row in reversed(last_before) if c <= cycle and row >= 0), -1)
        team = SIDE_TEAM[side]
        if scorer < 0:
            goals.append(Goal(cycle, team, None, False))
            continue
        scorer_side, shirt = keys[scorer]
        goals.append(Goal(cycle, team, shirt, SIDE_TEAM[scorer_side] != team))
    return goals
