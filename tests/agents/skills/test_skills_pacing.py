"""The stamina policy (agents.skills.pacing): the dash-power budget of fresh and tired, urgent
and calm players on hand-built views, the floor over the recovery threshold, settling near
the target, the sprinted runs, the rest of players away from the play, the capacity's
pacing, the simulator charging no more than the budget, and a short match in which stamina
stays above the floor."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents.skills import MotionModel, PacingParams, SkillContext, SkillInputError, paced_dashes
from soccer_sim import Match, MatchConfig
from soccer_sim.kinematics import Kinematics
from soccer_sim.team import TeamView
from tests.agents.skills.skill_views import CONFIG, N, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
P = PacingParams()
MAX = CONFIG.stamina.maximum
INCOME = CONFIG.stamina.recovery_per_cycle
FLOOR = (CONFIG.stamina.recover_dec_thr + P.floor_margin) * MAX
PLAYER = 5  # an outfield player (the goalkeeper is row 0)


def budget_of(view: TeamView, target, urgent: bool = False, attacking: bool | None = None,
              player: int = PLAYER) -> tuple[float, np.ndarray]:
    """``player``'s power budget and dash for ``target`` (the others stay where they are)."""
    targets = view.own_pos.copy()
    targets[player] = target
    hurry = np.zeros(N, dtype=bool)
    hurry[player] = urgent
    budgets, out = np.empty(N), np.empty((N, 2))
    paced_dashes(CTX, view, targets, hurry, out, attacking=attacking, budgets=budgets)
    return float(budgets[player]), out[player]


def one_player(x: float = 0.0, y: float = 0.0, stamina: float = MAX, vel=(0.0, 0.0), ball=(30.0, 30.0),
               capacity: float | None = None, cycle: int = 0) -> TeamView:
    """A view with PLAYER at (x, y) and the given stamina (the others fresh)."""
    stam = np.full(N, MAX)
    stam[PLAYER] = stamina
    view = make_view(own={PLAYER: (x, y)}, own_vel={PLAYER: vel}, stamina=stam, ball=ball)
    if capacity is not None:
        view.capacity = np.full(N, capacity)
    view.cycle = cycle
    return view


def test_fresh_and_tired_urgent_and_calm_players_get_their_budgets() -> None:
    far = (20.0, 0.0)
    assert budget_of(one_player(), far, urgent=True)[0] == 100.0  # sprint
    assert budget_of(one_player(), far)[0] == pytest.approx(P.cruise * INCOME)  # brisk run, above the income
    tired = one_player(stamina=P.tired * MAX)
    assert budget_of(tired, far)[0] == pytest.approx(P.recover_share * INCOME)  # recovers while it jogs
    assert budget_of(tired, far, urgent=True)[0] == 100.0  # a tired player still sprints when it matters
    # Between tired and fresh the ceiling falls linearly.
    middle = one_player(stamina=0.5 * (P.tired + P.fresh) * MAX)
    assert budget_of(middle, far)[0] == pytest.approx(0.5 * (P.cruise + P.recover_share) * INCOME)


def test_no_dash_spends_below_the_floor_unless_the_ball_is_at_hand() -> None:
    far = (20.0, 0.0)
    near_floor = one_player(stamina=FLOOR + 30.0)
    assert budget_of(near_floor, far, urgent=True)[0] == pytest.approx(30.0)
    below = one_player(stamina=FLOOR - 100.0)
    budget, dash = budget_of(below, far, urgent=True)
    assert budget == 0.0 and not dash.any()
    # About to play the ball: it may spend what the simulator lets it.
    at_ball = one_player(stamina=FLOOR - 100.0, ball=(1.0, 0.0))
    assert budget_of(at_ball, (1.0, 0.0), urgent=True)[0] == 100.0
    assert FLOOR > CONFIG.stamina.recover_dec_thr * MAX


