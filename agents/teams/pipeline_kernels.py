"""Compiled steps of the built-in team's pipeline (:mod:`agents.teams.pipeline`): the derived
world of each distinct belief, the goals of each player row, their dashes and what they say.

Every kernel takes the team's :class:`~agents.teams.pipeline_state.PipelineState` (one named
record: the beliefs, each belief's memory, the constants) and only what changes every cycle.
Two axes, never mixed up:

* a **belief row** ``b``: what one believer holds (row ``b`` of the world model's arrays) and
  everything derived from it once per cycle -- its ball race, attack/defend switch and block,
  formation targets, support spots, role assignment and the assignment it follows;
* a **player row** ``i``: a player of ours, who takes its world from belief ``belief_of[i]``
  (under full observation every row believes the truth, one belief row 0; under partial
  observation each player its own, ``belief_of[i] == i``), and whose goal, hurry, dash and
  role figures are its own.

Row ``i``'s outputs depend only on belief ``belief_of[i]`` and row ``i``'s own senses, so a
team whose players each hold their own beliefs stays decentralised. Team frame (we attack +x),
metres, m/cycle, cycles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.message_kernels import number_digits
from agents.roles.conflicts import believed_conflicts
from agents.skills.interception_kernels import UNREACHABLE, MotionTables, Runners, race_kernel
from agents.skills.player_kernels import Bodies, DashOut, paced_dash_rows
from agents.teams.role_behaviours import adjust_role_targets
from agents.teams.role_kernels import shape_targets
from agents.teams.shape_kernels import advance_block, settle_targets, support_spots, switch_side
from agents.teams.speaking import settles, speaker_message, take_proposal
from formations.interpolation_kernels import value_kernel
from soccer_sim.rules.offside import offside_line

OUR_SET_PLAY, THEIR_SET_PLAY, NORMAL = 0, 1, 2
"""Codes of the formation a play mode other than play on uses (``other`` of :func:`derive_worlds`)."""


@njit(cache=True, nogil=True)
def plan_cycle(s, deciding: np.ndarray, mode: int, placed: bool, saw: np.ndarray, cycle: int,
               assigning: int) -> tuple[int, int, int, int]:  # pragma: no cover - compiled
    """Who decides this cycle and what is derived: the ``deciding`` players into ``s.rows``,
    the outfield ones among them into ``s.outfield_rows``, the distinct beliefs they take
    their world from into ``s.belief_rows`` and, of those, the beliefs whose assignment is due
    into ``s.due``. The belief of player ``assigning`` (-1: none) is due every cycle and derived
    even when that player does not position itself (with the speaking turns,
    :mod:`agents.teams.speaking`, the speaker: its proposal is what it says). With the turns a
    belief that holds an assignment heard within ``s.said_horizon`` cycles follows it (into
    ``s.following``). A belief without one (no talk, or nothing heard lately) assigns for itself: at once when the play mode
    changed since its last assignment, else on a cycle its believer sees, at least
    ``s.assign_every`` cycles after it. ``s.full`` marks the beliefs that need every role's
    target (those that assign, all with a steering assigner, our first outfield player's,
    drawn). Returns the four counts."""
    n = deciding.shape[0]
    seen = np.zeros(n, dtype=np.bool_)
    n_rows = n_out = n_beliefs = n_due = 0
    talks = s.turns.followed.shape[1] > 0
    speaker_belief = s.belief_of[assigning] if assigning >= 0 else -1
    for i in range(n):
        if not deciding[i]:
            continue
        s.rows[n_rows] = i
        n_rows += 1
        if s.rank[i] >= 0:
            s.outfield_rows[n_out] = i
            n_out += 1
        b = s.belief_of[i]
        gap = math.hypot(s.ball[b, 0] - s.mate_pos[b, i, 0], s.ball[b, 1] - s.mate_pos[b, i, 1])
        if seen[b]:
            s.ball_gap[b] = min(s.ball_gap[b], gap)
            continue
        seen[b] = True
        s.ball_gap[b] = gap
        s.belief_rows[n_beliefs] = b
        n_beliefs += 1
    if speaker_belief >= 0 and not seen[speaker_belief]:  # (a speaker on the ball still says an assignment)
        seen[speaker_belief] = True
        s.ball_gap[speaker_belief] = math.hypot(s.ball[speaker_belief, 0] - s.mate_pos[speaker_belief, assigning, 0],
                                                s.ball[speaker_belief, 1] - s.mate_pos[speaker_belief, assigning, 1])
        s.belief_rows[n_beliefs] = speaker_belief
        n_beliefs += 1
    if s.outfield.shape[0] > 0:
        for d in range(n_beliefs):
            b = s.belief_rows[d]
            heard = talks and cycle - s.turns.heard_cycle[b] <= s.said_horizon
            if heard and not placed:
                s.following[b, :] = s.turns.followed[b, :]
            if b == speaker_belief or (not heard and (s.assigned_mode[b] != mode
                                                      or (saw[b] and cycle - s.assigned_at[b] >= s.assign_every))):
                s.due[n_due] = b
                n_due += 1
    s.full[:] = s.steers
    for d in range(n_due):
        s.full[s.due[d]] = True
    if s.first_outfield >= 0:
        s.full[s.belief_of[s.first_outfield]] = True
    return n_rows, n_out, n_beliefs, n_due


@njit(cache=True, nogil=True)
def _race(s, b: int, cycle: int) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s ball race (both teams, on what it believes: positions, velocities and
    efforts; our players it holds unable to play the ball left out) into its race memory."""
    oc = s.our_cycles[b:b + 1]
    op = s.our_points[b:b + 1]
    tc = s.their_cycles[b:b + 1]
    tp = s.their_points[b:b + 1]
    firsts = race_kernel(s.ball[b:b + 1], s.ball_vel[b:b + 1],
                         Runners(s.mate_pos[b], s.mate_vel[b], s.mate_effort[b], s.radius, s.catch_radius),
                         Runners(s.opp_pos[b], s.opp_vel[b], s.opp_effort, s.opp_radius, s.opp_catch_radius),
                         MotionTables(s.reach, s.ball_travel, s.coast), s.able[b], oc, op, tc, tp, s.race_constants, True)
    first, first_cycle = firsts.first, firsts.first_cycle
    their_first, their_first_cycle = firsts.their_first, firsts.their_first_cycle
    s.raced[b] = cycle
    s.our_first[b] = first
    s.their_first[b] = their_first
    s.their_cycle[b] = their_first_cycle
    if their_first_cycle - first_cycle > 0 and first >= 0:
        s.win_point[b] = s.our_points[b, first]
    elif their_first >= 0:
        s.win_point[b] = s.their_points[b, their_first]
    else:
        s.win_point[b] = s.ball[b]


