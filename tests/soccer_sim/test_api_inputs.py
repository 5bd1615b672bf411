"""Bad arguments to the Python API are one clear SoccerSimError, raised before anything runs:
recorders that are not recorders, a scenario path that is not a path, an empty scenario file."""

from __future__ import annotations

import pytest

from soccer_sim import SoccerSimError, run_match
from soccer_sim.recorder import RecorderError
from soccer_sim.scenarios import ScenarioError, load_scenario


class Counting:
    """A recorder counting the cycles it saw."""

    def __init__(self) -> None:
        self.cycles = 0

    def on_start(self, match) -> None:
        pass

    def on_cycle(self, match) -> None:
        self.cycles += 1

    def on_end(self, match) -> None:
        pass


@pytest.mark.parametrize("recorders, message", [
    ("replay.rrd", "recorders must be a list or other iterable of recorders, got str"),
    (5, "recorders must be a list or other iterable of recorders, got int"),
    ([None], "recorders[0] (NoneType) is not a recorder: it lacks on_start, on_cycle, on_end"),
    ([object()], "recorders[0] (object) is not a recorder: it lacks on_start, on_cycle, on_end"),
    ([Counting(), "x"], "recorders[1] (str) is not a recorder"),
    (Counting(), "recorders must be a list or other iterable of recorders, got Counting; put a single recorder in a "
                 "list: recorders=[recorder]"),
])
def test_recorders_that_are_not_recorders_are_one_clear_error(recorders, message) -> None:
    with pytest.raises(RecorderError) as refused:
        run_match("idle", "idle", recorders=recorders)
    assert isinstance(refused.value, SoccerSimError)
    assert str(refused.value).startswith(message) and "\n" not in str(refused.value)


def test_real_recorders_still_observe() -> None:
    from soccer_sim import MatchConfig

    counting = Counting()
    run_match("idle", "idle", config=MatchConfig(max_cycles=3), recorders=(r for r in [counting]))
    assert counting.cycles == 3


@pytest.mark.parametrize("path, kind", [(None, "NoneType"), (5, "int"), (b"s.json", "bytes")])
def test_load_scenario_needs_a_path(path, kind) -> None:
    with pytest.raises(ScenarioError, match=f"load_scenario needs the path of a .json or .toml file, got {kind}$"):
        load_scenario(path)


@pytest.mark.parametrize("name, text", [("empty.toml", ""), ("blank.toml", "# nothing set\n\n"), ("empty.json", "{}")])
def test_an_empty_scenario_file_is_refused_naming_the_file(tmp_path, name, text) -> None:
    path = tmp_path / name
    path.write_text(text)
    with pytest.raises(ScenarioError) as refused:
        load_scenario(path)
    assert str(refused.value) == (f"Scenario: {path} sets no scenario field: an empty scenario would play the regular "
                                  "match; give at least one field (name, home, away, ball, ...)")


def test_a_scenario_file_setting_one_field_still_loads(tmp_path) -> None:
    path = tmp_path / "named.toml"
    path.write_text('name = "just a name"\n')
    assert load_scenario(path).name == "just a name"
