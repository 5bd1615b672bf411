"""Hand-made situations shared by the role-assigner tests (team frame, metres)."""

from __future__ import annotations

import itertools
from dataclasses import replace

import numpy as np

from agents.roles import RoleAssigner, RoleContext, make_assigner, offensive_order

HALF_LENGTH, HALF_WIDTH = 52.5, 34.0
OWN_GOAL, OPP_GOAL = np.array([-HALF_LENGTH, 0.0]), np.array([HALF_LENGTH, 0.0])


def context(ball=(0.0, 0.0), cycle: int = 0, attacking: bool = True, n_opp: int = 11) -> RoleContext:
    """A context with the ball at ``ball`` and the opponents all on the centre spot."""
    return RoleContext(ball=np.asarray(ball, dtype=float), own_goal=OWN_GOAL.copy(), opp_goal=OPP_GOAL.copy(),
                       opponents=np.zeros((n_opp, 2)), field_half_length=HALF_LENGTH,
                       field_half_width=HALF_WIDTH, cycle=cycle, attacking=attacking)


def at_cycle(ctx: RoleContext, cycle: int, **changes) -> RoleContext:
    """``ctx`` at another cycle (and with other fields changed)."""
    return replace(ctx, cycle=cycle, **changes)


def ready(name: str, k: int, seed: int = 0, **params) -> RoleAssigner:
    """Assigner ``name`` reset for ``k`` roles with a generator seeded ``seed``."""
    assigner = make_assigner(name, **params)
    assigner.reset(k, np.random.default_rng(seed))
    return assigner


def run(assigner: RoleAssigner, players, targets, previous=None, ctx: RoleContext | None = None) -> np.ndarray:
    """One ``assign`` call with the targets' offensive order."""
    players, targets = np.asarray(players, dtype=float), np.asarray(targets, dtype=float)
    return assigner.assign(players, targets, offensive_order(targets), previous, ctx or context())


def distances(players, targets) -> np.ndarray:
    """(k, k) Euclidean player-target distances."""
    players, targets = np.asarray(players, dtype=float), np.asarray(targets, dtype=float)
    return np.hypot(*(players[:, None, :] - targets[None, :, :]).transpose(2, 0, 1))


def all_assignments(k: int):
    """Every role_of_player of k players, as arrays (k <= 7 keeps this small)."""
    return (np.array(p) for p in itertools.permutations(range(k)))


def random_field_points(rng: np.random.Generator, k: int) -> np.ndarray:
    """k points uniformly spread over the field, a metre inside the lines."""
    return np.column_stack((rng.uniform(-HALF_LENGTH + 1, HALF_LENGTH - 1, k),
                            rng.uniform(-HALF_WIDTH + 1, HALF_WIDTH - 1, k)))
