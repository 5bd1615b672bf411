"""Every kind of malformed formation gets a FormationError naming file and culprit."""

from __future__ import annotations

import copy
from typing import Any, Callable

import numpy as np
import pytest
from scipy.spatial import QhullError

import formations
from formations import Formation, FormationError, FormationSet, Role
from tests.formations.formation_samples import eleven_roles, small_document
from soccer_sim.config import STANDARD_FIELD as FIELD

Mutation = Callable[[dict[str, Any]], Any]


def _set(path: list, value: Any) -> Mutation:
    def mutate(document: dict[str, Any]) -> None:
        target = document
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value

    return mutate


def _delete(path: list) -> Mutation:
    def mutate(document: dict[str, Any]) -> None:
        target = document
        for key in path[:-1]:
            target = target[key]
        del target[path[-1]]

    return mutate


def _samples(balls: list[list[float]]) -> Mutation:
    def mutate(document: dict[str, Any]) -> None:
        template = document["samples"][0]["positions"]
        document["samples"] = [{"ball": ball, "positions": copy.deepcopy(template)} for ball in balls]

    return mutate


BAD_DOCUMENTS: list[tuple[str, Mutation, str]] = [
    ("missing role position", _delete(["samples", 2, "positions", "3"]), r"sample 2: missing the position of role 3"),
    ("extra role position", _set(["samples", 1, "positions", "12"], [0.0, 0.0]), r"sample 1: role 12 is not one of"),
    ("sample without positions", _delete(["samples", 3, "positions"]), r"sample 3: missing field 'positions'"),
    ("sample without ball", _delete(["samples", 0, "ball"]), r"sample 0: missing field 'ball'"),
    (
        "NaN coordinate",
        _set(["samples", 1, "positions", "2"], [float("nan"), 1.0]),
        r"sample 1, role 2: .*not a finite",
    ),
    ("infinite ball", _set(["samples", 2, "ball"], [0.0, float("inf")]), r"sample 2, ball: .*not a finite"),
    (
        "string coordinate",
        _set(["samples", 0, "positions", "1"], ["-50", 0.0]),
        r"sample 0, role 1: coordinate '-50' is not a number",
    ),
    ("boolean coordinate", _set(["samples", 0, "positions", "1"], [True, 0.0]), r"sample 0, role 1: coordinate True"),
    (
        "three coordinates",
        _set(["samples", 3, "positions", "2"], [1.0, 2.0, 3.0]),
        r"sample 3, role 2: a position must be",
    ),
    ("duplicate ball", _set(["samples", 3, "ball"], [0.0, 20.0]), r"sample 3: .*0 m from that of sample 2"),
    ("nearly duplicate ball", _set(["samples", 3, "ball"], [0.3, 19.8]), r"sample 3: .*0.361 m from that of sample 2"),
    ("two samples", _samples([[0.0, 0.0], [10.0, 0.0]]), r"at least 3 samples.*got 2"),
    ("no samples", _samples([]), r"at least 3 samples.*got 0"),
    ("collinear samples", _samples([[0.0, 0.0], [10.0, 5.0], [20.0, 10.0], [-30.0, -15.0]]), r"lie on one line"),
    (
        "ball far outside",
        _set(["samples", 1, "ball"], [80.0, 0.0]),
        r"sample 1, ball: position \(80, 0\) is far outside",
    ),
    ("player far outside", _set(["samples", 2, "positions", "3"], [0.0, -3400.0]), r"sample 2, role 3: .*far outside"),
    ("unknown role kind", _set(["roles", 1, "kind"], "winger"), r"role 2: unknown kind 'winger'"),
    ("duplicate role number", _set(["roles", 2, "number"], 2), r"role 2: .*(used twice|unknown)"),
    ("one-sided partner", _set(["roles", 1, "partner"], 1), r"role 2: partner 1 does not name role 2"),
    ("partner is not a role", _set(["roles", 0, "partner"], 9), r"role 1: partner 9 is not a role"),
    ("role without name", _delete(["roles", 0, "name"]), r"role 1: missing field 'name'"),
    ("misspelt role field", _set(["roles", 0, "kinds"], "goalkeeper"), r"role 1: unknown field\(s\) 'kinds'"),
    ("misspelt sample field", _set(["samples", 1, "positons"], {}), r"sample 1: unknown field\(s\) 'positons'"),
    ("roles not a list", _set(["roles"], {"1": "keeper"}), r"field 'roles' must be a list"),
    ("unknown format", _set(["format"], "other"), r"unknown layout"),
    ("future version", _set(["version"], 2), r"unsupported layout version 2"),
]


