"""Each player's own world model under partial observation: what it believes about the ball,
its team-mates and the opponents, from its own sees and the messages it hears.

:class:`TeamBeliefs` holds one model per player of a team, as arrays with the believing player
first (row ``i`` is player ``i``'s model, and nothing in row ``i`` is computed from another
row), so a whole team's models advance in a few compiled calls per cycle. Team frame, metres,
m/cycle, cycles. Per cycle (:meth:`TeamBeliefs.update`):

1. **Predict.** The believed ball rolls on with its believed velocity and slows by
   ``ball_decay``; players are believed to stay where they were seen; every age grows by one.
2. **Own sees.** The ball through an alpha-beta filter (restarted when a sighting falls outside
   the noise its distance allows: the ball was kicked), the velocity of a restart from the last
   two sightings; players seen with a number update that player, those seen without one the
   nearest believed player of their side (or of either side) within a gate
   (:mod:`agents.teams.belief_kernels`). Each player's own position is its self-localisation.
3. **Messages.** The team message heard (:class:`~agents.messages.TeamMessage`, said last
   cycle by the team-mate whose turn it was, :mod:`agents.teams.speaking`) tells where the
   speaker believed the ball would be now, with the belief's age and either the ball's velocity
   or where the speaker stands (age 1); the listener takes the ball from it when that is
   fresher than its own belief.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import NamedTuple

import numpy as np

from agents.message_kernels import number_digits
from agents.messages import MESSAGE_GRID, MESSAGE_LENGTH, digit_texts, heard_pairs, said_bytes, text_digits
from agents.teams.belief_kernels import AGE_NEVER, BELIEF_PARAMS, own_kicks
from agents.teams.belief_record import (SeeRecords, belief_record, hear_and_believe, hear_block_and_believe,
                                        message_codes)
from agents.teams.speaking import TurnMemory, speaker_message, turn_memory
from soccer_sim.config import MatchConfig
from soccer_sim.kernels import make_record
from soccer_sim.perception.views import HeardLog, PlayerViews
from soccer_sim.state import NO_PLAYER, PlayMode
from soccer_sim.team import SideInfo, TeamView


class Senses(NamedTuple):
    """What each player of a team senses of itself this cycle, whatever it believes of the
    rest ((n, ...) arrays, team frame, metres, m/cycle): the rows the pipeline's dashes and its
    choice of who decides on the ball read."""

    position: np.ndarray
    velocity: np.ndarray
    effort: np.ndarray
    stamina: np.ndarray
    capacity: np.ndarray
    holds: np.ndarray
    """(n,) bool: the player holds the ball (a goalkeeper's catch)."""
    present: np.ndarray
    """(n,) bool: the player is on the field (not sent off)."""
    saw: np.ndarray
    """(n,) bool: the player received a see this cycle (every cycle under full observation)."""


@dataclass(frozen=True)
class BeliefParams:
    """How the world model weighs what it sees (dimensionless gains, metres)."""

    ball_gain: float = 0.6
    """Share of a ball sighting's residual taken into the believed position (the rest is the
    prediction, which averages out the see model's distance quantisation)."""
    ball_velocity_gain: float = 0.2
    """Share of the residual (m) taken into the believed velocity (m/cycle) per sighting."""
    ball_noise_share: float = 0.12
    """A sighting farther from the prediction than this share of its distance (plus 0.3 m)
    restarts the filter: more than the +-5 % distance quantisation and 1 degree direction
    steps explain, so the ball's motion changed."""
    near: float = 5.0
    """A ball sighting nearer than this (m) is taken as it is (its distance errs by at most
    about 0.25 m), the velocity from the last two sightings."""
    gate_share: float = 0.15
    """Players seen without a number are matched to a believed player within this share of the
    reported distance..."""
    gate_floor: float = 2.0
    """... plus this (m)."""


class TruthBeliefs:
    """Full observation as a world model: every player believes the truth, so a team holds
    one belief row (row 0, what the team view says), which every player takes its world from
    (:attr:`belief_of`). The same arrays as :class:`TeamBeliefs` (with one row), so the
    pipeline reads both alike; the truth needs no messages."""

    talks = False
    """Whether the players keep their beliefs fresh through the say channel (no: nothing to tell)."""

    def __init__(self, n: int, m: int) -> None:
        self.n, self.m = n, m
        self.ball = np.zeros((1, 2))
        self.ball_vel = np.zeros((1, 2))
        self.ball_age = np.zeros(1, dtype=np.int64)
        self.mate_pos = np.zeros((1, n, 2))
        self.mate_vel = np.zeros((1, n, 2))
        self.mate_effort = np.ones((1, n))
        self.opp_pos = np.zeros((1, m, 2))
        self.opp_age = np.zeros((1, m), dtype=np.int64)
        """(1, m) cycles since each opponent's position was seen: 0, the truth is always current."""
        self.opp_vel = np.zeros((1, m, 2))
        self.belief_of = np.zeros(n, dtype=np.int64)
        """(n,) the belief row each player takes its world from: row 0 for all."""
        self.view: TeamView | None = None
        self._holds = np.zeros(n, dtype=bool)
        self._saw = np.ones(n, dtype=bool)

    def update(self, view: TeamView, turns: TurnMemory | None = None, horizon: int = 0) -> Senses:
        """Row 0 becomes the team view's truth; returns the players' senses of this cycle."""
        self.view = view
        self.ball[0] = view.ball
        self.ball_vel[0] = view.ball_vel
        self.mate_pos[0] = view.own_pos
        self.mate_vel[0] = view.own_vel
        self.mate_effort[0] = view.effort
        self.opp_pos[0] = view.opp_pos
        self.opp_vel[0] = view.opp_vel
        self._holds[:] = False
        if view.ball_holder != NO_PLAYER and 0 <= view.ball_holder < self.n:
            self._holds[view.ball_holder] = True
        return Senses(view.own_pos, view.own_vel, view.effort, view.stamina, view.capacity, self._holds,
                      view.present, self._saw)

    def view_of(self, b: int) -> TeamView:
        """Belief ``b`` (0) as a team view: the team view itself."""
        assert self.view is not None, "view_of before update"
        return self.view

    def kicked(self, kick: np.ndarray, kickable: float) -> None:
        """The truth needs no telling what the players kicked."""


class TeamBeliefs:
    """The world models of a team's ``n`` players about ``m`` opponents (module docstring)."""

    talks = True
    """Whether the players keep their beliefs fresh and their roles agreed through the say
    channel (yes: the team message, in turns)."""

    def __init__(self, n: int, m: int, config: MatchConfig, params: BeliefParams = BeliefParams(),
                 side_info: SideInfo | None = None) -> None:
        self.n, self.m, self.params = n, m, params
        self.side_info = side_info
        """The side the players play on (its goalkeeper and player types, for :meth:`view_of`;
        None: no goalkeeper, default types)."""
        self._ball_decay = float(config.physics.ball_decay)
        self._ball_speed_max = float(config.physics.ball_speed_max)
        self.ball = np.zeros((n, 2))
        """(n, 2) each player's believed ball position (m; the centre spot before any sighting)."""
        self.ball_vel = np.zeros((n, 2))
        """(n, 2) each player's believed ball velocity (m/cycle)."""
        self.ball_age = np.full(n, AGE_NEVER, dtype=np.int64)
        """(n,) cycles since the ball information each player holds was seen (by it or the
        team-mate who told it); AGE_NEVER before any."""
        self.mate_pos = np.zeros((n, n, 2))
        """(n, n, 2) where player i believes team-mate j is (row i, column i: itself)."""
        self.mate_age = np.full((n, n), AGE_NEVER, dtype=np.int64)
        self.opp_pos = np.zeros((n, m, 2))
        """(n, m, 2) where player i believes opponent k is."""
        self.opp_age = np.full((n, m), AGE_NEVER, dtype=np.int64)
        self._last_seen = np.zeros((n, 2))
        self._last_seen_cycle = np.full(n, -AGE_NEVER, dtype=np.int64)
        self.mate_vel = np.zeros((n, n, 2))
        """(n, n, 2) the velocity player i believes team-mate j has: its own sensed one, zero for
        the others (it cannot tell how they move)."""
        self.mate_effort = np.ones((n, n))
        """(n, n) the effort player i believes team-mate j has: its own for everybody."""
        self.opp_vel = np.zeros((n, m, 2))
        """(n, m, 2) the velocity player i believes opponent k has: zero (it cannot tell)."""
        self.belief_of = np.arange(n, dtype=np.int64)
        """(n,) the belief row each player takes its world from: its own."""
        self._rows = np.arange(n)
        self._views: list[TeamView] = []
        self._goalie = side_info.goalie_index if side_info is not None else -1
        self._last: PlayerViews | None = None
        self.record = belief_record(ball=self.ball, ball_vel=self.ball_vel, ball_age=self.ball_age,
                                    mate_pos=self.mate_pos, mate_age=self.mate_age, opp_pos=self.opp_pos,
                                    opp_age=self.opp_age, last_seen=self._last_seen,
                                    last_seen_cycle=self._last_seen_cycle,
                                    params=make_record(BELIEF_PARAMS, **asdict(params)),
                                    ball_decay=self._ball_decay, speed_max=self._ball_speed_max)
        """These arrays and constants as one compiled record
        (:class:`~agents.teams.belief_record.BeliefRecord`)."""
        self._sees = SeeRecords()
        """The views' sees as a compiled record, kept while the views hand the same arrays."""
        self._codes = message_codes()
        """The say channel's decoding tables as a compiled record."""
        self._no_turns = turn_memory(n, 0)
        """A memory that keeps no assignment heard, for an update without one."""

    def update(self, views: PlayerViews, turns: TurnMemory | None = None, horizon: int = 0) -> Senses:
        """One cycle of every player's model from its own row of ``views`` and the team
        message it heard (module docstring). With ``turns`` (the pipeline's memory of the
        proposals heard, :class:`~agents.teams.speaking.TurnMemory`) the proposal heard is
        taken into it too (a team assignment unheard for ``horizon`` cycles gives way at once): one compiled call
        (:func:`~agents.teams.belief_record.hear_and_believe`; for a match's
        :class:`~soccer_sim.perception.views.HeardLog` of messages all of our length,
        :func:`~agents.teams.belief_record.hear_block_and_believe` on the delivery itself).
        Returns the players' senses of this cycle."""
        self._last = views
        rows = self._rows
        self.mate_vel[rows, rows] = views.velocity
        self.mate_effort[:] = views.effort[:, None]
        log = views.heard_mates
        memory = turns if turns is not None else self._no_turns
        characters = said_bytes(log.messages) if isinstance(log, HeardLog) else None
        see = self._sees.of(views)
        if characters is not None:  # (a match's delivery, decoded as it stands)
            hear_block_and_believe(self.record, see, log.heard, characters, self._codes, memory, int(horizon),
                                   views.cycle)
            return self._senses(views)
        listeners, speakers, texts = heard_pairs(log)
        hear_and_believe(self.record, see, listeners, speakers, text_digits(texts), self._codes, memory,
                         int(horizon), views.cycle)
        return self._senses(views)

    @staticmethod
    def _senses(views: PlayerViews) -> Senses:
        return Senses(views.position, views.velocity, views.effort, views.stamina, views.capacity, views.holds_ball,
                      views.present, views.saw)

    def view_of(self, b: int) -> TeamView:
        """Player ``b``'s beliefs as a team view (team-mates and opponents where it believes them,
        their velocities unknown and taken as zero, everyone's stamina its own; its own rows
        from its own senses), for the skills that read a team view."""
        views = self._last
        assert views is not None, "view_of before update"
        if not self._views:
            n, m, side = self.n, self.m, self.side_info
            own_types = np.array(side.own_types if side is not None and side.own_types else (0,) * n, dtype=np.intp)
            opp_types = np.array(side.opponent_types if side is not None and side.opponent_types else (0,) * m,
                                 dtype=np.intp)
            self._views = [TeamView(own_pos=np.zeros((n, 2)), own_vel=np.zeros((n, 2)), opp_pos=np.zeros((m, 2)),
                                    opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2),
                                    stamina=np.zeros(n), effort=np.ones(n), capacity=np.full(n, np.inf),
                                    frozen=np.zeros(n, dtype=np.int64), cards=np.zeros(n, dtype=np.int64),
                                    own_types=own_types,
                                    opp_types=opp_types) for _ in range(n)]
        view = self._views[b]
        view.own_pos[:] = self.mate_pos[b]
        view.own_vel[:] = self.mate_vel[b]
        view.opp_pos[:] = self.opp_pos[b]
        view.ball[:] = self.ball[b]
        view.ball_vel[:] = self.ball_vel[b]
        view.stamina[:] = views.stamina[b]
        view.effort[:] = views.effort[b]
        view.capacity[:] = views.capacity[b]
        view.frozen[:] = 0
        view.frozen[b] = views.frozen[b]
        view.cards[:] = 0  # (a player knows its own card only)
        if views.cards is not None:
            view.cards[b] = views.cards[b]
        view.play_mode, view.mode_ours, view.score = views.play_mode, views.mode_ours, views.score
        view.cycle, view.half = views.cycle, views.half
        if views.holds_ball[b]:
            view.ball_holder = b
        elif views.play_mode == PlayMode.GOALIE_HOLDS and views.mode_ours and self._goalie >= 0:
            view.ball_holder = self._goalie
        else:
            view.ball_holder = NO_PLAYER
        return view

    def kicked(self, kick: np.ndarray, kickable: float) -> None:
        """Each player's own kicks of this cycle (``kick`` (n, 2) m/cycle, team frame; zero rows
        for none) change the velocity it believes the ball has, when it believes the ball is
        within ``kickable`` m: a player knows what it just did."""
        own_kicks(kick, float(kickable), self.ball, self.ball_vel, self.mate_pos, self._ball_speed_max)

    def message(self, speaker: int, cycle: int, proposal: tuple[int, ...] = (), settled: bool = False) -> str:
        """The team message ``speaker`` says at ``cycle`` from its beliefs
        (:func:`~agents.teams.speaking.speaker_message`: its ball, and its velocity or the
        speaker's position as the turn has it), with a role ``proposal`` (none by default), for
        a team that speaks in turns (:func:`~agents.teams.speaking.speaker_of`)."""
        digits = np.empty(MESSAGE_LENGTH, dtype=np.int64)
        number_digits(speaker_message(np.array(proposal, dtype=np.int64), int(cycle), bool(settled),
                                      self.ball[speaker], self.ball_vel[speaker], int(self.ball_age[speaker]),
                                      self.mate_pos[speaker, speaker], self.n, self._ball_decay, MESSAGE_GRID),
                      digits)
        return digit_texts(digits[None], np.ones(1, dtype=bool))[0]