@njit(cache=True, nogil=True)
def _one_cycle_nearer(s, b: int) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s last race, one cycle on (cycles still to go one fewer)."""
    for j in range(s.our_cycles.shape[1]):
        if 0 < s.our_cycles[b, j] < UNREACHABLE:
            s.our_cycles[b, j] -= 1
    for j in range(s.their_cycles.shape[1]):
        if 0 < s.their_cycles[b, j] < UNREACHABLE:
            s.their_cycles[b, j] -= 1
    if 0 < s.their_cycle[b] < UNREACHABLE:
        s.their_cycle[b] -= 1


@njit(cache=True, nogil=True)
def _read_play(s, b: int, play_on: bool, saw: bool, cycle: int) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s ball race and, in play on, its attack/defend switch with hysteresis and
    its block moved at the block's pace towards where the ball will be controlled (``block``:
    query x, y and the shift ``depth`` or ``depth + attack_push``). The race is run again on
    the cycles its believer sees when it believes the ball within ``race_near`` m or raced
    ``race_every`` cycles ago or more, and at the latest ``race_every + 1`` cycles after the
    last; in between its beliefs only roll forward, so its last race holds, a cycle nearer."""
    since = cycle - s.raced[b]
    if since <= s.race_every and not (saw and (s.ball_gap[b] < s.race_near or since >= s.race_every)):
        _one_cycle_nearer(s, b)
    else:
        _race(s, b, cycle)
    first = s.our_first[b]
    lead = s.their_cycle[b] - (s.our_cycles[b, first] if first >= 0 else UNREACHABLE)
    if not play_on:
        s.in_play[b] = False
        return
    s.attacking[b], s.pending[b] = switch_side(lead, s.in_play[b], s.attacking[b], s.pending[b], s.switch_margin,
                                               s.switch_persist)
    advance_block(s.block[b], s.win_point[b], s.depth + s.attack_push if s.attacking[b] else s.depth, s.in_play[b],
                  s.knobs)
    s.in_play[b] = True


