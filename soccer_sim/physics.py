"""Collision solving with pymunk: the player discs, the ball and four static goal posts.

The world lives in the :class:`~soccer_sim.state.WorldState`'s arrays; pymunk is used once per
cycle as a collision solver. The state's body table (:attr:`WorldState.body_table
<soccer_sim.state.WorldState.body_table>`) is laid out exactly like pymunk's bulk body data
(``pymunk.batch`` with POSITION | VELOCITY: ``x, y, vx, vy`` per body, in the order the
bodies are added here: the players, the ball, then pymunk's static body, the posts' anchor),
so writing the whole world into pymunk and reading it back are one call each, straight from
and into the state's own table, with no per-body Python objects.

Units: pymunk's time unit is one cycle, so velocities are m/cycle and one cycle is a total
``dt`` of 1, split into sub-steps when bodies that can meet close in fast (so that players,
and with rigid body-ball contacts the ball, cannot jump over each other between two collision
checks; see :class:`SubstepPlanner`). Body-ball contacts follow
:attr:`PhysicsConfig.body_ball_contact <soccer_sim.config.PhysicsConfig.body_ball_contact>`:
by default rcssserver's separation of the overlaps left at the end of the cycle.
"""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pymunk.batch as pbatch

from soccer_sim.config import MatchConfig
from soccer_sim.errors import SoccerSimError
from soccer_sim.kernels import (BALL_CONTACT_PARAMS, MARGIN_PARAMS, OVERLAP_PARAMS, SUBSTEP_PARAMS,
                                keep_in_field_and_count_contacts, make_record, resolve_ball_contacts,
                                separate_ball_overlaps, substeps_needed)
from soccer_sim.state import PlayMode, WorldState

#: pymunk collision types of the bodies.
HOME_PLAYER, AWAY_PLAYER, BALL, POST = 1, 2, 3, 4

_BODY_FIELDS = pbatch.BodyFields.POSITION | pbatch.BodyFields.VELOCITY
_NO_TOUCHERS = np.zeros(0, dtype=np.int64)
_NO_COLLISIONS = pymunk.ShapeFilter(categories=0, mask=0)
_ALL_COLLISIONS = pymunk.ShapeFilter()
_KICK_GROUP = pymunk.ShapeFilter(group=1)
"""Shapes sharing a non-zero group never collide: the ball and this cycle's kickers."""
_PLAYER_BIT, _BALL_BIT, _POST_BIT = 0b001, 0b010, 0b100
_PLAYER_NOT_BALL = pymunk.ShapeFilter(categories=_PLAYER_BIT, mask=_PLAYER_BIT | _POST_BIT)
_BALL_NOT_PLAYER = pymunk.ShapeFilter(categories=_BALL_BIT, mask=_POST_BIT)
"""With rcssserver's or swept body-ball contacts, pymunk never sees the ball meet a player: the
physics resolves those contacts itself after the move (see
:func:`soccer_sim.kernels.separate_ball_overlaps` and :func:`soccer_sim.kernels.resolve_ball_contacts`)."""
_CONTACT_PASSES = 3
"""Rounds of swept body-ball contact resolution per cycle (the first finds the earliest contact
on the ball's path; later ones catch players that ran into the ball's corrected position)."""
_SEPARATION_ROUNDS = 10
"""Rounds of rcssserver's overlap resolution per cycle at most (its ``max_loop``)."""
_PLAY_ON = int(PlayMode.PLAY_ON)
_SOLVER_ITERATIONS = 3
"""Constraint-solver iterations per sub-step: frictionless circles converge fast, and the
sub-steps repeat the solve anyway."""
_COLLISION_SLOP = 0.005
"""Overlap (m) pymunk tolerates between touching bodies before pushing them apart."""
_HASH_CELL = 10.0
"""Cell size (m) of pymunk's spatial hash. Large cells suit 23 bodies: in a scrum, where the
collision solver spends its time, a few big cells beat many small ones (and the hash beats
pymunk's default bounding-box tree by about a quarter)."""
_HASH_CELLS = 50
"""Number of buckets of the spatial hash table (small: it stays in cache)."""
CONTACT_BEGIN_GAP = 0.01
"""Two teammates come into contact when the gap between their bodies drops below this (m)..."""
CONTACT_END_GAP = 0.05
"""...and the contact ends when the gap grows beyond this (m); the hysteresis keeps a pair
jostling at the threshold from counting as many contacts."""


