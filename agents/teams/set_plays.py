"""The built-in team's set plays: who takes ours, when and how, kick-off placement, and the
goalkeeper's held ball.

At our set plays the outfield player nearest the ball (our goalkeeper at our goal kicks,
``TeamStyle.goalkeeper_goal_kicks``) takes it after the others had ``set_play_wait`` cycles
to take their places; if the taker is not there after the patience
(half the referee's set-play timeout, at least the wait), whoever of ours can kick the ball
takes it, so a set play is always taken well within the timeout. A set play of ours given
again at the same spot soon after our kick is that set play retaken: another player takes it,
another way (goal kicks avoid the directions that were retaken). Corner kicks and kick-ins
follow the routines of :mod:`agents.teams.routines` (runners into the box, a team-mate
coming short, crosses, the ball down the line).
"""

from __future__ import annotations

import numpy as np

from agents import skills
from agents.teams import routines
from agents.teams.style import TeamStyle
from soccer_sim.config import MatchConfig
from soccer_sim.state import PlayMode
from soccer_sim.team import TeamCommand, TeamView

RETAKE_WINDOW = 50
"""A set play of ours given again at the same spot within this many cycles of our kick is
that set play retaken."""


class SetPlays:
    """Our set plays during one match (see the module docstring). The team hands it, each
    cycle, the view, its players' goal points, the command and the urgent flags it fills."""

    def __init__(self, ctx: skills.SkillContext, config: MatchConfig, style: TeamStyle,
                 outfield: np.ndarray) -> None:
        model = ctx.model
        self.ctx = ctx
        self.style = style
        self.n = model.players_per_team
        self.goalie = model.goalie_index
        self.outfield = outfield
        self.kickable = model.kickable_distance
        self.proper_goal_kicks = config.rules.proper_goal_kicks
        self.taker = -1
        """Our taker of the current set play (-1: not chosen yet)."""
        self.routine: tuple[np.ndarray, np.ndarray] | None = None
        """The current corner's or kick-in's routine players and their goal points (None: not
        chosen yet; :func:`agents.teams.routines.routine_goals`)."""
        self.goal_kick_leaving = False
        """Our goal kick is on its way out of the penalty area (with proper goal kicks nobody
        of ours may play it yet)."""
        self.taken: tuple[int, float, float, int] | None = None
        """(mode, ball x, ball y, cycle) of the last set play we kicked."""
        self.tried_takers: list[int] = []
        self.tried_kicks: list[np.ndarray] = []
        """Takers and kick directions of the current set play's attempts (a retake tries others)."""
        self.patience = max(style.set_play_wait, config.rules.set_play_timeout // 2)
        """Cycles of a set play after which whoever of ours can kick the ball takes it."""
        self.kick_off_gap = model.touch_distance + 0.1
        """How far behind the ball our kick-off taker is placed (m)."""
        self.goal_centre_guard = np.array([-model.half_length + skills.GoalieParams().depth_far, 0.0])
        """Where our goalkeeper waits at our goal kicks: in front of the goal's centre, away
        from the spot on the goal area's corner and from every kick out of it."""

    def kicked_last_cycle(self, view: TeamView) -> bool:
        """Whether we kicked a set play in the cycle before this view's."""
        return self.taken is not None and self.taken[3] == view.cycle - 1

    def begin(self, view: TeamView) -> None:
        """A new play mode other than play on: forget the taker; at a set play of ours that is
        the one we just kicked given again (a retake), remember who took it and how, so that
        another player takes it another way."""
        self.goal_kick_leaving = False
        self.taker = -1
        self.routine = None
        taken = self.taken
        retake = (view.mode_ours and taken is not None and taken[0] == int(view.play_mode)
                  and view.cycle - taken[3] <= RETAKE_WINDOW
                  and taken[1] == float(view.ball[0]) and taken[2] == float(view.ball[1]))
        if not retake:
            self.tried_takers.clear()
            self.tried_kicks.clear()

    def kick_off(self, view: TeamView, goals: np.ndarray, command: TeamCommand, urgent: np.ndarray,
                 since: int) -> None:
        """Before a kick-off (and in the pause after a goal) place everybody on their ``goals``
        (the set-play formation); at our kick-off the taker is placed just behind the ball and
        plays it once the wait is over. ``since``: the cycle the play mode began."""
        taker = self.take(view, goals, command, urgent, since) \
            if view.play_mode == PlayMode.KICK_OFF and view.mode_ours else -1
        move = goals.copy()
        if taker >= 0:
            move[taker] = (view.ball[0] - self.kick_off_gap, view.ball[1])
        command.move = move

    def set_play(self, view: TeamView, goals: np.ndarray, command: TeamCommand, urgent: np.ndarray,
                 since: int) -> None:
        """A set play other than a kick-off: ours is taken (our goalkeeper waiting in front
        of the goal at our goal kicks); theirs needs nothing more than the formation."""
        if not view.mode_ours:
            return
        mode = view.play_mode
        taker = self.take(view, goals, command, urgent, since)
        if mode == PlayMode.GOAL_KICK and self.goalie >= 0 and taker != self.goalie:
            goals[self.goalie] = self.goal_centre_guard
        elif mode in (PlayMode.CORNER_KICK, PlayMode.KICK_IN):
            if self.routine is None:
                self.routine = routines.routine_goals(view, self.ctx.model, goals, self.outfield, taker,
                                                      mode == PlayMode.CORNER_KICK, self.style.routines)
            rows, points = self.routine
            goals[rows] = points
            goals[taker] = view.ball  # (a routine made around another taker never holds this one back)

    def take(self, view: TeamView, goals: np.ndarray, command: TeamCommand, urgent: np.ndarray,
             since: int) -> int:
        """Our set play: the taker (chosen once per set play) runs to the ball and, the wait
        over, kicks it; if it is not there after the patience, whoever of ours can kick the
        ball takes it. Returns the taker."""
        taker = self.taker
        if taker < 0:
            taker = self.taker = self._choose_taker(view)
        goals[taker] = view.ball
        urgent[taker] = True
        waited = view.cycle - since
        wait = self.style.set_play_wait
        if view.play_mode == PlayMode.CORNER_KICK:  # the runners need longer to get into the box
            wait = min(max(wait, self.style.routines.corner_wait), self.patience)
        if waited < wait:
            return taker
        gaps = np.hypot(*(view.own_pos - view.ball).T)
        kicker = taker
        if gaps[taker] > self.kickable:
            kicker = int(np.argmin(gaps))
            if waited < self.patience or gaps[kicker] > self.kickable:
                return taker
        self._kick(view, kicker, command)
        return taker

    def run_if_held_back(self, view: TeamView, goals: np.ndarray, dash: np.ndarray) -> None:
        """Our set-play taker, if the stamina policy left it standing short of the ball (at the
        stamina floor late in a half, when the capacity no longer pays for recovery), runs to
        the ball anyway: a set play not taken in time is lost (the ball is dropped)."""
        taker = self.taker
        if taker < 0 or dash[taker].any() or np.hypot(*(view.own_pos[taker] - view.ball)) <= self.kickable:
            return
        rows = slice(taker, taker + 1)
        skills.dash_to_points(self.ctx.model, self.ctx.arrays(view).ours.rows(taker, taker + 1), goals[rows],
                              out=dash[rows])

    def goalie_holds(self, view: TeamView, goals: np.ndarray, command: TeamCommand, since: int) -> None:
        """Our goalkeeper holding the ball distributes it once the wait is over, standing still
        meanwhile."""
        if self.goalie < 0:
            return
        if view.ball_holder == self.goalie and view.cycle - since >= self.style.set_play_wait:
            command.kick[self.goalie] = skills.distribute(self.ctx, view, self.goalie).kick
        goals[self.goalie] = view.own_pos[self.goalie]

    def _choose_taker(self, view: TeamView) -> int:
        """Our goalkeeper at our goal kicks if it has not tried this one yet, else the outfield
        player nearest the ball that has not tried this set play yet (a lone goalkeeper takes
        it)."""
        if (view.play_mode == PlayMode.GOAL_KICK and self.style.goalkeeper_goal_kicks and self.goalie >= 0
                and self.goalie not in self.tried_takers):
            return self.goalie
        candidates = self.outfield if len(self.outfield) else np.arange(self.n)  # (rows in order)
        if self.tried_takers:
            fresh = [c for c in candidates.tolist() if c not in self.tried_takers]
            if fresh:
                candidates = np.array(fresh, dtype=np.int64)
        gaps = np.hypot(*(view.own_pos[candidates] - view.ball).T)
        return int(candidates[int(np.argmin(gaps))])

    def _kick(self, view: TeamView, kicker: int, command: TeamCommand) -> None:
        """``kicker`` takes our set play. A goal kick is cleared along a path nobody else can
        reach before the ball leaves our penalty area (the kicks of earlier attempts avoided);
        other set plays are played as in open play, or cleared when retaken."""
        ctx = self.ctx
        if view.play_mode == PlayMode.GOAL_KICK:
            plan = skills.goal_kick_clearance(ctx, view, kicker, avoid=tuple(self.tried_kicks))
            kick, direction = plan.kick, plan.direction
            # With proper goal kicks our own players must keep off the ball until it is out of
            # the area.
            self.goal_kick_leaving = self.proper_goal_kicks
        else:
            kick = None
            if not self.tried_kicks:
                mode = view.play_mode
                if mode == PlayMode.CORNER_KICK:
                    _, kick = routines.corner_kick(ctx, view, kicker, self.outfield, self.style.routines)
                elif mode == PlayMode.KICK_IN:
                    kick = routines.kick_in(ctx, view, kicker, self.style.decision, self.style.routines)
                else:
                    kick = skills.decide_on_ball(ctx, view, kicker, self.style.decision).kick
            if kick is None or not kick.any():
                kick = skills.best_clearance(ctx, view, kicker).kick
            speed = float(np.hypot(*kick))
            direction = kick / speed if speed > 0.0 else np.array([1.0, 0.0])
        command.kick[kicker] = kick
        self.taken = (int(view.play_mode), float(view.ball[0]), float(view.ball[1]), view.cycle)
        self.tried_takers.append(kicker)
        self.tried_kicks.append(direction)