@pytest.mark.parametrize("label, mutate, message", BAD_DOCUMENTS, ids=[case[0] for case in BAD_DOCUMENTS])
def test_bad_document_is_reported_with_file_and_culprit(write_json, label, mutate, message):
    document = small_document()
    mutate(document)
    path = write_json("bad.json", document)
    with pytest.raises(FormationError, match=message) as caught:
        formations.load(path, field=FIELD)
    assert str(caught.value).startswith(str(path) + ":")
    assert isinstance(caught.value, ValueError)
    assert "\n" not in str(caught.value)
    assert not isinstance(caught.value.__cause__, QhullError)


@pytest.mark.parametrize(
    "text, message",
    [
        ('{"format": "soccer-sim-formation", ', r"invalid JSON: .*line 1"),
        ("", r"invalid JSON"),
        ("[1, 2, 3]", r"expected a JSON object at the top level, got a list"),
    ],
)
def test_invalid_json_names_the_file(write_json, text, message):
    path = write_json("broken.json", text)
    with pytest.raises(FormationError, match=message) as caught:
        formations.load(path, field=FIELD)
    assert str(caught.value).startswith(str(path))


def test_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(FileNotFoundError):
        formations.load(tmp_path / "absent.json", field=FIELD)


def test_a_sample_equal_to_another_after_rounding_noise_is_rejected_programmatically():
    roles = eleven_roles()
    balls = np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0], [1e-9, 1e-9]])
    with pytest.raises(FormationError, match=r"<formation>: sample 3: .*from that of sample 0"):
        Formation(roles, balls, np.zeros((4, 11, 2)))


def test_programmatic_shape_errors():
    roles = eleven_roles()
    balls = np.array([[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]])
    with pytest.raises(FormationError, match=r"role positions must have shape \(3, 11, 2\)"):
        Formation(roles, balls, np.zeros((3, 10, 2)), name="short")
    with pytest.raises(FormationError, match="formation 'x': role positions are not an array"):
        Formation(roles, balls, [["a"]], name="x")
    with pytest.raises(FormationError, match="more than one goalkeeper"):
        Formation([Role(1, "a", "goalkeeper"), Role(2, "b", "goalkeeper")], balls, np.zeros((3, 2, 2)))


def test_formation_set_errors(random_formation):
    with pytest.raises(FormationError, match="needs a 'normal' formation"):
        FormationSet("s", {"attack": random_formation})
    with pytest.raises(FormationError, match="unknown situation 'counter'"):
        FormationSet("s", {"normal": random_formation, "counter": random_formation})
    other_roles = [Role(r.number, r.name.upper(), r.kind, r.partner) for r in random_formation.roles]
    other = Formation(other_roles, random_formation.balls, random_formation.sample_positions)
    with pytest.raises(FormationError, match="formation 'defend': roles differ"):
        FormationSet("s", {"normal": random_formation, "defend": other})


def test_error_inside_a_set_file_names_the_situation(tmp_path, write_json):
    bad = small_document()
    del bad["samples"][1]["positions"]["2"]
    good = small_document()
    document = {
        "format": "soccer-sim-formation-set",
        "version": 1,
        "name": "x",
        "formations": {"normal": good, "attack": bad},
    }
    path = write_json("set.json", document)
    with pytest.raises(FormationError, match=r"set.json: formation 'attack', sample 1: missing the position of role 2"):
        formations.load_set(path, field=FIELD)


