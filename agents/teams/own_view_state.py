"""One compiled record of everything a team's own-view positioning keeps from cycle to cycle.

:class:`~agents.teams.own_view.OwnViewPositioning` runs three compiled steps a cycle
(:func:`~agents.teams.own_view_kernels.before_roles`, then
:func:`~agents.teams.own_view_after.follow_and_goals` and
:func:`~agents.teams.own_view_after.dash_and_gaps`), which together read about 150 arrays and
numbers. Handing them over one by one costs numba's dispatcher some 0.2 µs each, about 25 µs
per team and cycle. Here they live in one numba structure (:class:`PositioningState`, a
``StructRef``: its arrays are the positioning's own arrays, not copies) made once per team,
and the three steps are called through thin compiled wrappers that take the structure and
only what changes every cycle (the play mode, the players' senses).

The structure holds the team's world models' arrays too (:class:`~agents.teams.world_model.TeamBeliefs`
changes them in place), its vote book's, and every formation's query tables (the set plays'
and the normal one as well as attack and defend, chosen by :data:`OTHER_TABLES` codes).
"""

from __future__ import annotations

from collections.abc import Mapping

from numba import njit
from numba.core import types
from numba.experimental import structref

from agents.message_kernels import number_digits, vote_number, world_message_number
from agents.roles.voting import believed_conflicts
from agents.teams.own_view_after import dash_and_gaps, follow_and_goals
from agents.teams.own_view_kernels import before_roles

FIELDS = (
    # the world models (TeamBeliefs)
    "ball", "ball_vel", "ball_age", "mate_pos", "opp_pos",
    # who assigns (plan_rows' planning) and the votes (its voting)
    "assigned_at", "assigned_mode", "assign_every", "steers", "first_outfield", "votes", "vote_cycle", "vote_horizon",
    # the ball race (read_play)
    "radius", "catch_radius", "opp_radius", "opp_catch_radius", "reach", "ball_travel", "coast", "race_constants",
    "raced", "race_near", "race_every",
    # the attack/defend switch and the block (Shape)
    "switch_margin", "switch_persist", "depth", "attack_push", "knobs",
    # the settled targets
    "outfield_roles", "back_roles", "x_limit", "forwards", "narrowing", "narrow_x",
    # the support spots
    "is_forward", "is_back", "offsets", "support_players", "support_pressure", "support_horizon", "third_x",
    "support_knobs",
    # the formations' query tables
    "tables_attack", "tables_defend", "tables_our_set_play", "tables_their_set_play", "tables_normal",
    # each player's memory
    "attacking", "pending", "in_play", "block", "our_cycles", "our_points", "our_first", "their_cycle", "win_point",
    "previous", "primed",
    # assignments, targets and this cycle's rows
    "proposals", "followed", "following", "rank", "match_roles", "full", "targets", "rows", "outfield_rows", "due",
    # goals, dashes and the role figures
    "stationary", "spots", "outfield", "goalie", "offside_margin", "pressers", "keeper_margin", "area_x", "area_y",
    "half_length", "goals", "urgent", "phase", "pacing", "budgets", "last_followed", "unfilled",
    # what the players say
    "world_grid", "vote_modulus",
)
"""The fields of :class:`PositioningState`, in the order :func:`new_state` takes them (:func:`state_of`
takes them by name)."""

OTHER_TABLES = {"our_set_play": 0, "their_set_play": 1, "normal": 2}
"""Codes of the formation a play mode other than play on uses (``other`` of :func:`before_roles_of`)."""


@structref.register
class PositioningStateType(types.StructRef):
    """The numba type of :class:`PositioningState`."""

    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


class PositioningState(structref.StructRefProxy):
    """A team's own-view positioning arrays and constants as one compiled structure (module
    docstring); made by :func:`new_state`, read by the compiled wrappers."""


structref.define_proxy(PositioningState, PositioningStateType, list(FIELDS))

@njit(cache=True)
def new_state(values: tuple) -> PositioningState:  # pragma: no cover - compiled
    """A :class:`PositioningState` of ``values``, the values of :data:`FIELDS` in that order
    (arrays are shared, not copied). Compiled and cached, so a new process does not compile the
    structure's constructor again."""
    return PositioningState(*values)


def state_of(values: Mapping[str, object]) -> PositioningState:
    """A :class:`PositioningState` of ``values`` by field name (every name of :data:`FIELDS`,
    no other; arrays shared, not copied); ValueError naming the names that are missing or
    unknown."""
    missing, unknown = sorted(set(FIELDS) - set(values)), sorted(set(values) - set(FIELDS))
    if missing or unknown:
        raise ValueError(f"PositioningState: fields missing {missing}, unknown {unknown}")
    return new_state(tuple(values[name] for name in FIELDS))


