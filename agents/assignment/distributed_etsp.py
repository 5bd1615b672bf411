"""ETSP ASSGMT: agents walk a ring of the targets and settle conflicts with their neighbours.

From "Monotonic Target Assignment for Robotic Networks" (Smith and Bullo),
Section V and Appendix A, under full target knowledge. Every agent orders the
targets along the same short closed tour (:func:`.etsp.etsp_tour`), heads for
its nearest target ``curr`` and remembers ``next`` and ``prev``, the first
targets after and before ``curr`` on the ring it still believes free, and one
availability bit per target. At every round each agent broadcasts
``(prev, curr, next, id, distance to curr)`` and, for every message received
from an agent within ``r_comm``:

* every target strictly between the sender's ``prev`` and ``next`` (other than
  its own ``curr``) is known to be taken;
* when both head for the same target the one farther from it (the smaller id
  on a tie) loses: it marks the target taken; the winner marks both agents'
  ``next`` taken, because the loser will move on at least that far.

Then it moves ``curr`` forward to the first target still free, recomputes
``next`` and ``prev``, and drives straight to ``curr`` at full speed. An agent
that knows every target taken stops for good (only when agents outnumber
targets).

Arrays hold the state: positions ``(n, 2)``, the three ring indices ``(n,)``
and the availability bits packed 64 to a word ``(n, ceil(m / 64))``. Each
round's neighbour pairs come from a k-d tree; the round's message processing is
one numba kernel that reads a snapshot of the round's broadcasts, so the
outcome does not depend on the order in which messages are handled.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from .bitset import clear_bit, clear_cyclic, full_rows, next_set_cyclic, prev_set_cyclic, set_bit, test_bit
from .distributed_model import DistributedResult, NetworkModel, finished_run, move_toward
from .etsp import etsp_tour, tour_length


class Ring(NamedTuple):
    """Each agent's three ring indices (n,) int64: ``curr`` the target it heads for, ``next``
    and ``prev`` the first targets after and before it it still believes free (-1 once stopped)."""

    prev: np.ndarray
    curr: np.ndarray
    next: np.ndarray


@njit(cache=True, nogil=True)
def _communication_round(
    indptr: np.ndarray,
    neighbours: np.ndarray,
    sent: Ring,
    dist0: np.ndarray,
    ring: Ring,
    bits: np.ndarray,
    counts: np.ndarray,
    active: np.ndarray,
    m: int,
) -> None:
    """COMM-RD for every active agent: ``sent`` and ``dist0`` are the broadcasts (the state at
    the start of the round), ``ring`` receives the new state."""
    prev0, curr0, next0 = sent.prev, sent.curr, sent.next
    prev, curr, nxt = ring.prev, ring.curr, ring.next
    n = prev0.shape[0]
    for i in range(n):
        if not active[i]:
            continue
        ci = curr0[i]
        for e in range(indptr[i], indptr[i + 1]):
            k = neighbours[e]
            # Targets strictly between the sender's prev and next are taken (its curr
            # included when prev and next coincide) - except our own current target.
            # (prev == next gives m - 1 targets: all but that one.)
            keep = test_bit(bits, i, ci)
            clear_cyclic(bits, counts, i, (prev0[k] + 1) % m, (next0[k] - prev0[k] - 1) % m, m)
            if keep:
                set_bit(bits, counts, i, ci)
            if curr0[k] == ci:
                if dist0[i] > dist0[k] or (dist0[i] == dist0[k] and i < k):
                    clear_bit(bits, counts, i, ci)  # conflict lost
                else:
                    if next0[i] != ci:
                        clear_bit(bits, counts, i, next0[i])
                    if next0[k] != ci:
                        clear_bit(bits, counts, i, next0[k])
        if counts[i] == 0:
            active[i] = False  # every target is taken by someone else: stop for good
            curr[i] = -1
            nxt[i] = -1
            prev[i] = -1
            continue
        c = next_set_cyclic(bits, i, ci, m)
        curr[i] = c
        nxt[i] = next_set_cyclic(bits, i, (c + 1) % m, m)
        prev[i] = prev_set_cyclic(bits, i, (c - 1) % m, m)


@njit(cache=True, nogil=True)
def _distances_to_current(positions: np.ndarray, ring: np.ndarray, curr: np.ndarray, out: np.ndarray) -> None:
    for i in range(positions.shape[0]):
        c = curr[i]
        if c < 0:
            out[i] = np.inf
            continue
        dx = ring[c, 0] - positions[i, 0]
        dy = ring[c, 1] - positions[i, 1]
        out[i] = np.sqrt(dx * dx + dy * dy)


@njit(cache=True, nogil=True)
def _held_count(dist: np.ndarray, curr: np.ndarray, active: np.ndarray, m: int, holders: np.ndarray) -> int:
    """Number of ring positions held by exactly one agent standing on it (``holders`` gets
    the number of agents standing on each)."""
    for j in range(m):
        holders[j] = 0
    for i in range(dist.shape[0]):
        if active[i] and dist[i] == 0.0:
            holders[curr[i]] += 1
    held = 0
    for j in range(m):
        if holders[j] == 1:
            held += 1
    return held


@njit(cache=True, nogil=True)
def _csr_from_pairs(pairs: np.ndarray, ids: np.ndarray, positions: np.ndarray, n: int) -> tuple:
    """Both directions of each pair (indices into ``ids``) as CSR lists over all ``n`` agents,
    and the longest pair distance."""
    indptr = np.zeros(n + 1, dtype=np.int64)
    for e in range(pairs.shape[0]):
        indptr[ids[pairs[e, 0]] + 1] += 1
        indptr[ids[pairs[e, 1]] + 1] += 1
    for i in range(n):
        indptr[i + 1] += indptr[i]
    fill = indptr[:-1].copy()
    neighbours = np.empty(2 * pairs.shape[0], dtype=np.int64)
    longest = 0.0
    for e in range(pairs.shape[0]):
        a = ids[pairs[e, 0]]
        c = ids[pairs[e, 1]]
        neighbours[fill[a]] = c
        fill[a] += 1
        neighbours[fill[c]] = a
        fill[c] += 1
        dx = positions[a, 0] - positions[c, 0]
        dy = positions[a, 1] - positions[c, 1]
        longest = max(longest, np.sqrt(dx * dx + dy * dy))
    return indptr, neighbours, longest


def _neighbour_lists(positions: np.ndarray, active: np.ndarray, r_comm: float) -> tuple[np.ndarray, np.ndarray, float]:
    """CSR lists of the active agents within ``r_comm`` of each active agent (k-d tree), and
    the largest distance of a listed pair."""
    from scipy.spatial import cKDTree

    ids = np.flatnonzero(active)
    if ids.size < 2:
        return np.zeros(positions.shape[0] + 1, dtype=np.int64), np.zeros(0, dtype=np.int64), 0.0
    pairs = cKDTree(positions[ids], balanced_tree=False, compact_nodes=False).query_pairs(
        r_comm, output_type="ndarray"
    )
    return _csr_from_pairs(pairs.astype(np.int64), ids, positions, positions.shape[0])


def simulate_etsp(
    agents: np.ndarray,
    targets: np.ndarray,
    model: NetworkModel,
    max_time: float | None,
    record_trace: bool,
) -> DistributedResult:
    """Run ETSP ASSGMT from the given positions until the assignment is complete or ``max_time``.

    ``agents`` ``(n, 2)`` and ``targets`` ``(m, 2)`` are checked float arrays (distinct
    targets, inside the environment, ``n, m >= 1``). With ``max_time=None`` the limit is the
    paper's bound on any agent's path (distance to its nearest target plus one tour) plus
    one round per target, with a margin; not completing within it would be a defect, never an expected outcome.
    """
    n, m = agents.shape[0], targets.shape[0]
    order = etsp_tour(targets)
    ring = np.ascontiguousarray(targets[order])
    if max_time is None:
        bound = np.sqrt(2.0) * model.side + tour_length(targets, order)
        # + one round per target: an agent that reaches a target mid-round waits for the next.
        max_time = 2.0 * bound / model.v_max + (m + 4) * model.round_time
    max_rounds = int(np.ceil(max_time / model.round_time))

    from scipy.spatial import cKDTree

    positions = agents.copy()
    _, nearest = cKDTree(ring).query(positions)
    curr = np.asarray(nearest, dtype=np.int64)
    nxt = (curr + 1) % m
    prev = (curr - 1) % m
    bits, counts = full_rows(n, m)
    active = np.ones(n, dtype=np.bool_)
    travelled = np.zeros(n)
    arrived_at = np.zeros(n)
    dist = np.empty(n)
    holders = np.zeros(m, dtype=np.int64)
    goals = np.empty((n, 2))
    need = min(n, m)
    trace = [positions.copy()] if record_trace else None
    messages = 0
    longest = 0.0
    rounds = 0

    _distances_to_current(positions, ring, curr, dist)
    completed = _held_count(dist, curr, active, m, holders) == need
    while not completed and rounds < max_rounds:
        now = rounds * model.round_time
        indptr, neighbours, pair_longest = _neighbour_lists(positions, active, model.r_comm)
        messages += int(neighbours.shape[0])
        longest = max(longest, pair_longest)
        sent = Ring(prev=prev.copy(), curr=curr.copy(), next=nxt.copy())
        _communication_round(indptr, neighbours, sent, dist, Ring(prev=prev, curr=curr, next=nxt), bits, counts,
                             active, m)
        moving = active.copy()
        goals[moving] = ring[curr[moving]]
        move_toward(positions, goals, moving, model.step, travelled, arrived_at, now, model.v_max)
        rounds += 1
        _distances_to_current(positions, ring, curr, dist)
        if record_trace:
            trace.append(positions.copy())
        completed = _held_count(dist, curr, active, m, holders) == need
    target_of = np.full(n, -1, dtype=np.int64)
    on_target = active & (dist == 0.0)
    target_of[on_target] = order[curr[on_target]]
    if not completed:
        # Agents sharing a target have not settled yet: none of them holds it.
        shared = holders[curr[on_target]] > 1
        target_of[np.flatnonzero(on_target)[shared]] = -1
    return finished_run("etsp", model, target_of, completed, rounds, travelled, arrived_at, positions, messages,
                        longest, trace)