@njit(cache=True, nogil=True)
def guard_line_x(s, b: int) -> np.ndarray:  # pragma: no cover - compiled
    """Belief ``b``'s opponents' x as its players keep onside against (into ``s.guard_x[b]``):
    each opponent's believed x less ``guard_step`` m for every cycle since it was seen (at most
    ``guard_cycles``), as far up as it may have stepped meanwhile; under full observation (every
    age 0) the believed x itself. The offside line a belief's players keep to is
    :func:`~soccer_sim.rules.offside.offside_line` of these."""
    out = s.guard_x[b]
    for j in range(out.shape[0]):
        out[j] = s.opp_pos[b, j, 0] - s.guard_step * min(s.opp_age[b, j], s.guard_cycles)
    return out


@njit(cache=True, nogil=True)
def _query(s, b: int, play_on: bool, after_goal: bool, other: int) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s formation targets (into ``targets[b]``, roles x 2): in play on the
    attacking or the defending formation at its block's query point, otherwise the formation
    of the play mode (``other``: :data:`OUR_SET_PLAY`, :data:`THEIR_SET_PLAY`, :data:`NORMAL`)
    at its ball, or at the centre spot after a goal."""
    out = s.targets[b].reshape(s.targets.shape[1] * s.targets.shape[2])
    if play_on:
        if s.attacking[b]:
            value_kernel(s.block[b, 0], s.block[b, 1], s.tables_attack, out)
        else:
            value_kernel(s.block[b, 0], s.block[b, 1], s.tables_defend, out)
        return
    x, y = (0.0, 0.0) if after_goal else (s.ball[b, 0], s.ball[b, 1])
    if other == OUR_SET_PLAY:
        value_kernel(x, y, s.tables_our_set_play, out)
    elif other == THEIR_SET_PLAY:
        value_kernel(x, y, s.tables_their_set_play, out)
    else:
        value_kernel(x, y, s.tables_normal, out)


@njit(cache=True, nogil=True)
def _settle(s, b: int, play_on: bool) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s role targets changed as the team's shape has them: in play on the
    outfield moved up by its block's shift and, when it attacks with its block beyond
    ``narrow_x``, the forwards' y scaled by ``narrowing`` (:func:`shape_targets`); in play on
    each position's own behaviour (:func:`~agents.teams.role_behaviours.adjust_role_targets`,
    at the block's query point); then the back line held behind its ball and every target
    moved at most the block's pace from its last targets (:func:`settle_targets`)."""
    targets = s.targets[b]
    shift = s.block[b, 2]
    shifted = play_on and shift != 0.0
    narrowed = play_on and s.attacking[b] and s.block[b, 0] > s.narrow_x and s.narrowing != 1.0
    if shifted or narrowed:
        shape_targets(targets, s.match_roles[b], shift, shifted, s.x_limit, s.forwards, s.narrowing, narrowed)
    if play_on:
        adjust_role_targets(targets, s.role_codes, s.opp_pos[b], s.guard_x[b], s.block[b, 0], s.block[b, 1],
                            s.attacking[b], s.role_params)
    if s.stationary:
        return
    settle_targets(targets, s.previous[b], s.outfield_roles, s.back_roles, s.opp_pos[b], s.knobs, s.ball[b, 0], play_on,
                   s.attacking[b], play_on and s.primed[b])
    s.primed[b] = True


