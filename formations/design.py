"""The built-in formation sets, generated from a compact parametric design.

Run ``python -m tests.formations.write_builtin_sets`` to (re)write
``formations/data/*.json`` for the simulator's default field (this package is pure, so the
field, ``soccer_sim.config.STANDARD_FIELD``, comes from the caller: every function that
places players takes it); the test-suite checks that the shipped files equal what this
module produces for that field.

Design. Every role belongs to a *line* (goalkeeper, defence, midfield,
attack) and has a nominal lateral slot (metres, + to the left). For a ball at
(bx, by) and a *style* (one per situation):

* each line's depth is ``clip(base + gain * bx, lo, hi)`` plus the role's own
  offset, so the block moves up and down with the ball while the lines keep
  their order;
* each role's lateral position is ``slot * width + shift * by``: the team
  slides towards the ball side, and width grows in attack and shrinks in
  defence;
* when defending, the back line stays ``behind_ball`` metres goal-side of the
  ball, but never deeper than the line's lowest depth (so it does not collapse
  onto the goalkeeper when the ball reaches our goal line);
* in attack the full backs overlap, more so the farther up the ball is;
* set plays add rules: at a kick-off everyone stands in our own half, the lines
  staggered behind the halfway line, and at our kick-off the kick-off takers
  stand at the ball; at the opponents' set plays everyone but the goalkeeper
  keeps 9.15 m (plus a margin) from the ball;
* the goalkeeper stays in the goal area, sliding a little with the ball.

Keeping clear of the ball at the opponents' set plays cannot hold for every
ball position: a formation is a continuous map from ball positions to each
player's position, so (by Brouwer's fixed-point theorem) every player has some
ball position at which his target *is* the ball, and near it the interpolated
target passes close to the ball. The style of the opponents' set plays
(:data:`THEIR_SET_PLAY`) places those points where the opponents never restart
play in a match: inside our own half, away from the touchlines, the centre
spot and the front edge of our penalty area. At every real restart spot (kick
off, kick-ins, corners, goal kicks, free kicks in their half or on our penalty
area's edge) the interpolated positions keep the distance.

Samples are laid out on staggered columns (a half-spacing offset between
neighbouring columns) that reach every corner, both touchlines, both penalty
areas and the centre spot. The staggering matters: on a rectangular grid,
four samples can lie on one empty circle, and Delaunay's arbitrary choice of
diagonal would then break the left/right symmetry of the interpolation. The
design is evaluated on the left half (y >= 0) and completed by
:func:`formations.symmetry.mirror_complete`, so the data is exactly
symmetric.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from formations.field import FieldDimensions
from formations.files import save
from formations.formation import Formation
from formations.formation_set import FormationSet, Situation
from formations.roles import Role
from formations.symmetry import mirror_complete

INNER_COLUMNS_X: tuple[float, ...] = (
    -45.0,
    -36.0,
    -27.0,
    -18.0,
    -9.0,
    0.0,
    9.0,
    18.0,
    27.0,
    36.0,
    45.0,
)
"""x of the sample columns between the goal lines (:func:`sample_columns_x` adds those): the
penalty-area lines (|x| = 36 on the default field) and 9 m steps."""
INNER_EVEN_COLUMN_Y: tuple[float, ...] = (0.0, 12.0, 24.0)
"""Ball y (left half) in even-numbered columns, from the centre line; the touchline
(:func:`even_column_y`) closes the column."""
ODD_COLUMN_Y: tuple[float, ...] = (6.0, 18.0, 30.0)
"""Ball y (left half) in odd-numbered columns, offset by half a spacing."""

GOAL_LINE_GAP = 1.0
"""Players are kept this far inside the goal lines (|x|, metres)."""
TOUCHLINE_GAP = 1.5
"""Players are kept this far inside the touchlines (|y|, metres)."""
SET_PLAY_MARGIN = 2.0
"""Metres added to the field's centre-circle radius (the distance the rule keeps opponents
from the ball at set plays) at the samples of the opponents' set plays
(:func:`set_play_distance`). The margin absorbs the interpolation between samples: the
straight line between two points of a circle cuts inside it."""
KICK_OFF_MARGIN = 0.5
"""At a kick-off (ball on the centre spot) players stand at x <= -this."""
KICK_OFF_LINE_GAP: dict[str, float] = {"defence": 21.5, "midfield": 10.5, "attack": 0.0}
"""At a kick-off each line stands at least this many metres further behind the
halfway line than KICK_OFF_MARGIN (the limits relax with the ball's distance
from the centre spot): a back four 22 m deep (full backs level with the centre
backs), a midfield 11 m deep and the forwards on the halfway line, so the team
kicks off in its shape rather than bunched around the centre circle."""
KICK_OFF_TAKER_REACH = 9.0
"""Metres from the centre spot within which kick-off takers are drawn to their
kick-off spot (fully at the spot, not at all this far away). The nearest other
samples are farther, so only the centre-spot sample is affected."""
FULL_BACK_PUSH_RAMP = (-20.0, 10.0)
"""Ball x (metres) over which the full backs' overlap grows from none to full."""
POSITION_DECIMALS = 2
"""Positions are rounded to centimetres in the shipped files."""


