"""A custom team in a few lines: hold a built-in formation, assign roles with MMD+MSD² every
cycle, send the nearest player to the ball, and kick at the opponents' goal.

It plays a match against the built-in ``chaser`` team and prints the result.
Run: python examples/formation_team.py [CYCLES] [FORMATION]
(FORMATION: a built-in set such as 4-4-2, or a formation-set file such as one made by
``soccer-sim formation import helios formations-dt/ my-team.json``)
"""

import os
import sys

import numpy as np

import formations
import soccer_sim
from agents.assignment import assign
from soccer_sim import TeamCommand
from soccer_sim.state import SET_PLAYS, PlayMode


class FormationTeam:
    def __init__(self, system: "str | formations.FormationSet" = "4-3-3", method: str = "mmd+msd2") -> None:
        # A loaded FormationSet, a formation-set file, or the name of a built-in set.
        if isinstance(system, formations.FormationSet):
            self.formation_set = system
        elif os.path.exists(system):
            self.formation_set = formations.load_set(system, field=soccer_sim.config.STANDARD_FIELD)
        else:
            self.formation_set = formations.load_builtin(system)
        self.method = method

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        roles = len(self.formation_set.roles)
        if n != roles or not 0 <= side_info.goalie_index < n:
            # This small example maps player i to role i: it needs a full side with a goalkeeper.
            raise ValueError(f"FormationTeam example plays {roles} players with a goalkeeper, not {n} "
                             f"(goalkeeper index {side_info.goalie_index}); the built-in teams play any size")
        self.goalie = side_info.goalie_index
        self.outfield = np.array([i for i in range(n) if i != self.goalie])
        self.goal_x = config.field.half_length
        self.kick_speed = config.physics.kick_speed_max
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def situation(self, view) -> str:
        if view.play_mode in SET_PLAYS or view.play_mode == PlayMode.GOALIE_HOLDS:
            return "our_set_play" if view.mode_ours else "their_set_play"
        return "attack" if view.ball[0] > 0 else "defend"

    def act(self, view) -> TeamCommand:
        targets = self.formation_set.positions(view.ball, self.situation(view))
        desired = targets.copy()  # row i: where player i should go (the goalkeeper keeps role 0)
        roles = assign(view.own_pos[self.outfield], targets[self.outfield], method=self.method).target_of
        desired[self.outfield] = targets[self.outfield][roles]
        distances = np.linalg.norm(view.own_pos[self.outfield] - view.ball, axis=1)
        desired[self.outfield[np.argmin(distances)]] = view.ball  # nearest outfield player chases
        # Accelerate so as to arrive next cycle; the match clips to the physical limits.
        self.command.dash[:] = desired - view.own_pos - view.own_vel
        to_goal = np.array([self.goal_x, 0.0]) - view.ball
        self.command.kick[:] = to_goal / np.linalg.norm(to_goal) * self.kick_speed - view.ball_vel
        self.command.catch = bool(np.linalg.norm(view.ball - view.own_pos[self.goalie]) < 1.2)
        return self.command


if __name__ == "__main__":
    cycles = int(sys.argv[1]) if len(sys.argv) > 1 else 6000
    system = sys.argv[2] if len(sys.argv) > 2 else "4-3-3"
    result = soccer_sim.run_match(FormationTeam(system), "chaser", seed=1, config=soccer_sim.MatchConfig(max_cycles=cycles))
    print(f"formation team {result.score[0]} : {result.score[1]} chaser")
