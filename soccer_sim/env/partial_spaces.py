"""Observations under partial observation, built from each agent's own :class:`PlayerViews` row.

With ``observation="partial"`` the match gives every player its own perception
(:class:`~soccer_sim.perception.views.PlayerViews`, ``docs/simulator.md`` §14) and the
environment builds agent ``i``'s observation from row ``i`` of its team's views and from
memories that only row ``i`` feeds, never from the true state: its last sighting of the ball
and the players of its last see. Team frame (the team attacks +x), float32, the same
philosophy as :mod:`soccer_sim.env.spaces`: a fixed size whatever the sides' sizes (``k``
slots a side, :data:`~soccer_sim.env.spaces.OBSERVATION_SLOTS` by default), padding zeros,
finite bounds and clipping. Positions are divided by the field's half length ``L``, the sensed
velocity by the players' top speed, stamina by its maximum.

==========================  ======  ===========================================================
slice                       size    what
==========================  ======  ===========================================================
``0:2``                     2       own position as the agent believes it (self-localisation)
``2:4``                     2       own velocity as sensed (sense_body)
``4``                       1       own stamina
``5``                       1       1 for the goalkeeper, else 0
``6:8``                     2       own body direction: cos, sin (the agent looks along it)
``8``                       1       1 when a see arrived this cycle
``9``                       1       cycles since the agent's last see / 10, at most 1 (1 before the first)
``10:12``                   2       the ball where the agent last saw it (0, 0 before it first did)
``12:14``                   2       that position minus the own believed position
``14``                      1       cycles since the agent last saw the ball / 50, at most 1 (1 before it first did)
``15``                      1       1 when the agent sees the ball this cycle
``16:16+3k``                3k      team-mate slots by number, from the last see: x, y, 1 if that
                                    team-mate was identified in it (own slot: own believed position, 1)
``16+3k:16+6k``             3k      opponent slots by number, from the last see: x, y, identified
next                        4U      the ``U`` (:data:`UNIDENTIFIED_SLOTS`, 5) nearest players of the
                                    last see whose number was not seen: x, y, side (+1 team-mate,
                                    -1 opponent, 0 unknown), 1 for a filled slot
next                        9       play mode, one-hot (:class:`~soccer_sim.state.PlayMode` order)
next                        1       1 when the current set play is ours
next                        2       goals for, goals against
next                        1       time: cycle / the episode's horizon
next                        1       half: 0 first, 1 second
next (``say_values=s>0``)   s       the values of the team-mate message heard this cycle (decoded; zeros if none)
next                        1       1 when a decodable team-mate message was heard
next                        1       its speaker's number / (k - 1)
next                        1       1 when an opponent's message was heard (its content is left out)
==========================  ======  ===========================================================

The memories start empty with the match and carry over half time (the teams keep their ends).
A see arrives alternately after one and two cycles; between sees the player slots keep the last
see's content (``9`` says how old it is) and the own, ball and hear values are of this cycle.
Seen positions are where the agent places what it sees: its believed position plus the reported
distance and direction (a few per cent off, more far away). Nobody observes other players'
velocities or the ball's; a policy that wants them stacks observations or keeps a recurrent
state. With several team-mate messages heard in one cycle (``AudioParams.hear_max > 1``) the
first decodable one is shown; a message not in the codec (:mod:`soccer_sim.env.say_codec`)
counts as none.

**Bounds**: own and seen player positions within ``(L + margin) / L`` (1.095 on the regular
field), the ball within a cycle's flight more (1.152), the relative ball within the sum, the
velocity within 2, directions and decoded values within [-1, 1], sides within [-1, 1], goals
within the match's cycles, every flag, age and share in [0, 1]. Observations are clipped to them.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.kernels import make_record
from soccer_sim.env.partial_kernel import OBSERVATION_PARAMS, Memories, ViewRows, observe_rows
from soccer_sim.env.say_codec import SayCodec
from soccer_sim.env.spaces import _TAIL, MODES, VELOCITY_BOUND, Scales, observation_slots
from soccer_sim.perception.views import PlayerViews

UNIDENTIFIED_SLOTS = 5
"""Slots for seen players whose number was not seen (far away, or close behind the agent)."""
SEE_AGE_CAP = 10
"""Cycles after which the see age saturates (sees come every one or two cycles)."""
BALL_AGE_CAP = 50
"""Cycles (5 s) after which the ball's age saturates: a sighting that old says little."""
_OWN = 16
"""Values before the player slots."""
_NEVER = -(10 ** 9)
"""The cycle of a sighting that has not happened (ages saturate)."""


def partial_observation_size(slots: int, say_values: int = 0) -> int:
    """Values in one agent's partial observation, for ``slots`` player slots a side and
    ``say_values`` values per message (module docstring)."""
    return _OWN + 6 * slots + 4 * UNIDENTIFIED_SLOTS + _TAIL + (say_values + 3 if say_values else 0)


