"""Collision solving with pymunk: 2n player discs, the ball and four static goal posts.

The match keeps the world in numpy arrays (:class:`BodyBlock`); pymunk is used once per
cycle as a collision solver. The block is laid out exactly like pymunk's bulk body data
(``pymunk.batch`` with POSITION | VELOCITY: ``x, y, vx, vy`` per body, in the order the
bodies were added), so writing the whole world into pymunk and reading it back are one
call each, with no per-body Python objects.

Units: pymunk's time unit is one cycle, so velocities are m/cycle and one cycle is a total
``dt`` of 1, split into sub-steps when something moves fast (so that a full-speed ball
cannot jump over a player between two collision checks).
"""

from __future__ import annotations

import math

import numpy as np
import pymunk
import pymunk.batch as pbatch

from soccer_sim.config import MatchConfig

#: pymunk collision types of the bodies.
HOME_PLAYER, AWAY_PLAYER, BALL, POST = 1, 2, 3, 4

_BODY_FIELDS = pbatch.BodyFields.POSITION | pbatch.BodyFields.VELOCITY
_NO_TOUCHERS = np.zeros(0, dtype=np.int64)
_NO_COLLISIONS = pymunk.ShapeFilter(categories=0, mask=0)
_SOLVER_ITERATIONS = 6
"""Constraint-solver iterations per sub-step: circles with no friction converge fast."""
_COLLISION_SLOP = 0.005
"""Overlap (m) pymunk tolerates between touching bodies before pushing them apart."""


class BodyBlock:
    """The world's bodies as one contiguous float array, shaped like pymunk's bulk data.

    ``data`` has one row ``[x, y, vx, vy]`` per pymunk body: rows 0..2n-1 the players
    (home first), row 2n the ball, then pymunk's static body (the goal posts' anchor, never
    written). ``pos``/``vel``/``ball``/``ball_vel`` are views into it, used as the
    :class:`~soccer_sim.state.WorldState` arrays.
    """

    def __init__(self, players_per_team: int) -> None:
        n2 = 2 * players_per_team
        self.n_players = n2
        self.data = np.zeros((n2 + 2, 4), dtype=np.float64)
        self.pos = self.data[:n2, 0:2]
        self.vel = self.data[:n2, 2:4]
        self.ball = self.data[n2, 0:2]
        self.ball_vel = self.data[n2, 2:4]
        self.dynamic = self.data[: n2 + 1]
        """Players and ball (the rows a team-relative view mirrors)."""


class Physics:
    """A pymunk space mirroring a :class:`BodyBlock`; steps one cycle at a time.

    Counts contacts between teammates (a new contact between two players of the same team
    is one contact) and collects the players whose body touched the ball during a step.
    """

    def __init__(self, config: MatchConfig, block: BodyBlock) -> None:
        phys, fld = config.physics, config.field
        n = config.players_per_team
        self.block = block
        self.space = space = pymunk.Space()
        space.iterations = _SOLVER_ITERATIONS
        space.collision_slop = _COLLISION_SLOP
        self.teammate_contacts = [0, 0]
        """New contacts between two players of the same team, per team (home, away)."""
        self._touchers: list[int] = []
        self._ball_collides = True

        bodies: list[pymunk.Body] = []
        for row in range(2 * n):
            body = pymunk.Body(phys.player_mass, math.inf)
            shape = pymunk.Circle(body, phys.player_radius)
            shape.collision_type = HOME_PLAYER if row < n else AWAY_PLAYER
            shape.elasticity = phys.player_restitution
            shape.friction = 0.0
            shape.row = row  # read back by the ball-touch callback
            space.add(body, shape)
            bodies.append(body)
        self.ball_body = pymunk.Body(phys.ball_mass, math.inf)
        self.ball_shape = pymunk.Circle(self.ball_body, phys.ball_radius)
        self.ball_shape.collision_type = BALL
        self.ball_shape.elasticity = phys.ball_restitution
        self.ball_shape.friction = 0.0
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

        space.on_collision(HOME_PLAYER, HOME_PLAYER, begin=self._teammate_begin, data=0)
        space.on_collision(AWAY_PLAYER, AWAY_PLAYER, begin=self._teammate_begin, data=1)
        space.on_collision(BALL, HOME_PLAYER, begin=self._ball_begin)
        space.on_collision(BALL, AWAY_PLAYER, begin=self._ball_begin)

        self._write = pbatch.Buffer()
        self._write.set_float_buf(block.data.reshape(-1))
        self._read = pbatch.Buffer()
        self._check_layout(bodies)

    def _check_layout(self, bodies: list[pymunk.Body]) -> None:
        """Make sure pymunk iterates the bodies in the order the block assumes."""
        buffer = pbatch.Buffer()
        pbatch.get_space_bodies(self.space, pbatch.BodyFields.BODY_ID, buffer)
        ids = np.frombuffer(buffer.int_buf(), dtype=np.uintp)
        expected = [b.id for b in bodies]
        if ids.shape[0] != self.block.data.shape[0] or list(ids[: len(expected)]) != expected:
            raise RuntimeError("pymunk iterates bodies in an unexpected order; the bulk body layout is invalid")

    # --- collision callbacks (called by pymunk during step) -------------------------------
    def _teammate_begin(self, arbiter: pymunk.Arbiter, space: pymunk.Space, team: int) -> None:
        self.teammate_contacts[team] += 1

    def _ball_begin(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        self._touchers.append(arbiter.shapes[1].row)

    # --- per cycle ---------------------------------------------------------------------------
    def set_ball_collides(self, collides: bool) -> None:
        """Switch the ball's collisions off while a goalkeeper holds it (and back on after)."""
        if collides != self._ball_collides:
            self.ball_shape.filter = pymunk.ShapeFilter() if collides else _NO_COLLISIONS
            self._ball_collides = collides

    def step(self, substeps: int) -> np.ndarray:
        """Advance one cycle in ``substeps`` equal sub-steps; return the rows of the players whose
        body began touching the ball (in order of first contact, no repeats).

        Reads the block into pymunk first (so whatever the match or the referee wrote is
        used) and writes the result back into the block.
        """
        space = self.space
        pbatch.set_space_bodies(space, _BODY_FIELDS, self._write)
        if substeps == 1:
            space.step(1.0)
        else:
            dt = 1.0 / substeps
            for _ in range(substeps):
                space.step(dt)
        read = self._read
        read.clear()
        pbatch.get_space_bodies(space, _BODY_FIELDS, read)
        self.block.data.reshape(-1)[:] = np.frombuffer(read.float_buf(), dtype=np.float64)
        if not self._touchers:
            return _NO_TOUCHERS
        rows = np.fromiter(dict.fromkeys(self._touchers), dtype=np.int64)
        self._touchers.clear()
        return rows