@njit(cache=True, nogil=True)
def before_roles_of(s: PositioningState, deciding, mode: int, play_on: bool, after_goal: bool, placed: bool,
                    support: bool, sampled: bool, other: int, own_vel, effort, saw,
                    cycle: int) -> tuple[int, int, int]:  # pragma: no cover - compiled
    """:func:`~agents.teams.own_view_kernels.before_roles` on ``s`` (``other``: an
    :data:`OTHER_TABLES` code, the formation out of play on)."""
    if other == 0:
        tables_other = s.tables_our_set_play
    elif other == 1:
        tables_other = s.tables_their_set_play
    else:
        tables_other = s.tables_normal
    planning = (s.assigned_at, s.assigned_mode, s.assign_every, s.steers, s.first_outfield)
    voting = (s.votes, s.vote_cycle, s.vote_horizon, cycle)
    race = (s.radius, s.catch_radius, s.opp_radius, s.opp_catch_radius, s.reach, s.ball_travel, s.coast,
            s.race_constants, s.raced, s.race_near, s.race_every)
    shape = (s.switch_margin, s.switch_persist, s.depth, s.attack_push, s.knobs)
    settle = (s.outfield_roles, s.back_roles, s.x_limit, s.forwards, s.narrowing, s.narrow_x, s.knobs)
    supporting = (s.is_forward, s.is_back, s.offsets, s.support_players, s.support_pressure, s.support_horizon,
                  s.third_x, s.support_knobs)
    memory = (s.attacking, s.pending, s.in_play, s.block, s.our_cycles, s.our_points, s.our_first, s.their_cycle,
              s.win_point, s.previous, s.primed)
    return before_roles(deciding, mode, play_on, after_goal, placed, support, sampled, s.ball, s.ball_vel, s.mate_pos,
                        own_vel, s.opp_pos, effort, saw, cycle, planning, voting, race, shape, settle, supporting,
                        s.tables_attack, s.tables_defend, tables_other, memory, s.proposals, s.followed, s.following,
                        s.rank, s.match_roles, s.full, s.targets, s.rows, s.outfield_rows, s.due)


@njit(cache=True, nogil=True)
def follow_and_goals_of(s: PositioningState, n_rows: int, n_out: int, n_due: int, placed: bool, play_on: bool,
                        cycle: int) -> None:  # pragma: no cover - compiled
    """:func:`~agents.teams.own_view_after.follow_and_goals` on ``s``'s first ``n_rows`` rows,
    ``n_out`` outfield rows and ``n_due`` assigning rows."""
    voting = (s.votes, s.vote_cycle, s.vote_horizon, cycle)
    goals_args = (s.targets, s.match_roles, s.outfield, s.goalie, play_on, s.our_cycles, s.our_points, s.our_first,
                  s.their_cycle, s.ball, s.opp_pos, s.offside_margin, s.pressers, s.keeper_margin, s.area_x,
                  s.area_y, s.half_length, s.rank)
    follow_and_goals(s.rows[:n_rows], s.outfield_rows[:n_out], s.due[:n_due], placed, voting, s.proposals,
                     s.following, s.followed, s.stationary, s.spots, goals_args, s.goals, s.urgent)


@njit(cache=True, nogil=True)
def dash_and_gaps_of(s: PositioningState, n_rows: int, n_out: int, play_on: bool, position, velocity, effort, stamina,
                     capacity, cycle: int, half: int, dash) -> tuple[int, float, float, int]:  # pragma: no cover
    """:func:`~agents.teams.own_view_after.dash_and_gaps` on ``s``'s first ``n_rows`` rows
    and ``n_out`` outfield rows, with the players' senses of this cycle; dashes into ``dash``."""
    dashing = (position, velocity, effort, stamina, capacity, s.ball, s.goalie, cycle, half, s.pacing)
    measuring = (s.rank, s.followed, s.last_followed, s.targets, s.match_roles, s.unfilled)
    return dash_and_gaps(s.rows[:n_rows], s.outfield_rows[:n_out], play_on, s.attacking, s.phase, dashing, s.goals,
                         s.urgent, dash, s.budgets, measuring)


@njit(cache=True, nogil=True)
def dash_and_say_of(s: PositioningState, n_rows: int, n_out: int, play_on: bool, position, velocity, effort, stamina,
                    capacity, cycle: int, half: int, dash, say_world: bool,
                    digits) -> tuple[int, float, float, int, int, int]:  # pragma: no cover - compiled
    """The end of a team's cycle in one call, after its whole brains acted: :func:`dash_and_gaps_of`
    (its figures are the first four numbers returned), then the digits of what every player
    says into ``digits`` (n, 10): with ``say_world`` its world message (its believed ball, the
    ball's age and its own position), else its proposal as a vote computed at ``cycle``; and in
    play on the believed role conflicts (:func:`~agents.roles.voting.believed_conflicts`, the
    last two numbers; zeros otherwise)."""
    switches, mean, largest, far = dash_and_gaps_of(s, n_rows, n_out, play_on, position, velocity, effort, stamina,
                                                    capacity, cycle, half, dash)
    for i in range(digits.shape[0]):
        if say_world:
            number = world_message_number(s.ball[i], s.ball_vel[i], s.ball_age[i], s.mate_pos[i, i], s.world_grid)
        else:
            number = vote_number(s.proposals[i], cycle, s.vote_modulus)
        number_digits(number, digits[i])
    shared, empty = 0, 0
    if play_on and s.outfield.shape[0] > 0:
        shared, empty = believed_conflicts(s.followed, s.outfield)
    return switches, mean, largest, far, shared, empty