def partial_observation_bounds(slots: int, say_values: int, config: MatchConfig) -> tuple[np.ndarray, np.ndarray]:
    """(low, high) float32 arrays of the partial observation (module docstring)."""
    field, physics = config.field, config.physics
    half = field.length / 2.0
    player = (half + field.margin) / half
    ball = (half + field.margin + physics.ball_speed_max) / half
    high = np.ones(partial_observation_size(slots, say_values), dtype=np.float64)
    low = np.zeros_like(high)
    high[0:2], high[2:4], high[10:12], high[12:14] = player, VELOCITY_BOUND, ball, player + ball
    low[0:4], low[6:8], low[10:14] = -high[0:4], -1.0, -high[10:14]
    people = _OWN + 6 * slots
    slot_high = high[_OWN:people].reshape(2 * slots, 3)
    slot_high[:, 0:2] = player
    low[_OWN:people].reshape(2 * slots, 3)[:, 0:2] = -player
    unknown = people + 4 * UNIDENTIFIED_SLOTS
    high[people:unknown].reshape(UNIDENTIFIED_SLOTS, 4)[:, 0:2] = player
    low[people:unknown].reshape(UNIDENTIFIED_SLOTS, 4)[:, 0:3] = (-player, -player, -1.0)
    high[unknown + MODES + 1:unknown + MODES + 3] = max(config.total_cycles, 1)  # goals: at most one a cycle
    if say_values:
        low[unknown + _TAIL:unknown + _TAIL + say_values] = -1.0
    return low.astype(np.float32), high.astype(np.float32)


class PartialObservationBuilder:
    """Writes the partial observations of a team's ``n`` agents (one row each) from its
    :class:`PlayerViews`, keeping each agent's own memory of the ball and of its last see.

    Call :meth:`reset` at the start of a match and :meth:`build` once every cycle (with
    ``write=False`` on cycles nobody looks at: the memories must still see every cycle)."""

    def __init__(self, n: int, m: int, goalie: int, config: MatchConfig, slots: int | None = None,
                 horizon: int | None = None, say_values: int = 0) -> None:
        self.n, self.m = n, m
        self.slots = k = observation_slots(n, m, slots)
        self.say_values = say_values
        self.size = partial_observation_size(k, say_values)
        self.scales = Scales.of(config, horizon)
        self.low, self.high = partial_observation_bounds(k, say_values, config)
        self.codec = SayCodec(say_values) if say_values else None
        self._goalie = np.zeros(n, dtype=np.float32)
        if 0 <= goalie < n:
            self._goalie[goalie] = 1.0
        self._people = _OWN + 6 * k
        """End of the numbered slots; the unidentified slots follow."""
        self._tail = self._people + 4 * UNIDENTIFIED_SLOTS
        self._hear = self._tail + _TAIL
        self._params = make_record(OBSERVATION_PARAMS, length=self.scales.length, speed=self.scales.player_speed,
                                   stamina_max=self.scales.stamina, see_cap=SEE_AGE_CAP, ball_cap=BALL_AGE_CAP,
                                   slots=self.slots, unidentified=UNIDENTIFIED_SLOTS)
        self._seen = np.zeros((n, self._tail - _OWN), dtype=np.float32)
        """Each agent's player slots from its last see (it alone writes its row)."""
        self._ball = np.zeros((n, 2))
        self._ball_cycle = np.full(n, _NEVER, dtype=np.int64)
        self._see_cycle = np.full(n, _NEVER, dtype=np.int64)
        self._memory = Memories(last_ball=self._ball, ball_cycle=self._ball_cycle, see_cycle=self._see_cycle,
                                block=self._seen)
        self.out = np.zeros((n, self.size), dtype=np.float32)
        self.reset()

    def reset(self) -> None:
        """Forget every memory (a new match)."""
        self._seen[:] = 0.0
        self._ball[:] = 0.0
        self._ball_cycle[:] = _NEVER
        self._see_cycle[:] = _NEVER

    def build(self, views: PlayerViews, out: np.ndarray | None = None, write: bool = True) -> np.ndarray | None:
        """Update the memories with this cycle's ``views`` and return the (n, size) observations,
        clipped to the bounds: written into ``out`` when given, else into a new array. With
        ``write=False`` only the memories are updated (None is returned)."""
        cycle = views.cycle
        buf = self.out
        rows = ViewRows(views.position, views.velocity, views.stamina, views.body_direction, views.saw,
                        views.ball_seen, views.ball, views.seen_count, views.seen_position, views.seen_side,
                        views.seen_number)
        observe_rows(cycle, self._params, rows, self._goalie, self._memory, write, buf)
        if not write:
            return None
        tail = buf[:, self._tail:self._hear]
        tail[:, :MODES] = 0.0
        tail[:, int(views.play_mode)] = 1.0
        tail[:, MODES] = float(views.mode_ours)
        tail[:, MODES + 1] = views.score[0]
        tail[:, MODES + 2] = views.score[1]
        tail[:, MODES + 3] = cycle / self.scales.total_cycles
        tail[:, MODES + 4] = views.half
        if self.codec is not None:
            self._write_heard(views, buf[:, self._hear:])
        if out is None:
            out = np.empty_like(buf)
        np.maximum(buf, self.low, out=out)
        return np.minimum(out, self.high, out=out)

    def _write_heard(self, views: PlayerViews, hear: np.ndarray) -> None:
        """The hear part (module docstring) of every agent from its own heard messages: the first
        decodable team-mate message of each, and the opponent flag."""
        values, codec = self.say_values, self.codec
        hear[:] = 0.0
        hear[:, values + 2] = [1.0 if heard else 0.0 for heard in views.heard_opponents]
        rows, decoded, speakers = [], [], []
        for i, mates in enumerate(views.heard_mates):
            for speaker, message in mates:
                said = codec.values_of(message)
                if said is not None:
                    rows.append(i)
                    decoded.append(said)
                    speakers.append(speaker)
                    break
        if rows:
            hear[rows, :values] = decoded
            hear[rows, values] = 1.0
            hear[rows, values + 1] = np.array(speakers, dtype=np.float32) / max(self.slots - 1, 1)
