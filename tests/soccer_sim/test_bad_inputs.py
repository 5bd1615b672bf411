"""Bad inputs to the simulator's API: team modules that cannot be imported, scenario files that
are not text, command values too large to square, and team code that calls ``sys.exit``."""

from __future__ import annotations

import numpy as np
import pytest
from tests.soccer_sim.core_helpers import Scripted, quiet_config

from soccer_sim import TeamError, TeamNotFoundError, resolve_team, run_match
from soccer_sim.scenarios import BallStart, Scenario, ScenarioError, Side, load_scenario

N = 11


# --- team modules that fail while being imported ---------------------------------------------
def test_a_syntax_error_names_the_team_the_module_and_file_line(team_module) -> None:
    module = team_module("syntax_broken_team", "class Team:\n    def act(self view):\n        pass\n")
    with pytest.raises(TeamNotFoundError) as info:
        resolve_team(f"{module}:Team")
    message = str(info.value)
    assert f"team path '{module}:Team'" in message and f"module '{module}' has a syntax error" in message
    assert f"{module}.py:2" in message and "\n" not in message


def test_an_exception_on_import_names_the_team_module_and_error(team_module) -> None:
    module = team_module("raising_on_import_team", "import os\nraise RuntimeError('needs a GPU\\nand more')\n")
    with pytest.raises(TeamNotFoundError) as info:
        resolve_team(f"{module}:Team")
    message = str(info.value)
    assert f"importing module '{module}' raised RuntimeError: needs a GPU and more" in message
    assert f"{module}.py:2" in message and "\n" not in message


def test_sys_exit_on_import_or_in_a_factory_is_a_team_error(team_module) -> None:
    module = team_module("exiting_on_import_team", "import sys\nsys.exit(4)\n")
    with pytest.raises(TeamNotFoundError, match=rf"importing module '{module}' called sys.exit\(4\)"):
        resolve_team(f"{module}:Team")
    module = team_module("exiting_factory_team", "import sys\ndef make():\n    sys.exit('no')\n")
    with pytest.raises(TeamNotFoundError, match=r"without arguments called sys.exit\('no'\)"):
        resolve_team(f"{module}:make")


# --- scenario files ---------------------------------------------------------------------------
@pytest.mark.parametrize("suffix", [".toml", ".json"])
def test_a_binary_scenario_file_is_named_and_said_not_to_be_text(tmp_path, suffix) -> None:
    path = tmp_path / f"bad{suffix}"
    path.write_bytes(b"name = \"x\"\n\xff\xfe\x00\x81")
    with pytest.raises(ScenarioError) as info:
        load_scenario(path)
    assert str(info.value) == f"Scenario: {path} is not a UTF-8 text {suffix[1:].upper()} file (byte 11 is not UTF-8)"


def test_a_scenario_nested_too_deeply_is_a_scenario_error(tmp_path) -> None:
    path = tmp_path / "deep.json"
    path.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(ScenarioError, match="deep.json is not a usable JSON scenario: nested too deeply"):
        load_scenario(path)


# --- command values: huge finite values clip, non-finite ones are errors ----------------------
def _dash_match(request: tuple[float, float]) -> np.ndarray:
    """Velocities of the away side after three noise-free cycles of every player dashing by
    ``request`` (own frame)."""
    team = Scripted(lambda view: (np.tile(request, (N, 1)), np.zeros((N, 2))))
    team.name = "dasher"
    return run_match("idle", team, config=quiet_config(max_cycles=3)).state.vel[N:]


@pytest.mark.parametrize("size", [1e150, 1e160, 1e300, 1.7e308])
def test_a_huge_dash_is_clipped_like_any_dash_over_the_limit(size: float) -> None:
    limit = _dash_match((1e3, 0.0))
    assert np.count_nonzero(np.hypot(*limit.T) > 0.3) >= N - 1  # the players run (the kick-off taker waits)
    np.testing.assert_allclose(_dash_match((size, 0.0)), limit, rtol=1e-12, atol=1e-15)
    diagonal = _dash_match((size, -size))
    np.testing.assert_allclose(diagonal, _dash_match((1e3, -1e3)), rtol=1e-12, atol=1e-15)
    assert np.allclose(diagonal[:, 0], -diagonal[:, 1])  # direction kept (away side: frame turned by 180°)


def test_a_huge_kick_is_clipped_like_any_kick_over_the_limit() -> None:
    scenario = Scenario(name="kick", home=Side(positions=[(0.0, 0.0)], goalie=None), away=Side(players=0),
                        ball=BallStart(position=(0.5, 0.0)), start_mode="play_on", cycle_limit=1, half_time=False)

    def ball_after(kick: tuple[float, float]) -> np.ndarray:
        team = Scripted(lambda view: (np.zeros((1, 2)), np.array([kick])))
        return run_match(team, "idle", config=quiet_config(), scenario=scenario).state.ball_vel

    limit = ball_after((1e3, 5e2))
    assert np.hypot(*limit) > 1.0
    for size in (1e160, 1e308, 1.7e308):  # the last one's length overflows
        np.testing.assert_allclose(ball_after((size, size / 2)), limit, rtol=1e-12)


@pytest.mark.parametrize("field", ["dash", "kick"])
@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_non_finite_commands_stay_errors(field: str, bad: float) -> None:
    def script(view):
        values = {"dash": np.zeros((N, 2)), "kick": np.zeros((N, 2))}
        values[field][5, 0] = bad
        return values["dash"], values["kick"]

    team = Scripted(script)
    team.name = "bad"
    with pytest.raises(TeamError, match=rf"team 'bad', player 5: command.{field} is not finite"):
        run_match("idle", team, config=quiet_config(max_cycles=2))


# --- sys.exit inside a team's code --------------------------------------------------------------
class _Exiting:
    def __init__(self, where: str, code: object) -> None:
        self.where, self.code, self.name = where, code, "quitter"

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        if self.where == "reset":
            raise SystemExit(self.code)

    def act(self, view):
        import sys

        sys.exit(self.code)


@pytest.mark.parametrize("where, code, text", [("act", 3, "sys.exit(3) in act()"),
                                               ("reset", None, "sys.exit(None) in reset()"),
                                               ("act", "bye", "sys.exit('bye') in act()")])
def test_sys_exit_in_team_code_is_a_team_error_naming_the_team(where, code, text) -> None:
    with pytest.raises(TeamError) as info:
        run_match(_Exiting(where, code), "idle", config=quiet_config(max_cycles=3))
    assert str(info.value) == f"team 'quitter': called {text}"
    assert info.value.team_name == "quitter" and isinstance(info.value.__cause__, SystemExit)
