"""How hard each player runs: the dash-power budget of the stamina policy.

The simulator's stamina rules (rcssserver's, :class:`soccer_sim.config.StaminaConfig`) make
one line matter above all: a player whose stamina falls to ``recover_dec_thr * maximum``
loses recovery rate for the rest of the half (and below ``effort_dec_thr * maximum`` effort
too), so from then on it can afford only half the running. On top of that, the stamina it
can recover in a half (``capacity``) pays for about ``recovery_per_cycle`` a cycle and no
more. The policy therefore budgets **dash power** (stamina per cycle), not speed, as
helios-base does:

* **The floor.** No dash spends stamina below ``floor = recover_dec_thr * maximum +
  floor_margin * maximum`` (2,800 of 8,000 by default), sprint or not, except by a player
  who is about to play the ball (urgent and within ``play_distance`` of it). A player at the
  floor can still spend what it recovers each cycle, so it keeps jogging at its sustainable
  speed.
* **The income.** What a player may spend on average for the rest of the half: the
  recovery per cycle, or less when the stamina it can still recover (``capacity``) plus what
  it holds above the floor would not last until half time at that rate.
* **Urgent players sprint** (full power, down to the floor): those the team marks (the
  player going for the ball, pressers, our set-play taker) and, in play on, two runs that
  win or save matches: with the ball ours in their half, an attacking run to a target in
  the final third (``final_third``) at least ``run_distance`` ahead; with the ball theirs in
  our half (``danger_x``), the run back of a player caught in front of the ball to a target
  goal-side of it, ``run_distance`` or more behind the player.
* **Everybody else paces** by how far its target is: ``walk`` times the income for a
  target close by, rising to ``cruise`` times it for one ``far`` metres away or more (so
  the players whose places move most with play, wide players and midfielders, run most);
  and by how tired it is: the share is capped at ``recover_share`` at or below ``tired``
  (the player recovers while it runs) rising to ``cruise`` at ``fresh``. An outfield player
  within ``settle`` metres (``settle_share`` of its distance to the ball, at least
  ``settle``) of its target does not dash at all: the player decay stops it within a few
  tenths of a metre, and chasing every small move of a target costs stamina for nothing.
  It still steps back when it stands in front of a target in the opponents' half (the
  offside line is there). A player away from the play (its target well behind the ball
  when we attack, well ahead of it when they attack) paces at most at ``rest_share``. The
  goalkeeper always paces at ``cruise`` and never settles.

The budget becomes a dash in :func:`agents.skills.movement.paced_dashes`: the dash that
arrives and stops (as :func:`~agents.skills.movement.dash_to_points`) at the speed the budget
holds, shortened when its power, counted as the simulator counts it (side and back dashes
cost more), exceeds the budget.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.model import MotionModel, SkillInputError, check_params
from soccer_sim.kernels import make_record


@dataclass(frozen=True)
class PacingParams:
    """The stamina policy's choices (see the module docstring). Stamina levels are fractions
    of ``StaminaConfig.maximum``; powers are multiples of the income (about the recovery per
    cycle, 45 by default); distances in metres."""

    floor_margin: float = 0.05
    """How far above the recovery threshold (``recover_dec_thr``) no dash goes, as a share
    of the maximum: 400 stamina, eight cycles of a flat-out sprint, so the last sprint before
    the floor never crosses the threshold (helios-base keeps 1 stamina; we keep a little more
    because our dash power is decided before the side-dash cost is known exactly)."""
    fresh: float = 0.7
    """Stamina at or above which a player not in a hurry may run at ``cruise`` (helios-base
    leaves its recovery mode at 70 %)."""
    tired: float = 0.5
    """Stamina at or below which a player not in a hurry runs at ``recover_share`` of its
    income (helios-base enters its recovery mode at 50 %)."""
    recover_share: float = 0.5
    """Power of a tired player, as a share of the income: it recovers half the income a
    cycle while it still jogs (helios-base: the income less 25, 0.44 of it)."""
    cruise: float = 1.6
    """Power for a far target when fresh, as a multiple of the income: 0.72 m/cycle, a
    brisk run that reaches a far place in time without sprinting (helios-base runs its
    normal moves at 1.7 times the income)."""
    walk: float = 0.6
    """Power for a target just outside the settling distance, as a multiple of the income:
    a walk of 0.27 m/cycle for small adjustments."""
    far: float = 12.0
    """Distance to the target at which the pace reaches ``cruise`` (m): about a
    possession change's shift of the formation."""
    settle: float = 1.0
    """An outfield player not in a hurry this near its target does not dash (m; helios-base's
    positioning tolerance)."""
    settle_share: float = 0.05
    """... nor within this share of its distance to the ball (a place far from play needs
    less precision: 2 m at 40 m; helios-base allows twice that, which leaves a formation
    visibly ragged)."""
    play_distance: float = 2.0
    """An urgent player this near the ball is about to play it and may spend below the
    floor (m): losing the ball costs more than a little recovery."""
    final_third: float = 1.0 / 3.0
    """Attacking runs (the ball ours in their half) to targets beyond this share of the half
    length (the final third) are sprinted."""
    run_distance: float = 4.0
    """An attacking run or a run back counts only for a target at least this far (m)."""
    rest_share: float = 0.8
    """Power, as a multiple of the income, of a player away from the play: its target more
    than ``rest_gap`` behind the ball when we attack (the rest defence holds its place) or
    ahead of it when they attack (forwards wait for the counter). Below 1, such players
    recover while they shadow the play, so the roles nearest the ball run most (helios-base
    halves the income for players well behind a ball its team controls)."""
    rest_gap: float = 10.0
    """How far (m, along x) from the ball a target must be for its player to count as away
    from the play."""
    danger_x: float = 0.0
    """Runs back goal-side by players caught in front of the ball are sprinted when the
    opponents have the ball at or behind this x (m, team frame: 0 is the halfway line, so in
    our half)."""

    def __post_init__(self) -> None:
        check_params(self, positive=("cruise", "walk", "far", "play_distance", "run_distance"),
                     non_negative=("settle", "settle_share", "recover_share", "rest_share", "rest_gap"),
                     fractions=("floor_margin", "fresh", "tired", "final_third"), finite=("danger_x",))
        if self.tired >= self.fresh:
            raise SkillInputError(f"PacingParams.tired ({self.tired}) must be below fresh ({self.fresh})")
        if self.walk > self.cruise:
            raise SkillInputError(f"PacingParams.walk ({self.walk}) must not exceed cruise ({self.cruise})")


