"""A team's world models, a cycle's sees and the message codes as named compiled records, and a
cycle's hearing and seeing in one call.

:class:`~agents.teams.world_model.TeamBeliefs` keeps every player's model in a dozen arrays
that :func:`~agents.teams.belief_kernels.believe` updates in place. Handing arrays to numba
one by one each cycle costs its dispatcher about 0.2 µs apiece, and a kernel of twenty
positional parameters cannot be read, so the kernels take three records (numba
``StructRef`` structures sharing the arrays, not copying them), whose fields they read by name:

* :class:`BeliefRecord`: the world models and their constants (:data:`BELIEF_FIELDS`), made
  with the model;
* :class:`SeeRecord`: what the players' sees of this cycle told them (:data:`SEE_FIELDS`, the
  :class:`~soccer_sim.perception.views.PlayerViews` arrays of the same names), made by a
  :class:`SeeRecords` once for the arrays of a match's views, which the match overwrites in
  place every cycle, and again whenever the views hand other arrays;
* :class:`MessageCodes`: the tables the say channel's messages are decoded with
  (:data:`CODE_FIELDS`, from :mod:`agents.messages`), one for every team (:func:`message_codes`).

:func:`hear_and_believe` then does a team's whole intake of a cycle in one compiled call:
decode the team messages heard (:func:`~agents.message_kernels.decode_digits`), update the
world models (:func:`~agents.teams.belief_kernels.believe`) and keep each listener's newest
assignment heard (:func:`store_assignments`).
:meth:`~agents.teams.world_model.TeamBeliefs.update` makes the call.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from functools import cache
from operator import attrgetter, is_

import numpy as np
from numba import njit
from numba.core import types
from numba.experimental import structref

from agents.message_kernels import DECODED, decode_digits, stamp_cycle
from agents.messages import DIGIT_OF_BYTE, MESSAGE_GRID
from agents.teams.belief_kernels import believe
from agents.teams.speaking import TurnMemory, take_proposal
from soccer_sim.perception.views import PlayerViews

BELIEF_FIELDS = ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age", "last_seen",
                 "last_seen_cycle", "params", "ball_decay", "speed_max")
"""The fields of :class:`BeliefRecord`: the world models' arrays of
:class:`~agents.teams.world_model.TeamBeliefs` (the ball, the team-mates and the opponents as
each player believes them, with their ages; where and when each player last saw the ball),
``params`` (a :data:`~agents.teams.belief_kernels.BELIEF_PARAMS` record), the ball's decay
per cycle and its largest speed (m/cycle)."""

SEE_FIELDS = ("ball_seen", "ball", "ball_distance", "saw", "seen_count", "seen_position", "seen_side",
              "seen_number", "seen_distance", "position")
"""The fields of :class:`SeeRecord`: the :class:`~soccer_sim.perception.views.PlayerViews`
arrays of these names, what a cycle's intake reads of the players' sees (their
self-localisation ``position`` included)."""

CODE_FIELDS = ("digit_of_byte", "grid")
"""The fields of :class:`MessageCodes`: each character byte's alphabet digit
(:data:`agents.messages.DIGIT_OF_BYTE`), the message grid
:func:`~agents.message_kernels.decode_digits` decodes with (:data:`agents.messages.MESSAGE_GRID`)."""


class _Record(types.StructRef):
    """A numba record type whose fields take the types of the values given, literals unliteral."""

    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


@structref.register
class BeliefRecordType(_Record):
    """The numba type of :class:`BeliefRecord`."""


@structref.register
class SeeRecordType(_Record):
    """The numba type of :class:`SeeRecord`."""


@structref.register
class MessageCodesType(_Record):
    """The numba type of :class:`MessageCodes`."""


class BeliefRecord(structref.StructRefProxy):
    """A team's world-model arrays and constants as one compiled structure (module docstring)."""


class SeeRecord(structref.StructRefProxy):
    """A team's sees of a cycle as one compiled structure (module docstring)."""


class MessageCodes(structref.StructRefProxy):
    """The say channel's decoding tables as one compiled structure (module docstring)."""


structref.define_proxy(BeliefRecord, BeliefRecordType, list(BELIEF_FIELDS))
structref.define_proxy(SeeRecord, SeeRecordType, list(SEE_FIELDS))
structref.define_proxy(MessageCodes, MessageCodesType, list(CODE_FIELDS))


@njit(cache=True)
def _new_belief_record(values: tuple) -> BeliefRecord:  # pragma: no cover - compiled
    return BeliefRecord(*values)


@njit(cache=True)
def _new_see_record(values: tuple) -> SeeRecord:  # pragma: no cover - compiled
    return SeeRecord(*values)


@njit(cache=True)
def _new_message_codes(values: tuple) -> MessageCodes:  # pragma: no cover - compiled
    return MessageCodes(*values)


def _by_name(kind: str, fields: tuple[str, ...], values: Mapping[str, object],
             make: Callable[[tuple], object]) -> object:
    """``make`` (a compiled constructor, cached like the kernels) of ``values`` taken by the
    names ``fields`` in their order (arrays shared, not copied); ValueError naming the names
    that are missing or unknown."""
    missing, unknown = sorted(set(fields) - set(values)), sorted(set(values) - set(fields))
    if missing or unknown:
        raise ValueError(f"{kind}: fields missing {missing}, unknown {unknown}")
    return make(tuple(values[name] for name in fields))


