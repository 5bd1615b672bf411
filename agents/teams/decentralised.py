"""The built-in team under partial observation: every player decides on its own.

Each player ``i`` has its own copy of the team's brain (a :class:`FormationTeam` of the same
assigner and style, with its own memory and random generator), its own world model (row ``i``
of :class:`~agents.teams.world_model.TeamBeliefs`) and its own memory of the votes it heard
(row ``i`` of :class:`~agents.roles.voting.VoteBook`). Per cycle:

1. every player's world model takes in its own observation and the messages it heard;
2. player ``i``'s brain acts (on cycles it sees, near the ball, or at set plays; otherwise
   it goes on with its last dash) on a team view made from its beliefs alone (team-mates
   and opponents where it believes them, their velocities unknown and taken as zero, everyone's
   stamina its own), running the formation query and the role assigner on that model; the
   assignment it computes is its *proposal*, and it follows the assignment most of the votes it
   holds agree on (:meth:`VoteBook.follow_one`);
3. the team's command takes from each player's brain only that player's own row (dash, kick,
   tackle, placement; the catch from the goalkeeper's);
4. players speak: on even cycles their world message (ball belief and own position), on odd
   cycles their proposal as a vote (so each kind reaches every team-mate about every other
   cycle, as SCRAM's agents share world models and votes).

Nothing player ``i`` does in a cycle depends on another player's observation of that cycle;
team-mates' information reaches it only through the messages it hears the next cycle.

Per-match figures (:meth:`DecentralisedPlay.statistics`): each brain's role figures averaged
over the players, and the disagreement left: the share of play-on cycles with a role that two
players both believe they hold, or a role nobody believes they hold.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from agents.roles.voting import VoteBook, role_conflicts
from agents.teams.world_model import TeamBeliefs
from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import NO_PLAYER, SET_PLAYS, PlayMode
from soccer_sim.team import SideInfo, TeamCommand, TeamView

if TYPE_CHECKING:
    from agents.teams.formation_team import FormationTeam

_RECHOSEN = frozenset(SET_PLAYS - {PlayMode.KICK_OFF})
"""Our set plays whose taker each player re-chooses every cycle (a kick-off's taker is placed)."""

THINK_DISTANCE = 30.0
"""A player whose believed ball is nearer than this (m) decides every cycle, a see or not;
farther away it decides on its see cycles and otherwise goes on with its last dash. Measured
over 4 half matches of mmdr against counter-442 (shots per half, ball path): deciding every
cycle 3.0, with 30 m 3.0, with 10 m 0.75: the players around the ball (support, follow-ups)
need every cycle, those far from it do not."""

VOTE_HORIZON = 20
"""Cycles a heard vote counts (2 s: the assignment moves on with the ball)."""


class DecentralisedPlay:
    """A team's players each deciding from their own view (module docstring).

    ``make_brain`` makes one brain (an unreset team of the same kind); the brains are reset with
    the side's ``side_info``, the ``config`` and generators spawned from ``rng``."""

    def __init__(self, make_brain: Callable[[], FormationTeam], side_info: SideInfo, config: MatchConfig,
                 rng: np.random.Generator) -> None:
        n, m = side_info.players_per_team, side_info.opponents
        self.n = n
        self.goalie = side_info.goalie_index
        self.brains = [make_brain() for _ in range(n)]
        for i, (brain, child) in enumerate(zip(self.brains, rng.spawn(n))):
            brain.role_filter = self._filter_for(i)  # (also marks it as one player's brain)
            brain.reset(side_info, config, child)
        first = self.brains[0] if n else None
        self.outfield = first.outfield if first is not None else np.zeros(0, dtype=np.int64)
        self._outfield_rank = {int(p): r for r, p in enumerate(self.outfield)}
        self.beliefs = TeamBeliefs(n, m, config)
        spots = first.kick_off_spots if first is not None else np.zeros((0, 2))
        self.beliefs.mate_pos[:] = spots[:n][None, :, :]          # where the team lines up
        self.beliefs.opp_pos[:] = -spots[:m][None, :, :] if m <= len(spots) else 0.0
        k = len(self.outfield)
        self.votes = VoteBook(n, VOTE_HORIZON, k) if k else None
        self.proposals = np.tile(np.arange(k), (n, 1))
        """(n, k): the assignment each player's brain computed last (its vote)."""
        self.followed = np.tile(np.arange(k), (n, 1))
        """(n, k): the assignment each player followed last."""
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self._last_dash = np.zeros((n, 2))
        self._kickable = first.model.kickable_distance + 0.2 if first is not None else 0.0
        self._views = [_empty_view(n, m, side_info) for _ in range(n)]
        self._cycle = 0
        self._play_on_cycles = 0
        self._conflict_cycles = 0
        self._unfilled_cycles = 0

    def _filter_for(self, i: int) -> Callable[[np.ndarray], np.ndarray]:
        """Player ``i``'s brain's hook from its computed assignment to the one it follows."""
        def follow(proposal: np.ndarray) -> np.ndarray:
            self.proposals[i] = proposal
            if self.votes is None:
                return proposal
            followed = self.votes.follow_one(i, self._cycle, proposal)
            self.followed[i] = followed
            return followed.copy()
        return follow

    def act(self, views: PlayerViews) -> TeamCommand:
        """Every player's command from its own view and memory (module docstring)."""
        n, command = self.n, self.command
        self._cycle = views.cycle
        self.beliefs.update(views)
        if self.votes is not None:
            self.votes.hear(views.cycle, views.heard_mates)
        command.dash[:] = 0.0
        command.kick[:] = 0.0
        command.catch = False
        move = tackle = foul = None
        # At our set plays each player picks the taker afresh every cycle from what it believes
        # now: a choice made on stale beliefs (each player sure another is nearer) would leave
        # the ball untaken, while beliefs about the players near the ball soon agree.
        rechoose = views.mode_ours and views.play_mode in _RECHOSEN
        thinks = self._thinking(views)
        for i in range(n):
            if not views.present[i]:
                continue
            if not thinks[i]:  # nothing new seen, the ball far: the last dash goes on
                command.dash[i] = self._last_dash[i]
                continue
            brain = self.brains[i]
            taker = brain.set_plays.taker
            if rechoose:
                brain.set_plays.taker = -1
            own = brain.act(self._view_of(i, views))
            if rechoose and brain.set_plays.taker != taker:
                brain.set_plays.routine = None  # the next cycle's routine is made around the new taker
            command.dash[i] = self._last_dash[i] = own.dash[i]
            command.kick[i] = own.kick[i]
            if i == self.goalie:
                command.catch = own.catch
            if own.move is not None:
                move = np.zeros((n, 2)) if move is None else move
                move[i] = own.move[i]
            if own.tackle is not None and np.isfinite(own.tackle[i]):
                tackle = np.full(n, np.nan) if tackle is None else tackle
                foul = np.zeros(n, dtype=bool) if foul is None else foul
                tackle[i] = own.tackle[i]
                foul[i] = bool(own.foul[i]) if own.foul is not None else False
        if move is not None:  # players without a placement of their own stay where they believe they are
            missing = ~move.any(axis=1)
            move[missing] = views.position[missing]
        command.move, command.tackle, command.foul = move, tackle, foul
        self.beliefs.kicked(command.kick, self._kickable)
        command.say = self._messages(views)
        self._count_conflicts(views)
        return command

    def _thinking(self, views: PlayerViews) -> np.ndarray:
        """(n,) which players' brains act this cycle: every player with a new see, and in play on
        without one only those near where they believe the ball is (within
        ``THINK_DISTANCE``) or holding it; everybody at set plays and restarts. The others go on
        with their last dash: their decisions follow their sees (every 1 or 2 cycles)."""
        if views.play_mode != PlayMode.PLAY_ON:
            return np.ones(self.n, dtype=bool)
        gap = self.beliefs.ball - views.position
        return views.saw | views.holds_ball | (np.einsum("ij,ij->i", gap, gap) < THINK_DISTANCE ** 2)

    def _view_of(self, i: int, views: PlayerViews) -> TeamView:
        """Player ``i``'s beliefs as a team view (its own rows from its own senses)."""
        view, beliefs = self._views[i], self.beliefs
        view.own_pos[:] = beliefs.mate_pos[i]
        view.own_vel[:] = 0.0
        view.own_vel[i] = views.velocity[i]
        view.opp_pos[:] = beliefs.opp_pos[i]
        view.ball[:] = beliefs.ball[i]
        view.ball_vel[:] = beliefs.ball_vel[i]
        view.stamina[:] = views.stamina[i]
        view.effort[:] = views.effort[i]
        view.capacity[:] = views.capacity[i]
        view.frozen[:] = 0
        view.frozen[i] = views.frozen[i]
        view.play_mode, view.mode_ours, view.score = views.play_mode, views.mode_ours, views.score
        view.cycle, view.half = views.cycle, views.half
        if views.holds_ball[i]:
            view.ball_holder = i
        elif views.play_mode == PlayMode.GOALIE_HOLDS and views.mode_ours and self.goalie >= 0:
            view.ball_holder = self.goalie
        else:
            view.ball_holder = NO_PLAYER
        return view

    def _messages(self, views: PlayerViews) -> list[str | None]:
        """What each player says: its world message on even cycles, its vote on odd ones."""
        n = self.n
        if views.cycle % 2 == 0 or self.votes is None:
            return [self.beliefs.world_message(i) if views.present[i] else None for i in range(n)]
        return [VoteBook.message(self.proposals[i], views.cycle) if views.present[i] else None for i in range(n)]

    def _count_conflicts(self, views: PlayerViews) -> None:
        """Count play-on cycles whose believed roles clash (two players on one role, or a role
        nobody holds)."""
        if views.play_mode != PlayMode.PLAY_ON or not len(self.outfield):
            return
        roles = np.array([self.followed[i, r] for r, i in enumerate(self.outfield.tolist())])
        shared, empty = role_conflicts(roles, len(self.outfield))
        self._play_on_cycles += 1
        self._conflict_cycles += shared > 0
        self._unfilled_cycles += empty > 0

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """The brains' role figures averaged over the players, and the conflict shares."""
        figures = [brain.statistics() for brain in self.brains]
        merged = {key: float(np.mean([f[key] for f in figures])) for key in figures[0]} if figures else {}
        cycles = max(self._play_on_cycles, 1)
        merged["role_conflict_share"] = self._conflict_cycles / cycles
        merged["believed_unfilled_share"] = self._unfilled_cycles / cycles
        return merged

    def role_labels(self) -> list[str]:
        """Each player's position as its own brain sees it."""
        return [brain.role_labels()[i] for i, brain in enumerate(self.brains)]


def _empty_view(n: int, m: int, side_info: SideInfo) -> TeamView:
    """A team view one player's beliefs are written into every cycle."""
    return TeamView(own_pos=np.zeros((n, 2)), own_vel=np.zeros((n, 2)), opp_pos=np.zeros((m, 2)),
                    opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2), stamina=np.zeros(n),
                    effort=np.ones(n), capacity=np.full(n, np.inf), frozen=np.zeros(n, dtype=np.int64),
                    own_types=np.array(side_info.own_types or (0,) * n, dtype=np.intp),
                    opp_types=np.array(side_info.opponent_types or (0,) * m, dtype=np.intp))