def sample_columns_x(field: FieldDimensions) -> tuple[float, ...]:
    """x of the sample columns on *field*: its goal lines and :data:`INNER_COLUMNS_X`."""
    return (-field.half_length, *INNER_COLUMNS_X, field.half_length)


def even_column_y(field: FieldDimensions) -> tuple[float, ...]:
    """Ball y (left half) in even-numbered columns on *field*: centre line to touchline."""
    return (*INNER_EVEN_COLUMN_Y, field.half_width)


def player_limits(field: FieldDimensions) -> tuple[float, float]:
    """(|x|, |y|) players are kept within on *field* (m): :data:`GOAL_LINE_GAP` inside the goal
    lines and :data:`TOUCHLINE_GAP` inside the touchlines."""
    return field.half_length - GOAL_LINE_GAP, field.half_width - TOUCHLINE_GAP


def set_play_distance(field: FieldDimensions) -> float:
    """Distance (m) kept from the ball at the samples of the opponents' set plays on *field*:
    its centre-circle radius (the rule's 9.15 m) plus :data:`SET_PLAY_MARGIN`."""
    return field.centre_circle_radius + SET_PLAY_MARGIN


@dataclass(frozen=True)
class Line:
    """Depth of a line of players: ``clip(base + gain * bx, lo, hi)``, metres."""

    base: float
    gain: float
    lo: float
    hi: float

    def depth(self, bx: float) -> float:
        return min(max(self.base + self.gain * bx, self.lo), self.hi)


@dataclass(frozen=True)
class Style:
    """How the team shapes itself in one situation."""

    defence: Line
    midfield: Line
    attack: Line
    width: float
    """Multiplier of the lateral slots."""
    wide_width: float
    """Multiplier of the lateral slots of wide roles (full backs, wingers)."""
    shift: dict[str, float]
    """Per line, how much of the ball's y the line follows."""
    full_back_push: float = 0.0
    """Extra depth of full backs (metres) when the ball is far up, to overlap in attack."""
    behind_ball: float | None = None
    """If set, the back line stays this many metres behind the ball (but no
    deeper than ``defence.lo``); a ``keep_away`` style keeps it
    :func:`set_play_distance` behind instead."""
    kick_off: bool = False
    """Keep everyone in our half when the ball is near the centre spot."""
    kick_off_takers: bool = False
    """Put the kick-off takers at their kick-off spots (our kick-off)."""
    keep_away: bool = False
    """Keep outfield players :func:`set_play_distance` from the ball."""

    def back_line_gap(self, field: FieldDimensions) -> float | None:
        """Metres the back line stays behind the ball on *field* (None: no such rule)."""
        return set_play_distance(field) if self.keep_away else self.behind_ball


@dataclass(frozen=True)
class RoleDesign:
    """A role and its place in the design."""

    role: Role
    line: str
    """"goalkeeper", "defence", "midfield" or "attack"."""
    slot: float = 0.0
    """Nominal y, metres (+ to the left)."""
    depth_offset: float = 0.0
    """Metres ahead (+) of or behind (-) the line."""
    wide: bool = False
    full_back: bool = False
    kick_off_spot: tuple[float, float] | None = None
    """Where this role stands to take our kick-off (metres), or None."""


