"""Misbehaving teams get a TeamError naming the team (and the player) with the cause chained."""

from __future__ import annotations

import numpy as np
import pytest
from tests.soccer_sim.core_helpers import Scripted

from soccer_sim import MatchConfig, TeamCommand, TeamError, run_match

N = 11
CONFIG = MatchConfig(max_cycles=5)


def zeros() -> np.ndarray:
    return np.zeros((N, 2))


def play(script, name="broken"):
    team = Scripted(script)
    team.name = name
    return run_match("idle", team, config=CONFIG)


def test_wrong_shape_names_team_and_field() -> None:
    with pytest.raises(TeamError, match=r"team 'broken'.*command.dash must have shape \(11, 2\), got \(10, 2\)"):
        play(lambda view: (np.zeros((10, 2)), zeros()))
    with pytest.raises(TeamError, match=r"command.kick must have shape \(11, 2\), got \(22,\)"):
        play(lambda view: (zeros(), np.zeros(22)))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_values_name_the_player(bad: float) -> None:
    def script(view):
        dash = zeros()
        dash[3, 1] = bad
        return dash, zeros()

    with pytest.raises(TeamError, match=r"team 'broken', player 3: command.dash is not finite") as info:
        play(script)
    assert info.value.team_name == "broken" and info.value.player == 3

    def kick_script(view):
        kick = zeros()
        kick[7, 0] = bad
        return zeros(), kick

    with pytest.raises(TeamError, match="player 7: command.kick is not finite"):
        play(kick_script)


def test_huge_finite_values_are_clipped_not_rejected() -> None:
    result = play(lambda view: (np.full((N, 2), 1e308), np.full((N, 2), -1e308)))
    speeds = np.hypot(*result.state.vel.T)
    assert np.isfinite(result.state.pos).all() and speeds.max() <= 1.05


def test_lists_and_integers_are_accepted_but_not_text() -> None:
    play(lambda view: ([[1, 0]] * N, [[0, 0]] * N))  # converted, no error
    with pytest.raises(TeamError, match="command.dash is not a numeric array"):
        play(lambda view: ([["a", "b"]] * N, zeros()))
    with pytest.raises(TeamError, match="command.kick must be numeric"):
        play(lambda view: (zeros(), np.full((N, 2), "x")))


def test_act_raising_is_wrapped_with_the_cause() -> None:
    def script(view):
        raise ZeroDivisionError("oops")

    with pytest.raises(TeamError, match=r"team 'broken': act\(\) raised ZeroDivisionError: oops") as info:
        play(script)
    assert isinstance(info.value.__cause__, ZeroDivisionError)


def test_act_returning_something_else_is_rejected() -> None:
    class Wrong(Scripted):
        def act(self, view):
            return (zeros(), zeros())

    with pytest.raises(TeamError, match="act\\(\\) must return a TeamCommand, got tuple"):
        run_match("idle", Wrong(), config=CONFIG)


def test_reset_raising_is_wrapped() -> None:
    class BadReset(Scripted):
        def reset(self, side_info, config, rng):
            raise KeyError("missing")

    with pytest.raises(TeamError, match=r"team 'BadReset': reset\(\) raised KeyError") as info:
        run_match(BadReset(), "idle", config=CONFIG)
    assert isinstance(info.value.__cause__, KeyError)


def test_bad_move_targets_are_rejected() -> None:
    class Mover(Scripted):
        def act(self, view):
            move = np.zeros((N, 2))
            move[2] = np.nan
            return TeamCommand(dash=zeros(), kick=zeros(), move=move)

    with pytest.raises(TeamError, match="player 2: command.move is not finite"):
        run_match(Mover(), "idle", config=CONFIG)


def test_missing_object_and_overflowing_arrays_are_rejected() -> None:
    with pytest.raises(TeamError, match=r"command.dash is None; expected an array of shape \(11, 2\)"):
        play(lambda view: (None, zeros()))
    with pytest.raises(TeamError, match="command.kick must be numeric, got dtype object"):
        play(lambda view: (zeros(), np.zeros((N, 2), dtype=object)))
    with pytest.raises(TeamError, match="command.dash is not a numeric array"):
        play(lambda view: ([[10**400, 0]] * N, zeros()))


class Catcher(Scripted):
    def __init__(self, catch) -> None:
        super().__init__()
        self.catch_value = catch
        self.name = "keeper"

    def act(self, view):
        return TeamCommand(dash=zeros(), kick=zeros(), catch=self.catch_value)


@pytest.mark.parametrize("catch", [np.array([True, False]), "no", None, 0.5, 2])
def test_a_catch_request_that_is_not_a_bool_is_rejected(catch) -> None:
    with pytest.raises(TeamError, match=r"team 'keeper': command.catch must be a bool, got"):
        run_match("idle", Catcher(catch), config=CONFIG)


@pytest.mark.parametrize("catch", [True, False, np.bool_(True), 1, 0, np.int64(1)])
def test_bool_like_catch_requests_are_accepted(catch) -> None:
    run_match("idle", Catcher(catch), config=CONFIG)


def test_move_targets_of_the_wrong_shape_are_rejected() -> None:
    class Mover(Scripted):
        def act(self, view):
            return TeamCommand(dash=zeros(), kick=zeros(), move=np.zeros((3, 2)))

    with pytest.raises(TeamError, match=r"team 'Mover': command.move must have shape \(11, 2\), got \(3, 2\)"):
        run_match(Mover(), "idle", config=CONFIG)


@pytest.mark.parametrize("report, cause", [({"role_switches": "many"}, "ValueError"), ([1, 2], "TypeError"),
                                           (ZeroDivisionError("x"), "ZeroDivisionError")])
def test_statistics_that_are_not_numbers_name_the_team(report, cause) -> None:
    class Reporting(Scripted):
        def statistics(self):
            if isinstance(report, Exception):
                raise report
            return report

    with pytest.raises(TeamError, match=rf"team 'Reporting': statistics\(\) must return a dict of numbers.*{cause}"):
        run_match(Reporting(), "idle", config=CONFIG)
