"""The built-in team's decisions on the ball and at set plays, one belief at a time.

The pipeline (:mod:`agents.teams.pipeline`) runs :meth:`BeliefDecisions.decide` for a belief
when one of the players who take their world from it is on the ball by it (it believes the
ball within reach, holds it, or is our set-play taker); under full observation that is the
team's one belief, under partial observation a player's own. On the belief's team view and
ball race it decides, in this order and each in one named place:

* **play on** (:meth:`BeliefDecisions._play_on`): who of ours kicks
  (:func:`~agents.teams.on_ball.choose_kicker`: the ball player if it can, else the nearest
  in reach); the goalkeeper's catch (:func:`agents.skills.should_catch`, never a back-pass);
  the kick (:func:`~agents.teams.on_ball.on_ball_kick`: the goalkeeper's, a block of their
  shot, or :func:`agents.skills.decide_on_ball`, the one place where the team shoots, passes,
  dribbles or clears); our tackle when none of ours can kick
  (:func:`~agents.teams.on_ball.tackle_if_worth`);
* **set plays** (:class:`~agents.teams.set_plays.SetPlays`): kick-off placement, our set
  plays' taker and kick (re-chosen every cycle from what the belief holds now), the
  goalkeeper's held ball;
* **follow-ups** of the belief's own shot (:func:`follow_up_goals`).

Only the rows of the players who take their world from the belief are written into the
team's command and goals (under partial observation: the player's own row).
"""

from __future__ import annotations

import numpy as np

from agents import skills
from agents.skills.tackling import Tackling
from agents.teams.on_ball import able_players, choose_kicker, on_ball_kick, tackle_if_worth
from agents.teams.set_plays import SetPlays
from agents.teams.shape import ShapeParams
from agents.teams.style import TeamStyle
from soccer_sim.config import MatchConfig
from soccer_sim.state import SET_PLAYS, PlayMode
from soccer_sim.team import TeamCommand, TeamView

RECHOSEN = frozenset(SET_PLAYS - {PlayMode.KICK_OFF})
"""Our set plays whose taker a belief re-chooses every cycle (a kick-off's taker is known to
all: the outfield player whose own spot is nearest the centre)."""

NO_SHOT = -(1 << 30)
"""A shot cycle that never was."""