NORMAL = Style(
    defence=Line(-19.0, 0.5, -45.0, 10.0),
    midfield=Line(-5.0, 0.55, -36.0, 28.0),
    attack=Line(9.0, 0.55, -20.0, 42.0),
    width=1.0,
    wide_width=1.0,
    shift={"defence": 0.35, "midfield": 0.45, "attack": 0.4},
)
ATTACK = Style(
    defence=Line(-12.0, 0.55, -38.0, 20.0),
    midfield=Line(2.0, 0.6, -28.0, 35.0),
    attack=Line(15.0, 0.55, -12.0, 46.0),
    width=1.15,
    wide_width=1.35,
    shift={"defence": 0.3, "midfield": 0.35, "attack": 0.3},
    full_back_push=8.0,
)
DEFEND = Style(
    defence=Line(-25.0, 0.45, -47.0, -2.0),
    midfield=Line(-13.0, 0.5, -41.0, 12.0),
    attack=Line(0.0, 0.45, -28.0, 26.0),
    width=0.8,
    wide_width=0.8,
    shift={"defence": 0.45, "midfield": 0.55, "attack": 0.45},
    behind_ball=4.0,
)
OUR_SET_PLAY = Style(**{**ATTACK.__dict__, "kick_off": True, "kick_off_takers": True})
THEIR_SET_PLAY = Style(
    defence=Line(-25.0, 0.45, -47.0, -2.0),
    midfield=Line(-15.0, 0.5, -36.0, 10.0),
    attack=Line(-9.0, 0.45, -28.0, 16.0),
    width=0.8,
    wide_width=0.8,
    shift={"defence": 0.35, "midfield": 0.5, "attack": 0.45},
    kick_off=True,
    keep_away=True,
)
"""Like DEFEND, with the midfield and attack lines lower, so that each
player's target meets the ball (see the module docstring) only for ball
positions in our half where the opponents never restart play."""

STYLES: dict[Situation, Style] = {
    Situation.NORMAL: NORMAL,
    Situation.ATTACK: ATTACK,
    Situation.DEFEND: DEFEND,
    Situation.OUR_SET_PLAY: OUR_SET_PLAY,
    Situation.THEIR_SET_PLAY: THEIR_SET_PLAY,
}


def _gk() -> RoleDesign:
    return RoleDesign(Role(1, "goalkeeper", "goalkeeper"), "goalkeeper")


@dataclass(frozen=True)
class System:
    """A playing system: its roles and a description."""

    name: str
    description: str
    roles: tuple[RoleDesign, ...] = field(default_factory=tuple)


