"""No compiled kernel takes more than :data:`MAX_PARAMETERS` parameters.

A kernel's arguments travel as named records (numpy structured records read by field name, made
from the parameter dataclasses, as :mod:`soccer_sim.kernels` does) and named tuples of arrays,
not as long lists of positional scalars and arrays. The scan reads the source (no import, no
compilation): every function decorated with numba's ``njit`` or ``jit`` (bare, called, or as
``numba.njit``) under the project's packages.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("soccer_sim", "agents", "formations", "rcss_bridge")
MAX_PARAMETERS = 12
JIT_DECORATORS = frozenset({"njit", "jit"})

STILL_CONVERTING: frozenset[str] = frozenset()
"""Modules whose kernels may still take more parameters while they are converted to named
records: none now, and it is to stay empty (a module is removed as soon as its kernels
comply (:func:`test_the_allow_list_names_only_modules_still_over_the_limit` insists)."""


def _decorator_name(node: ast.expr) -> str:
    """The last name of a decorator: ``njit`` for ``@njit``, ``@njit(cache=True)`` and ``@numba.njit``."""
    if isinstance(node, ast.Call):
        node = node.func
    if isinstance(node, ast.Attribute):
        return node.attr
    return node.id if isinstance(node, ast.Name) else ""


def parameter_count(node: ast.FunctionDef) -> int:
    """Parameters of a function: positional, keyword-only and a ``*args`` (counted as one)."""
    a = node.args
    return len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (1 if a.vararg else 0) + (1 if a.kwarg else 0)


def kernels_over(limit: int, source: str, path: str) -> list[tuple[str, int, str, int]]:
    """(path, line, name, parameters) of each njit/jit-decorated function in ``source`` with
    more than ``limit`` parameters."""
    found = []
    for node in ast.walk(ast.parse(source, filename=path)):
        if isinstance(node, ast.FunctionDef) and any(_decorator_name(d) in JIT_DECORATORS
                                                     for d in node.decorator_list):
            count = parameter_count(node)
            if count > limit:
                found.append((path, node.lineno, node.name, count))
    return found


def project_kernels_over(limit: int) -> list[tuple[str, int, str, int]]:
    """:func:`kernels_over` for every module of :data:`PACKAGES`, paths relative to the project."""
    found = []
    for package in PACKAGES:
        for file in sorted((ROOT / package).rglob("*.py")):
            path = file.relative_to(ROOT).as_posix()
            found += kernels_over(limit, file.read_text(encoding="utf-8"), path)
    return found


def test_no_kernel_takes_more_than_twelve_parameters() -> None:
    offenders = [f"{path}:{line} {name} ({count} parameters)"
                 for path, line, name, count in project_kernels_over(MAX_PARAMETERS)
                 if path not in STILL_CONVERTING]
    assert not offenders, "kernels over the limit (pass named records instead):\n" + "\n".join(offenders)


def test_the_allow_list_names_only_modules_still_over_the_limit() -> None:
    over = {path for path, *_ in project_kernels_over(MAX_PARAMETERS)}
    done = sorted(STILL_CONVERTING - over)
    assert not done, f"these modules comply now: remove them from STILL_CONVERTING: {done}"


@pytest.mark.parametrize("decorator", ["@njit", "@njit(cache=True, nogil=True)", "@numba.jit(nopython=True)"])
def test_the_scan_finds_a_kernel_of_thirteen_parameters(tmp_path, decorator) -> None:
    module = tmp_path / "wide.py"
    names = ", ".join(f"p{i}" for i in range(13))
    module.write_text(f"import numba\nfrom numba import njit\n\n\n{decorator}\ndef wide({names}):\n    return p0\n\n\n"
                      f"{decorator}\ndef narrow({names.rsplit(', ', 1)[0]}):\n    return p0\n\n\n"
                      f"def plain({names}):\n    return p0\n", encoding="utf-8")
    assert kernels_over(MAX_PARAMETERS, module.read_text(encoding="utf-8"), "wide.py") == [("wide.py", 6, "wide", 13)]
