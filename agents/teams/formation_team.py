"""The built-in team: formation positioning with a pluggable role assigner, plus soccer skills.

:class:`FormationTeam` is the team's configuration (its formation set, style and role
assigner); every match it builds the one decision pipeline (:mod:`agents.teams.pipeline`) on
the world model of the match's observation: under full observation every player believes the
truth (:class:`~agents.teams.world_model.TruthBeliefs`), under partial observation each
believes what it saw and heard (:class:`~agents.teams.world_model.TeamBeliefs`). The pipeline's
steps, per cycle and per distinct belief (team frame: we attack +x):

1. **Who wins the ball.** The ball race finds, for both teams, the first player that can
   control the ball and where.
2. **Situation and formation.** Set plays use the set-play formations; in play on we *attack*
   or *defend* as the race says, with hysteresis, and query the formation at a block moving at
   a running pace towards where the ball will be controlled; the targets are settled (each
   position's own behaviour, rest defence, support spots around our carrier).
3. **Roles.** The role assigner (``mmdr``, ``mmd+msd2``, ``static``, ``greedy``, ...; see
   :mod:`agents.roles`) maps the outfield players to the outfield role targets; it may also
   steer the players (potential-field bidding) and name the ball player. This is the only
   thing that differs between the assigner variants of the team.
4. **The ball** (:mod:`agents.teams.decisions`). The player who goes for the ball runs to its
   interception point; a player who can kick decides with :func:`agents.skills.decide_on_ball`
   (shoot, pass, dribble or clear); at our set plays the taker takes the ball after the others
   had ``set_play_wait`` cycles to take their places; the goalkeeper guards the line between
   ball and goal, catches (never a back-pass) and distributes a held ball.
5. **Everybody else** runs to their targets (kept onside), sprinting only when it matters and
   otherwise at a pace the stamina recovery pays for (:mod:`agents.skills.pacing`).

**Smaller sides** (a scenario's 0 to 11 players, the goalkeeper optional): the goalkeeper, if
any, keeps the goalkeeper role, and the outfield players take as many of the formation's
outfield roles, those whose targets lie nearest them when play starts, for the whole match.

The team reports per-match figures through :meth:`FormationTeam.statistics`
(:mod:`agents.teams.reporting`) and what it would like drawn through
:meth:`FormationTeam.drawing` (a :class:`soccer_sim.team_hooks.Drawing`).
"""

from __future__ import annotations

import numpy as np

import formations
from agents.roles import make_assigner
from agents.teams.ball_role import LeaveMatching, check_ball_role
from agents.teams.belief_kernels import AGE_NEVER
from agents.teams.pipeline import Pipeline, TeamSetup
from agents.teams.positions import current_labels, position_labels
from agents.teams.reporting import team_drawing
from agents.teams.speaking import check_agreement
from agents.teams.style import ATTACKING_DECISIONS, TeamStyle
from agents.teams.type_choice import choose_types
from agents.teams.world_model import TeamBeliefs, TruthBeliefs
from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.team import SideInfo, TeamCommand, TeamView
from soccer_sim.team_hooks import Drawing

__all__ = ["ATTACKING_DECISIONS", "FormationTeam", "TeamStyle"]