SYSTEMS: dict[str, System] = {
    "4-3-3": System(
        "4-3-3",
        "Four defenders, a holding midfielder with two central midfielders, two wingers and a centre forward.",
        (
            _gk(),
            RoleDesign(Role(2, "right back", "defender", 3), "defence", -21.0, wide=True, full_back=True),
            RoleDesign(Role(3, "left back", "defender", 2), "defence", 21.0, wide=True, full_back=True),
            RoleDesign(Role(4, "right centre back", "defender", 5), "defence", -7.5),
            RoleDesign(Role(5, "left centre back", "defender", 4), "defence", 7.5),
            RoleDesign(Role(6, "defensive midfielder", "midfielder"), "midfield", 0.0, -6.0),
            RoleDesign(Role(7, "right winger", "forward", 11), "attack", -23.0, -2.0, wide=True),
            RoleDesign(Role(8, "right central midfielder", "midfielder", 10), "midfield", -13.0),
            RoleDesign(Role(9, "centre forward", "forward"), "attack", 0.0, 2.0, kick_off_spot=(-0.5, 0.0)),
            RoleDesign(Role(10, "left central midfielder", "midfielder", 8), "midfield", 13.0),
            RoleDesign(Role(11, "left winger", "forward", 7), "attack", 23.0, -2.0, wide=True),
        ),
    ),
    "4-4-2": System(
        "4-4-2",
        "Four defenders, a flat midfield four with wide midfielders, and two strikers.",
        (
            _gk(),
            RoleDesign(Role(2, "right back", "defender", 3), "defence", -21.0, wide=True, full_back=True),
            RoleDesign(Role(3, "left back", "defender", 2), "defence", 21.0, wide=True, full_back=True),
            RoleDesign(Role(4, "right centre back", "defender", 5), "defence", -7.5),
            RoleDesign(Role(5, "left centre back", "defender", 4), "defence", 7.5),
            RoleDesign(Role(6, "right central midfielder", "midfielder", 8), "midfield", -8.0, -2.0),
            RoleDesign(Role(7, "right midfielder", "midfielder", 11), "midfield", -24.0, wide=True),
            RoleDesign(Role(8, "left central midfielder", "midfielder", 6), "midfield", 8.0, -2.0),
            RoleDesign(Role(9, "right striker", "forward", 10), "attack", -7.0, kick_off_spot=(-0.5, -1.2)),
            RoleDesign(Role(10, "left striker", "forward", 9), "attack", 7.0, kick_off_spot=(-0.5, 1.2)),
            RoleDesign(Role(11, "left midfielder", "midfielder", 7), "midfield", 24.0, wide=True),
        ),
    ),
}
"""The built-in systems, by name."""


def sample_balls_left_half(field: FieldDimensions) -> np.ndarray:
    """(n, 2) ball positions of the design on *field* with y >= 0 (the rest are mirrored)."""
    balls = []
    for column, x in enumerate(sample_columns_x(field)):
        for y in even_column_y(field) if column % 2 == 0 else ODD_COLUMN_Y:
            balls.append((x, y))
    return np.array(balls, dtype=np.float64)


def goalkeeper_position(bx: float, by: float, field: FieldDimensions) -> tuple[float, float]:
    """In the goal area of *field*: 1 m off the line, coming out a little as the ball advances."""
    x = -field.half_length + 1.0 + 0.035 * (bx + field.half_length)
    y = 0.12 * by
    return x, y


def role_position(design: RoleDesign, style: Style, bx: float, by: float,
                  field: FieldDimensions) -> tuple[float, float]:
    """Position of one role for ball (bx, by) in *style* on *field*, before set-play rules."""
    if design.line == "goalkeeper":
        return goalkeeper_position(bx, by, field)
    line: Line = getattr(style, design.line)
    x = line.depth(bx) + design.depth_offset
    if design.full_back:
        start, end = FULL_BACK_PUSH_RAMP
        x += style.full_back_push * min(max((bx - start) / (end - start), 0.0), 1.0)
    if style.kick_off:
        x = min(x, -KICK_OFF_MARGIN - KICK_OFF_LINE_GAP[design.line] + math.hypot(bx, by) + design.depth_offset)
    behind_ball = style.back_line_gap(field)
    if design.line == "defence" and behind_ball is not None:
        x = max(min(x, bx - behind_ball), style.defence.lo)
    width = style.wide_width if design.wide else style.width
    y = design.slot * width + style.shift[design.line] * by
    if style.kick_off_takers and design.kick_off_spot is not None:
        pull = max(0.0, 1.0 - math.hypot(bx, by) / KICK_OFF_TAKER_REACH)
        x += pull * (design.kick_off_spot[0] - x)
        y += pull * (design.kick_off_spot[1] - y)
    return x, y


def team_positions(system: System, style: Style, bx: float, by: float, field: FieldDimensions) -> np.ndarray:
    """(11, 2) positions of *system* for ball (bx, by) in *style* on *field*."""
    x_limit, y_limit = player_limits(field)
    positions = np.array([role_position(d, style, bx, by, field) for d in system.roles])
    outfield = np.array([d.line != "goalkeeper" for d in system.roles])
    if style.kick_off:
        # Near the centre spot everyone is in our half; the limit relaxes
        # with the ball's distance from the spot, keeping positions continuous.
        limit = -KICK_OFF_MARGIN + math.hypot(bx, by)
        positions[outfield, 0] = np.minimum(positions[outfield, 0], limit)
    positions[:, 0] = np.clip(positions[:, 0], -x_limit, x_limit)
    positions[outfield, 1] = np.clip(positions[outfield, 1], -y_limit, y_limit)
    if style.keep_away:
        positions[outfield, 1] = _clear_of_touchline_ball(positions[outfield, 1], by, field)
        _keep_away_from_ball(positions, outfield, bx, by, field)
    return positions