PACING_PARAMS = np.dtype([(name, np.float64) for name in (
    "accel_max", "speed_max", "top_speed", "power_rate", "decay", "power_max", "side_rate", "back_rate",
    "heading_speed", "income", "floor", "fresh", "tired", "recover_share", "cruise", "walk", "far", "settle",
    "settle_share", "play_distance", "final_third_x", "danger_x", "run_distance", "extra", "tolerance", "rest_share",
    "rest_gap", "half_cycles")])
"""The constants the compiled pacing kernels read (:func:`pacing_constants`): the motion
model's dash rule (largest acceleration and speed, top running speed, ``dash_power_rate``,
player decay, ``power_max``, the side and back dash rates and ``dash_heading_speed``), the
stamina income per cycle, the policy's stamina levels in absolute stamina (``floor``,
``fresh``, ``tired``), its shares and distances (:class:`PacingParams`; ``final_third_x`` in
metres), ``extra_stamina``, the arrival ``tolerance`` (m) and the cycles of a half."""


def pacing_constants(model: MotionModel, params: PacingParams, tolerance: float) -> np.ndarray:
    """The :data:`PACING_PARAMS` record the compiled pacing kernels read: the motion model's
    dash rule, the stamina levels in absolute stamina and the policy's choices."""
    config = model.config
    phys, stam = config.physics, config.stamina
    return make_record(
        PACING_PARAMS, accel_max=model.accel_max, speed_max=model.speed_max, top_speed=model.top_speed,
        power_rate=phys.dash_power_rate, decay=model.player_decay, power_max=phys.dash_power_max,
        side_rate=phys.side_dash_rate, back_rate=phys.back_dash_rate, heading_speed=phys.dash_heading_speed,
        income=stam.recovery_per_cycle, floor=(stam.recover_dec_thr + params.floor_margin) * stam.maximum,
        fresh=params.fresh * stam.maximum, tired=params.tired * stam.maximum, recover_share=params.recover_share,
        cruise=params.cruise, walk=params.walk, far=params.far, settle=params.settle,
        settle_share=params.settle_share, play_distance=params.play_distance,
        final_third_x=params.final_third * model.half_length, danger_x=params.danger_x,
        run_distance=params.run_distance, extra=stam.extra_stamina, tolerance=tolerance,
        rest_share=params.rest_share, rest_gap=params.rest_gap, half_cycles=config.rules.half_cycles)
