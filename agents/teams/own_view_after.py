"""Compiled kernels of :mod:`agents.teams.own_view` after the role assigner: each deciding
player follows the assignment its votes agree on, makes its goal point, dashes towards it at
its pace, and the team's role figures are measured -- two calls for the whole team a cycle
(:func:`follow_and_goals`, :func:`dash_and_gaps`).

As in :mod:`agents.teams.own_view_kernels`, row ``i`` of every output depends only on row
``i`` of the inputs (player ``i``'s beliefs and memory). Team frame (we attack +x), metres,
m/cycle, cycles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.roles.voting import follow_votes
from agents.skills.interception_kernels import UNREACHABLE
from agents.skills.player_kernels import Bodies, DashOut, paced_dash_rows
from soccer_sim.rules.offside import offside_line


@njit(cache=True, nogil=True)
def follow_and_goals(rows: np.ndarray, outfield_rows: np.ndarray, due: np.ndarray, placed: bool, voting: tuple,
                     proposals: np.ndarray, following: np.ndarray, followed: np.ndarray, stationary: bool,
                     spots: np.ndarray, goals_args: tuple, goals: np.ndarray,
                     urgent: np.ndarray) -> None:  # pragma: no cover - compiled
    """Steps 4 (the end) and 5 of :class:`~agents.teams.own_view.OwnViewPositioning`: out of
    the play modes that place players, each of the ``due`` players (who assigned this cycle)
    finds the assignment its votes agree on (``voting``: votes, vote cycles, horizon, cycle;
    :func:`~agents.roles.voting.follow_votes`) and every outfield player of ``rows`` follows
    what it found (``following`` into ``followed``); then each one's goal point: a
    stationary team's own kick-off spot (``spots``), else :func:`own_goals` (``goals_args``:
    its arguments after ``followed``)."""
    votes, vote_cycle, horizon, cycle = voting
    if not placed:
        if votes.shape[2] > 0:
            follow_votes(due, votes, vote_cycle, proposals, cycle, horizon, following)
        for i in outfield_rows:
            followed[i, :] = following[i, :]
    targets, out_roles, outfield, goalie, play_on, our_cycles, our_points, our_first, their_cycle, ball, opp_pos, \
        offside_margin, pressers, keeper_margin, area_x, area_y, half_length, rank = goals_args
    if stationary:
        for i in outfield_rows:
            role = out_roles[i, rank[i]]
            goals[i, 0], goals[i, 1] = spots[role, 0], spots[role, 1]
        for i in rows:
            urgent[i] = False
        return
    own_goals(outfield_rows, rank, followed, targets, out_roles, outfield, goalie, play_on, our_cycles, our_points,
              our_first, their_cycle, ball, opp_pos, offside_margin, pressers, keeper_margin, area_x, area_y,
              half_length, goals, urgent)


@njit(cache=True, nogil=True)
def dash_and_gaps(rows: np.ndarray, outfield_rows: np.ndarray, play_on: bool, attacking: np.ndarray,
                  phase: np.ndarray, dashing: tuple, goals: np.ndarray, urgent: np.ndarray, dash: np.ndarray,
                  budgets: np.ndarray, measuring: tuple) -> tuple[int, float, float, int]:  # pragma: no cover
    """Step 6 of :class:`~agents.teams.own_view.OwnViewPositioning` and its figures: each
    deciding player's pacing phase (1 it believes we attack, 0 we defend, -1 not in play), its
    dash to its goal into ``dash`` (``dashing``: the players' positions, velocities, efforts,
    stamina and capacity, the balls, the goalkeeper's row, cycle, half and the pacing record of
    :func:`~agents.skills.player_kernels.paced_dash_rows`); in play on, the role
    figures of the outfield rows (:func:`followed_role_gaps`; ``measuring``: its arguments
    after ``rows``), else zeros."""
    for i in rows:
        phase[i] = (1 if attacking[i] else 0) if play_on else -1
    position, velocity, effort, stamina, capacity, balls, goalie, cycle, half, pacing = dashing
    paced_dash_rows(rows, Bodies(position, velocity, effort, stamina, capacity), goals, urgent, balls, goalie, phase,
                    cycle, half, pacing, DashOut(dash, budgets))
    if not play_on or outfield_rows.shape[0] == 0:
        return 0, 0.0, 0.0, 0
    rank, followed, last_followed, targets, out_roles, unfilled = measuring
    return followed_role_gaps(outfield_rows, rank, followed, last_followed, targets, out_roles, position, unfilled)


@njit(cache=True, nogil=True)
def own_goals(rows: np.ndarray, rank: np.ndarray, followed: np.ndarray, targets: np.ndarray,
              out_roles: np.ndarray, outfield: np.ndarray, goalie: int, play_on: bool, our_cycles: np.ndarray,
              our_points: np.ndarray, our_first: np.ndarray, their_cycle: np.ndarray, ball: np.ndarray,
              opp_pos: np.ndarray, offside_margin: float, pressers: int, keeper_margin: int, area_x: float,
              area_y: float, half_length: float, goals: np.ndarray,
              urgent: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each deciding outfield player's goal point (into ``goals[i]``) and hurry: its followed
    role's target (``followed[i, rank[i]]``, an index into its ``out_roles[i]``); in play on
    pulled back behind the offside line it believes in, its interception point when it believes
    it is the one who goes for the ball (the first of ours, the goalkeeper only for a ball it
    wins by ``keeper_margin`` cycles in our penalty area, ``-half_length <= x <= -area_x``,
    ``|y| <= area_y``, as :func:`agents.skills.comes_out` has it:
    :func:`agents.teams.on_ball.ball_player` on its own race), and as one of the first
    ``pressers`` when it believes they win the ball."""
    for i in rows:
        r = rank[i]
        if r < 0:
            continue
        t = out_roles[i, followed[i, r]]
        gx, gy = targets[i, t, 0], targets[i, t, 1]
        urgent[i] = False
        if play_on:
            limit = offside_line(opp_pos[i, :, 0], ball[i, 0]) - offside_margin
            if gx > limit:
                gx = max(limit, 0.0)
            first = our_first[i]
            if first == goalie and first >= 0:
                mine = our_cycles[i, goalie]
                px, py = our_points[i, goalie, 0], our_points[i, goalie, 1]
                comes_out = (mine < UNREACHABLE and their_cycle[i] - mine >= keeper_margin
                             and -half_length <= px <= -area_x and abs(py) <= area_y)
                if not comes_out:  # an outfield player goes instead
                    first, best = -1, UNREACHABLE
                    for j in outfield:
                        if our_cycles[i, j] < best:
                            first, best = j, our_cycles[i, j]
            if first == i:
                gx, gy = our_points[i, i, 0], our_points[i, i, 1]
                urgent[i] = True
            elif pressers > 1 and not (our_first[i] >= 0 and our_cycles[i, our_first[i]] < their_cycle[i]):
                ahead = 0  # our players nearer the ball than i (ties: lower row)
                for j in outfield:
                    if our_cycles[i, j] < our_cycles[i, i] or (our_cycles[i, j] == our_cycles[i, i] and j < i):
                        ahead += 1
                if ahead < pressers:
                    if our_cycles[i, i] < UNREACHABLE:
                        gx, gy = our_points[i, i, 0], our_points[i, i, 1]
                    else:
                        gx, gy = ball[i, 0], ball[i, 1]
                    urgent[i] = True
        goals[i, 0], goals[i, 1] = gx, gy


@njit(cache=True, nogil=True)
def followed_role_gaps(rows: np.ndarray, rank: np.ndarray, followed: np.ndarray, last_followed: np.ndarray,
                       targets: np.ndarray, out_roles: np.ndarray, position: np.ndarray,
                       unfilled: float) -> tuple[int, float, float, int]:  # pragma: no cover - compiled
    """One cycle's role figures of the deciding outfield players ``rows``: how many switched
    role since ``last_followed`` (then set to ``followed``), and the mean and the largest
    distance from a player (its ``position``) to its followed role's target as it believes
    it, and how many are farther than ``unfilled`` (m)."""
    switches, far = 0, 0
    total, largest = 0.0, 0.0
    for i in rows:
        r = rank[i]
        role = followed[i, r]
        if role != last_followed[i, r]:
            switches += 1
        last_followed[i, :] = followed[i, :]
        t = out_roles[i, role]
        d = math.hypot(position[i, 0] - targets[i, t, 0], position[i, 1] - targets[i, t, 1])
        total += d
        largest = max(largest, d)
        if d > unfilled:
            far += 1
    return switches, total / max(rows.shape[0], 1), largest, far