def test_pace_grows_with_the_distance_to_the_target_and_settles_near_it() -> None:
    view = one_player(ball=(3.0, 0.0))
    budgets = [budget_of(view, (d, 0.0))[0] for d in (3.0, 6.0, P.far, 2 * P.far)]
    assert budgets[0] == pytest.approx((P.walk + (P.cruise - P.walk) * 3.0 / P.far) * INCOME)
    assert budgets[0] < budgets[1] < budgets[2] == budgets[3]
    budget, dash = budget_of(view, (0.8, 0.0))  # within the settling distance: no dash
    assert budget == 0.0 and not dash.any()
    assert budget_of(view, (0.8, 0.0), urgent=True)[1].any()  # unless in a hurry
    # The settling distance grows with the distance to the ball.
    far_ball = one_player(ball=(-40.0, 30.0))  # 50 m away: settles within 2.5 m
    assert not budget_of(far_ball, (2.4, 0.0))[1].any()
    assert budget_of(far_ball, (2.6, 0.0))[1].any()
    # In their half, a player in front of its target steps back (the offside line is there).
    assert budget_of(one_player(x=20.5, ball=(3.0, 0.0)), (20.0, 0.0))[1].any()
    # The goalkeeper never settles and always paces at cruise.
    keeper = make_view(own={0: (-50.0, 0.0)}, ball=(-40.0, 0.0))
    assert budget_of(keeper, (-49.5, 0.0), player=0)[0] == pytest.approx(P.cruise * INCOME)


def test_runs_that_matter_are_sprinted() -> None:
    # Our ball in their half: a run into the final third.
    attack = one_player(x=10.0, ball=(12.0, 0.0))
    assert budget_of(attack, (30.0, 0.0), attacking=True)[0] == 100.0
    assert budget_of(attack, (30.0, 0.0), attacking=None)[0] < 100.0  # not in a set play
    assert budget_of(attack, (15.0, 0.0), attacking=True)[0] < 100.0  # short of the final third
    assert budget_of(one_player(x=10.0, ball=(-5.0, 0.0)), (30.0, 0.0), attacking=True)[0] < 100.0
    # Their ball in our half: a player caught in front of it runs back goal-side.
    caught = one_player(x=-10.0, ball=(-20.0, 0.0))
    assert budget_of(caught, (-35.0, 0.0), attacking=False)[0] == 100.0
    behind = one_player(x=-30.0, ball=(-20.0, 0.0))  # already goal-side
    assert budget_of(behind, (-40.0, 0.0), attacking=False)[0] < 100.0
    assert budget_of(one_player(x=30.0, ball=(20.0, 0.0)), (5.0, 0.0), attacking=False)[0] < 100.0


def test_players_away_from_the_play_rest() -> None:
    # We attack with the ball at x = 30: a centre-back's place at x = 0 is the rest defence.
    back = one_player(x=-20.0, ball=(30.0, 0.0))
    assert budget_of(back, (0.0, 0.0), attacking=True)[0] == pytest.approx(P.rest_share * INCOME)
    assert budget_of(back, (0.0, 0.0), attacking=None)[0] == pytest.approx(P.cruise * INCOME)
    # They attack at x = -30: a forward's place at x = 0 waits for the counter.
    forward = one_player(x=20.0, ball=(-30.0, 0.0))
    assert budget_of(forward, (0.0, 0.0), attacking=False)[0] == pytest.approx(P.rest_share * INCOME)


def test_the_capacity_paces_the_rest_of_the_half() -> None:
    far = (20.0, 0.0)
    half = CONFIG.rules.half_cycles
    # Stamina left to recover for a quarter of the income over the rest of the half.
    view = one_player(capacity=0.25 * INCOME * half - (MAX - FLOOR))
    assert budget_of(view, far)[0] == pytest.approx(P.cruise * 0.25 * INCOME)
    # With as much left late in the half, the recovery is the limit again.
    late = one_player(capacity=0.25 * INCOME * half - (MAX - FLOOR), cycle=half - 100)
    assert budget_of(late, far)[0] == pytest.approx(P.cruise * INCOME)
    # Nothing left to recover: only what is above the floor, spread over the half.
    empty = one_player(capacity=0.0)
    assert budget_of(empty, far)[0] == pytest.approx(P.cruise * (MAX - FLOOR) / half)


