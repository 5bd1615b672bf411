"""A team's world models as one compiled record, and a cycle's hearing and seeing in one call.

:class:`~agents.teams.world_model.TeamBeliefs` keeps every player's model in a dozen arrays
that :func:`~agents.teams.belief_kernels.believe` updates in place. Handing them to numba one
by one each cycle costs its dispatcher about 0.2 µs apiece, so they live in one numba
structure (:class:`BeliefRecord`, a ``StructRef`` sharing the arrays, made with the model).
:func:`hear_and_believe` then does a team's whole intake of a cycle in one compiled call:
decode the team-mates' messages (:func:`~agents.message_kernels.decode_digits`), update the
world models (:func:`~agents.teams.belief_kernels.believe`) and store the votes heard
(:func:`agents.roles.voting._store_votes`), what :func:`~agents.messages.heard_batch`, the
world-model kernel and :meth:`~agents.roles.voting.VoteBook.hear` would do one after the other.
:meth:`~agents.teams.world_model.TeamBeliefs.update` makes the call.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from numba.core import types
from numba.experimental import structref

from agents.message_kernels import decode_digits
from agents.roles.voting import _store_votes
from agents.teams.belief_kernels import believe

FIELDS = ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age", "last_seen",
          "last_seen_cycle", "params", "ball_decay", "speed_max")
"""The fields of :class:`BeliefRecord`: :func:`believe`'s arguments that stay from cycle to cycle."""


@structref.register
class BeliefRecordType(types.StructRef):
    """The numba type of :class:`BeliefRecord`."""

    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


class BeliefRecord(structref.StructRefProxy):
    """A team's world-model arrays and constants as one compiled structure (module docstring)."""


structref.define_proxy(BeliefRecord, BeliefRecordType, list(FIELDS))


@njit(cache=True)
def new_record(values: tuple) -> BeliefRecord:  # pragma: no cover - compiled
    """A :class:`BeliefRecord` of ``values``, the values of :data:`FIELDS` in that order (arrays
    are shared, not copied); compiled and cached like the kernels."""
    return BeliefRecord(*values)


@njit(cache=True, nogil=True)
def hear_and_believe(r: BeliefRecord, ball_seen, ball_at, ball_distance, saw, count, at, side, number, distance,
                     position, listener, speaker, digits, decoding: np.ndarray, codes: tuple, votes, vote_cycle,
                     cycle: int) -> None:  # pragma: no cover - compiled
    """A cycle's intake (module docstring): the messages ``digits`` (p, 10) that ``listener``
    (p,) heard from ``speaker`` (p,) decoded (``decoding``: :data:`agents.messages.WORLD_GRID`),
    the world models updated with the senses and the world messages, the votes of the right
    size stored in ``votes`` (n, n, k) and ``vote_cycle`` (n, n) (k = 0: none kept).
    ``codes``: the world and vote kinds' codes and the most players a vote covers
    (:data:`agents.messages.CODES`). The senses are the views' arrays in
    :func:`~agents.teams.belief_kernels.believe`'s order."""
    p = digits.shape[0]
    kind = np.full(p, -1, dtype=np.int64)
    grid = np.zeros((p, 7), dtype=np.int64)
    world = np.zeros((p, 7))
    vote = np.zeros((p, codes[2]), dtype=np.int64)
    vote_size = np.zeros(p, dtype=np.int64)
    vote_cycle_sent = np.zeros(p, dtype=np.int64)
    if p > 0:
        decode_digits(digits, decoding, kind, grid, world, vote, vote_size, vote_cycle_sent)
    believe(r.ball, r.ball_vel, r.ball_age, r.mate_pos, r.mate_age, r.opp_pos, r.opp_age, r.last_seen,
            r.last_seen_cycle, ball_seen, ball_at, ball_distance, saw, count, at, side, number, distance, position,
            listener, speaker, kind, world, codes[0], cycle, r.params, r.ball_decay, r.speed_max)
    if p > 0 and votes.shape[2] > 0:
        _store_votes(listener, speaker, kind, vote, vote_size, vote_cycle_sent, codes[1], cycle, decoding[0].modulus,
                     votes, vote_cycle)


@njit(cache=True, nogil=True)
def hear_block_and_believe(r: BeliefRecord, ball_seen, ball_at, ball_distance, saw, count, at, side, number, distance,
                           position, heard, said, digit_of_byte, decoding: np.ndarray, codes: tuple, votes, vote_cycle,
                           cycle: int) -> None:  # pragma: no cover - compiled
    """:func:`hear_and_believe` with the messages as the delivery has them: ``heard`` (n, n)
    bool, listener ``l`` heard team-mate ``s``; ``said`` (n, 10) uint8 the characters each
    team-mate said (any row for one that said nothing: it is never heard); ``digit_of_byte``
    (256,) each character's alphabet digit (-1 outside it). The messages go in listener then
    speaker order, as :meth:`~soccer_sim.perception.views.HeardLog.pairs` lists them."""
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
    hear_and_believe(r, ball_seen, ball_at, ball_distance, saw, count, at, side, number, distance, position, listeners,
                     speakers, digits, decoding, codes, votes, vote_cycle, cycle)