@njit(cache=True, nogil=True)
def _supports(s, b: int, i: int, candidates: np.ndarray, carrier: np.ndarray) -> bool:  # pragma: no cover
    """Whether player ``i``'s own role (in belief ``b``'s assignment from this cycle on) is
    among the ``support_players`` candidates whose targets are nearest the carrier (ties: the
    earlier candidate), the ones :func:`support_spots` sends."""
    if s.rank[i] < 0:
        return False
    own = s.match_roles[b, s.following[b, s.rank[i]]]
    place = -1
    for c in range(candidates.shape[0]):
        if candidates[c] == own:
            place = c
    if place < 0:
        return False
    cx, cy = carrier[0], carrier[1]
    d_own = math.hypot(s.targets[b, own, 0] - cx, s.targets[b, own, 1] - cy)
    nearer = 0
    for c in range(candidates.shape[0]):
        r = candidates[c]
        d = math.hypot(s.targets[b, r, 0] - cx, s.targets[b, r, 1] - cy)
        if d < d_own or (d == d_own and c < place):
            nearer += 1
    return nearer < s.support_players


@njit(cache=True, nogil=True)
def _support(s, b: int) -> None:  # pragma: no cover - compiled
    """Belief ``b``'s support spots as role targets (in place, before its roles are assigned):
    when it believes we attack, our first player reaches the ball within ``support_horizon``
    cycles and an opponent could be there within ``support_pressure`` (a pressed carrier needs
    a pass), the targets of the ``support_players`` eligible roles nearest that carrier (not
    forwards, not the back line unless the ball is in our third, ``x <= -third_x``, not the
    carrier's own role) move to open spots around it (:func:`support_spots`). A belief not
    marked ``full`` serves only its own player, who needs only its own role's target: it looks
    for spots only when that role is one of the supporters."""
    carrier_row = s.our_first[b]
    if not s.attacking[b] or carrier_row < 0 or s.rank[carrier_row] < 0 or s.their_cycle[b] > s.support_pressure \
            or s.our_cycles[b, carrier_row] > s.support_horizon or s.support_players == 0:
        return
    k = s.match_roles.shape[1]
    candidates = np.empty(k, dtype=np.int64)
    cx = s.our_points[b, carrier_row, 0]
    carrier_role = s.match_roles[b, s.followed[b, s.rank[carrier_row]]]
    count = 0
    for r in range(k):
        role = s.match_roles[b, r]
        if s.is_forward[role] or role == carrier_role or (cx > -s.third_x and s.is_back[role]):
            continue
        candidates[count] = role
        count += 1
    if count == 0 or not (s.full[b] or _supports(s, b, b, candidates[:count], s.our_points[b, carrier_row])):
        return
    players = s.support_players
    out_rows = np.zeros(players, dtype=np.int64)
    out_spots = np.zeros((players, 2))
    x_max = offside_line(s.guard_x[b], s.ball[b, 0]) - 1.0
    chosen = support_spots(s.our_points[b, carrier_row], s.targets[b], s.targets[b], candidates[:count], s.opp_pos[b],
                           s.offsets, players, x_max, s.support_knobs, out_rows, out_spots)
    for c in range(chosen):
        s.targets[b, out_rows[c], 0] = out_spots[c, 0]
        s.targets[b, out_rows[c], 1] = out_spots[c, 1]


@njit(cache=True, nogil=True)
def derive_worlds(s, n_beliefs: int, play_on: bool, after_goal: bool, other: int, support: bool, saw: np.ndarray,
                  cycle: int) -> None:  # pragma: no cover - compiled
    """The derived world of each of the first ``n_beliefs`` beliefs of ``s.belief_rows``,
    before its role assignment: its ball race, switch and block (:func:`_read_play`), its
    formation query (:func:`_query`, ``other`` out of play on), its targets settled
    (:func:`_settle`) and, with ``support``, its support spots (:func:`_support`)."""
    for d in range(n_beliefs):
        b = s.belief_rows[d]
        guard_line_x(s, b)
        _read_play(s, b, play_on, saw[b], cycle)
        _query(s, b, play_on, after_goal, other)
        _settle(s, b, play_on)
        if support:
            _support(s, b)


