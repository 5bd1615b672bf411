"""The view width (rcssserver's ``change_view``): a narrow cone seen every 75 ms, a wide one
every 300 ms, the change asked in a command (docs/simulator.md §12)."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.match import Match
from soccer_sim.perception import SeeParams
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.params import see_cycles
from soccer_sim.perception.view_width import KEEP, NARROW, NORMAL, WIDE, SeeTimer
from soccer_sim.team import TeamError
from tests.soccer_sim.test_neck import Asking, one_runner_observer

PARAMS = SeeParams()


@pytest.mark.parametrize("start", [0, 1, 7, 100])
def test_at_normal_width_the_timer_is_the_see_schedule(start):
    offsets = np.random.default_rng(start).integers(0, PARAMS.send_step, 40)
    timer, out = SeeTimer(PARAMS, offsets, start), np.empty(40, dtype=bool)
    for cycle in range(start, start + 150):
        assert np.array_equal(timer.sees(cycle, out), see_cycles(cycle, PARAMS, offsets))


def test_narrow_sees_every_cycle_wide_every_third():
    timer, out = SeeTimer(PARAMS, np.array([0, 40, 149, 75])), np.empty(4, dtype=bool)
    timer.change(np.array([NARROW, WIDE, WIDE, KEEP]), 0)
    counts = sum(timer.sees(cycle, out).astype(int) for cycle in range(300))
    assert counts.tolist() == [300, 100, 100, 200]


def test_a_change_to_a_shorter_interval_sees_at_the_next_tick_when_due():
    """A wide player whose last see was 200 ms ago turns narrow: its count (5 ticks) is past
    narrow's 2, so it sees at its first tick of the next cycle."""
    timer, out = SeeTimer(PARAMS, np.array([0])), np.empty(1, dtype=bool)
    timer.change(np.array([WIDE]), 0)
    seen = [bool(timer.sees(cycle, out)[0]) for cycle in range(5)]  # wide: sees at 150, 450 ms
    assert seen == [False, True, False, False, True]
    timer.change(np.array([NARROW]), 7)  # last see at 450 ms, the count at 700 ms far past 2 ticks
    assert timer.next_see[0] == 712.5  # its first tick from cycle 7 on (ticks at 0 + 37.5 k ms)
    assert [bool(timer.sees(cycle, out)[0]) for cycle in range(5, 9)] == [False, False, True, True]
    assert timer.next_see[0] == 937.5  # then every 75 ms: 787.5, 862.5 (cycle 8), 937.5


def test_the_cone_is_narrower_or_wider_with_the_view_width():
    """The runner of the neck tests with its face turned 30 degrees off the ball: seen in a
    normal (45 degrees a side) or wide cone, not in a narrow one (22.5)."""
    seen = {}
    for width in (NORMAL, NARROW, WIDE):
        observer, state = one_runner_observer()
        observer.turn_necks(np.array([75.0, 0.0]), np.ones(2, dtype=bool))  # face 105, ball at 135
        observer.change_views(0, np.array([width, KEEP]), np.ones(2, dtype=bool))
        for cycle in range(1, 4):  # (a wide view sees every other cycle at this send_step, 100 ms)
            state.cycle = cycle
            home = observer.observe(state)[0]
            if home.saw[0]:
                break
        assert home.view_width[0] == width and home.saw[0]
        seen[width] = bool(home.ball_seen[0])
    assert seen == {NORMAL: True, NARROW: False, WIDE: True}


def viewer(widths) -> Asking:
    """A chaser whose players ask for the view widths ``widths(cycle, n)``."""
    return Asking("change_view", widths, ("saw", "view_width"))


def partial(cycles: int) -> MatchConfig:
    return MatchConfig(observation=ObservationConfig("partial"), max_cycles=cycles)


def test_in_a_match_a_narrow_player_sees_every_cycle_and_a_wide_one_every_third():
    def widths(cycle, n):
        codes = np.full(n, KEEP)
        codes[0], codes[1] = NARROW, WIDE
        return codes

    team = viewer(widths)
    Match(team, "chaser", seed=3, config=partial(61)).run()
    saw, reported = np.array(team.views["saw"][1:]), np.array(team.views["view_width"][1:])  # (cycle 0: before the change)
    assert (reported[:, 0] == NARROW).all() and (reported[:, 1] == WIDE).all() and (reported[:, 2:] == NORMAL).all()
    assert saw[:, 0].all()
    assert saw[:, 1].sum() == 20 and saw[:, 2].sum() == 40, (saw[:, 1].sum(), saw[:, 2].sum())


def test_asking_for_the_width_a_player_has_changes_nothing():
    config = partial(80)
    plain = Match("chaser", "chaser", seed=4, config=config).run()
    asked = Match(viewer(lambda cycle, n: np.full(n, NORMAL)), "chaser", seed=4, config=config).run()
    assert np.array_equal(plain.state.pos, asked.state.pos)


@pytest.mark.parametrize("widths, message", [
    (lambda n: np.full(n, 3), r"command.change_view\[0\] is 3: not a view width"),
    (lambda n: np.full(n, 1.0), "command.change_view must hold integer codes .* got dtype float64"),
    (lambda n: ["narrow"] * n, "command.change_view must hold integer codes .* got dtype <U6"),
    (lambda n: np.ones(n + 2, dtype=int), r"command.change_view must have shape \(\d+,\) \(a code per player\)"),
])
def test_a_bad_view_width_is_a_team_error_naming_the_field(widths, message):
    with pytest.raises(TeamError, match=message) as info:
        Match(viewer(lambda cycle, n: widths(n)), "chaser", seed=1, config=partial(5)).run()
    assert info.value.team_name == "Asking"
