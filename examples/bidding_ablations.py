"""Potential-field bidding with one part switched off at a time: the ablation teams of
docs/teams.md, "The baselines checked".

Every team here is the built-in ``bidding`` team (4-3-3, default style) with one change, so a
paired case study against the same opponents and seeds measures what that part is worth::

    soccer-sim experiment case-study --opponents counter-442 --games 20 --workers 2 \\
        --teams mmd+msd2,bidding,examples.bidding_ablations:no_ball_role,examples.bidding_ablations:no_hold

(run from the checkout's directory, so that ``examples.*`` resolves). The teams:

* ``no_ball_role``: the auction as it is, but the team sends the first of its own ball race to
  the ball (as every other assigner's team does) instead of the ball role's winner;
* ``no_steer``: the supporters run straight to their role targets (no potential field);
* ``no_hold``: no hysteresis (``min_hold=0``, ``switch_margin=0``);
* ``no_angle``, ``no_cap``: the ball bid without its alignment term, without its cap (a cap of
  200 m, beyond any reach on the field);
* ``plain_ball_bid``: no hysteresis, no alignment term and no cap: the ball role goes to the
  player who reaches the ball first; ``no_hold_no_cap``, ``no_hold_no_angle``: two of them;
* ``no_<term>``: the supporters' field without one of its terms (``teammate``, ``ball``,
  ``forward``, ``defensive``, ``side``) or without both shot-corridor terms (``corridors``).
"""

from __future__ import annotations

from collections.abc import Callable

from agents.roles import ASSIGNERS, BiddingAssigner, RoleAssigner
from agents.teams.formation_team import FormationTeam


class UnsteeredBidding(BiddingAssigner):
    """Bidding whose supporters go straight to their role targets (the default ``steer``)."""

    name = "bidding-no-steer"
    steer = RoleAssigner.steer


class BiddingWithoutBallRole(BiddingAssigner):
    """Bidding's auction, but no ball player named: the team sends the first of its ball race."""

    name = "bidding-no-ball-role"

    def ball_player(self) -> int | None:
        return None


ASSIGNERS.setdefault(UnsteeredBidding.name, UnsteeredBidding)
ASSIGNERS.setdefault(BiddingWithoutBallRole.name, BiddingWithoutBallRole)


def _team(name: str, assigner: str = "bidding", **params: object) -> Callable[[], FormationTeam]:
    """A factory of the built-in team with ``assigner`` and its ``params``, called ``name``."""

    def make() -> FormationTeam:
        return FormationTeam(assigner, name=name, **params)

    make.__name__ = make.__qualname__ = name.replace("-", "_")
    make.__doc__ = f"The bidding team, ablation {name!r}."
    return make


no_ball_role = _team("bidding-no-ball-role", BiddingWithoutBallRole.name)
no_steer = _team("bidding-no-steer", UnsteeredBidding.name)
no_hold = _team("bidding-no-hold", min_hold=0, switch_margin=0.0)
no_angle = _team("bidding-no-angle", angle_weight=0.0)
no_cap = _team("bidding-no-cap", ball_cap=200.0)
plain_ball_bid = _team("bidding-plain-ball-bid", min_hold=0, switch_margin=0.0, angle_weight=0.0, ball_cap=200.0)
no_hold_no_cap = _team("bidding-no-hold-no-cap", min_hold=0, switch_margin=0.0, ball_cap=200.0)
no_hold_no_angle = _team("bidding-no-hold-no-angle", min_hold=0, switch_margin=0.0, angle_weight=0.0)
no_teammate = _team("bidding-no-teammate", teammate_weight=0.0)
no_ball = _team("bidding-no-ball", ball_weight=0.0)
no_forward = _team("bidding-no-forward", forward_weight=0.0)
no_defensive = _team("bidding-no-defensive", defensive_weight=0.0)
no_side = _team("bidding-no-side", side_weight=0.0)
no_corridors = _team("bidding-no-corridors", corridor_clear_weight=0.0, corridor_block_weight=0.0)

ABLATIONS: tuple[Callable[[], FormationTeam], ...] = (
    no_ball_role, no_steer, no_hold, no_angle, no_cap, plain_ball_bid, no_hold_no_cap, no_hold_no_angle,
    no_teammate, no_ball, no_forward, no_defensive, no_side, no_corridors,
)
"""Every ablation team factory of this module."""