def belief_record(**values: object) -> BeliefRecord:
    """A :class:`BeliefRecord` of ``values`` by field name (every name of
    :data:`BELIEF_FIELDS`, no other; arrays shared, not copied)."""
    return _by_name("BeliefRecord", BELIEF_FIELDS, values, _new_belief_record)


def see_record(views: PlayerViews) -> SeeRecord:
    """A :class:`SeeRecord` sharing ``views``' arrays of :data:`SEE_FIELDS`."""
    return _new_see_record(_see_arrays(views))


_see_arrays = attrgetter(*SEE_FIELDS)
"""``views``' arrays of :data:`SEE_FIELDS`, in that order."""


class SeeRecords:
    """The :class:`SeeRecord` of the views a team is given, made once for as long as the views
    hand the same arrays (a match's observer overwrites its views' arrays in place every cycle)
    and made again when they hand others (views built anew, by a test or a bridge to a real
    server)."""

    def __init__(self) -> None:
        self._arrays: tuple[np.ndarray, ...] = ()
        self._record: SeeRecord | None = None

    def of(self, views: PlayerViews) -> SeeRecord:
        """The :class:`SeeRecord` of ``views``' arrays."""
        arrays = _see_arrays(views)
        if self._record is None or not all(map(is_, arrays, self._arrays)):
            self._record = _new_see_record(arrays)
            self._arrays = arrays
        return self._record


@cache
def message_codes() -> MessageCodes:
    """The :class:`MessageCodes` of :mod:`agents.messages` (one for every team: the tables never
    change)."""
    tables = dict(grid=MESSAGE_GRID, digit_of_byte=DIGIT_OF_BYTE)
    return _by_name("MessageCodes", CODE_FIELDS, tables, _new_message_codes)


@njit(cache=True, nogil=True)
def hear_and_believe(r: BeliefRecord, see: SeeRecord, listener: np.ndarray, speaker: np.ndarray, digits: np.ndarray,
                     codes: MessageCodes, memory: TurnMemory, horizon: int,
                     cycle: int) -> None:  # pragma: no cover - compiled
    """A cycle's intake (module docstring): the messages ``digits`` (p, 10) that ``listener``
    (p,) heard from ``speaker`` (p,) decoded with ``codes``, the world models ``r`` updated
    with the sees ``see`` of ``cycle`` and the messages' world information, and the proposals
    of the right size each listener heard taken into ``memory``
    (:func:`store_assignments`; no columns: none kept)."""
    p = digits.shape[0]
    decoded = np.zeros(p, dtype=DECODED)
    assignment = np.zeros((p, codes.grid[0].max_roles), dtype=np.int64)
    if p > 0:
        decode_digits(digits, codes.grid, decoded, assignment)
    believe(r, see, listener, speaker, decoded, codes.grid[0].max_age, cycle)
    if p > 0 and memory.followed.shape[1] > 0:
        store_assignments(listener, speaker, decoded, assignment, cycle, codes.grid[0].stamps, memory, horizon)


@njit(cache=True, nogil=True)
def store_assignments(listener: np.ndarray, speaker: np.ndarray, decoded: np.ndarray, assignment: np.ndarray,
                      cycle: int, stamps: int, memory: TurnMemory, horizon: int) -> None:  # pragma: no cover
    """Each proposal of the team's size (k) a listener heard from a team-mate at ``cycle``,
    computed later than the last it heard (its cycle recovered from the stamp,
    :func:`~agents.message_kernels.stamp_cycle`), taken into the listener's ``memory``
    (:func:`~agents.teams.speaking.take_proposal`, with ``horizon``)."""
    n, k = memory.followed.shape
    for p in range(listener.shape[0]):
        i, j = listener[p], speaker[p]
        row = decoded[p]
        if not row.valid or row.size != k or j < 0 or j >= n or j == i or i < 0 or i >= n:
            continue
        computed = stamp_cycle(row.stamp, cycle, stamps)
        if computed > memory.proposal_cycle[i]:
            take_proposal(i, assignment[p, :k], computed, row.settled, memory, horizon)


@njit(cache=True, nogil=True)
def hear_block_and_believe(r: BeliefRecord, see: SeeRecord, heard: np.ndarray, said: np.ndarray, codes: MessageCodes,
                           memory: TurnMemory, horizon: int, cycle: int) -> None:  # pragma: no cover - compiled
    """:func:`hear_and_believe` with the messages as the delivery has them: ``heard`` (n, n)
    bool, listener ``l`` heard team-mate ``s``; ``said`` (n, 10) uint8 the characters each
    team-mate said (any row for one that said nothing: it is never heard), each read as its
    alphabet digit (``codes.digit_of_byte``, -1 outside the alphabet). The messages go in
    listener then speaker order, as :meth:`~soccer_sim.perception.views.HeardLog.pairs` lists
    them."""
    digit_of_byte = codes.digit_of_byte
    n = heard.shape[0]
    p = 0
    for listener in range(n):
        for speaker in range(heard.shape[1]):
            p += heard[listener, speaker]
    listeners = np.empty(p, dtype=np.int64)
    speakers = np.empty(p, dtype=np.int64)
    digits = np.empty((p, said.shape[1]), dtype=np.int64)
    k = 0
    for listener in range(n):
        for speaker in range(heard.shape[1]):
            if heard[listener, speaker]:
                listeners[k] = listener
                speakers[k] = speaker
                for d in range(said.shape[1]):
                    digits[k, d] = digit_of_byte[said[speaker, d]]
                k += 1
    hear_and_believe(r, see, listeners, speakers, digits, codes, memory, horizon, cycle)
