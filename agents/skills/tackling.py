"""Tackles: when one of our players tackles an opponent's ball, in which direction, and
whether as a foul.

The simulator's tackle (:mod:`soccer_sim.tackles`, rcssserver's) reaches the ball up to
``tackle_dist`` ahead of the tackler's body and ``tackle_width`` to its side, succeeds with a
probability falling steeply with the ball's distance, pushes it hardest straight ahead of the
body and not at all straight back, and **freezes the tackler** for ``tackle_cycles`` (10)
cycles whether it reached the ball or not. So a tackle is a trade: a good chance of knocking
the ball away from an opponent who has it, against a player who cannot move for ten cycles
(a second of play) in which a missed opponent runs past it. It is worth it only when the
chance is high and the push goes somewhere useful.

**When.** Only when no player of ours can kick the ball this cycle, and either an opponent
controls it (can kick it now) or, with :attr:`TackleParams.blocks`, it is a ball the
opponents played into our half that heads into our goal or that they will reach first (a
shot or a cross to block: the tackle reaches twice as far as a kick); see
:meth:`Tackling.occasion`. :meth:`Tackling.choose` then looks only at our outfield players
within ``tackle_dist`` of the ball that can act (present, not frozen), so it costs nothing in
the rest of the match. Our goalkeeper, who catches what it can, tackles only a shot it
cannot catch before the ball crosses our goal line (:attr:`TackleParams.keeper_saves`: a
diving save that pushes it wide). A player tackles when its success probability (computed as the
simulator computes it: :func:`soccer_sim.tackles.body_frame_failure`, with the player's own
``inertia_moment``) is at least :attr:`TackleParams.min_probability`, or
:attr:`TackleParams.danger_probability` near our goal where losing the tackler for ten
cycles costs less than letting the opponent shoot; and when its best push is worth having
(:attr:`TackleParams.min_score`). Of several candidates the likeliest tackles; only one.

**Direction** (team frame: we attack +x). The push (:func:`soccer_sim.tackles.push_acceleration`)
is added to the ball's velocity, so each of :attr:`TackleParams.directions` push directions
is scored by the ball's velocity after it: its speed (as a share of the strongest push,
at most 1) times how good its direction is, the cosine to an aim: the opponents' goal, or in
our third away from our goal and towards the nearer touchline. A ball sent on a path that
crosses our goal line between the posts (with :attr:`TackleParams.post_margin`) is never
taken; near our goal one over our goal line wide of the posts (a corner kick) is worth
:attr:`TackleParams.corner_value` -- a tackler chasing an opponent towards our goal line
faces that line, a shot deflected sideways keeps going towards the line, and a corner is
better than a weak poke the opponent keeps.

**Foul tackles** (:attr:`TackleParams.foul_tackles`): a foul tackle succeeds more easily
(``foul_exponent``), does not freeze the tackler when it pushes the ball, and stops the
opponent on the ball for ``foul_cycles``; but the referee sees it half the time (a free kick
for the opponents where the tackler stands, kept out of our penalty area), and a seen foul on
an opponent the tackler charges is a yellow card. As helios-base's basic tackle does, a
player without a card tackles with the foul flag whenever the ball is outside our penalty
area (by :attr:`TackleParams.foul_area_margin`) and the foul tackle is the likelier to
succeed; once carded it tackles fairly, so that it is not sent off by a second yellow card.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import IntEnum
from typing import NamedTuple

import numpy as np

from agents.skills.model import MotionModel, SkillInputError, check_params
from soccer_sim.config import TackleConfig
from soccer_sim.tackles import body_frame_failure, push_acceleration
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class TackleParams:
    """When and how our players tackle (probabilities, metres, shares of the full push)."""

    enabled: bool = True
    """Whether the team tackles at all."""
    min_probability: float = 0.8
    """Tackle when the success probability is at least this: a failed tackle leaves the
    player frozen while the opponent goes on, so only a likely one is worth it (0.8 is about
    1.5 m from the ball, facing it: beyond the kickable distance, inside the tackle's reach)."""
    danger_probability: float = 0.6
    """The lower threshold within :attr:`danger_distance` of our goal, where the opponent on
    the ball is about to shoot or cross and a frozen tackler costs less than the chance."""
    danger_distance: float = 25.0
    """Metres from our goal centre within which :attr:`danger_probability` applies and a push
    over our goal line (a corner kick) is acceptable: the penalty area and a little more."""
    min_score: float = 0.25
    """Tackle only if the best direction's push share times its worth reaches this: a tackler
    whose body faces away from anywhere useful (chasing from behind towards our goal) would
    only poke the ball along to the opponent."""
    corner_value: float = 0.45
    """Worth of a push over our goal line wide of the posts near our goal (on the scale of the
    aim's cosine, 1 the best): worse than a push up the field, better than a weak one."""
    touchline_weight: float = 1.0
    """In our third the aim is away from our goal plus this much of the way towards the
    nearer touchline (0: straight away from the goal; 1: halfway between)."""
    post_margin: float = 2.0
    """A push whose path crosses our goal line within this far outside a post is never taken
    (the ball's noise and its roll must not carry it in), m."""
    blocks: bool = True
    """Also tackle a ball the opponents played into our half that we cannot kick: one heading
    into our goal, or one they will reach before us (a block; see :meth:`Tackling.occasion`)."""
    shot_probability: float = 0.15
    """The threshold for blocking a ball heading into our goal: the tackler loses ten cycles,
    but the ball would otherwise reach the goalkeeper or the net."""
    keeper_saves: bool = True
    """Our goalkeeper tackles (dives at) a ball heading into our goal that it cannot catch
    before the ball crosses the line: a save that knocks the ball wide, often for a corner."""
    keeper_probability: float = 0.15
    """The goalkeeper's threshold for such a save: the alternative is a goal."""
    block_speed: float = 1.0
    """A block is only for a ball at least this fast (m/cycle): a kicked ball, not one rolling out."""
    foul_tackles: bool = True
    """Tackle with the foul flag while uncarded and outside our penalty area, as helios-base
    does (see the module docstring); False: never foul on purpose."""
    foul_area_margin: float = 0.5
    """A foul tackle only for a ball more than this beyond our penalty area's line or side
    (helios-base's 0.5 m), m."""
    directions: int = 32
    """Directions weighed for the push (evenly spaced)."""

    def __post_init__(self) -> None:
        for name in ("enabled", "blocks", "keeper_saves", "foul_tackles"):
            if not isinstance(getattr(self, name), bool):
                raise SkillInputError(f"TackleParams.{name} must be a bool, got {getattr(self, name)!r}")
        check_params(self, fractions=("min_probability", "danger_probability", "shot_probability",
                                        "keeper_probability", "min_score", "corner_value"),
                     non_negative=("danger_distance", "touchline_weight", "post_margin", "block_speed",
                                   "foul_area_margin"),
                     counts=("directions",))


class Occasion(IntEnum):
    """What calls for a tackle this cycle (:meth:`Tackling.occasion`)."""

    NONE = 0
    ON_BALL = 1
    """An opponent can kick the ball."""
    BLOCK = 2
    """A ball the opponents played in our half that they reach before us."""
    SHOT = 3
    """A ball the opponents played that heads into our goal."""


class Tackle(NamedTuple):
    """One player's tackle this cycle."""

    player: int
    """The tackler's index (team row)."""
    direction: float
    """Degrees, team frame (0: towards the opponents' goal), as ``TeamCommand.tackle`` takes it."""
    foul: bool
    """A foul tackle (``TeamCommand.foul``)."""
    probability: float
    """Its success probability."""


class Tackling:
    """One team's tackle decisions during a match (see the module docstring).

    ``inertia`` (n,): each of our players' ``inertia_moment`` (its player type's), which sets
    where a moving player's body faces; ``goalie``: our goalkeeper's index (-1: none), who
    never tackles (it catches)."""

    def __init__(self, model: MotionModel, config: TackleConfig, inertia: np.ndarray, goalie: int,
                 params: TackleParams = TackleParams()) -> None:
        if not isinstance(params, TackleParams):
            raise SkillInputError(f"params must be a TackleParams, got {type(params).__name__}")
        n = model.players_per_team
        self.inertia = np.asarray(inertia, dtype=np.float64)
        if self.inertia.shape != (n,):
            raise SkillInputError(f"inertia must have shape ({n},), got {self.inertia.shape}")
        self.model, self.config, self.params, self.goalie = model, config, params, goalie
        self.enabled = params.enabled and config.enabled and n > 0
        angles = np.linspace(-math.pi, math.pi, params.directions, endpoint=False)
        self._angles = angles
        self._units = np.stack((np.cos(angles), np.sin(angles)), axis=1)
        self._full_push = config.max_tackle_power * config.tackle_power_rate

    def occasion(self, view: TeamView, their_cycle: int, our_cycle: int, ours_last: bool) -> Occasion:
        """What this cycle calls for, when none of our players can kick the ball: a tackle on
        the ball an opponent can kick (``their_cycle`` 0: the cycles until their first player
        controls it), or a block (:attr:`TackleParams.blocks`) of a ball not last played by
        us (``ours_last``), at least :attr:`TackleParams.block_speed` fast in our half, that
        heads into our goal (between the posts with :attr:`TackleParams.post_margin`: a shot)
        or that the opponents reach before we do (``our_cycle``: a pass or a cross)."""
        if not self.enabled:
            return Occasion.NONE
        if their_cycle == 0:
            return Occasion.ON_BALL
        params = self.params
        if not params.blocks or ours_last or view.ball[0] >= 0.0:
            return Occasion.NONE
        vx, vy = float(view.ball_vel[0]), float(view.ball_vel[1])
        if math.hypot(vx, vy) < params.block_speed:
            return Occasion.NONE
        if self.shot_at_us(view, ours_last):
            return Occasion.SHOT
        return Occasion.BLOCK if their_cycle < our_cycle else Occasion.NONE

    def shot_at_us(self, view: TeamView, ours_last: bool) -> bool:
        """Whether the ball, not last played by us, at least :attr:`TackleParams.block_speed`
        fast, heads into our goal (between the posts with :attr:`TackleParams.post_margin`)."""
        vx, vy = float(view.ball_vel[0]), float(view.ball_vel[1])
        if ours_last or vx >= 0.0 or math.hypot(vx, vy) < self.params.block_speed:
            return False
        crossing = float(view.ball[1]) + vy * (-self.model.half_length - float(view.ball[0])) / vx
        return abs(crossing) <= self.model.goal_half_width + self.params.post_margin

    def choose(self, view: TeamView, occasion: Occasion = Occasion.ON_BALL,
               keeper_misses: bool = False) -> Tackle | None:
        """Our tackle this cycle, or None. Call it only when none of our players can kick the
        ball, with what :meth:`occasion` says (the module docstring); ``keeper_misses``: our
        goalkeeper cannot catch the ball before it leaves the field (then, on a shot and with
        :attr:`TackleParams.keeper_saves`, it may dive at it)."""
        if not self.enabled or occasion == Occasion.NONE:
            return None
        cfg, params, model = self.config, self.params, self.model
        ball = view.ball
        gaps = np.hypot(view.own_pos[:, 0] - ball[0], view.own_pos[:, 1] - ball[1])
        able = (gaps <= cfg.tackle_dist) & view.present & (view.frozen == 0)
        keeper = 0 <= self.goalie < able.size
        keeper_dives = keeper and occasion == Occasion.SHOT and keeper_misses and params.keeper_saves
        if keeper and not keeper_dives:
            able[self.goalie] = False
        if not able.any():
            return None
        own_goal_x = -model.half_length
        danger = math.hypot(float(ball[0]) - own_goal_x, float(ball[1])) <= params.danger_distance
        if occasion == Occasion.SHOT:
            threshold = params.shot_probability
        else:
            threshold = params.danger_probability if danger else params.min_probability
        may_foul = self._may_foul(ball)
        best: Tackle | None = None
        for row in np.flatnonzero(able).tolist():
            dx, dy = float(ball[0] - view.own_pos[row, 0]), float(ball[1] - view.own_pos[row, 1])
            vx, vy = float(view.own_vel[row, 0]), float(view.own_vel[row, 1])
            failure, x, y, fx, fy = body_frame_failure(cfg, dx, dy, vx, vy, float(self.inertia[row]), False)
            probability, foul = 1.0 - min(failure, 1.0), False
            if may_foul and not (view.cards is not None and view.cards[row] > 0):
                foul_failure = body_frame_failure(cfg, dx, dy, vx, vy, float(self.inertia[row]), True)[0]
                if 1.0 - min(foul_failure, 1.0) > probability:
                    probability, foul = 1.0 - min(foul_failure, 1.0), True
            least = params.keeper_probability if row == self.goalie else threshold
            if probability < least or (best is not None and probability <= best.probability):
                continue
            direction = self.direction(ball, view.ball_vel, math.atan2(fy, fx), math.atan2(y, x), danger)
            if direction is not None:
                best = Tackle(row, direction, foul, probability)
        return best

    def direction(self, ball: np.ndarray, ball_vel: np.ndarray, body: float, ball_angle: float,
                  danger: bool) -> float | None:
        """The best push direction (degrees, team frame) for a tackler whose body points at
        ``body`` (radians) with the ball (at ``ball``, moving at ``ball_vel``) ``ball_angle``
        radians off it, or None when none scores :attr:`TackleParams.min_score` (the module
        docstring); ``danger``: near our goal."""
        params, model = self.params, self.model
        bx, by = float(ball[0]), float(ball[1])
        own_goal_x = -model.half_length
        if bx < -model.half_length / 3.0:  # our third: away from our goal, towards the nearer touchline
            side = 1.0 if by >= 0.0 else -1.0
            norm = math.hypot(bx - own_goal_x, by) or 1.0
            aim_x, aim_y = (bx - own_goal_x) / norm, by / norm + params.touchline_weight * side
        else:  # towards the opponents' goal
            aim_x, aim_y = model.half_length - bx, -by
        norm = math.hypot(aim_x, aim_y) or 1.0
        aim_x, aim_y = aim_x / norm, aim_y / norm
        relative = np.remainder(self._angles - body + math.pi, 2.0 * math.pi) - math.pi
        push = push_acceleration(self.config, relative, ball_angle)
        out_x = float(ball_vel[0]) + push * self._units[:, 0]  # the ball's velocity after the push
        out_y = float(ball_vel[1]) + push * self._units[:, 1]
        speed = np.maximum(np.hypot(out_x, out_y), 1.0e-9)
        ux, uy = out_x / speed, out_y / speed
        worth = ux * aim_x + uy * aim_y
        # Paths towards our goal line: never into the goal mouth, a corner when in danger.
        back = ux < -1.0e-9
        crossing_y = by + uy * np.divide(own_goal_x - bx, ux, out=np.zeros_like(ux), where=back)
        mouth = back & (np.abs(crossing_y) <= model.goal_half_width + params.post_margin)
        if danger:
            np.maximum(worth, np.where(back & ~mouth, params.corner_value, -1.0), out=worth)
        score = np.where(mouth, -np.inf, worth * np.minimum(speed / self._full_push, 1.0))
        best = int(np.argmax(score))
        if score[best] < params.min_score:
            return None
        return math.degrees(float(self._angles[best]))

    def _may_foul(self, ball: np.ndarray) -> bool:
        """Whether a player without a card may tackle with the foul flag for the ball at
        ``ball``: :attr:`TackleParams.foul_tackles`, and the ball more than
        :attr:`TackleParams.foul_area_margin` beyond our penalty area's line or side."""
        params, model = self.params, self.model
        if not params.foul_tackles:
            return False
        area_line = -model.half_length + model.penalty_area_length
        return bool(ball[0] > area_line + params.foul_area_margin
                    or abs(float(ball[1])) > model.penalty_area_half_width + params.foul_area_margin)


def player_inertia(model: MotionModel, player_types: tuple, own_types: tuple[int, ...]) -> np.ndarray:
    """(n,) each of our players' ``inertia_moment``: its player type's (``SideInfo.player_types``
    and ``own_types``), or the configuration's when the match has no types."""
    n = model.players_per_team
    if not player_types or len(own_types) != n:
        return np.full(n, model.inertia_moment)
    return np.array([float(player_types[t].inertia_moment) for t in own_types])
