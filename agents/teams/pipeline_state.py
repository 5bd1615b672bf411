"""The built-in team's pipeline arrays as one named compiled record (:class:`PipelineState`).

The compiled steps of :mod:`agents.teams.pipeline_kernels` read about 120 arrays and numbers:
the world model's belief rows, each belief's memory (its race, switch, block, targets and
assignments), each player row's goal, hurry and pacing, and the constants of the team's shape,
formations and stamina policy. Handing them to numba one by one would cost its dispatcher
about 0.2 µs apiece every call, and a kernel of a hundred positional parameters cannot be
read. Here they live in one numba structure (a ``StructRef`` whose arrays are the pipeline's
own arrays, not copies), made once per match, which every kernel reads by field name.
"""

from __future__ import annotations

from collections.abc import Mapping

from numba import njit
from numba.core import types
from numba.experimental import structref

FIELDS = (
    # the beliefs (the world model's arrays: row b is one believer's) and who takes which
    "ball", "ball_vel", "ball_age", "mate_pos", "mate_vel", "mate_effort", "opp_pos", "opp_age", "opp_vel",
    "opp_effort", "belief_of", "able", "ball_gap",
    # the offside line each belief keeps its players behind
    "guard_x", "guard_step", "guard_cycles",
    # who assigns, and the assignments heard (the speaking turns)
    "assigned_at", "assigned_mode", "assign_every", "steers", "first_outfield", "turns", "said_horizon", "settle_every",
    # the ball race
    "radius", "catch_radius", "opp_radius", "opp_catch_radius", "reach", "ball_travel", "coast", "race_constants",
    "raced", "race_near", "race_every",
    # the attack/defend switch and the block
    "switch_margin", "switch_persist", "depth", "attack_push", "knobs",
    # the settled targets and the positions' own behaviours
    "outfield_roles", "back_roles", "x_limit", "forwards", "narrowing", "narrow_x", "role_codes", "role_params",
    # the support spots
    "is_forward", "is_back", "offsets", "support_players", "support_pressure", "support_horizon", "third_x",
    "support_knobs",
    # the formations' query tables
    "tables_attack", "tables_defend", "tables_our_set_play", "tables_their_set_play", "tables_normal",
    # each belief's memory
    "attacking", "pending", "in_play", "block", "our_cycles", "our_points", "our_first", "their_cycles",
    "their_points", "their_first", "their_cycle", "win_point", "previous", "primed", "named_ball",
    # each belief's assignments and targets; this cycle's rows and beliefs
    "proposals", "followed", "following", "rank", "match_roles", "full", "targets", "rows", "outfield_rows",
    "belief_rows", "due",
    # each player row's goal, hurry, dash and role figures
    "stationary", "spots", "outfield", "goalie", "offside_margin", "pressers", "keeper_margin", "area_x", "area_y",
    "half_length", "goals", "urgent", "phase", "row_ball", "pacing", "budgets", "last_role", "unfilled",
    # who decides on the ball
    "on_ball_distance", "keeper_area_x", "keeper_area_y",
    # what the speaker says
    "message_grid", "ball_decay",
)
"""The fields of :class:`PipelineState`, in the order :func:`new_state` takes them
(:func:`state_of` takes them by name)."""


@structref.register
class PipelineStateType(types.StructRef):
    """The numba type of :class:`PipelineState`."""

    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


class PipelineState(structref.StructRefProxy):
    """A team's pipeline arrays and constants as one compiled structure (module docstring);
    made by :func:`state_of`, read by the kernels of :mod:`agents.teams.pipeline_kernels`."""


structref.define_proxy(PipelineState, PipelineStateType, list(FIELDS))


@njit(cache=True)
def new_state(values: tuple) -> PipelineState:  # pragma: no cover - compiled
    """A :class:`PipelineState` of ``values``, the values of :data:`FIELDS` in that order
    (arrays are shared, not copied). Compiled and cached, so a new process does not compile the
    structure's constructor again."""
    return PipelineState(*values)


def state_of(values: Mapping[str, object]) -> PipelineState:
    """A :class:`PipelineState` of ``values`` by field name (every name of :data:`FIELDS`, no
    other; arrays shared, not copied); ValueError naming the names that are missing or unknown."""
    missing, unknown = sorted(set(FIELDS) - set(values)), sorted(set(values) - set(FIELDS))
    if missing or unknown:
        raise ValueError(f"PipelineState: fields missing {missing}, unknown {unknown}")
    return new_state(tuple(values[name] for name in FIELDS))
