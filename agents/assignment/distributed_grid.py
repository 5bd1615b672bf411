"""GRID ASSGMT: cell leaders count free targets and guide unassigned agents to them.

From "Monotonic Target Assignment for Robotic Networks" (Smith and Bullo),
Section VI and Appendix B. The square environment is cut into ``b x b`` cells
with ``b = ceil(sqrt(5) * side / r_comm)``, so that any two points in the same
or in edge-adjacent cells are within ``r_comm`` (Lemma 2.3): every message
below (agent to leader, leader to leader of the cell above or, in the top row,
to the left) is between such points. Rows are numbered from the top (row 0 at
``y = side``), columns from the left.

* Role assignment: the agents in a cell match themselves greedily to the
  cell's targets (MAXIMAL MATCH: closest pair first); the matched agent with the
  smallest id becomes the cell's leader. A cell with targets and no agent gets
  its leader when the first agents arrive.
* Leaders keep ``delta`` (targets minus agents in the cell), ``below`` (an
  estimate, initially +infinity, of the same difference summed over the cells
  below in the column) and, in the top row, ``right`` (summed over all columns
  to the right); each round a leader sends ``below + delta`` up and, in the top
  row, ``right + below + delta`` left, and corrects its estimates with the
  enter / exit messages of agents crossing its borders.
* An unassigned agent asks the leader of the cell it has just reached for a
  free target; failing that, it walks down its column while the leader grants
  "free targets below" (at most ``below`` grants per round), back up otherwise,
  and along the top row to the next column (right while the leader grants
  "free targets to the right", else left), skipping columns it knows full.
  Agents move from cell centre to cell centre at full speed.

Where the paper is silent: a cell without targets has no leader, so its
estimates are unknown and a question asked there gets the optimistic answer
(as if the estimate were +infinity: "yes" whenever there is a cell below /
to the right); an agent whose top-row walk has no further column stops (only
when agents outnumber targets); when a cell's first agents arrive, the
targets free in it are matched to the agents arriving that round; a leader
gives a querying agent its nearest free target.

State is held in arrays: per agent (position, role, target, current cell,
directions, the columns it knows full) and per cell (leader, the three
estimates, the round's enter / exit counts); one numba kernel runs a round.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from .distributed_model import DistributedResult, NetworkModel, finished_run, move_toward

#: Stands for "+infinity" in the leaders' integer estimates (sums of a few stay far from overflow).
UNKNOWN = 1 << 40

SEARCHING, ASSIGNED, STOPPED = 0, 1, 2


def cells_per_side(side: float, r_comm: float) -> int:
    """``b`` of Lemma 2.3: cells per side so that points in adjacent cells are within ``r_comm``."""
    return max(1, math.ceil(math.sqrt(5.0) * side / r_comm))


def _cell_of(x: float, y: float, side: float, b: int) -> int:
    """Cell id ``row * b + col`` of a point (a point on a border goes to the cell right / below);
    plain Python: it runs once per agent and target when a simulation starts."""
    s = side / b
    col = min(int(x / s), b - 1)
    row = min(int((side - y) / s), b - 1)
    return row * b + col


@njit(cache=True, nogil=True)
def _centre(cell: int, side: float, b: int) -> tuple[float, float]:
    s = side / b
    row = cell // b
    col = cell % b
    return (col + 0.5) * s, side - (row + 0.5) * s


@njit(cache=True, nogil=True)
def _note(stats: np.ndarray, positions: np.ndarray, a: int, c: int) -> None:
    """Count one message from agent ``a`` to agent ``c`` and track the longest."""
    dx = positions[a, 0] - positions[c, 0]
    dy = positions[a, 1] - positions[c, 1]
    d = np.sqrt(dx * dx + dy * dy)
    stats[0] += 1.0
    if d > stats[1]:
        stats[1] = d


@njit(cache=True, nogil=True)
def _role_assignment(
    cell: int, deciders: np.ndarray, count: int, positions: np.ndarray, targets: np.ndarray,
    cell_ptr: np.ndarray, cell_targets: np.ndarray, taken: np.ndarray,
    role: np.ndarray, target: np.ndarray, deciding: np.ndarray, stats: np.ndarray,
) -> int:
    """MAXIMAL MATCH between the cell's deciding agents and its free targets; returns the
    leader (smallest matched id) or -1 when nothing could be matched."""
    lo, hi = cell_ptr[cell], cell_ptr[cell + 1]
    free = 0
    for e in range(lo, hi):
        if not taken[cell_targets[e]]:
            free += 1
    if free == 0 or count == 0:
        return -1
    for p in range(count):  # everyone hears everyone in the cell (one broadcast each)
        for q in range(count):
            if p != q:
                _note(stats, positions, deciders[p], deciders[q])
    pairs = count * free
    dist = np.empty(pairs)
    pa = np.empty(pairs, dtype=np.int64)
    pt = np.empty(pairs, dtype=np.int64)
    k = 0
    for p in range(count):
        a = deciders[p]
        for e in range(lo, hi):
            t = cell_targets[e]
            if taken[t]:
                continue
            dx = positions[a, 0] - targets[t, 0]
            dy = positions[a, 1] - targets[t, 1]
            dist[k] = np.sqrt(dx * dx + dy * dy)
            pa[k] = a
            pt[k] = t
            k += 1
    order = np.argsort(dist, kind="mergesort")  # ties: smaller agent id, then target order
    leader = -1
    for q in range(pairs):
        a = pa[order[q]]
        t = pt[order[q]]
        if role[a] != SEARCHING or taken[t]:
            continue
        role[a] = ASSIGNED
        target[a] = t
        taken[t] = True
        deciding[a] = False
        if leader < 0 or a < leader:
            leader = a
    return leader


@njit(cache=True, nogil=True)
def _nearest_free(a: int, cell: int, positions: np.ndarray, targets: np.ndarray,
                  cell_ptr: np.ndarray, cell_targets: np.ndarray, taken: np.ndarray) -> int:
    best = -1
    best_d = np.inf
    for e in range(cell_ptr[cell], cell_ptr[cell + 1]):
        t = cell_targets[e]
        if taken[t]:
            continue
        dx = positions[a, 0] - targets[t, 0]
        dy = positions[a, 1] - targets[t, 1]
        d = dx * dx + dy * dy
        if d < best_d:
            best_d = d
            best = t
    return best


@njit(cache=True, nogil=True)
def _grant(exists: bool, boss: int, granted: np.ndarray, estimate: np.ndarray, cell: int) -> bool:
    """A leader's answer to "are there free targets below / to the right?": yes to at most
    ``estimate[cell]`` agents this round (``granted`` counts them); a cell without a leader
    has no estimate and answers yes whenever the neighbouring cell exists."""
    if not exists:
        return False
    if boss < 0:
        return True
    if granted[cell] < estimate[cell]:
        granted[cell] += 1
        return True
    return False


#: Rows of the per-cell scratch array ``work`` of :func:`_grid_round` (reset after each round).
(UP_MSG, LEFT_MSG, SENT, YES_BELOW, YES_RIGHT, ENTERS, EXITS, IN_FROM_BELOW, OUT_TO_BELOW, IN_FROM_RIGHT,
 OUT_TO_RIGHT) = range(11)
WORK_ROWS = 11


class CellTargets(NamedTuple):
    """The targets (m, 2), grouped by cell (``cell_targets[cell_ptr[c]:cell_ptr[c + 1]]`` lie in
    cell c), and which are taken (m,) bool."""

    targets: np.ndarray
    cell_ptr: np.ndarray
    cell_targets: np.ndarray
    taken: np.ndarray


class Searchers(NamedTuple):
    """Each agent's state (n,): its role (SEARCHING, ASSIGNED, STOPPED), target (-1 none), current
    cell, column and row directions (+1 / -1), the columns it knows full (n, b) and whether it
    decides this round (it stands on its cell's centre)."""

    role: np.ndarray
    target: np.ndarray
    currcell: np.ndarray
    dircol: np.ndarray
    dirrow: np.ndarray
    colfull: np.ndarray
    deciding: np.ndarray


class Cells(NamedTuple):
    """Each cell's state (cells,): its leader (-1 none), the leader's estimates (free targets less
    agents: ``delta`` in the cell, ``below`` and ``right`` beyond it) and the agents in it;
    ``led[:n_led[0]]`` the cells that have a leader; ``work`` the zeroed per-cell scratch
    ``(WORK_ROWS, cells)``."""

    leader: np.ndarray
    delta: np.ndarray
    below: np.ndarray
    right: np.ndarray
    cell_agents: np.ndarray
    led: np.ndarray
    n_led: np.ndarray
    work: np.ndarray


@njit(cache=True, nogil=True)
def _grid_round(b: int, positions: np.ndarray, on_cells: CellTargets, agents: Searchers, cells: Cells,
                stats: np.ndarray) -> None:
    """One communication round: leaders' messages, role assignment in newly reached cells,
    the decisions of the agents that have reached a cell centre, and the leaders' updates.

    ``work`` is left zeroed again. A round costs O(leaders + deciding agents), not O(cells), so
    fine partitions of large environments stay cheap.
    """
    targets, cell_ptr, cell_targets, taken = on_cells.targets, on_cells.cell_ptr, on_cells.cell_targets, on_cells.taken
    role, target, currcell, deciding = agents.role, agents.target, agents.currcell, agents.deciding
    dircol, dirrow, colfull = agents.dircol, agents.dirrow, agents.colfull
    leader, delta, below, right, cell_agents = cells.leader, cells.delta, cells.below, cells.right, cells.cell_agents
    led, n_led, work = cells.led, cells.n_led, cells.work
    n = positions.shape[0]
    # (a) Broadcasts of the leaders in office at the start of the round.
    leaders_before = n_led[0]
    for q in range(leaders_before):
        cell = led[q]
        work[SENT, cell] = 1
        work[UP_MSG, cell] = below[cell] + delta[cell]
        if cell < b:
            work[LEFT_MSG, cell] = right[cell] + below[cell] + delta[cell]
    for q in range(leaders_before):
        cell = led[q]
        if cell >= b and work[SENT, cell - b] == 1:
            _note(stats, positions, leader[cell], leader[cell - b])
        if cell < b and cell % b > 0 and work[SENT, cell - 1] == 1:
            _note(stats, positions, leader[cell], leader[cell - 1])
    # (b) Role assignment where the first agents reach a leaderless cell that has targets.
    count = 0
    for a in range(n):
        if deciding[a] and role[a] == SEARCHING:
            count += 1
    deciders = np.empty(count, dtype=np.int64)
    keys = np.empty(count, dtype=np.int64)
    k = 0
    for a in range(n):
        if deciding[a] and role[a] == SEARCHING:
            deciders[k] = a
            keys[k] = currcell[a]
            k += 1
    order = np.argsort(keys, kind="mergesort")  # by cell, ids ascending within a cell
    grouped = deciders[order]
    lo = 0
    while lo < count:
        cell = currcell[grouped[lo]]
        hi = lo
        while hi < count and currcell[grouped[hi]] == cell:
            hi += 1
        if leader[cell] < 0 and cell_ptr[cell + 1] > cell_ptr[cell]:
            chosen = _role_assignment(cell, grouped[lo:hi], hi - lo, positions, targets, cell_ptr, cell_targets,
                                      taken, role, target, deciding, stats)
            if chosen >= 0:
                leader[cell] = chosen
                led[n_led[0]] = cell
                n_led[0] += 1
                row, col = cell // b, cell % b
                delta[cell] = (cell_ptr[cell + 1] - cell_ptr[cell]) - cell_agents[cell]
                below[cell] = 0 if row == b - 1 else UNKNOWN
                right[cell] = 0 if col == b - 1 else UNKNOWN
        lo = hi
    # (c) Decisions, in id order; each touches only its cell's leader and its own state.
    touched = np.empty(2 * count, dtype=np.int64)
    n_touched = 0
    for a in deciders:
        if not deciding[a] or role[a] != SEARCHING:
            continue
        cell = currcell[a]
        row, col = cell // b, cell % b
        boss = leader[cell]
        if boss >= 0:
            _note(stats, positions, a, boss)
            _note(stats, positions, boss, a)
            t = _nearest_free(a, cell, positions, targets, cell_ptr, cell_targets, taken)
            if t >= 0:
                role[a] = ASSIGNED
                target[a] = t
                taken[t] = True
                deciding[a] = False
                continue
        touched[n_touched] = cell
        n_touched += 1
        new = -1
        top_row_turn = False
        if dircol[a] == 1:
            if _grant(row < b - 1, boss, work[YES_BELOW], below, cell):
                new = cell + b
            else:
                dircol[a] = -1
                if row > 0:
                    new = cell - b
                else:
                    top_row_turn = True
        elif row > 0:
            new = cell - b
        else:
            top_row_turn = True
        if top_row_turn:
            if dirrow[a] == 1:
                colfull[a, col] = True
                if _grant(col < b - 1, boss, work[YES_RIGHT], right, cell):
                    new = cell + 1
                else:
                    dirrow[a] = -1
                    for c2 in range(col + 1, b):
                        colfull[a, c2] = True
                    if col > 0:
                        new = cell - 1
            elif col > 0:
                new = cell - 1
            if new >= 0 and not colfull[a, new % b]:
                dircol[a] = 1
        if new < 0:
            role[a] = STOPPED  # no column left to search
            deciding[a] = False
            continue
        touched[n_touched] = new
        n_touched += 1
        # Leave `cell` for `new`: exit to this cell's leader, enter to the new cell's leader.
        work[EXITS, cell] += 1
        work[ENTERS, new] += 1
        cell_agents[cell] -= 1
        cell_agents[new] += 1
        if new == cell + b:
            work[OUT_TO_BELOW, cell] += 1
        elif new == cell - b:
            work[IN_FROM_BELOW, new] += 1
        elif new == cell + 1:
            work[OUT_TO_RIGHT, cell] += 1
        else:
            work[IN_FROM_RIGHT, new] += 1
        if boss >= 0:
            _note(stats, positions, a, boss)
        if leader[new] >= 0:
            _note(stats, positions, a, leader[new])
        currcell[a] = new
        deciding[a] = False
    # (d) Leaders update their estimates from the messages of this round.
    for q in range(n_led[0]):
        cell = led[q]
        row, col = cell // b, cell % b
        if row == 0:
            if col < b - 1 and work[SENT, cell + 1] == 1:
                right[cell] = work[LEFT_MSG, cell + 1]
            right[cell] += work[IN_FROM_RIGHT, cell] - work[OUT_TO_RIGHT, cell]
            if right[cell] > 0 and work[IN_FROM_RIGHT, cell] > 0:
                right[cell] = 0
        if row < b - 1 and work[SENT, cell + b] == 1:
            below[cell] = work[UP_MSG, cell + b]
        below[cell] += work[IN_FROM_BELOW, cell] - work[OUT_TO_BELOW, cell]
        if below[cell] > 0 and work[IN_FROM_BELOW, cell] > 0:
            below[cell] = 0
        delta[cell] += work[EXITS, cell] - work[ENTERS, cell]
    # Leave the scratch zeroed for the next round.
    for q in range(leaders_before):
        for w in range(WORK_ROWS):
            work[w, led[q]] = 0
    for q in range(n_touched):
        for w in range(WORK_ROWS):
            work[w, touched[q]] = 0


@njit(cache=True, nogil=True)
def _set_goals(b: int, side: float, positions: np.ndarray, targets: np.ndarray, role: np.ndarray,
               target: np.ndarray, currcell: np.ndarray, deciding: np.ndarray,
               goals: np.ndarray, moving: np.ndarray) -> None:
    for a in range(positions.shape[0]):
        if role[a] == ASSIGNED:
            goals[a, 0] = targets[target[a], 0]
            goals[a, 1] = targets[target[a], 1]
            moving[a] = True
        elif role[a] == SEARCHING and not deciding[a]:
            cx, cy = _centre(currcell[a], side, b)
            goals[a, 0] = cx
            goals[a, 1] = cy
            moving[a] = True
        else:
            moving[a] = False


@njit(cache=True, nogil=True)
def _after_motion(positions: np.ndarray, goals: np.ndarray, role: np.ndarray, deciding: np.ndarray) -> int:
    """Mark searching agents that reached their cell centre as deciding; return how many
    assigned agents stand on their target."""
    settled = 0
    for a in range(positions.shape[0]):
        on_goal = positions[a, 0] == goals[a, 0] and positions[a, 1] == goals[a, 1]
        if role[a] == ASSIGNED and on_goal:
            settled += 1
        elif role[a] == SEARCHING and not deciding[a] and on_goal:
            deciding[a] = True
    return settled


def simulate_grid(
    agents: np.ndarray,
    targets: np.ndarray,
    model: NetworkModel,
    max_time: float | None,
    record_trace: bool,
) -> DistributedResult:
    """Run GRID ASSGMT from the given positions until the assignment is complete or ``max_time``.

    ``agents`` ``(n, 2)`` and ``targets`` ``(m, 2)`` are checked float arrays inside the
    environment, ``n, m >= 1``. With ``max_time=None`` the limit is the paper's worst-case
    path (up and down every column and along the top row, Theorem 6.5) plus one round per
    cell visited, with a margin; not completing within it would be a defect.
    """
    n, m = agents.shape[0], targets.shape[0]
    side = model.side
    b = cells_per_side(side, model.r_comm)
    cells = b * b
    if max_time is None:
        path = 2.0 * side * (b + 2) + math.sqrt(2.0) * side
        visits = 2 * b * b + 2 * b + 2
        max_time = 2.0 * (path / model.v_max + 2 * visits * model.round_time) + 4.0 * model.round_time
    max_rounds = int(math.ceil(max_time / model.round_time))

    target_cell = np.array([_cell_of(x, y, side, b) for x, y in targets], dtype=np.int64)
    cell_targets = np.argsort(target_cell, kind="stable").astype(np.int64)
    cell_ptr = np.zeros(cells + 1, dtype=np.int64)
    np.cumsum(np.bincount(target_cell, minlength=cells), out=cell_ptr[1:])

    positions = agents.copy()
    currcell = np.array([_cell_of(x, y, side, b) for x, y in positions], dtype=np.int64)
    cell_agents = np.bincount(currcell, minlength=cells).astype(np.int64)
    role = np.full(n, SEARCHING, dtype=np.int64)
    target = np.full(n, -1, dtype=np.int64)
    dircol = np.ones(n, dtype=np.int64)
    dirrow = np.ones(n, dtype=np.int64)
    colfull = np.zeros((n, b), dtype=np.bool_)
    deciding = np.ones(n, dtype=np.bool_)
    taken = np.zeros(m, dtype=np.bool_)
    leader = np.full(cells, -1, dtype=np.int64)
    led = np.empty(cells, dtype=np.int64)
    n_led = np.zeros(1, dtype=np.int64)
    work = np.zeros((WORK_ROWS, cells), dtype=np.int64)
    delta = np.zeros(cells, dtype=np.int64)
    below = np.zeros(cells, dtype=np.int64)
    right = np.zeros(cells, dtype=np.int64)
    stats = np.zeros(2)
    travelled = np.zeros(n)
    arrived_at = np.zeros(n)
    goals = positions.copy()
    moving = np.zeros(n, dtype=np.bool_)
    need = min(n, m)
    trace = [positions.copy()] if record_trace else None

    on_cells = CellTargets(targets=targets, cell_ptr=cell_ptr, cell_targets=cell_targets, taken=taken)
    agents_state = Searchers(role=role, target=target, currcell=currcell, dircol=dircol, dirrow=dirrow,
                             colfull=colfull, deciding=deciding)
    cell_state = Cells(leader=leader, delta=delta, below=below, right=right, cell_agents=cell_agents, led=led,
                       n_led=n_led, work=work)
    rounds = 0
    completed = False
    while not completed and rounds < max_rounds:
        now = rounds * model.round_time
        _grid_round(b, positions, on_cells, agents_state, cell_state, stats)
        _set_goals(b, side, positions, targets, role, target, currcell, deciding, goals, moving)
        move_toward(positions, goals, moving, model.step, travelled, arrived_at, now, model.v_max)
        rounds += 1
        if record_trace:
            trace.append(positions.copy())
        completed = _after_motion(positions, goals, role, deciding) == need
    assigned = role == ASSIGNED
    on_target = assigned & (positions == targets[np.maximum(target, 0)]).all(axis=1)
    target_of = np.where(on_target, target, -1)
    return finished_run("grid", model, target_of, completed, rounds, travelled, arrived_at, positions,
                        int(stats[0]), float(stats[1]), trace)
