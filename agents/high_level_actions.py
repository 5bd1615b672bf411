"""High-level actions for the PettingZoo environment, built on the built-in team's skills.

Like Google Research Football's and Half Field Offense's action sets, each player picks one
of a few meaningful actions per cycle instead of raw dash and kick vectors. For ``k`` team-mate
slots (the environment's observation slots: 11 by default, whatever the team's size ``n``) the
actions (a ``Discrete(13 + k)`` space) are:

=============  ===============================================================================
0 - 7          run at full speed towards +x, then counter-clockwise every 45 degrees (team frame)
8              go to my formation target (the built-in 4-3-3, role by shirt number) and stop
9              intercept the ball: run to where I can first reach it (``skills.ball_race``)
10             shoot: the best shot (``skills.best_shot``), else a hard kick at the goal centre
11             dribble (``skills.dribble``)
12             idle: no dash, no kick
13 + k        pass to team-mate k (arriving at about 0.5 m/cycle; to myself: keep the ball; to an
              empty slot or a team-mate sent off: no kick)
=============  ===============================================================================

:meth:`HighLevelActions.action_mask` says which of them a player can take now. Kicks happen
only when the ball is kickable; the goalkeeper asks to catch when it chooses
"intercept" and the ball is within its reach. The environment finds this class through the
entry point group ``soccer_sim.action_modes`` (name ``high_level``), so ``soccer_sim`` never
imports ``agents``.
"""

from __future__ import annotations

import numpy as np

import formations
from agents import skills
from formations import Situation
from soccer_sim import MatchConfig, PlayMode, SideInfo, TeamCommand, TeamView

MOVES = 8
GO_TO_TARGET, INTERCEPT, SHOOT, DRIBBLE, IDLE, PASS = 8, 9, 10, 11, 12, 13
_ANGLES = np.arange(MOVES) * (np.pi / 4)
DIRECTIONS = np.column_stack([np.cos(_ANGLES), np.sin(_ANGLES)])
_NO_KICK_MODES = (PlayMode.AFTER_GOAL, PlayMode.TIME_OVER)
PASS_ARRIVAL_SPEED = 0.5
"""m/cycle: how fast a pass should reach its receiver."""


class HighLevelActions:
    """Turns each player's high-level action into the team's command (see the module docstring)."""

    def __init__(self, system: str = "4-3-3") -> None:
        self.formation_set = formations.load_builtin(system)

    @staticmethod
    def size(n: int) -> int:
        """How many actions a player of a team of ``n`` has."""
        return PASS + n

    def reset(self, side_info: SideInfo, config: MatchConfig) -> None:
        n, goalie = side_info.players_per_team, side_info.goalie_index
        self.n, self.goalie = n, goalie
        self.skills = skills.SkillContext.for_match(config, side_info)
        self.model = self.skills.model
        kinds = [role.kind for role in self.formation_set.roles]
        keeper_role = kinds.index("goalkeeper")
        outfield_roles = [r for r in range(len(kinds)) if r != keeper_role]
        self.role_of = np.zeros(n, dtype=np.int64)
        rows = [i for i in range(n) if i != goalie]
        self.role_of[rows] = outfield_roles[:len(rows)]
        if 0 <= goalie < n:
            self.role_of[goalie] = keeper_role
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def action_mask(self, view: TeamView, slots: int | None = None) -> np.ndarray:
        """(n, ``size(slots)``) bool, which actions each player can take now (``slots``: the
        team-mate slots of the action space, default n). Running, going to the target,
        intercepting and idling always; shooting, dribbling and passing only with the ball
        kickable, the play mode letting the team kick (play on, or its own restart) and the
        player not frozen after a tackle; a pass only to a team-mate on the pitch."""
        n = self.n
        mask = np.zeros((n, self.size(n if slots is None else slots)), dtype=bool)
        mask[:, :SHOOT] = True
        mask[:, IDLE] = True
        mode = view.play_mode
        may_kick = mode == PlayMode.PLAY_ON or (view.mode_ours and mode not in _NO_KICK_MODES)
        if not may_kick:
            return mask
        able = skills.kickable(self.model, view.own_pos, view.ball) & view.present
        if view.frozen is not None:
            able &= view.frozen == 0
        mask[:, SHOOT] = mask[:, DRIBBLE] = able
        mask[:, PASS:PASS + n] = able[:, None] & view.present[None, :]
        return mask

    def command_for(self, view: TeamView, actions: np.ndarray) -> TeamCommand:
        """The team's command for the players' ``actions`` ((n,) ints, already checked)."""
        ctx, model, command = self.skills, self.model, self.command
        command.kick[:] = 0.0
        command.catch = False
        goals = view.own_pos.copy()
        urgent = np.zeros(self.n, dtype=bool)
        run = np.zeros(self.n, dtype=bool)
        race = None
        targets = None
        can_kick = skills.kickable(model, view.own_pos, view.ball)
        for i, action in enumerate(actions.tolist()):
            if action < MOVES:
                goals[i] = view.own_pos[i] + DIRECTIONS[action] * 10.0
                urgent[i] = run[i] = True
            elif action == GO_TO_TARGET:
                if targets is None:
                    targets = self.formation_set.positions(view.ball, Situation.NORMAL)
                goals[i] = targets[self.role_of[i]]
            elif action == INTERCEPT:
                if race is None:
                    race = skills.ball_race(ctx, view)
                reachable = race.ours.cycles[i] < skills.UNREACHABLE
                goals[i] = race.ours.points[i] if reachable else view.ball
                urgent[i] = True
                if i == self.goalie and skills.should_catch(ctx, view, i):
                    command.catch = True
            elif action == SHOOT and can_kick[i]:
                shot = skills.best_shot(ctx, view, i)
                command.kick[i] = shot.kick if shot is not None else self._kick_towards(
                    view, i, np.array([model.half_length, 0.0]), model.ball_speed_max)
            elif action == DRIBBLE and can_kick[i]:
                plan = skills.dribble(ctx, view, i)
                command.kick[i] = plan.kick
                goals[i] = view.own_pos[i] + plan.dash * 10.0
                urgent[i] = run[i] = True
            elif action >= PASS and can_kick[i]:
                receiver = action - PASS
                if receiver != i and receiver < self.n and view.present[receiver]:  # else: no kick
                    distance = float(np.hypot(*(view.own_pos[receiver] - view.ball)))
                    speed = min(distance * (1.0 - model.ball_decay) + PASS_ARRIVAL_SPEED, model.ball_speed_max)
                    command.kick[i] = self._kick_towards(view, i, view.own_pos[receiver], speed)
        skills.paced_dashes(ctx, view, goals, urgent, command.dash)
        command.dash[actions == IDLE] = 0.0
        return command

    def _kick_towards(self, view: TeamView, player: int, point: np.ndarray, speed: float) -> np.ndarray:
        """The kick sending the ball towards ``point`` at ``speed`` m/cycle (as near as one kick can)."""
        direction = point - view.ball
        size = float(np.hypot(*direction))
        if size < 1e-9:
            return np.zeros(2)
        kick, _ = skills.kick_for_velocity(self.model, view.own_pos[player], view.ball, view.ball_vel,
                                           direction / size * speed, player_vel=view.own_vel[player])
        return kick