@njit(cache=True, nogil=True)
def follow_assignments(s, n_due: int, placed: bool, cycle: int) -> None:  # pragma: no cover - compiled
    """The end of the assignment, out of the play modes that place players: each belief that
    assigned this cycle (the first ``n_due`` of ``s.due``) follows its own proposal unless it
    holds an assignment heard within ``s.said_horizon`` cycles (which :func:`plan_cycle` set
    it to follow: a speaker's own proposal takes effect when it is heard)."""
    if placed:
        return
    talks = s.turns.followed.shape[1] > 0
    for d in range(n_due):
        b = s.due[d]
        if not (talks and cycle - s.turns.heard_cycle[b] <= s.said_horizon):
            s.following[b, :] = s.proposals[b, :]


@njit(cache=True, nogil=True)
def player_goals(s, n_rows: int, n_beliefs: int, play_on: bool) -> None:  # pragma: no cover - compiled
    """Every deciding player's goal point and hurry (into ``goals[i]``, ``urgent[i]``), from
    its belief ``b``: its followed role's target (a stationary team's own kick-off spot); in
    play on pulled back behind the offside line it believes in, its interception point when it
    believes it is the one who goes for the ball (the assigner's named ball player if belief
    ``b`` has one, else the first of ours, the goalkeeper only for a ball it wins by
    ``keeper_margin`` cycles in our penalty area: :func:`ball_player` on belief ``b``'s race),
    and as one of the first ``pressers`` when it believes they win it.
    The goalkeeper's goal is made by the team (its guard point)."""
    for d in range(n_beliefs):
        b = s.belief_rows[d]
        s.followed[b, :] = s.following[b, :]
    for r in range(n_rows):
        i = s.rows[r]
        b = s.belief_of[i]
        rank = s.rank[i]
        s.urgent[i] = False
        if rank < 0:
            continue
        role = s.match_roles[b, s.followed[b, rank]]
        if s.stationary:
            gx, gy = s.spots[role, 0], s.spots[role, 1]
        else:
            gx, gy = s.targets[b, role, 0], s.targets[b, role, 1]
        if play_on:
            if not s.stationary:
                limit = offside_line(s.guard_x[b], s.ball[b, 0]) - s.offside_margin
                if gx > limit:
                    gx = max(limit, 0.0)
            first = ball_player(s, b)
            if first == i:
                gx, gy = s.our_points[b, i, 0], s.our_points[b, i, 1]
                s.urgent[i] = True
            elif not s.stationary and s.pressers > 1 and not (
                    s.our_first[b] >= 0 and s.our_cycles[b, s.our_first[b]] < s.their_cycle[b]):
                ahead = 0  # our players nearer the ball than i (ties: lower row)
                for j in s.outfield:
                    if s.our_cycles[b, j] < s.our_cycles[b, i] or (s.our_cycles[b, j] == s.our_cycles[b, i] and j < i):
                        ahead += 1
                if ahead < s.pressers:
                    if s.our_cycles[b, i] < UNREACHABLE:
                        gx, gy = s.our_points[b, i, 0], s.our_points[b, i, 1]
                    else:
                        gx, gy = s.ball[b, 0], s.ball[b, 1]
                    s.urgent[i] = True
        s.goals[i, 0], s.goals[i, 1] = gx, gy


