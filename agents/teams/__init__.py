"""The built-in teams: :class:`FormationTeam` (formation positioning with a pluggable role
assigner and soccer skills) and the named variants and reference opponents of
:mod:`agents.teams.builtin`. The team's parts: its style (:mod:`~agents.teams.style`), set plays
(:mod:`~agents.teams.set_plays`), per-match figures (:mod:`~agents.teams.reporting`) and
positioning kernels (:mod:`~agents.teams.role_kernels`)."""

from agents.teams.formation_team import FormationTeam
from agents.teams.style import TeamStyle

__all__ = ["FormationTeam", "TeamStyle"]
