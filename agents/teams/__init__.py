"""The built-in teams: :class:`FormationTeam` (formation positioning with a pluggable role
assigner and soccer skills) and the named variants and reference opponents of
:mod:`agents.teams.builtin`."""

from agents.teams.formation_team import FormationTeam, TeamStyle

__all__ = ["FormationTeam", "TeamStyle"]
