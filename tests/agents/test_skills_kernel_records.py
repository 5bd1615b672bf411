"""The skills' and the shape's compiled kernels take named records, not long argument lists:
none has more than 12 parameters, and none reads its constants from a float array by index
constants (the ``K_*`` of the old pacing array, the ``knobs`` positions of the shape)."""

from __future__ import annotations

import ast
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
MODULES = sorted(ROOT.glob("agents/skills/*.py")) + [ROOT / "agents/teams/shape_kernels.py",
                                                     ROOT / "agents/teams/role_kernels.py"]
MOST_PARAMETERS = 12


def _kernels(path: pathlib.Path) -> list[ast.FunctionDef]:
    tree = ast.parse(path.read_text())
    return [node for node in ast.walk(tree) if isinstance(node, ast.FunctionDef)
            and any("jit" in ast.unparse(d) for d in node.decorator_list)]


def _count(node: ast.FunctionDef) -> int:
    a = node.args
    return len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (a.vararg is not None) + (a.kwarg is not None)


@pytest.mark.parametrize("path", MODULES, ids=lambda p: p.name)
def test_no_kernel_takes_more_than_twelve_parameters(path: pathlib.Path) -> None:
    long = [f"{node.name} ({_count(node)})" for node in _kernels(path) if _count(node) > MOST_PARAMETERS]
    assert not long, f"{path.name}: kernels with more than {MOST_PARAMETERS} parameters: {long}"


def test_the_kernels_in_these_modules_are_found() -> None:
    """The scan above sees the kernels (a renamed decorator would leave it checking nothing)."""
    names = {node.name for path in MODULES for node in _kernels(path)}
    assert {"intercept_kernel", "race_kernel", "kick_kernel", "best_pass_search", "paced_dash_rows", "fan_kernel",
            "settle_targets", "support_spots"} <= names


def test_the_pacing_and_shape_numbers_are_read_by_name() -> None:
    """No index constants into a float array are left for the pacing and shape kernels."""
    import agents.skills.pacing as pacing
    import agents.teams.shape_kernels as shape_kernels

    assert not [name for name in vars(pacing) if name.startswith("K_")]
    assert not {"KNOBS", "MODE", "BALL_X", "LIMITED", "OFF", "ATTACKING", "DEFENDING"} & set(vars(shape_kernels))
    assert {"half_cycles", "tolerance", "floor"} <= set(pacing.PACING_PARAMS.names)
    assert set(shape_kernels.SHAPE_PARAMS.names) >= {"push", "drop", "back_floor"}
