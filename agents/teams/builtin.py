"""The built-in teams by name (entry points of the group ``soccer_sim.teams``).

* The **assigner variants** (``mmdr``, ``mmd+msd2``, ``static``, ``greedy``,
  ``greedy-offense``, ``bidding``, ``msd``, ``msd2``, ``random``) are one team, a 4-3-3 with
  the default style, that differ only in their role assigner: the experiments compare them.
* ``<assigner>-leave`` (every assigner variant but ``bidding``, e.g. ``mmdr-leave``,
  ``mmd+msd2-leave``, ``static-leave``): the same team with ``ball_role="leave"``, the player
  who goes for the ball out of the matching (:mod:`agents.teams.ball_role`; ``bidding``
  already leaves its ball player out of its auction).
* ``statues``: the same team whose outfield players never leave their kick-off spots (they
  kick a ball that comes to them); the baseline that says whether positioning matters.
* Three **reference opponents** with their own formations and styles:
  ``counter-442`` (a deep, compact 4-4-2 that clears long and counter-attacks, tackles only
  when nearly sure and never fouls on purpose),
  ``press-433`` (a high 4-3-3 that hunts the ball with two players and tackles more readily) and ``possession``
  (a 4-3-3 that keeps the ball with short passes and shoots only from close in).
"""

from __future__ import annotations

from collections.abc import Callable

from dataclasses import replace

from agents.skills import PassParams
from agents.skills.tackling import TackleParams
from agents.teams.formation_team import FormationTeam
from agents.teams.style import ATTACKING_DECISIONS, TeamStyle

ASSIGNER_VARIANTS: tuple[str, ...] = (
    "mmdr", "mmd+msd2", "static", "greedy", "greedy-offense", "bidding", "msd", "msd2", "random",
)
"""Team names that are the built-in team with that role assigner."""

LEAVE_VARIANTS: tuple[str, ...] = tuple(f"{a}-leave" for a in ASSIGNER_VARIANTS if a != "bidding")
"""Team names that are the built-in team with that assigner and ``ball_role="leave"``."""

COUNTER_442 = TeamStyle(
    system="4-4-2", depth=-6.0, pressers=1,
    tackling=TackleParams(min_probability=0.85, foul_tackles=False),
    decision=replace(ATTACKING_DECISIONS, pass_good=2.4, dribble_clearance=2.0, clear_line=-0.1,
                     passing=PassParams(weight_forward=1.6, weight_space=0.4, max_distance=45.0)),
)
PRESS_433 = TeamStyle(
    system="4-3-3", depth=6.0, pressers=2,
    tackling=TackleParams(min_probability=0.7, danger_probability=0.5),
    decision=replace(ATTACKING_DECISIONS, pass_good=2.5, pressure_cycles=4),
)
POSSESSION = TeamStyle(
    system="4-3-3", depth=0.0, pressers=1,
    decision=replace(ATTACKING_DECISIONS, pass_good=2.2, dribble_clearance=3.0,
                     passing=PassParams(weight_forward=0.6, weight_space=1.0, max_distance=25.0),
                     shot=replace(ATTACKING_DECISIONS.shot, max_range=22.0)),
)


def _variant(assigner: str, ball_role: str = "keep") -> Callable[[], FormationTeam]:
    leave = ball_role == "leave"

    def make(**style_options: object) -> FormationTeam:
        if leave:
            return FormationTeam(assigner, styled(LEAVE_STYLE, style_options), name=f"{assigner}-leave")
        return FormationTeam(assigner, styled(TeamStyle(), style_options))

    stem = assigner.replace('+', '_').replace('-', '_')
    make.__name__ = make.__qualname__ = f"{stem}_leave_team" if leave else f"{stem}_team"
    make.__doc__ = (f"The built-in team with the {assigner!r} role assigner" +
                    (", its ball player out of the matching." if leave else "."))
    return make


def styled(style: TeamStyle, options: dict[str, object]) -> TeamStyle:
    """``style`` with the :class:`TeamStyle` fields ``options`` names changed (every built-in
    team's factory takes them as keyword arguments, e.g. the ablation study's
    ``shared_assignment=True``); a name that is not a field is a TypeError naming it."""
    unknown = sorted(set(options) - set(TeamStyle.__dataclass_fields__))
    if unknown:
        raise TypeError(f"not a TeamStyle field: {', '.join(unknown)}")
    return replace(style, **options) if options else style


LEAVE_STYLE = TeamStyle(ball_role="leave")
"""The assigner variants' style with the ball player out of the matching."""


mmdr_team = _variant("mmdr")
mmd_msd2_team = _variant("mmd+msd2")
static_team = _variant("static")
greedy_team = _variant("greedy")
greedy_offense_team = _variant("greedy-offense")
bidding_team = _variant("bidding")
msd_team = _variant("msd")
msd2_team = _variant("msd2")
random_team = _variant("random")
mmdr_leave_team = _variant("mmdr", "leave")
mmd_msd2_leave_team = _variant("mmd+msd2", "leave")
static_leave_team = _variant("static", "leave")
greedy_leave_team = _variant("greedy", "leave")
greedy_offense_leave_team = _variant("greedy-offense", "leave")
msd_leave_team = _variant("msd", "leave")
msd2_leave_team = _variant("msd2", "leave")
random_leave_team = _variant("random", "leave")


def statues_team(**style_options: object) -> FormationTeam:
    """Outfield players hold their kick-off spots (goalkeeper and skills as usual)."""
    return FormationTeam("static", styled(TeamStyle(stationary=True), style_options), name="statues")


def counter_442_team(**style_options: object) -> FormationTeam:
    """A deep, compact 4-4-2 that clears long and counter-attacks."""
    return FormationTeam("static", styled(COUNTER_442, style_options), name="counter-442")


def press_433_team(**style_options: object) -> FormationTeam:
    """A high 4-3-3 hunting the ball with two players."""
    return FormationTeam("mmd+msd2", styled(PRESS_433, style_options), name="press-433")


def possession_team(**style_options: object) -> FormationTeam:
    """A 4-3-3 that keeps the ball with short passes and shoots only from close in."""
    return FormationTeam("greedy-offense", styled(POSSESSION, style_options), name="possession")