@njit(cache=True, nogil=True)
def ball_player(s, b: int) -> int:  # pragma: no cover - compiled
    """Belief ``b``'s player of ours who goes for the ball (-1: none can reach it in time), on
    its race: its assigner's named one unless our goalkeeper wins the ball in its area, else
    the first of ours, the goalkeeper only for a ball it wins by ``keeper_margin`` cycles in
    our penalty area (an outfield player goes instead); a stationary team's players only for a
    ball that comes to them (within 2 cycles)."""
    first = s.our_first[b]
    goalie = s.goalie
    if s.stationary:
        return first if first >= 0 and s.our_cycles[b, first] <= 2 else -1
    keeper = False
    if first == goalie and first >= 0:
        mine = s.our_cycles[b, goalie]
        px, py = s.our_points[b, goalie, 0], s.our_points[b, goalie, 1]
        keeper = (mine < UNREACHABLE and s.their_cycle[b] - mine >= s.keeper_margin
                  and -s.half_length <= px <= -s.area_x and abs(py) <= s.area_y)
    if s.named_ball[b] >= 0 and not keeper:
        return s.named_ball[b]
    if first == goalie and first >= 0 and not keeper:
        first, best = -1, UNREACHABLE
        for j in s.outfield:
            if s.our_cycles[b, j] < best:
                first, best = j, s.our_cycles[b, j]
    return first


@njit(cache=True, nogil=True)
def dash_and_say(s, n_rows: int, n_out: int, play_on: bool, senses: Bodies, cycle: int, half: int, dash: np.ndarray,
                 speaker: int, digits: np.ndarray) -> tuple[int, float, float, int, int, int]:  # pragma: no cover
    """The end of a team's cycle in one call: each deciding player's pacing phase (1 its
    belief says we attack, 0 we defend, -1 not in play) and its dash to its goal into ``dash``
    (:func:`~agents.skills.player_kernels.paced_dash_rows`; ``senses``: every player's own
    position, velocity, effort, stamina and capacity as it senses them); in play on the role figures of the
    outfield rows (:func:`_role_gaps`, the first four numbers returned); the team message of
    the ``speaker`` (-1: nobody speaks) into its row of ``digits`` (:func:`say`); and in play on
    the believed role conflicts of the beliefs the players follow
    (:func:`~agents.roles.conflicts.believed_conflicts`, the last two numbers)."""
    rows = s.rows[:n_rows]
    position = senses.pos
    for i in rows:
        b = s.belief_of[i]
        s.phase[i] = (1 if s.attacking[b] else 0) if play_on else -1
        s.row_ball[i, 0], s.row_ball[i, 1] = s.ball[b, 0], s.ball[b, 1]
    paced_dash_rows(rows, senses, s.goals, s.urgent, s.row_ball, s.goalie, s.phase, cycle, half, s.pacing,
                    DashOut(dash, s.budgets))
    figures = (0, 0.0, 0.0, 0)
    if play_on and n_out > 0:
        figures = _role_gaps(s, s.outfield_rows[:n_out], position)
    if speaker >= 0 and digits.shape[0] > 0:
        say(s, speaker, cycle, digits[speaker])
    shared, empty = 0, 0
    if play_on and s.outfield.shape[0] > 0 and digits.shape[0] > 0:
        shared, empty = believed_conflicts(s.followed, s.outfield)
    return figures[0], figures[1], figures[2], figures[3], shared, empty


@njit(cache=True, nogil=True)
def say(s, speaker: int, cycle: int, digits: np.ndarray) -> None:  # pragma: no cover - compiled
    """The ``speaker``'s team message of ``cycle`` into ``digits``
    (:func:`~agents.teams.speaking.speaker_message`): the assignment its belief proposed this
    cycle, settled or not (:func:`~agents.teams.speaking.settles`; every proposal with
    ``s.settle_every``, the ``"speaker"`` agreement), and its world information.
    The speaker knows what it said: its belief takes its own proposal as heard
    (:func:`~agents.teams.speaking.take_proposal`), as its listeners do the next cycle."""
    b = s.belief_of[speaker]
    talks = s.turns.followed.shape[1] == s.proposals.shape[1]
    settled = talks and (s.settle_every or settles(b, s.proposals[b], cycle, s.turns))
    number_digits(speaker_message(s.proposals[b], cycle, settled, s.ball[b], s.ball_vel[b], s.ball_age[b],
                                  s.mate_pos[b, speaker], s.belief_of.shape[0], s.ball_decay, s.message_grid),
                  digits)
    if talks:
        take_proposal(b, s.proposals[b], cycle, settled, s.turns, s.said_horizon)


