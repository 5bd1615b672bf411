"""The built-in team under partial observation: every player decides on its own.

Each player ``i`` has its own world model (row ``i`` of
:class:`~agents.teams.world_model.TeamBeliefs`), its own memory of the votes it heard (row
``i`` of :class:`~agents.roles.voting.VoteBook`) and its own brain (a :class:`FormationTeam`
of the same assigner and style, with its own memory and random generator). Per cycle:

1. every player's world model takes in its own observation and the messages it heard, and
   its vote book the votes among them (one compiled call for the team,
   :meth:`~agents.teams.world_model.TeamBeliefs.update`);
2. a player on the ball (it believes the ball within :data:`BRAIN_DISTANCE`, or holds it),
   the goalkeeper with the ball in our penalty area, and at our set plays the player who
   believes it is the taker (re-chosen every cycle; at kick-offs the player whose own spot
   is nearest the centre) or can kick the ball, decide with their
   whole brain on a team view made from their beliefs alone (team-mates and opponents where
   they believe them, their velocities unknown and taken as zero, everyone's stamina their
   own): kicks, passes, dribbles, tackles, catches, set-play kicks;
3. everybody else positions itself on its own model (:mod:`agents.teams.own_view`: its ball
   race, the formation query, the role assigner -- its *proposal* -- and the assignment most
   of the votes it holds agree on, its goal and its dash), the team's players in one compiled
   call per step;
4. the team's command takes from each player's decision only that player's own row;
5. players speak: on even cycles their world message (ball belief and own position), on odd
   cycles their proposal as a vote (so each kind reaches every team-mate about every other
   cycle, as SCRAM's agents share world models and votes).

The positioned players' dashes, the messages and the count of believed role conflicts are made
in one compiled call after the whole brains acted (:meth:`OwnViewPositioning.finish`).

Nothing player ``i`` does in a cycle depends on another player's observation of that cycle;
team-mates' information reaches it only through the messages it hears the next cycle.

Per-match figures (:meth:`DecentralisedPlay.statistics`): the role figures of
:class:`~agents.teams.reporting.RoleFigures` from each player's distance to the target of the
role it follows, and the disagreement left: the share of play-on cycles with a role that two
players both believe they hold, or a role nobody believes they hold.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from agents.messages import MESSAGE_LENGTH, digit_messages
from agents.roles.voting import VoteBook
from agents.teams.own_view import PLACED, OwnViewPositioning
from agents.teams.own_view_kernels import whole_brain_rows
from agents.teams.positions import current_labels
from agents.teams.reporting import team_drawing
from agents.teams.world_model import TeamBeliefs
from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import NO_PLAYER, SET_PLAYS, PlayMode
from soccer_sim.team import SideInfo, TeamCommand, TeamView
from soccer_sim.team_hooks import Drawing

if TYPE_CHECKING:
    from agents.teams.formation_team import FormationTeam

_RECHOSEN = frozenset(SET_PLAYS - {PlayMode.KICK_OFF})
"""Our set plays whose taker each player re-chooses every cycle (a kick-off's taker is placed)."""

BRAIN_DISTANCE = 2.2
"""A player who believes the ball within this (m) decides with its whole brain (a kick, a
dribble, a tackle: rcssserver's ``tackle_dist`` is 2 m, the kickable distance about 1 m)."""

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
        self.beliefs = TeamBeliefs(n, m, config)
        spots = first.kick_off_spots if first is not None else np.zeros((0, 2))
        self.beliefs.mate_pos[:] = spots[:n][None, :, :]          # where the team lines up
        self.beliefs.opp_pos[:] = -spots[:m][None, :, :] if m <= len(spots) else 0.0
        k = len(self.outfield)
        self.votes = VoteBook(n, VOTE_HORIZON, k) if k else None
        self._vote_arrays = (self.votes.votes, self.votes.vote_cycle) if self.votes is not None else None
        """The vote book's arrays, which the world models' update fills (None: no outfield roles)."""
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self._said = np.zeros((n, MESSAGE_LENGTH), dtype=np.int64)
        """The digits of what each player says this cycle (filled by the positioning's finish)."""
        self._kickable = first.model.kickable_distance + 0.2 if first is not None else 0.0
        self._views = [_empty_view(n, m, side_info) for _ in range(n)]
        self.positioning = OwnViewPositioning(self.brains, config, self._views[0]) if n else None
        """Every player's positioning on its own model (:mod:`agents.teams.own_view`)."""
        self._goal_kick_keeper = first is not None and first.style.goalkeeper_goal_kicks and self.goalie >= 0
        self._area = (first.model.half_length - first.model.penalty_area_length - 2.0,
                      first.model.penalty_area_half_width + 2.0) if first is not None else (0.0, 0.0)
        self._kick_off_taker = -1
        """Our kick-off taker: the outfield player whose own spot is nearest the centre (lowest
        number on a tie), which every player knows without a word, as all line up by number."""
        if len(self.outfield):
            gaps = np.hypot(*spots[self.outfield].T)
            self._kick_off_taker = int(self.outfield[int(np.argmin(gaps))])
        self._cycle = 0
        self._brain_cycle = np.full(n, -2, dtype=np.int64)
        self._on_ball_rows = np.zeros(n, dtype=bool)
        self._deciding = np.zeros(n, dtype=bool)
        """(n,) the players who position themselves this cycle (present, not on the ball)."""
        self._mode_key: tuple[int, bool] = (-1, False)
        self._mode_since = 0
        self._play_on_cycles = 0
        self._conflict_cycles = 0
        self._unfilled_cycles = 0

    def _filter_for(self, i: int) -> Callable[[np.ndarray], np.ndarray]:
        """Player ``i``'s brain's hook from its computed assignment to the one it follows."""
        def follow(proposal: np.ndarray) -> np.ndarray:
            positioning = self.positioning
            if self._mode_key[0] in PLACED:  # lined up by shirt number, as everybody else
                positioning.line_up(np.array([i]))
                return positioning.followed[i].copy()
            positioning.proposals[i] = proposal
            if self.votes is None:
                return proposal
            followed = self.votes.follow_one(i, self._cycle, proposal)
            positioning.followed[i] = followed
            return followed.copy()
        return follow

    def act(self, views: PlayerViews) -> TeamCommand:
        """Every player's command from its own view and memory (module docstring)."""
        n, command = self.n, self.command
        cycle = self._cycle = views.cycle
        key = (int(views.play_mode), bool(views.mode_ours))
        if key != self._mode_key:
            self._mode_key, self._mode_since = key, cycle
        self.beliefs.update(views, self._vote_arrays)
        command.catch = False
        command.tackle = command.foul = None
        if n == 0:
            command.move, command.say = None, []
            return command
        n_brains, n_deciding = self._on_ball(views)
        deciding = self._deciding
        placed = self.positioning.step(views, self.beliefs, deciding, self.votes, n_deciding)
        move = None
        if placed is not None:  # players without a placement of their own stay where they believe they are
            move = views.position.copy()
            move[deciding] = placed[deciding]
        rechoose = views.mode_ours and views.play_mode in _RECHOSEN
        deciders = np.flatnonzero(self._on_ball_rows).tolist() if n_brains else []
        for i in deciders:
            move = self._brain_acts(i, views, rechoose, move)
        command.move = move
        if deciders:  # (only a whole brain kicks)
            self.beliefs.kicked(command.kick, self._kickable)
        say_world = views.cycle % 2 == 0 or self.votes is None
        shared, empty = self.positioning.finish(views, self.beliefs, self.votes, command.dash, say_world, self._said)
        command.say = digit_messages(self._said, views.present)
        self._count_conflicts(views, shared, empty)
        return command

    def _on_ball(self, views: PlayerViews) -> tuple[int, int]:
        """Who decides with the whole brain this cycle (module docstring, step 2) into
        ``self._on_ball_rows`` and who positions itself into ``self._deciding``, with the
        command's dashes and kicks cleared (one compiled call,
        :func:`~agents.teams.own_view_kernels.whole_brain_rows`); returns how many of each."""
        mode = views.play_mode
        play_on = mode == PlayMode.PLAY_ON
        set_play = not play_on and views.mode_ours and mode in SET_PLAYS
        taker, reach, nearest = -1, self._kickable + 1.0, False
        if not play_on and views.mode_ours and mode == PlayMode.GOALIE_HOLDS:  # the goalkeeper alone
            set_play, taker, reach = True, self.goalie, 0.0
        elif set_play:
            if mode == PlayMode.KICK_OFF:
                taker = self._kick_off_taker
            elif mode == PlayMode.GOAL_KICK and self._goal_kick_keeper:
                taker = self.goalie
            nearest = mode != PlayMode.KICK_OFF and taker < 0
        beliefs, command = self.beliefs, self.command
        return whole_brain_rows(play_on, set_play, beliefs.ball, views.position, views.holds_ball, views.present,
                                beliefs.mate_pos, self.outfield, taker, nearest, self.goalie, BRAIN_DISTANCE, reach,
                                self._area[0], self._area[1], self._on_ball_rows, self._deciding, command.dash,
                                command.kick)

    def _brain_acts(self, i: int, views: PlayerViews, rechoose: bool, move: np.ndarray | None) -> np.ndarray | None:
        """Player ``i`` decides with its whole brain on its beliefs; its own row of the brain's
        command goes into the team's. Returns the placements (``move``, made when needed)."""
        brain, command = self.brains[i], self.command
        if self._brain_cycle[i] != views.cycle - 1:
            brain.wake(self._mode_since)
        self._brain_cycle[i] = views.cycle
        taker = brain.set_plays.taker
        # At our set plays each player picks the taker afresh every cycle from what it believes
        # now: a choice made on stale beliefs (each player sure another is nearer) would leave
        # the ball untaken, while beliefs about the players near the ball soon agree.
        if rechoose:
            brain.set_plays.taker = -1
        elif views.play_mode == PlayMode.KICK_OFF and views.mode_ours and self._kick_off_taker >= 0:
            brain.set_plays.taker = self._kick_off_taker
        own = brain.act(self._view_of(i, views))
        if rechoose and brain.set_plays.taker != taker:
            brain.set_plays.routine = None  # the next cycle's routine is made around the new taker
        command.dash[i] = own.dash[i]
        command.kick[i] = own.kick[i]
        if i == self.goalie:
            command.catch = own.catch
        if own.move is not None:
            move = views.position.copy() if move is None else move
            move[i] = own.move[i]
        if own.tackle is not None and np.isfinite(own.tackle[i]):
            n = self.n
            command.tackle = np.full(n, np.nan) if command.tackle is None else command.tackle
            command.foul = np.zeros(n, dtype=bool) if command.foul is None else command.foul
            command.tackle[i] = own.tackle[i]
            command.foul[i] = bool(own.foul[i]) if own.foul is not None else False
        return move

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

    def _count_conflicts(self, views: PlayerViews, shared: int, empty: int) -> None:
        """Count the play-on cycles whose believed roles clash: ``shared`` roles two players both
        believe they hold, ``empty`` roles nobody believes they hold (:meth:`OwnViewPositioning.finish`)."""
        if views.play_mode != PlayMode.PLAY_ON or not len(self.outfield):
            return
        self._play_on_cycles += 1
        self._conflict_cycles += shared > 0
        self._unfilled_cycles += empty > 0

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """The players' role figures (module docstring) and the conflict shares."""
        merged = self.positioning.figures.statistics() if self.positioning is not None else {}
        cycles = max(self._play_on_cycles, 1)
        merged["role_conflict_share"] = self._conflict_cycles / cycles
        merged["believed_unfilled_share"] = self._unfilled_cycles / cycles
        return merged

    def drawing(self) -> Drawing:
        """What a replay may draw: where each player is going (its own goal), and the role
        targets, roles and formation as the first outfield player believes them."""
        positioning = self.positioning
        if positioning is None:  # a side of no players
            return Drawing(targets=np.zeros((0, 2)), goals=np.zeros((0, 2)), outfield=np.zeros(0, dtype=np.int64))
        first = self.brains[0]
        i = int(self.outfield[0]) if len(self.outfield) else 0
        return team_drawing(first.formation_set.formation(positioning.situation(i)), positioning.targets[i],
                            positioning.match_roles[i], positioning.goals, self.outfield,
                            positioning.followed[i] if len(self.outfield) else None)

    def role_labels(self) -> list[str]:
        """Each player's position as it believes it (the role it follows)."""
        if not self.n:
            return []
        first, followed = self.brains[0], self.positioning.followed
        return [current_labels(first._role_labels, self.n, self.outfield, self.positioning.match_roles[i],
                               followed[i], first.goalie, first._goalie_role)[i] for i in range(self.n)]


def _empty_view(n: int, m: int, side_info: SideInfo) -> TeamView:
    """A team view one player's beliefs are written into every cycle."""
    return TeamView(own_pos=np.zeros((n, 2)), own_vel=np.zeros((n, 2)), opp_pos=np.zeros((m, 2)),
                    opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2), stamina=np.zeros(n),
                    effort=np.ones(n), capacity=np.full(n, np.inf), frozen=np.zeros(n, dtype=np.int64),
                    own_types=np.array(side_info.own_types or (0,) * n, dtype=np.intp),
                    opp_types=np.array(side_info.opponent_types or (0,) * m, dtype=np.intp))
