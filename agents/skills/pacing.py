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


# Indices of the kernel's constants (see pacing_constants).
(K_ACCEL_MAX, K_SPEED_MAX, K_TOP_SPEED, K_POWER_RATE, K_DECAY, K_POWER_MAX, K_SIDE_RATE, K_BACK_RATE,
 K_HEADING_SPEED, K_INCOME, K_FLOOR, K_FRESH, K_TIRED, K_RECOVER_SHARE, K_CRUISE, K_WALK, K_FAR, K_SETTLE,
 K_SETTLE_SHARE, K_PLAY_DISTANCE, K_FINAL_THIRD_X, K_DANGER_X, K_RUN_DISTANCE, K_EXTRA, K_TOLERANCE,
 K_REST_SHARE, K_REST_GAP, K_HALF_CYCLES, K_SIZE) = range(29)


def pacing_constants(model: MotionModel, params: PacingParams, tolerance: float) -> np.ndarray:
    """The (K_SIZE,) float64 constants the compiled pacing kernel reads: the motion model's
    dash rule, the stamina levels in absolute stamina and the policy's choices."""
    config = model.config
    phys, stam = config.physics, config.stamina
    k = np.empty(K_SIZE)
    k[K_ACCEL_MAX], k[K_SPEED_MAX], k[K_TOP_SPEED] = model.accel_max, model.speed_max, model.top_speed
    k[K_POWER_RATE], k[K_DECAY], k[K_POWER_MAX] = phys.dash_power_rate, model.player_decay, phys.dash_power_max
    k[K_SIDE_RATE], k[K_BACK_RATE], k[K_HEADING_SPEED] = (phys.side_dash_rate, phys.back_dash_rate,
                                                          phys.dash_heading_speed)
    k[K_INCOME] = stam.recovery_per_cycle
    k[K_FLOOR] = (stam.recover_dec_thr + params.floor_margin) * stam.maximum
    k[K_FRESH], k[K_TIRED] = params.fresh * stam.maximum, params.tired * stam.maximum
    k[K_RECOVER_SHARE], k[K_CRUISE], k[K_WALK] = params.recover_share, params.cruise, params.walk
    k[K_FAR], k[K_SETTLE], k[K_SETTLE_SHARE] = params.far, params.settle, params.settle_share
    k[K_PLAY_DISTANCE] = params.play_distance
    k[K_FINAL_THIRD_X] = params.final_third * model.half_length
    k[K_DANGER_X], k[K_RUN_DISTANCE] = params.danger_x, params.run_distance
    k[K_EXTRA], k[K_TOLERANCE] = stam.extra_stamina, tolerance
    k[K_REST_SHARE], k[K_REST_GAP] = params.rest_share, params.rest_gap
    k[K_HALF_CYCLES] = config.rules.half_cycles
    return k