# ----------------------------------------------------------------- helios
def _helios() -> dict[str, Any]:
    from test_formation_files import helios_document

    return helios_document()


HELIOS_BAD: list[tuple[str, Mutation, str]] = [
    ("other method", _set(["method"], "KNN"), r"method 'KNN' is not supported"),
    ("missing role", lambda d: d["role"].pop(), r"roles \[11\] are missing"),
    ("duplicate role", _set(["role", 10, "number"], 3), r"role 3: role number is used twice"),
    ("bad type", _set(["role", 3, "type"], "XX"), r"role 4: 'type' must be one of"),
    ("bad pair", _set(["role", 2, "pair"], 4), r"role 3: pairs with role 4, but role 4 has pair 0"),
    ("extra player", _set(["data", 2, "12"], {"x": 0, "y": 0}), r"sample 2: unknown role\(s\) or field\(s\) '12'"),
    ("missing player", _delete(["data", 4, "7"]), r"sample 4: missing the position of role 7"),
    ("missing y", _delete(["data", 1, "5", "y"]), r"sample 1, role 5: a position must be an object"),
    ("non-numeric", _set(["data", 0, "ball", "x"], "zero"), r"sample 0, ball: x = 'zero' is not a finite number"),
    ("NaN", _set(["data", 3, "8", "y"], float("nan")), r"sample 3, role 8: y = nan is not a finite number"),
    ("duplicate ball", _set(["data", 5, "ball"], {"x": 0.2, "y": 0.1}), r"sample 5: .*from that of sample 0"),
]


@pytest.mark.parametrize("label, mutate, message", HELIOS_BAD, ids=[case[0] for case in HELIOS_BAD])
def test_bad_helios_file_is_reported(write_json, label, mutate, message):
    document = _helios()
    mutate(document)
    path = write_json("helios.json", document)
    with pytest.raises(FormationError, match=message) as caught:
        formations.load(path, field=FIELD)
    assert str(caught.value).startswith(str(path) + ":")


def test_every_error_class_of_the_package_derives_from_formation_error():
    import importlib
    import inspect
    import pkgutil

    from formations.errors import FormationInputError, UnknownRoleError

    found = set()
    for info in pkgutil.walk_packages(formations.__path__, "formations."):
        module = importlib.import_module(info.name)
        for _, cls in inspect.getmembers(module, inspect.isclass):
            if issubclass(cls, BaseException) and cls.__module__.startswith("formations"):
                found.add(cls)
                assert issubclass(cls, FormationError) and issubclass(cls, ValueError), cls
    assert {FormationError, FormationInputError, UnknownRoleError} <= found


def test_bad_query_arguments_are_formation_errors_and_stay_value_errors(random_formation):
    import pickle

    from formations.errors import FormationInputError, UnknownRoleError

    cases = [
        (lambda: formations.parse_situation("counter"), "unknown situation 'counter'"),
        (lambda: formations.load_builtin("no-such-set"), "no built-in formation set 'no-such-set'"),
        (lambda: random_formation.positions((float("nan"), 0.0)), "query point must be finite"),
        (lambda: random_formation.positions((1.0, 2.0, 3.0)), r"two numbers \(x, y\), got 3"),
        (lambda: random_formation.positions_many(np.zeros((2, 3))), r"shape \(k, 2\)"),
    ]
    for call, message in cases:
        with pytest.raises(FormationInputError, match=message) as caught:
            call()
        assert isinstance(caught.value, FormationError) and isinstance(caught.value, ValueError)
        again = pickle.loads(pickle.dumps(caught.value))
        assert type(again) is type(caught.value) and str(again) == str(caught.value)
    with pytest.raises(UnknownRoleError, match="has no role 99") as caught:
        random_formation.role(99)
    assert isinstance(caught.value, KeyError) and isinstance(caught.value, FormationError)
    assert str(caught.value).endswith(")")  # the message itself, not KeyError's quoted repr of it
    assert str(caught.value.within("formation 'attack'")).startswith("formation 'attack': ")
