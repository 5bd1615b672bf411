"""Compiled kernels of :mod:`agents.teams.own_view` before the role assigner: the built-in
team's positioning, done by each player on its own world model, for a whole team in one call
(:func:`before_roles`; the steps after the assigner are in :mod:`agents.teams.own_view_after`).

Every kernel loops over the deciding players ``rows``; row ``i`` of every output depends only
on row ``i`` of the inputs (player ``i``'s beliefs and memory), so the team stays
decentralised. The steps are those of :class:`agents.teams.formation_team.FormationTeam`
(the ball race, the attack/defend switch and the block, the targets settled, the goal),
reusing its kernels. Team frame (we attack +x), metres, m/cycle, cycles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.roles.voting import follow_votes
from agents.skills.interception_kernels import UNREACHABLE, MotionTables, Runners, race_kernel
from formations.interpolation_kernels import value_kernel
from agents.teams.role_kernels import shape_targets
from soccer_sim.rules.offside import offside_line
from agents.teams.shape_kernels import advance_block, settle_targets, support_spots, switch_side


@njit(cache=True, nogil=True)
def read_play(rows: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray, mate_pos: np.ndarray, own_vel: np.ndarray,
              opp_pos: np.ndarray, effort: np.ndarray, radius: np.ndarray, catch_radius: np.ndarray,
              opp_radius: np.ndarray, opp_catch_radius: np.ndarray, reach: np.ndarray, ball_travel: np.ndarray,
              coast: np.ndarray, c: np.ndarray, saw: np.ndarray, cycle: int, raced: np.ndarray, near: float,
              every: int, play_on: bool, switch_margin: int, switch_persist: int,
              depth: float, attack_push: float, knobs: np.ndarray, attacking: np.ndarray, pending: np.ndarray,
              in_play: np.ndarray, block: np.ndarray, our_cycles: np.ndarray, our_points: np.ndarray,
              our_first: np.ndarray, their_cycle: np.ndarray, win_point: np.ndarray) -> None:  # pragma: no cover
    """Each deciding player's ball race on its own beliefs (team-mates where it believes them
    and standing, itself at its sensed velocity, everyone at its own effort; the opponents
    fresh), into ``our_cycles`` (n, n), ``our_points`` (n, n, 2), ``our_first`` (n,),
    ``their_cycle`` (n,) and ``win_point`` (n, 2: where the ball will be controlled, the
    winner's interception point or the ball). In play on, also its attack/defend switch with
    hysteresis (:meth:`agents.teams.shape.Shape.play_on`) and its block moved at the block's
    pace towards ``win_point`` (``block`` (n, 3): query x, y and the shift ``depth`` or
    ``depth + attack_push``). ``c``: the race's constants (an
    :data:`~agents.skills.interception_kernels.INTERCEPT_PARAMS` record).

    A player runs its race again on the cycles it sees when it believes the ball within
    ``near`` m or raced ``every`` cycles ago or more, and at the latest ``every + 1`` cycles
    after the last (``raced``: the cycle of each player's last race); in between its beliefs
    only roll forward, so its last race holds, a cycle nearer."""
    n, m = mate_pos.shape[1], opp_pos.shape[1]
    vel = np.zeros((n, 2))
    opp_vel = np.zeros((m, 2))
    eff = np.empty(n)
    opp_eff = np.ones(m)
    oc = np.empty((1, n), dtype=np.int64)
    op = np.empty((1, n, 2))
    tc = np.empty((1, m), dtype=np.int64)
    tp = np.empty((1, m, 2))
    everyone = np.zeros(0, dtype=np.bool_)
    for i in rows:
        since = cycle - raced[i]
        gap = math.hypot(ball[i, 0] - mate_pos[i, i, 0], ball[i, 1] - mate_pos[i, i, 1])
        if since <= every and not (saw[i] and (gap < near or since >= every)):
            _one_cycle_nearer(our_cycles[i], their_cycle, i)
            _switch_and_block(i, their_cycle[i] - our_cycles[i, our_first[i]] if our_first[i] >= 0
                              else their_cycle[i] - UNREACHABLE, play_on, switch_margin, switch_persist, depth,
                              attack_push, knobs, attacking, pending, in_play, block, win_point)
            continue
        raced[i] = cycle
        vel[:] = 0.0
        vel[i, 0], vel[i, 1] = own_vel[i, 0], own_vel[i, 1]
        eff[:] = effort[i]
        firsts = race_kernel(ball[i:i + 1], ball_vel[i:i + 1], Runners(mate_pos[i], vel, eff, radius, catch_radius),
                             Runners(opp_pos[i], opp_vel, opp_eff, opp_radius, opp_catch_radius),
                             MotionTables(reach, ball_travel, coast), everyone, oc, op, tc, tp, c, True)
        first, first_cycle = firsts.first, firsts.first_cycle
        their_first, their_first_cycle = firsts.their_first, firsts.their_first_cycle
        our_cycles[i] = oc[0]
        our_points[i] = op[0]
        our_first[i] = first
        their_cycle[i] = their_first_cycle
        lead = their_first_cycle - first_cycle
        winning = lead > 0
        if winning and first >= 0:
            win_point[i] = op[0, first]
        elif their_first >= 0:
            win_point[i] = tp[0, their_first]
        else:
            win_point[i] = ball[i]
        _switch_and_block(i, lead, play_on, switch_margin, switch_persist, depth, attack_push, knobs, attacking,
                          pending, in_play, block, win_point)


@njit(cache=True, nogil=True)
def _one_cycle_nearer(our_cycles: np.ndarray, their_cycle: np.ndarray, i: int) -> None:  # pragma: no cover
    """A player's last race, one cycle on (cycles still to go one fewer)."""
    for j in range(our_cycles.shape[0]):
        if 0 < our_cycles[j] < UNREACHABLE:
            our_cycles[j] -= 1
    if 0 < their_cycle[i] < UNREACHABLE:
        their_cycle[i] -= 1


@njit(cache=True, nogil=True)
def _switch_and_block(i: int, lead: int, play_on: bool, switch_margin: int, switch_persist: int, depth: float,
                      attack_push: float, knobs: np.ndarray, attacking: np.ndarray, pending: np.ndarray,
                      in_play: np.ndarray, block: np.ndarray, win_point: np.ndarray) -> None:  # pragma: no cover
    """Player ``i``'s attack/defend switch for a race ``lead`` (cycles; positive: we are first)
    and its block's move (:meth:`agents.teams.shape.Shape.play_on`); out of play on, only
    noted."""
    if not play_on:
        in_play[i] = False
        return
    attacking[i], pending[i] = switch_side(lead, in_play[i], attacking[i], pending[i], switch_margin, switch_persist)
    advance_block(block[i], win_point[i], depth + attack_push if attacking[i] else depth, in_play[i], knobs)
    in_play[i] = True


@njit(cache=True, nogil=True)
def settle_each(rows: np.ndarray, targets: np.ndarray, previous: np.ndarray, primed: np.ndarray,
                match_roles: np.ndarray, outfield_roles: np.ndarray, back_roles: np.ndarray, opp_pos: np.ndarray,
                ball: np.ndarray, block: np.ndarray, attacking: np.ndarray, play_on: bool, x_limit: float,
                forwards: np.ndarray, narrowing: float, narrow_x: float,
                knobs: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each deciding player's role targets ``targets[i]`` (roles, 2; the formation's for its
    query) changed as the team's are: in play on the outfield moved up by its block's shift and,
    when it attacks with its block beyond ``narrow_x`` and ``narrowing`` is not 1, the forwards'
    y scaled by it (:func:`shape_targets`), then the back line held behind its ball and every
    target moved at most the block's pace from its own last targets ``previous[i]``
    (:func:`settle_targets`)."""
    for i in rows:
        shift = block[i, 2]
        shifted = play_on and shift != 0.0
        narrowed = play_on and attacking[i] and block[i, 0] > narrow_x and narrowing != 1.0
        if shifted or narrowed:
            shape_targets(targets[i], match_roles[i], shift, shifted, x_limit, forwards, narrowing, narrowed)
        settle_targets(targets[i], previous[i], outfield_roles, back_roles, opp_pos[i], knobs, ball[i, 0], play_on,
                       attacking[i], play_on and primed[i])
        primed[i] = True


@njit(cache=True, nogil=True)
def query_each(rows: np.ndarray, play_on: bool, after_goal: bool, block: np.ndarray, ball: np.ndarray,
               attacking: np.ndarray, tables_attack: tuple, tables_defend: tuple, tables_other: tuple,
               targets: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each deciding player's formation targets (into ``targets[i]``, roles x 2): in play on the
    attacking or the defending formation at its block's query point, otherwise the one
    formation of the play mode (``tables_other``) at its ball, or at the centre spot after a
    goal. ``tables_*``: a formation's compiled query tables
    (:attr:`formations.Formation.query_tables`)."""
    width = targets.shape[1] * targets.shape[2]
    for i in rows:
        out = targets[i].reshape(width)
        if play_on:
            if attacking[i]:
                value_kernel(block[i, 0], block[i, 1], tables_attack, out)
            else:
                value_kernel(block[i, 0], block[i, 1], tables_defend, out)
        elif after_goal:
            value_kernel(0.0, 0.0, tables_other, out)
        else:
            value_kernel(ball[i, 0], ball[i, 1], tables_other, out)


@njit(cache=True, nogil=True)
def plan_rows(deciding: np.ndarray, rank: np.ndarray, saw: np.ndarray, cycle: int, mode: int, placed: bool,
              sampled: bool, planning: tuple, voting: tuple, proposals: np.ndarray, following: np.ndarray,
              full: np.ndarray, rows: np.ndarray, outfield_rows: np.ndarray,
              due: np.ndarray) -> tuple[int, int, int]:  # pragma: no cover - compiled
    """Who decides this cycle and who of them assigns roles: the ``deciding`` players into
    ``rows``, the outfield ones among them into ``outfield_rows``, and into ``due`` those who
    assign (at once when the play mode changed since their last assignment, else on a cycle
    they see at least ``every`` cycles after it; ``planning``: last assignment cycles, their
    modes, every, whether the assigner steers, our first outfield row or -1). Out of the play
    modes that place players, the others find the assignment their votes agree on
    (``voting``: votes, vote cycles, horizon, cycle; into ``following``). ``full`` marks who
    needs every role's target: those who assign, all of a steering assigner, our first outfield
    player (drawn) and on ``sampled`` cycles the first deciding one. Returns the three counts."""
    assigned_at, assigned_mode, every, steers, first_outfield = planning
    votes, vote_cycle, horizon, _ = voting
    settled = np.empty(deciding.shape[0], dtype=np.int64)
    n_rows = n_out = n_due = n_settled = 0
    for i in range(deciding.shape[0]):
        if not deciding[i]:
            continue
        rows[n_rows] = i
        n_rows += 1
        if rank[i] < 0:
            continue
        outfield_rows[n_out] = i
        n_out += 1
        if assigned_mode[i] != mode or (saw[i] and cycle - assigned_at[i] >= every):
            due[n_due] = i
            n_due += 1
        else:
            settled[n_settled] = i
            n_settled += 1
    if not placed and votes.shape[2] > 0:
        follow_votes(settled[:n_settled], votes, vote_cycle, proposals, cycle, horizon, following)
    full[:] = steers
    for d in range(n_due):
        full[due[d]] = True
    if first_outfield >= 0:
        full[first_outfield] = True
    if n_out > 0 and sampled:
        full[outfield_rows[0]] = True
    return n_rows, n_out, n_due


@njit(cache=True, nogil=True)
def before_roles(deciding: np.ndarray, mode: int, play_on: bool, after_goal: bool, placed: bool, support: bool,
                 sampled: bool, ball: np.ndarray, ball_vel: np.ndarray, mate_pos: np.ndarray, own_vel: np.ndarray,
                 opp_pos: np.ndarray, effort: np.ndarray, saw: np.ndarray, cycle: int, planning: tuple,
                 voting: tuple, race: tuple, shape: tuple, settle: tuple, supporting: tuple, tables_attack: tuple,
                 tables_defend: tuple, tables_other: tuple, memory: tuple, proposals: np.ndarray,
                 followed: np.ndarray, following: np.ndarray, rank: np.ndarray, match_roles: np.ndarray,
                 full: np.ndarray, targets: np.ndarray, rows: np.ndarray, outfield_rows: np.ndarray,
                 due: np.ndarray) -> tuple[int, int, int]:  # pragma: no cover - compiled
    """A team's steps before the role assigner, in one call: who decides and who assigns
    (:func:`plan_rows`, whose counts it returns), then for each deciding player its ball
    race, switch and block (:func:`read_play`), its formation query (:func:`query_each`), its
    targets settled (:func:`settle_each`) and, with ``support``, its support spots
    (:func:`support_each`; in full for the players marked ``full``). The tuples hold those
    kernels' other arguments in their order: ``planning`` and ``voting`` (:func:`plan_rows`),
    ``race`` (radius ... race constants, raced, near, every), ``shape`` (switch margin,
    persist, depth, attack push, knobs), ``settle`` (outfield roles, back roles, x limit,
    forwards, narrowing, narrow x, knobs), ``supporting`` (is_forward ... support knobs) and
    ``memory`` (attacking, pending, in play, block, our cycles, our points, our first, their
    cycle, win point, previous, primed)."""
    counts = plan_rows(deciding, rank, saw, cycle, mode, placed, sampled, planning, voting, proposals, following,
                       full, rows, outfield_rows, due)
    active = rows[:counts[0]]
    attacking, pending, in_play, block, our_cycles, our_points, our_first, their_cycle, win_point, previous, \
        primed = memory
    read_play(active, ball, ball_vel, mate_pos, own_vel, opp_pos, effort, race[0], race[1], race[2], race[3],
              race[4], race[5], race[6], race[7], saw, cycle, race[8], race[9], race[10], play_on, shape[0], shape[1],
              shape[2], shape[3], shape[4], attacking, pending, in_play, block, our_cycles, our_points, our_first,
              their_cycle, win_point)
    query_each(active, play_on, after_goal, block, ball, attacking, tables_attack, tables_defend, tables_other,
               targets)
    settle_each(active, targets, previous, primed, match_roles, settle[0], settle[1], opp_pos, ball, block, attacking,
                play_on, settle[2], settle[3], settle[4], settle[5], settle[6])
    if support:
        support_each(active, attacking, our_first, our_cycles, our_points, their_cycle, targets, match_roles, followed,
                     following, rank, full, supporting[0], supporting[1], opp_pos, ball, supporting[2], supporting[3],
                     supporting[4], supporting[5], supporting[6], supporting[7])
    return counts


@njit(cache=True, nogil=True)
def _supports(i: int, rank: np.ndarray, followed: np.ndarray, match_roles: np.ndarray, targets: np.ndarray,
              candidates: np.ndarray, carrier: np.ndarray, players: int) -> bool:  # pragma: no cover - compiled
    """Whether player ``i``'s own role is among the ``players`` candidates whose targets are
    nearest the carrier (ties: the earlier candidate), the ones :func:`support_spots` sends."""
    if rank[i] < 0:
        return False
    own = match_roles[i, followed[i, rank[i]]]
    place = -1
    for c in range(candidates.shape[0]):
        if candidates[c] == own:
            place = c
    if place < 0:
        return False
    cx, cy = carrier[0], carrier[1]
    d_own = math.hypot(targets[i, own, 0] - cx, targets[i, own, 1] - cy)
    nearer = 0
    for c in range(candidates.shape[0]):
        r = candidates[c]
        d = math.hypot(targets[i, r, 0] - cx, targets[i, r, 1] - cy)
        if d < d_own or (d == d_own and c < place):
            nearer += 1
    return nearer < players


@njit(cache=True, nogil=True)
def support_each(rows: np.ndarray, attacking: np.ndarray, our_first: np.ndarray, our_cycles: np.ndarray,
                 our_points: np.ndarray, their_cycle: np.ndarray, targets: np.ndarray, match_roles: np.ndarray,
                 followed: np.ndarray, following: np.ndarray, rank: np.ndarray, full: np.ndarray,
                 is_forward: np.ndarray,
                 is_back: np.ndarray, opp_pos: np.ndarray, ball: np.ndarray, offsets: np.ndarray, players: int,
                 pressure: int, horizon: int, third_x: float, knobs: np.ndarray) -> None:  # pragma: no cover
    """Each deciding player's support spots as role targets (in place, before its roles are
    assigned), as :meth:`agents.teams.shape.Shape.support` does for the team: when it believes
    we attack, our first player reaches the ball within ``horizon`` cycles and an opponent
    could be there within ``pressure`` (a pressed carrier needs a pass), the targets of the
    ``players`` eligible roles nearest that carrier (not forwards, not the back line unless
    the ball is in our third, ``x <= -third_x``, not the carrier's own role) move to open
    spots around it (:func:`support_spots`). A player not marked ``full`` (who does not
    assign this cycle) only needs the target of its own role
    (in ``following``: what it follows from this cycle on; the carrier's role is as it was,
    in ``followed``): it looks for spots only when its own role is one of those supporters."""
    k = match_roles.shape[1]
    out_rows = np.zeros(max(players, 1), dtype=np.int64)
    out_spots = np.zeros((max(players, 1), 2))
    candidates = np.empty(k, dtype=np.int64)
    for i in rows:
        carrier_row = our_first[i]
        if not attacking[i] or carrier_row < 0 or rank[carrier_row] < 0 or their_cycle[i] > pressure \
                or our_cycles[i, carrier_row] > horizon or players == 0:
            continue
        cx = our_points[i, carrier_row, 0]
        carrier_role = match_roles[i, followed[i, rank[carrier_row]]]
        count = 0
        for r in range(k):
            role = match_roles[i, r]
            if is_forward[role] or role == carrier_role or (cx > -third_x and is_back[role]):
                continue
            candidates[count] = role
            count += 1
        if count == 0 or not (full[i] or _supports(i, rank, following, match_roles, targets, candidates[:count],
                                                   our_points[i, carrier_row], players)):
            continue
        x_max = offside_line(opp_pos[i, :, 0], ball[i, 0]) - 1.0
        chosen = support_spots(our_points[i, carrier_row], targets[i], targets[i], candidates[:count], opp_pos[i],
                               offsets, players, x_max, knobs, out_rows, out_spots)
        for c in range(chosen):
            targets[i, out_rows[c], 0] = out_spots[c, 0]
            targets[i, out_rows[c], 1] = out_spots[c, 1]


@njit(cache=True, nogil=True)
def whole_brain_rows(play_on: bool, set_play: bool, ball: np.ndarray, position: np.ndarray, holds: np.ndarray,
                     present: np.ndarray, mate_pos: np.ndarray, outfield: np.ndarray, taker: int, nearest_taker: bool,
                     goalie: int, brain_distance: float, reach: float, area_x: float, area_y: float,
                     out: np.ndarray, deciding: np.ndarray, dash: np.ndarray,
                     kick: np.ndarray) -> tuple[int, int]:  # pragma: no cover - compiled
    """A team's cycle begins: its command's ``dash`` and ``kick`` (n, 2) cleared, and which
    present players decide with their whole brain this cycle (into ``out``), each by its own
    beliefs: in play on those who believe the ball within ``brain_distance`` m or hold it, and
    the goalkeeper who believes it in or near its penalty area (``x <= -area_x``,
    ``|y| <= area_y``); at our set plays (``set_play``) those who believe the ball within
    ``reach`` m, ``taker`` (>= 0) and, with ``nearest_taker``, each outfield player who
    believes itself the nearest of the outfield to the ball. The other present players go
    into ``deciding`` (they position themselves). Returns how many there are of each."""
    n_brains, n_deciding = 0, 0
    for i in range(out.shape[0]):
        dash[i, 0], dash[i, 1], kick[i, 0], kick[i, 1] = 0.0, 0.0, 0.0, 0.0
        dx, dy = ball[i, 0] - position[i, 0], ball[i, 1] - position[i, 1]
        near = dx * dx + dy * dy
        row = False
        if play_on:
            row = near < brain_distance * brain_distance or holds[i]
            if i == goalie:
                row = row or (ball[i, 0] <= -area_x and abs(ball[i, 1]) <= area_y)
        elif set_play:
            row = near < reach * reach or i == taker
            # Each player's guess at the taker: the outfield player nearest the ball as it
            # believes them (SetPlays._choose_taker's rule without the retaken set play's
            # tried takers, which only the brain that took it knows).
            if nearest_taker and not row and outfield.shape[0] > 0:
                best, best_d = -1, np.inf
                for j in outfield:
                    ex, ey = mate_pos[i, j, 0] - ball[i, 0], mate_pos[i, j, 1] - ball[i, 1]
                    d = ex * ex + ey * ey
                    if d < best_d:
                        best, best_d = j, d
                row = best == i
        out[i] = row and present[i]
        deciding[i] = present[i] and not out[i]
        n_brains += out[i]
        n_deciding += deciding[i]
    return n_brains, n_deciding


@njit(cache=True, nogil=True)
def assignment_problems(rows: np.ndarray, outfield: np.ndarray, mate_pos: np.ndarray, targets: np.ndarray,
                        match_roles: np.ndarray, players: np.ndarray,
                        role_targets: np.ndarray) -> None:  # pragma: no cover - compiled
    """The role assignment problem of each player of ``rows`` (p,) on its own beliefs: where it
    believes the ``outfield`` players are (``mate_pos[i, outfield]`` into ``players[c]``) and its
    outfield roles' targets (``targets[i, match_roles[i]]`` into ``role_targets[c]``)."""
    for c in range(rows.shape[0]):
        i = rows[c]
        for j in range(outfield.shape[0]):
            players[c, j, 0], players[c, j, 1] = mate_pos[i, outfield[j], 0], mate_pos[i, outfield[j], 1]
        for r in range(match_roles.shape[1]):
            t = match_roles[i, r]
            role_targets[c, r, 0], role_targets[c, r, 1] = targets[i, t, 0], targets[i, t, 1]