class PymunkChangedError(SoccerSimError, RuntimeError):
    """The installed pymunk does not behave like the pymunk 7 releases the bulk body transfer
    was written for (see :class:`_BulkBodies`)."""

    def __init__(self, detail: str) -> None:
        self.detail = detail
        super().__init__(
            f"soccer_sim cannot exchange body data with pymunk {pymunk.version}: {detail}. The bulk "
            "transfer relies on pymunk 7 internals (pymunk._chipmunk, Space._space, pymunk.batch.Buffer; "
            "tested with 7.1 and 7.3); install a supported release: pip install 'pymunk>=7.1,<8'")

    def __reduce__(self) -> tuple[type, tuple[str]]:
        """Rebuild from the detail alone, so the error crosses process boundaries (a worker
        pool's pickling) with its message intact."""
        return type(self), (self.detail,)


class SubstepPlanner:
    """How many equal sub-steps a cycle needs so that nothing can pass through anything.

    ``max_substep_distance`` bounds how far bodies move *relative to each other* in one
    sub-step, for every pair that could meet during the cycle (gap between their surfaces no
    larger than their relative displacement in the cycle):

    * two players: at most twice the distance (each may move it, head-on: then they close by
      at most the sum of their radii when it is 0.3 m, so their centres cannot cross);
    * the ball and a player, when the collision solver handles them (``body_ball_contact =
      "rigid"``): at most the distance itself (below their contact distance); rcssserver's
      contacts look only at the end of the cycle, and swept ones sweep the ball's path
      against every player's exactly, whatever their speeds, so these pairs need no sub-steps;
    * the ball and a goal post: at most the ball-post contact distance (a post is thin).

    Pairs that cannot meet impose nothing, so a fast ball in free flight or a sprinter in
    open space costs no sub-steps; only closing speeds near other bodies do. This is the
    guarantee the per-body reading of the limit gives (no pair closes faster), at a
    fraction of the sub-steps: in a scrum most players run the same way.
    """

    def __init__(self, config: MatchConfig) -> None:
        phys, fld = config.physics, config.field
        post_contact = fld.goal_post_radius + phys.ball_radius
        self._params = make_record(
            SUBSTEP_PARAMS, player_radius=phys.player_radius, ball_radius=phys.ball_radius,
            max_step=phys.max_substep_distance, post_contact=post_contact,
            post_step=min(phys.max_substep_distance, post_contact), post_x=fld.half_length,
            post_y=fld.goal_width / 2 + fld.goal_post_radius,
            ball_meets_players=phys.body_ball_contact == "rigid")

    def count(self, bodies: np.ndarray, ball_free: bool) -> int:
        """Sub-steps for the cycle about to be simulated. ``bodies``: rows ``[x, y, vx, vy]``,
        the players then the ball (:attr:`WorldState.bodies <soccer_sim.state.WorldState.bodies>`);
        ``ball_free``: False while a goalkeeper holds the ball (it does not collide then)."""
        return substeps_needed(bodies, ball_free, self._params)


