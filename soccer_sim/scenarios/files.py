"""Scenarios as files: JSON or TOML, one scenario per file.

The file holds the :class:`~soccer_sim.scenarios.Scenario` fields by name; ``home``,
``away`` and ``ball`` are tables of the :class:`Side` and :class:`BallStart` fields, points
are ``[x, y]`` lists (absolute frame at the start, metres; velocities in m/cycle). TOML has
no null: ``goalie = false`` means no goalkeeper. Omitted fields take their defaults::

    name = "3-vs-1-with-keeper"
    description = "three attackers on the edge of the box against a defender and a goalkeeper"
    start_mode = "play_on"
    end_on = ["goal", "out", "lost"]
    cycle_limit = 300
    half_time = false

    [ball]
    position = [32.0, 0.0]

    [home]
    goalie = false
    positions = [[31.0, 0.0], [32.0, 10.0], [32.0, -10.0]]

    [away]
    goalie = 0
    positions = [[51.5, 0.0], [37.0, 0.0]]

Unknown keys and wrong types are a :class:`ScenarioError` naming the key.
"""

from __future__ import annotations

import json
import os
import sys
from dataclasses import fields
from pathlib import Path
from typing import Any

from soccer_sim.scenarios.scenario import BallStart, Scenario, ScenarioError, Side

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib


def scenario_from_dict(data: dict[str, Any], source: str = "scenario") -> Scenario:
    """Build a :class:`Scenario` from its dict form (as read from JSON or TOML)."""
    if not isinstance(data, dict):
        raise ScenarioError("Scenario", f"{source} must be a table of scenario fields, got {type(data).__name__}")
    known = {f.name for f in fields(Scenario)}
    _refuse_unknown(data, known, "")
    values = dict(data)
    for name, kind in (("home", Side), ("away", Side), ("ball", BallStart)):
        if name in values:
            part = values[name]
            if not isinstance(part, dict):
                raise ScenarioError(name, f"must be a table of {kind.__name__} fields, got {part!r}")
            _refuse_unknown(part, {f.name for f in fields(kind)}, f"{name}.")
            try:
                values[name] = kind(**part)
            except ScenarioError as exc:
                raise ScenarioError(f"{name}.{exc.field.split('.', 1)[-1]}", exc.message) from None
            except TypeError as exc:
                raise ScenarioError(name, str(exc)) from None
    if "end_on" in values and isinstance(values["end_on"], list):
        values["end_on"] = tuple(values["end_on"])
    try:
        return Scenario(**values)
    except TypeError as exc:
        raise ScenarioError("Scenario", f"{source}: {exc}") from None


def scenario_to_dict(scenario: Scenario) -> dict[str, Any]:
    """The dict form of ``scenario`` (JSON-ready: points as lists, no goalkeeper as None)."""
    def plain(value: Any) -> Any:
        if isinstance(value, tuple):
            return [plain(v) for v in value]
        return value

    out: dict[str, Any] = {}
    for f in fields(Scenario):
        value = getattr(scenario, f.name)
        if isinstance(value, (Side, BallStart)):
            value = {g.name: plain(getattr(value, g.name)) for g in fields(value)}
        out[f.name] = plain(value)
    return out


SCENARIO_FILE_LIMIT = 1 << 20
"""The largest scenario file read, in bytes (1 MiB; a scenario is a few hundred bytes): a device
or a runaway file is refused instead of filling memory."""


def load_scenario(path: str | Path) -> Scenario:
    """Read a scenario from a ``.json`` or ``.toml`` file; ScenarioError for a bad file, one that
    sets no field at all (an empty file would silently play the regular match) or a ``path``
    that is not a path."""
    if not isinstance(path, (str, os.PathLike)):
        raise ScenarioError("Scenario", f"load_scenario needs the path of a .json or .toml file, got "
                                        f"{type(path).__name__}")
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".json", ".toml"):
        raise ScenarioError("Scenario", f"{path}: expected a .json or .toml file")
    kind = suffix[1:].upper()
    from formations.input_files import read_input  # the project's one rule for files it reads

    try:
        text = read_input(path, limit=SCENARIO_FILE_LIMIT, what="a scenario file").decode("utf-8")
        data = json.loads(text) if suffix == ".json" else tomllib.loads(text)
    except OSError as exc:
        raise ScenarioError("Scenario", f"cannot read {path}: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise ScenarioError("Scenario", f"{path} is not a UTF-8 text {kind} file (byte {exc.start} is not "
                                        "UTF-8)") from None
    except (json.JSONDecodeError, tomllib.TOMLDecodeError) as exc:
        raise ScenarioError("Scenario", f"{path} is not valid {kind}: {exc}") from None
    except RecursionError:
        raise ScenarioError("Scenario", f"{path} is not a usable {kind} scenario: nested too deeply") from None
    if data == {}:
        raise ScenarioError("Scenario", f"{path} sets no scenario field: an empty scenario would play the regular "
                                        "match; give at least one field (name, home, away, ball, ...)")
    return scenario_from_dict(data, str(path))


def save_scenario(scenario: Scenario, path: str | Path) -> Path:
    """Write ``scenario`` as JSON (the form :func:`load_scenario` reads back)."""
    path = Path(path)
    if path.suffix.lower() != ".json":
        raise ScenarioError("Scenario", f"{path}: scenarios are written as .json files")
    path.write_text(json.dumps(scenario_to_dict(scenario), indent=2) + "\n")
    return path


def _refuse_unknown(data: dict[str, Any], known: set[str], prefix: str) -> None:
    unknown = sorted(set(data) - known)
    if unknown:
        raise ScenarioError(f"{prefix}{unknown[0]}" if prefix else unknown[0],
                            f"unknown key; expected some of {', '.join(sorted(known))}")