@njit(cache=True, nogil=True)
def _role_gaps(s, rows: np.ndarray, position: np.ndarray) -> tuple[int, float, float, int]:  # pragma: no cover
    """One cycle's role figures of the deciding outfield players ``rows``: how many switched
    role since the last cycle (``last_role``), and the mean and the largest distance from a
    player (its ``position``) to its followed role's target as its belief has it, and how
    many are farther than ``unfilled`` (m)."""
    switches, far = 0, 0
    total, largest = 0.0, 0.0
    for i in rows:
        b = s.belief_of[i]
        role = s.followed[b, s.rank[i]]
        if role != s.last_role[i]:
            switches += 1
        s.last_role[i] = role
        t = s.match_roles[b, role]
        d = math.hypot(position[i, 0] - s.targets[b, t, 0], position[i, 1] - s.targets[b, t, 1])
        total += d
        largest = max(largest, d)
        if d > s.unfilled:
            far += 1
    return switches, total / max(rows.shape[0], 1), largest, far


@njit(cache=True, nogil=True)
def on_ball_rows(s, play_on: bool, set_play: bool, nearest_taker: bool, taker: int, reach: float, senses: tuple,
                 out: np.ndarray, deciding: np.ndarray) -> int:  # pragma: no cover - compiled
    """Which present players' beliefs decide on the ball this cycle (into ``out``), each by
    its own belief ``b``: in play on a player who believes the ball within ``on_ball_distance``
    m or holds it, and the goalkeeper who believes it in or near our penalty area; at our set
    plays (``set_play``) a player who believes the ball within ``reach`` m, the
    ``taker`` (>= 0) and, with ``nearest_taker``, each outfield player its belief holds the
    nearest of the outfield to the ball. Every present player positions itself (into
    ``deciding``). ``senses``: each player's own position, whether it holds the ball, whether
    it is present. Returns how many decide on the ball."""
    position, holds, present = senses
    count = 0
    if play_on:
        reach = s.on_ball_distance
    for i in range(out.shape[0]):
        b = s.belief_of[i]
        dx, dy = s.ball[b, 0] - position[i, 0], s.ball[b, 1] - position[i, 1]
        near = dx * dx + dy * dy < reach * reach
        row = False
        if play_on:
            row = near or holds[i]
            if i == s.goalie:
                row = row or (s.ball[b, 0] <= -s.keeper_area_x and abs(s.ball[b, 1]) <= s.keeper_area_y)
        elif set_play:
            row = near or i == taker
            if nearest_taker and not row and s.outfield.shape[0] > 0:
                best, best_d = -1, np.inf
                for j in s.outfield:
                    ex, ey = s.mate_pos[b, j, 0] - s.ball[b, 0], s.mate_pos[b, j, 1] - s.ball[b, 1]
                    d = ex * ex + ey * ey
                    if d < best_d:
                        best, best_d = j, d
                row = best == i
        out[i] = row and present[i]
        deciding[i] = present[i]
        count += out[i]
    return count


@njit(cache=True, nogil=True)
def assignment_problems(s, beliefs: np.ndarray, players: np.ndarray,
                        role_targets: np.ndarray) -> None:  # pragma: no cover - compiled
    """The role assignment problem of each belief of ``beliefs`` (p,): where it holds the
    outfield players (into ``players[c]``) and its outfield roles' targets (into
    ``role_targets[c]``)."""
    outfield = s.outfield
    for c in range(beliefs.shape[0]):
        b = beliefs[c]
        for j in range(outfield.shape[0]):
            players[c, j, 0], players[c, j, 1] = s.mate_pos[b, outfield[j], 0], s.mate_pos[b, outfield[j], 1]
        for r in range(s.match_roles.shape[1]):
            t = s.match_roles[b, r]
            role_targets[c, r, 0], role_targets[c, r, 1] = s.targets[b, t, 0], s.targets[b, t, 1]