class BeliefDecisions:
    """One belief's decisions on the ball and at set plays, and what it remembers for them
    (module docstring). ``ctx``: the team's skill context; ``tackling``: its tackle
    decisions; ``kick_off_taker``: the row that takes our kick-offs (-1: none)."""

    def __init__(self, ctx: skills.SkillContext, config: MatchConfig, style: TeamStyle, outfield: np.ndarray,
                 tackling: Tackling, kick_off_taker: int) -> None:
        model = ctx.model
        self.ctx = ctx
        self.style = style
        self.model = model
        self.goalie = model.goalie_index
        self.outfield = outfield
        self.tackling = tackling
        self.kick_off_taker = kick_off_taker
        self.kickable = model.kickable_distance
        self.set_plays = SetPlays(ctx, config, style, outfield)
        """Our set plays as this belief sees them: takers, retakes, routines, the held ball."""
        n = model.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        """This belief's command before only its own rows are taken into the team's."""
        self.goals = np.zeros((n, 2))
        self.urgent = np.zeros(n, dtype=bool)
        self.mode_key: tuple[int, bool] = (-1, False)
        self.mode_since = 0
        """The cycle the play mode began, as this belief knows it (a retake of its own set play
        begins it anew)."""
        self.last_cycle = -2
        """The cycle this belief last decided (a gap: it forgets what holds from cycle to cycle)."""
        self.dribble_dash: np.ndarray | None = None
        """The dribbler's dash of this cycle (it runs with the ball, not to a point), or None."""
        self.kicker = -1
        self.shot_cycle = NO_SHOT
        self.shot_from = np.zeros(2)
        """When and from where this belief last shot (for the follow-ups)."""

    def decide(self, view: TeamView, race: skills.BallRace, ball_player: int, rows: np.ndarray, mode_since: int,
               goals: np.ndarray, urgent: np.ndarray, command: TeamCommand, in_flight: bool,
               eligible: np.ndarray) -> bool:
        """The belief's decisions of this cycle (module docstring) on ``view`` and ``race``;
        only ``rows`` ((n,) bool: the players who take their world from it) are written into
        the team's ``goals``, ``urgent`` and ``command``. ``mode_since``: the cycle the play
        mode began. ``ball_player``: the player of ours
        the belief sends to the ball (-1: none). ``in_flight``: the belief's memory
        that our pass is in flight, ``eligible`` (n,) who of ours may play it (not offside when
        it was played). Returns whether the belief kicked."""
        mode = view.play_mode
        own = self.command
        own.kick[:] = 0.0
        own.catch = False
        own.move = None
        own.tackle = own.foul = None
        self.dribble_dash = None
        self.kicker = -1
        g, u = self.goals, self.urgent
        g[:] = goals
        u[:] = urgent
        woken = self.last_cycle != view.cycle - 1
        if woken:  # it did not decide last cycle: the play mode is new to it (and began at mode_since)
            self.mode_key = (-1, False)
        self.last_cycle = view.cycle
        set_plays = self.set_plays
        key = (int(mode), bool(view.mode_ours))
        restarted = mode != PlayMode.PLAY_ON and set_plays.kicked_last_cycle(view)
        if key != self.mode_key or restarted:
            if mode != PlayMode.PLAY_ON:
                set_plays.begin(view)
            self.mode_key = key
            self.mode_since = mode_since if woken else view.cycle  # (a retaken set play begins anew)
        # Each cycle the taker is chosen afresh from what the belief holds now: a choice made on
        # stale beliefs (each player sure another is nearer) would leave the ball untaken.
        rechoose = view.mode_ours and mode in RECHOSEN
        taker = set_plays.taker
        if rechoose:
            set_plays.taker = -1
        elif mode == PlayMode.KICK_OFF and view.mode_ours and self.kick_off_taker >= 0:
            set_plays.taker = self.kick_off_taker
        since = self.mode_since
        if mode == PlayMode.PLAY_ON:
            self._play_on(view, race, ball_player, own, in_flight, eligible)
        elif mode in (PlayMode.KICK_OFF, PlayMode.AFTER_GOAL):
            set_plays.kick_off(view, g, own, u, since)
        elif mode == PlayMode.GOALIE_HOLDS:
            set_plays.goalie_holds(view, g, own, since)
        else:
            set_plays.set_play(view, g, own, u, since)
        if rechoose and set_plays.taker != taker:
            set_plays.routine = None  # the next cycle's routine is made around the new taker
        return self._take_rows(rows, goals, urgent, command)

    def _take_rows(self, rows: np.ndarray, goals: np.ndarray, urgent: np.ndarray, command: TeamCommand) -> bool:
        """The belief's ``rows`` of its goals and command into the team's; whether one of them kicks."""
        own = self.command
        goals[rows] = self.goals[rows]
        urgent[rows] = self.urgent[rows]
        mine = rows & own.kick.any(axis=1)
        command.kick[mine] = own.kick[mine]
        if self.goalie >= 0 and rows[self.goalie] and own.catch:
            command.catch = True
        if own.move is not None:
            if command.move is None:
                command.move = goals.copy()
            command.move[rows] = own.move[rows]
        if own.tackle is not None:
            tackling = rows & np.isfinite(own.tackle)
            if tackling.any():
                n = rows.shape[0]
                command.tackle = np.full(n, np.nan) if command.tackle is None else command.tackle
                command.foul = np.zeros(n, dtype=bool) if command.foul is None else command.foul
                command.tackle[tackling] = own.tackle[tackling]
                if own.foul is not None:
                    command.foul[tackling] = own.foul[tackling]
        if self.kicker >= 0 and not rows[self.kicker]:
            self.dribble_dash = None
        return bool(mine.any())

    def _play_on(self, view: TeamView, race: skills.BallRace, ball_player: int, command: TeamCommand,
                 in_flight: bool, eligible: np.ndarray) -> None:
        """Play on: who kicks, the goalkeeper's catch, the kick or our tackle (module docstring)."""
        ctx, set_plays = self.ctx, self.set_plays
        if set_plays.goal_kick_leaving:
            if self.model.in_penalty_area(view.ball):
                return  # our goal kick is on its way out: with proper goal kicks nobody may play it yet
            set_plays.goal_kick_leaving = False
        able = able_players(view, eligible if in_flight else None)
        kicker = choose_kicker(view, race, ball_player, self.kickable, able)
        goalie_near = self.goalie >= 0 and race.ours.cycles[self.goalie] <= 1
        if kicker >= 0 and kicker == self.goalie and skills.should_catch(ctx, view, self.goalie,
                                                                         teammate_kicked_last=in_flight):
            command.catch = True  # a held ball is safer than a kick
            kicker = -1
        self.kicker = kicker
        if kicker >= 0:
            blocking = self.tackling.shot_at_us(view, in_flight)
            contested = race.theirs.first_cycle == 0
            kick, self.dribble_dash, shot = on_ball_kick(ctx, view, kicker, self.goalie, self.style.decision, race,
                                                         contested, blocking)
            command.kick[kicker] = kick
            if shot:
                self.shot_cycle, self.shot_from = view.cycle, view.ball.copy()
        elif goalie_near and not command.catch and skills.should_catch(ctx, view, self.goalie,
                                                                       teammate_kicked_last=in_flight):
            command.catch = True
        elif not command.catch:
            tackle_if_worth(self.tackling, view, command, race, in_flight)


def follow_up_goals(params: ShapeParams, is_forward: np.ndarray, half_length: float, shot_from: np.ndarray,
                    view: TeamView, ball_player: int, outfield: np.ndarray, player_roles: np.ndarray,
                    rows: np.ndarray, goals: np.ndarray, urgent: np.ndarray) -> None:
    """After a shot from ``shot_from`` the ``follow_up_players`` forwards nearest the rebound
    spots (``rebound_depth`` in front of their goal, ``rebound_spread`` either side of the
    shot's line) run there, each to the nearest free spot (goals and hurry in place, team
    frame); ``outfield[j]`` plays formation role ``player_roles[j]``; only ``rows`` ((n,) bool)
    are written."""
    if params.follow_up_players == 0:
        return
    goal_x = half_length - params.rebound_depth
    from_x, from_y = float(shot_from[0]), float(shot_from[1])
    t = (goal_x - from_x) / (half_length - from_x) if half_length - from_x > 1e-9 else 1.0
    centre_y = from_y * (1.0 - min(max(t, 0.0), 1.0))
    spots = np.array([[goal_x, centre_y - params.rebound_spread], [goal_x, centre_y + params.rebound_spread]])
    runners = outfield[is_forward[player_roles] & (outfield != ball_player)]
    if not runners.size:
        return
    gaps = np.hypot(view.own_pos[runners, 0] - goal_x, view.own_pos[runners, 1] - centre_y)
    runners = runners[np.argsort(gaps, kind="stable")[: min(params.follow_up_players, len(spots))]]
    for row in runners.tolist():
        k = int(np.argmin(np.hypot(*(spots - view.own_pos[row]).T)))
        if rows[row]:
            goals[row] = spots[k]
            urgent[row] = True
        spots[k] = np.inf  # taken