def _clear_of_touchline_ball(y: np.ndarray, by: float, field: FieldDimensions) -> np.ndarray:
    """Lateral positions squeezed towards the middle so that nobody is within
    :func:`set_play_distance` (sideways) of a ball on a touchline of *field*.

    Every player's target meets a ball on the touchline at some x (he stands
    ahead of a ball on our goal line and behind one on theirs), so at kick-ins
    only a lateral gap can keep him clear. A smooth, strictly increasing
    squeeze (``cap * tanh(y / cap)``) keeps the players' left-to-right order;
    the cap on the ball's side shrinks to half the width - the set-play distance - 1 m
    as the ball reaches that touchline.
    """
    half_width = field.half_width
    tight = half_width - set_play_distance(field) - 1.0
    loose = player_limits(field)[1]
    left_cap = loose - (loose - tight) * max(by, 0.0) / half_width
    right_cap = loose - (loose - tight) * max(-by, 0.0) / half_width
    cap = np.where(y >= 0.0, left_cap, right_cap)
    return cap * np.tanh(y / cap)


def _keep_away_from_ball(positions: np.ndarray, movable: np.ndarray, bx: float, by: float,
                         field: FieldDimensions) -> None:
    """Push movable players near the ball radially outwards, in place.

    With D = :func:`set_play_distance` on *field*, a player at distance r < 2 D from the
    ball moves to distance D + r / 2 along the same direction: nobody stays
    within D, players farther than twice that do not move, and
    (unlike projecting everyone onto the circle) two players never end on the
    same spot because their order along each ray is kept. Positions are then
    clipped to the players' limits.
    """
    distance_kept = set_play_distance(field)
    x_limit, y_limit = player_limits(field)
    offset = positions - (bx, by)
    distance = np.hypot(offset[:, 0], offset[:, 1])
    near = movable & (distance < 2.0 * distance_kept)
    scale = (distance_kept + 0.5 * distance[near]) / np.maximum(distance[near], 1e-9)
    positions[near] = (bx, by) + offset[near] * scale[:, None]
    positions[:, 0] = np.clip(positions[:, 0], -x_limit, x_limit)
    positions[:, 1] = np.clip(positions[:, 1], -y_limit, y_limit)


def design_formation(system: System, situation: Situation, field: FieldDimensions) -> Formation:
    """The symmetric formation of *system* in *situation* on *field*."""
    style = STYLES[situation]
    balls = sample_balls_left_half(field)
    positions = np.array([team_positions(system, style, bx, by, field) for bx, by in balls])
    positions = np.round(positions, POSITION_DECIMALS) + 0.0  # + 0.0 turns -0.0 into 0.0
    name = f"{system.name} {situation.value.replace('_', ' ')}"
    half = Formation([d.role for d in system.roles], balls, positions, name=name, description=system.description)
    return mirror_complete(half)


def design_set(name: str, field: FieldDimensions) -> FormationSet:
    """The built-in formation set *name* (one of :data:`SYSTEMS`) on *field*."""
    system = SYSTEMS[name]
    formations = {situation: design_formation(system, situation, field) for situation in Situation}
    return FormationSet(system.name, formations, description=system.description)


def data_directory() -> Path:
    """Where the built-in sets are stored (inside the package)."""
    return Path(__file__).resolve().parent / "data"


def write_builtin_sets(out: Path, field: FieldDimensions) -> list[Path]:
    """Write every built-in set, designed for *field*, to ``out/NAME.json``; the paths written."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for name in SYSTEMS:
        path = out / f"{name}.json"
        save(design_set(name, field), path)
        written.append(path)
    return written