class FormationTeam:
    """The built-in team (see the module docstring) with role assigner ``assigner`` and style
    ``style``; ``name`` is how it reports itself (defaults to the assigner's name). It plays
    under both observation modes with the same pipeline."""

    observation_modes = ("full", "partial")

    def __init__(self, assigner: str = "mmd+msd2", style: TeamStyle | None = None, name: str | None = None,
                 **assigner_params: object) -> None:
        self.style = style or TeamStyle()
        self.assigner_name = assigner
        self.assigner = make_assigner(assigner, **assigner_params)
        """The role assigner (a fresh one per belief is made for each match)."""
        self.name = name or assigner
        self.formation_set = formations.load_builtin(self.style.system)
        kinds = [role.kind for role in self.formation_set.roles]
        self._role_labels = position_labels(self.formation_set)
        if kinds.count("goalkeeper") != 1:
            raise ValueError(f"formation set {self.style.system!r} needs exactly one goalkeeper role")
        self._goalie_role = kinds.index("goalkeeper")
        self._outfield_roles = np.array([r for r in range(len(kinds)) if r != self._goalie_role], dtype=np.int64)
        forward_roles = np.array([r for r in range(len(kinds)) if kinds[r] == "forward"], dtype=np.int64)
        leave = check_ball_role(self.style.ball_role, assigner) == "leave"
        check_agreement(self.style.agreement)
        params = dict(assigner_params)
        self._setup = TeamSetup(
            self.formation_set, self.style, make_assigner=lambda: make_assigner(assigner, **params),
            make_leave=(lambda: LeaveMatching(assigner, params)) if leave else (lambda: None),
            outfield_roles=self._outfield_roles, forward_roles=forward_roles)
        self.pipeline: Pipeline | None = None
        """This match's decision pipeline (None before the first reset)."""

    def choose_player_types(self, types: tuple, side_info: SideInfo) -> list[int]:
        """Each player's type, by its role (:mod:`agents.teams.type_choice`)."""
        return choose_types(types, self.formation_set, self._outfield_roles, side_info.players_per_team,
                            side_info.goalie_index)

    # ------------------------------------------------------------------ match lifecycle
    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        roles = len(self.formation_set.roles)
        goalie = side_info.goalie_index
        outfield_count = n - (1 if 0 <= goalie < n else 0)
        if n > roles or outfield_count > len(self._outfield_roles):
            raise ValueError(f"{type(self).__name__} plays at most {roles} players per side, "
                             f"{len(self._outfield_roles)} of them outfield (formation {self.style.system!r}), "
                             f"not {n} with {outfield_count} outfield")
        m = side_info.opponents
        world = TeamBeliefs(n, m, config, side_info=side_info) if config.observation.partial else TruthBeliefs(n, m)
        if config.observation.partial and n:
            spots = self.formation_set.positions((0.0, 0.0), formations.Situation.OUR_SET_PLAY)
            world.mate_pos[:] = spots[:n][None, :, :]          # where the team lines up
            world.opp_pos[:] = -spots[:m][None, :, :] if m <= len(spots) else 0.0
        self.pipeline = Pipeline(self._setup, side_info, config, rng, world)

    # ------------------------------------------------------------------ one cycle
    def act(self, view: TeamView | PlayerViews) -> TeamCommand:
        assert self.pipeline is not None, "act before reset"
        return self.pipeline.act(view)

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """Per-match figures (play-on cycles only): role switches per minute of play, the mean
        and the largest distance from the outfield players to their role targets (averaged over
        cycles: the largest is the assignment's makespan), the share of role-cycles a role was
        unfilled (its player farther than ``unfilled_distance``); under partial observation also
        the believed role conflicts (:meth:`~agents.teams.pipeline.Pipeline.statistics`)."""
        return self.pipeline.statistics() if self.pipeline is not None else {}

    def believed_ball(self) -> np.ndarray:
        """(n, 2) where each player believes the ball is after this cycle's ``act`` (team
        frame, m): the ball of the belief it takes its world from; NaN for a player that has
        had no ball information yet (:class:`~soccer_sim.team_hooks.BelievesBall`)."""
        pipeline = self.pipeline
        if pipeline is None:
            return np.zeros((0, 2))
        world = pipeline.world
        rows = world.belief_of
        ball = world.ball[rows].copy()
        ball[world.ball_age[rows] >= AGE_NEVER] = np.nan
        return ball

    def role_labels(self) -> list[str]:
        """Each player's current position as its belief has it (row order;
        :func:`~agents.teams.positions.current_labels`)."""
        pipeline = self.pipeline
        if pipeline is None or not pipeline.n:
            return []
        belief_of = pipeline.world.belief_of
        labels = {}
        for b in sorted(set(belief_of.tolist())):
            labels[b] = current_labels(self._role_labels, pipeline.n, pipeline.outfield, pipeline.match_roles[b],
                                       pipeline.followed[b] if len(pipeline.outfield) else None, pipeline.goalie,
                                       self._goalie_role)
        return [labels[int(belief_of[i])][i] for i in range(pipeline.n)]

    def drawing(self) -> Drawing:
        """What a replay may draw (team frame): each role's target, where each player is going,
        the outfield players and their roles and role targets, and the current formation's
        sample balls and triangles, as the first outfield player's belief has them."""
        pipeline = self.pipeline
        if pipeline is None or not pipeline.n:
            return Drawing(targets=np.zeros((0, 2)), goals=np.zeros((0, 2)), outfield=np.zeros(0, dtype=np.int64))
        outfield = pipeline.outfield
        b = int(pipeline.world.belief_of[outfield[0]]) if len(outfield) else 0
        return team_drawing(self.formation_set.formation(pipeline.situation(b)), pipeline.targets[b],
                            pipeline.match_roles[b], pipeline.goals, outfield,
                            pipeline.followed[b] if len(outfield) and pipeline.cycles else None)
