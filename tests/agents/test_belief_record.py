"""A team's intake in one compiled call (:mod:`agents.teams.belief_record`, made by
:meth:`TeamBeliefs.update`): the same world models and memory of proposals as decoding the
messages, updating the models and taking the proposals one after the other, bad messages and a
side that keeps no proposals included; and the named records the kernels read (the sees' record kept while
the views hand the same arrays and made again when they hand others, the records built by
field name, the belief parameters read by name)."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import fields, replace

import numpy as np
import pytest

from agents.messages import MAX_AGE, TeamMessage, encode, heard_batch
from agents.teams.belief_kernels import BELIEF_PARAMS, believe
from agents.teams.belief_record import SEE_FIELDS, SeeRecords, belief_record, see_record, store_assignments
from agents.teams.speaking import TurnMemory, turn_memory
from agents.teams.world_model import BeliefParams, TeamBeliefs
from soccer_sim.perception.views import PlayerViews
from tests.agents.test_world_model import CONFIG, M, N, see_ball_at
from tests.agents.test_world_model import views as hand_built_views

HORIZON = 20


def _heard(cycle: int) -> tuple:
    """Team-mates' messages of a cycle: team messages of both layouts, settled and not, and
    texts that are no message."""
    said = cycle - 1
    with_velocity = encode(TeamMessage((2, 0, 1), said, cycle % 2 == 0, ball=(3.0 + cycle, -2.0), ball_age=cycle % 5,
                                       ball_velocity=(0.4, 0.1)))
    with_sender = encode(TeamMessage((1, 2, 0), said, True, ball=(2.0 + cycle, -1.0), ball_age=cycle % 3,
                                     sender=(-4.0, 1.5)))
    return (((1, with_sender), (2, with_velocity)), ((0, with_velocity), (2, "not a msg!")),
            ((0, with_sender), (1, "(bad)")))


def _three_steps(beliefs: TeamBeliefs, memory: TurnMemory | None, views) -> None:
    """The intake one step after another: decode, the world-model kernel, the proposals taken."""
    heard = heard_batch(views.heard_mates)
    believe(beliefs.record, see_record(views), heard.listener, heard.speaker, heard.decoded.rows, MAX_AGE, views.cycle)
    if memory is not None and heard.listener.size:
        store_assignments(heard.listener, heard.speaker, heard.decoded.rows, heard.decoded.assignment, views.cycle,
                          2, memory, HORIZON)


@pytest.mark.parametrize("with_turns", [True, False])
def test_one_call_gives_what_the_three_steps_give(with_turns: bool) -> None:
    apart, together = TeamBeliefs(N, M, CONFIG), TeamBeliefs(N, M, CONFIG)
    memory_apart = turn_memory(N, N) if with_turns else None
    memory_together = turn_memory(N, N) if with_turns else None
    for cycle in range(1, 9):
        views = see_ball_at({0: (1.0 * cycle, 0.5), 2: (1.1 * cycle, 0.4)} if cycle < 4 else {}, cycle)
        views.heard_mates = _heard(cycle) if cycle % 3 else ((),) * N  # some silent cycles
        _three_steps(apart, memory_apart, views)
        together.update(views, memory_together, HORIZON)
    for name in ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age"):
        np.testing.assert_array_equal(getattr(together, name), getattr(apart, name), err_msg=name)
    assert together.ball_age[1] <= 5  # player 1 saw nothing: the ball came from a message
    if with_turns:
        for name, a, b in zip(TurnMemory._fields, memory_together, memory_apart):
            np.testing.assert_array_equal(a, b, err_msg=name)
        # player 0 took the settled proposal of cycle 7 it heard first (from player 1), not the later one
        assert memory_together.followed[0].tolist() == [1, 2, 0] and memory_together.proposal_cycle[0] == 7


def test_the_see_record_is_kept_while_the_views_hand_the_same_arrays_and_made_again_for_others() -> None:
    records = SeeRecords()
    given = see_ball_at({0: (3.0, 1.0)}, 1)
    first = records.of(given)
    assert records.of(given) is first
    assert records.of(replace(given, cycle=2, heard_mates=((),) * N)) is first  # other views, the same arrays
    for name in SEE_FIELDS:
        other = replace(given, **{name: getattr(given, name).copy()})
        assert records.of(other) is not first, name
        assert records.of(other) is records.of(other)
        records.of(given)


def _views_in_place(cycles: int) -> Iterator[tuple[PlayerViews, PlayerViews]]:
    """Pairs of views of each cycle: the same views object every cycle, its arrays overwritten
    in place as a match's observer does (from cycle ``cycles // 2`` on, its ball arrays are
    other arrays), and new views of the same sees."""
    kept = hand_built_views(0)
    for cycle in range(cycles):
        fresh = see_ball_at({0: (0.5 * cycle, 1.0), 1: (0.5 * cycle + 0.2, 0.8)} if cycle % 4 else {}, cycle)
        if cycle == cycles // 2:
            kept.ball = kept.ball.copy()
            kept.ball_seen = kept.ball_seen.copy()
        for name in SEE_FIELDS:
            getattr(kept, name)[...] = getattr(fresh, name)
        kept.cycle = cycle
        yield kept, fresh


def test_views_overwritten_in_place_or_handing_new_arrays_are_believed_alike() -> None:
    """A model fed one views object whose arrays change in place (and are once replaced)
    believes what a model fed new views every cycle believes."""
    in_place, anew = TeamBeliefs(N, M, CONFIG), TeamBeliefs(N, M, CONFIG)
    for kept, fresh in _views_in_place(12):
        in_place.update(kept)
        anew.update(fresh)
        for name in ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age"):
            np.testing.assert_array_equal(getattr(in_place, name), getattr(anew, name), err_msg=name)
    assert anew.ball_age[0] <= 3 and abs(anew.ball[0, 0] - 5.0) < 1.0  # the ball was followed


def test_a_belief_record_is_made_by_field_name() -> None:
    beliefs = TeamBeliefs(N, M, CONFIG)
    with pytest.raises(ValueError, match=r"missing \['speed_max'\], unknown \['speed'\]"):
        belief_record(ball=beliefs.ball, ball_vel=beliefs.ball_vel, ball_age=beliefs.ball_age,
                      mate_pos=beliefs.mate_pos, mate_age=beliefs.mate_age, opp_pos=beliefs.opp_pos,
                      opp_age=beliefs.opp_age, last_seen=np.zeros((N, 2)), last_seen_cycle=np.zeros(N, np.int64),
                      params=np.zeros(1, BELIEF_PARAMS), ball_decay=0.94, speed=3.0)


def test_the_belief_parameters_reach_the_kernels_by_name() -> None:
    """A ball seen 20 m away, then 0.3 m further along within the gate: the filter takes
    ``ball_gain`` of the residual into the position and ``ball_velocity_gain`` into the
    velocity, whatever the other parameters are."""
    assert BELIEF_PARAMS.names == tuple(f.name for f in fields(BeliefParams))
    for params in (BeliefParams(), BeliefParams(ball_gain=1.0, ball_velocity_gain=0.5, near=1.0, gate_floor=9.0)):
        beliefs = TeamBeliefs(N, M, CONFIG, params)
        beliefs.update(see_ball_at({0: (10.0, 0.0)}, 1))
        beliefs.update(see_ball_at({0: (10.3, 0.0)}, 2))
        np.testing.assert_allclose(beliefs.ball[0], [10.0 + params.ball_gain * 0.3, 0.0], atol=1e-12)
        np.testing.assert_allclose(beliefs.ball_vel[0], [params.ball_velocity_gain * 0.3, 0.0], atol=1e-12)
