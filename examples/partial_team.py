"""A team for partial observation: each player decides from its own view and what it heard.

Every player remembers where it last saw the ball, or where a team-mate said the ball was (a
10-character ``TeamMessage``); the player who believes no team-mate it sees is nearer the ball
runs to it and kicks at goal; the others keep a 4-4-2 shape that follows the ball; players who
see the ball tell the others (several may speak, and each listener hears one of them).

    soccer-sim play examples.partial_team:PartialTeam chaser --observation partial
    soccer-sim tournament --teams chaser,examples.partial_team:PartialTeam --observation partial --games 4
"""

import numpy as np

from agents.messages import X_RANGE, Y_RANGE, TeamMessage, decode, encode
from soccer_sim.perception.views import TEAMMATE, PlayerViews
from soccer_sim.team import TeamCommand

SPOTS = np.array([(-45, 0), (-32, -20), (-32, -7), (-32, 7), (-32, 20), (-12, -22), (-12, -7), (-12, 7), (-12, 22),
                  (5, -8), (5, 8)], dtype=float)  # home spots (m), own frame, goalkeeper first


class PartialTeam:
    observation_modes = ("partial",)  # act() takes per-player views

    def reset(self, side_info, config, rng):
        self.n = side_info.players_per_team
        self.ball = np.zeros((self.n, 2))           # each player's own memory of the ball
        self.goal = np.array([config.field.half_length, 0.0])
        self.kickable = config.physics.kickable_distance
        self.goalie = side_info.goalie_index

    def act(self, views: PlayerViews) -> TeamCommand:
        dash, kick, say = np.zeros((self.n, 2)), np.zeros((self.n, 2)), [None] * self.n
        for i in range(self.n):
            me = views.player(i)
            if me.ball_seen:
                self.ball[i] = me.ball
                say[i] = encode(TeamMessage((), 0, False, tuple(np.clip(me.ball, (-X_RANGE, -Y_RANGE), (X_RANGE, Y_RANGE))),
                                            0, sender=tuple(np.clip(me.position, (-X_RANGE, -Y_RANGE),
                                                                    (X_RANGE, Y_RANGE)))))
            elif me.heard_mates:                      # a team-mate's word about the ball
                self.ball[i] = decode(me.heard_mates[0][1]).ball
            ball = self.ball[i]
            mates = me.players[me.player_sides == TEAMMATE]
            mine = np.hypot(*(ball - me.position))
            if len(mates) == 0 or mine <= np.hypot(*(mates - ball).T).min():
                if mine <= self.kickable:                     # one body command a cycle: kick ...
                    kick[i] = (self.goal - ball) / max(np.hypot(*(self.goal - ball)), 1e-9) * 3.0
                else:                                         # ... or run (clipped to full power)
                    dash[i] = (ball - me.position) * 100.0
            else:
                spot = SPOTS[i % len(SPOTS)] + np.array([ball[0] * 0.5, ball[1] * 0.2])
                dash[i] = (spot - me.position) * 0.3
        keeper = views.player(self.goalie) if 0 <= self.goalie < self.n else None
        catch = keeper is not None and keeper.ball_seen and np.hypot(*(keeper.ball - keeper.position)) < 2.0
        return TeamCommand(dash=dash, kick=kick, catch=bool(catch), say=say)