def test_the_simulator_charges_no_more_than_the_budget() -> None:
    """Moving players turning towards targets in every direction (side and back dashes cost
    more): the power the simulator takes from stamina never exceeds the budget, so nobody
    ends below the floor."""
    rng = np.random.default_rng(3)
    kin = Kinematics(CONFIG, 2 * N)
    for _ in range(20):
        stamina = rng.uniform(FLOOR, MAX, N)
        own = rng.uniform(-40.0, 40.0, (N, 2))
        vel = rng.uniform(-0.6, 0.6, (N, 2))
        view = make_view(own=own, own_vel=vel, stamina=stamina, ball=(0.0, 60.0))  # nobody at the ball
        targets = own + rng.uniform(-15.0, 15.0, (N, 2))
        urgent = rng.uniform(size=N) < 0.3
        out, budgets = np.empty((N, 2)), np.empty(N)
        paced_dashes(CTX, view, targets, urgent, out, attacking=bool(rng.uniform() < 0.5), budgets=budgets)
        all_vel = np.zeros((2 * N, 2))
        all_vel[:N] = vel
        dash = np.zeros((2 * N, 2))
        dash[:N] = out
        st = np.full(2 * N, MAX)
        st[:N] = stamina
        before = st.copy()
        recovery, capacity, effort = np.ones(2 * N), np.zeros(2 * N), np.ones(2 * N)  # no recovery
        kin.dash(all_vel, np.zeros(2), st, effort, recovery, capacity, dash, np.zeros((2 * N + 1, 2)))
        spent = (before - st)[:N]
        assert np.all(spent <= budgets + 1e-6)
        assert np.all(st[:N] >= FLOOR - 1e-6)


def test_params_are_checked() -> None:
    with pytest.raises(SkillInputError, match="PacingParams.cruise"):
        PacingParams(cruise=-1.0)
    with pytest.raises(SkillInputError, match="tired"):
        PacingParams(tired=0.8, fresh=0.7)
    with pytest.raises(SkillInputError, match="walk"):
        PacingParams(walk=2.0, cruise=1.5)
    with pytest.raises(SkillInputError, match="floor_margin"):
        PacingParams(floor_margin=1.5)
    with pytest.raises(SkillInputError, match="params"):
        paced_dashes(CTX, make_view(), np.zeros((N, 2)), params="fast")


class _Low:
    """Stamina recorder: outfield player-cycles below the floor and below the recovery threshold."""

    def on_start(self, match: Match) -> None:
        goalies = set(match.setup.goalie_rows)
        self.rows = np.array([r for r in range(sum(match.sizes)) if r not in goalies])
        self.below_floor = self.below_threshold = self.cycles = 0
        self.lowest = np.inf

    def on_cycle(self, match: Match) -> None:
        stamina = match.state.stamina[self.rows]
        self.below_floor += int(np.count_nonzero(stamina < FLOOR))
        self.below_threshold += int(np.count_nonzero(stamina < CONFIG.stamina.recover_dec_thr * MAX))
        self.cycles += stamina.size
        self.lowest = min(self.lowest, float(stamina.min()))

    def on_end(self, match: Match) -> None:
        pass


def test_in_a_short_match_stamina_stays_above_the_floor() -> None:
    """600 cycles of a built-in match (the old speed caps had drained every outfield player
    to nothing by cycle 500): outfield stamina stays above the floor, the rare exceptions
    being players about to play the ball."""
    low = _Low()
    Match("mmdr", "counter-442", seed=1, config=replace(MatchConfig(), max_cycles=600), recorders=[low]).run()
    assert low.below_threshold == 0
    assert low.below_floor <= 0.01 * low.cycles
    assert low.lowest > 100.0