class Physics:
    """A pymunk space mirroring a :class:`~soccer_sim.state.WorldState`'s bodies; steps one
    cycle at a time, reading the state's body table before and writing it back after.

    Collects the players whose body touched the ball during a step (with rigid contacts, a
    pymunk collision callback: rare, so cheap), and counts contacts between teammates: a pair of
    players of one team comes into contact when the gap between their bodies at the end of
    a cycle is below ``CONTACT_BEGIN_GAP`` and was not in contact before. (Counting them in
    a collision callback instead cost more than the rest of the cycle's physics: in a
    scrum, teammates touch several times per cycle.)
    """

    def __init__(self, config: MatchConfig, state: WorldState) -> None:
        phys, fld = config.physics, config.field
        home, away = state.sizes
        n2 = home + away
        self._table = state.body_table
        """The state's (P + 2, 4) body table: the players, the ball, pymunk's static body."""
        self._dynamic = state.bodies
        """Its players and ball rows."""
        self._state = state
        self._contact_model = phys.body_ball_contact
        self._rigid_ball = phys.body_ball_contact == "rigid"
        self._ball_filter = _ALL_COLLISIONS if self._rigid_ball else _BALL_NOT_PLAYER
        player_filter = _ALL_COLLISIONS if self._rigid_ball else _PLAYER_NOT_BALL
        self._before = np.zeros_like(self._dynamic)
        """The players and the ball as they were before this cycle's move (contact sweeps)."""
        self._ghost = np.zeros(n2, dtype=np.bool_)
        """This cycle's kickers: their bodies let the ball pass (a kick plays it around them)."""
        self._swept_rows = np.zeros(_CONTACT_PASSES, dtype=np.int64)
        self._contact_rows = np.zeros(n2, dtype=np.int64)
        self._collided = np.zeros(n2, dtype=np.bool_)
        """Scratch flags of rcssserver's overlap resolution (all False between cycles)."""
        self._overlap_params = make_record(OVERLAP_PARAMS, contact=phys.player_radius + phys.ball_radius,
                                           factor=phys.collision_velocity_factor, rounds=_SEPARATION_ROUNDS)
        self._contact_params = make_record(BALL_CONTACT_PARAMS, contact=phys.player_radius + phys.ball_radius,
                                           factor=phys.collision_velocity_factor)
        self.space = space = pymunk.Space()
        space.iterations = _SOLVER_ITERATIONS
        space.collision_slop = _COLLISION_SLOP
        space.use_spatial_hash(_HASH_CELL, _HASH_CELLS)
        self.teammate_contacts = np.zeros(2, dtype=np.int64)
        """Contacts begun between two players of the same team, per team (home, away)."""
        self._in_contact = np.zeros((n2, n2), dtype=np.bool_)
        diameter = 2.0 * phys.player_radius
        self._after_params = make_record(
            MARGIN_PARAMS, home=home, players=n2, begin2=(diameter + CONTACT_BEGIN_GAP) ** 2,
            end2=(diameter + CONTACT_END_GAP) ** 2, x_max=fld.half_length + fld.margin,
            y_max=fld.half_width + fld.margin)
        self._touchers: list[int] = []
        self._ball_collides = True
        self._player_shapes: list[pymunk.Circle] = []

        bodies: list[pymunk.Body] = []
        for row in range(n2):
            body = pymunk.Body(phys.player_mass, math.inf)
            shape = pymunk.Circle(body, phys.player_radius)
            shape.collision_type = HOME_PLAYER if row < home else AWAY_PLAYER
            shape.elasticity = phys.player_restitution
            shape.friction = 0.0
            shape.row = row  # read back by the ball-touch callback
            shape.filter = player_filter
            space.add(body, shape)
            bodies.append(body)
            self._player_shapes.append(shape)
        self.ball_body = pymunk.Body(phys.ball_mass, math.inf)
        self.ball_shape = pymunk.Circle(self.ball_body, phys.ball_radius)
        self.ball_shape.collision_type = BALL
        self.ball_shape.elasticity = phys.ball_restitution
        self.ball_shape.friction = 0.0
        self.ball_shape.filter = self._ball_filter
        space.add(self.ball_body, self.ball_shape)
        bodies.append(self.ball_body)
        for sx in (-1.0, 1.0):
            for sy in (-1.0, 1.0):
                # Post centres sit just outside the goal mouth so the mouth stays goal_width wide.
                centre = (sx * fld.half_length, sy * (fld.goal_width / 2 + fld.goal_post_radius))
                post = pymunk.Circle(space.static_body, fld.goal_post_radius, centre)
                post.collision_type = POST
                post.elasticity = 1.0
                post.friction = 0.0
                space.add(post)

        if self._rigid_ball:
            space.on_collision(BALL, HOME_PLAYER, begin=self._ball_begin)
            space.on_collision(BALL, AWAY_PLAYER, begin=self._ball_begin)

        self._bulk = _BulkBodies(space, self._table)
        self._check_layout(bodies)

    def _check_layout(self, bodies: list[pymunk.Body]) -> None:
        """Make sure pymunk iterates the bodies in the order the body table assumes."""
        buffer = pbatch.Buffer()
        pbatch.get_space_bodies(self.space, pbatch.BodyFields.BODY_ID, buffer)
        ids = np.frombuffer(buffer.int_buf(), dtype=np.uintp)
        expected = [b.id for b in bodies]
        if ids.shape[0] != self._table.shape[0] or list(ids[: len(expected)]) != expected:
            raise PymunkChangedError("it iterates the bodies in an unexpected order")

    # --- collision callback (called by pymunk during step) ---------------------------------
    def _ball_begin(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        self._touchers.append(arbiter.shapes[1].row)

    # --- per cycle ---------------------------------------------------------------------------
    def set_ball_collides(self, collides: bool) -> None:
        """Switch the ball's collisions off while a goalkeeper holds it (and back on after)."""
        if collides != self._ball_collides:
            self.ball_shape.filter = self._ball_filter if collides else _NO_COLLISIONS
            self._ball_collides = collides

    def step(self, substeps: int, kickers: np.ndarray = _NO_TOUCHERS) -> np.ndarray:
        """Advance one cycle in ``substeps`` equal sub-steps; return the rows of the players whose
        body began touching the ball (in order of first contact, no repeats).

        With swept or rigid contacts, the players in ``kickers`` (rows that kicked this cycle)
        do not collide with the ball during this cycle: a kick plays the ball around the
        kicker's body. rcssserver's contacts ignore ``kickers``: a ball that ends the cycle
        overlapping its kicker meets it like any other body.
        Reads the state's bodies into pymunk first (so whatever the match or the referee wrote
        is used) and writes the result back into them; then keeps the players within the
        field plus its margin and counts new teammate contacts.
        """
        if self._contact_model == "rcssserver":
            return self._step_with_overlap_separation(substeps)
        if not self._rigid_ball:
            return self._step_with_swept_contacts(substeps, kickers)
        ghosts = kickers.size and self._ball_collides
        if ghosts:
            self.ball_shape.filter = _KICK_GROUP
            for row in kickers.tolist():
                self._player_shapes[row].filter = _KICK_GROUP
        bulk = self._bulk
        bulk.write()
        bulk.step(substeps)
        bulk.read()
        keep_in_field_and_count_contacts(self._table, self._in_contact, self._after_params, self.teammate_contacts)
        if ghosts:
            self.ball_shape.filter = _ALL_COLLISIONS
            for row in kickers.tolist():
                self._player_shapes[row].filter = _ALL_COLLISIONS
        if not self._touchers:
            return _NO_TOUCHERS
        rows = np.fromiter(dict.fromkeys(self._touchers), dtype=np.int64)
        self._touchers.clear()
        return rows

    def _step_with_overlap_separation(self, substeps: int) -> np.ndarray:
        """:meth:`step` when pymunk moves the players (and the ball off the posts) and the
        body-ball overlaps left at the end are separated as rcssserver does
        (:func:`soccer_sim.kernels.separate_ball_overlaps`; outside play on the ball stays)."""
        bulk = self._bulk
        bulk.write()
        bulk.step(substeps)
        bulk.read()
        count = 0
        if self._ball_collides:
            count = separate_ball_overlaps(self._dynamic, self._state.play_mode == _PLAY_ON, self._collided,
                                           self._overlap_params, self._contact_rows)
        keep_in_field_and_count_contacts(self._table, self._in_contact, self._after_params, self.teammate_contacts)
        if count == 0:
            return _NO_TOUCHERS
        return self._contact_rows[:count].copy()

    def _step_with_swept_contacts(self, substeps: int, kickers: np.ndarray) -> np.ndarray:
        """:meth:`step` when pymunk moves the players (and the ball off the posts) and the
        body-ball contacts are swept (:func:`soccer_sim.kernels.resolve_ball_contacts`)."""
        dynamic = self._dynamic
        np.copyto(self._before, dynamic)
        bulk = self._bulk
        bulk.write()
        bulk.step(substeps)
        bulk.read()
        count = 0
        if self._ball_collides:
            ghost = self._ghost
            if kickers.size:
                ghost[kickers] = True
            count = resolve_ball_contacts(self._before, dynamic, ghost, self._contact_params, self._swept_rows)
            if kickers.size:
                ghost[kickers] = False
        keep_in_field_and_count_contacts(self._table, self._in_contact, self._after_params, self.teammate_contacts)
        if count == 0:
            return _NO_TOUCHERS
        return np.unique(self._swept_rows[:count]) if count > 1 else self._swept_rows[:1].copy()


class _BulkBodies:
    """Bulk transfer between a body table (rows ``[x, y, vx, vy]`` in pymunk's body order) and
    pymunk, and the bare C step.

    Does what ``pymunk.batch.set_space_bodies``/``get_space_bodies`` and ``Space.step`` do,
    with the C-side argument structures built once instead of on every call (together they
    cost several microseconds per cycle otherwise). ``Space.step``'s Python bookkeeping
    (deferred additions and removals, post-step callbacks) is never needed here.

    This reaches into pymunk's private parts (``pymunk._chipmunk``, ``Space._space``,
    ``pymunk.batch.Buffer``'s C arrays), so it is checked when built: any of them missing,
    or a round trip disagreeing with the public ``pymunk.batch``, raises
    :class:`PymunkChangedError` naming the supported pymunk releases.
    """

    def __init__(self, space: pymunk.Space, data: np.ndarray) -> None:
        self._flat = data.reshape(-1)
        try:
            from pymunk._chipmunk import ffi, lib

            self._space_ptr = space._space
            self._each_body = lib.cpSpaceEachBody
            self._cp_step = lib.cpSpaceStep
            self._write_buffer = pbatch.Buffer()
            self._write_buffer.set_float_buf(self._flat)
            self._read_buffer = pbatch.Buffer()
            self._write_array = self._write_buffer._float_arr
            self._read_array = self._read_buffer._float_arr
            self._write_fn = ffi.addressof(lib, "pmSpaceBodySetIteratorFuncBatched")
            self._read_fn = ffi.addressof(lib, "pmSpaceBodyGetIteratorFuncBatched")
            self._write_data = self._batch_data(ffi, self._write_buffer)
            self._read_data = self._batch_data(ffi, self._read_buffer)
        except Exception as exc:  # a missing module, attribute, C function or struct
            raise PymunkChangedError(f"{type(exc).__name__}: {exc}") from exc
        self._check_against_pymunk_batch(space)

    def _check_against_pymunk_batch(self, space: pymunk.Space) -> None:
        """Write a test pattern (a distinct value in every field of every moving body) with the
        shortcut, read it back with ``pymunk.batch`` and with the shortcut, then restore the
        table. Also sizes pymunk's read array once; later reads refill it in place."""
        original = self._flat.copy()
        pattern = np.zeros_like(self._flat)
        moving = self._flat.size - 4  # the last row is the static body: it stays at rest
        pattern[:moving] = np.arange(1.0, moving + 1.0) * 0.5
        self._flat[:] = pattern
        self.write()
        pbatch.get_space_bodies(space, _BODY_FIELDS, self._read_buffer)
        self._read_view = np.frombuffer(self._read_buffer.float_buf(), dtype=np.float64)
        if self._read_view.shape != self._flat.shape:
            raise PymunkChangedError("pymunk.batch returned an unexpected amount of body data")
        if not np.array_equal(self._read_view, pattern):
            raise PymunkChangedError("the bulk write does not give what pymunk.batch reads back")
        self._flat[:] = 0.0
        self.read()
        if not np.array_equal(self._flat, pattern):
            raise PymunkChangedError("the bulk read does not give what pymunk.batch reads")
        self._flat[:] = original
        self.write()

    @staticmethod
    def _batch_data(ffi: object, buffer: pbatch.Buffer) -> object:
        data = ffi.new("pmBatchedData *")
        data.fields = _BODY_FIELDS.value
        data.floatArray = buffer._float_arr
        data.intArray = buffer._int_arr
        return data

    def write(self) -> None:
        """Table -> pymunk (positions and velocities of every body)."""
        array = self._write_array
        array.num = 0
        self._each_body(self._space_ptr, self._write_fn, self._write_data)
        array.num = array.max

    def read(self) -> None:
        """pymunk -> table."""
        array = self._read_array
        address = array.arr
        array.num = 0
        self._each_body(self._space_ptr, self._read_fn, self._read_data)
        if array.arr != address:  # pymunk grew its array: re-wrap it (never expected)
            self._read_view = np.frombuffer(self._read_buffer.float_buf(), dtype=np.float64)
        np.copyto(self._flat, self._read_view)

    def step(self, substeps: int) -> None:
        """One cycle (a total dt of 1) in ``substeps`` equal steps."""
        step, pointer, dt = self._cp_step, self._space_ptr, 1.0 / substeps
        for _ in range(substeps):
            step(pointer, dt)

