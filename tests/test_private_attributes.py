"""No object reads another's private attributes: dependencies are passed at construction and
what another object needs is a public, documented attribute or property.

The scan finds every ``x._name`` in the packages whose ``x`` is not ``self``, ``cls`` or an
imported module. What is left is listed below with its reason: the internals of third-party
libraries that have no public way to the same thing, and a class using its own private method."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("soccer_sim", "agents", "formations", "experiments", "rcss_bridge", "kernel_cache")

ALLOWED = {
    # pymunk 7's batch transfer has no public buffer or space handle (soccer_sim/physics.py says why)
    ("soccer_sim/physics.py", "buffer._float_arr"), ("soccer_sim/physics.py", "buffer._int_arr"),
    ("soccer_sim/physics.py", "space._space"), ("soccer_sim/physics.py", "self._write_buffer._float_arr"),
    ("soccer_sim/physics.py", "self._read_buffer._float_arr"),
    # a named tuple's public API is spelt with an underscore
    ("agents/skills/context.py", "self.intercept_constants._asdict"),
    # argparse keeps its sub-parsers only there
    ("experiments/cli.py", "node._actions"),
    # a class method checking the instance it made
    ("experiments/results/record.py", "record._check"),
    # numba's on-disk cache index has no public reader
    ("experiments/warmup.py", "dispatcher._cache"), ("experiments/warmup.py", "cache._index_key"),
    ("experiments/warmup.py", "cache._cache_file._load_index"), ("experiments/warmup.py", "cache._cache_file"),
    ("kernel_cache/__init__.py", "caching.CacheImpl._locator_classes"),
}


def private_reads(root: Path, packages: tuple[str, ...] = PACKAGES) -> set[tuple[str, str]]:
    """Every (file, expression) reading another object's private attribute in ``packages``."""
    found = set()
    for package in packages:
        for path in sorted((root / package).rglob("*.py")):
            tree = ast.parse(path.read_text())
            modules = {(alias.asname or alias.name).split(".")[0] for node in ast.walk(tree)
                       if isinstance(node, (ast.Import, ast.ImportFrom)) for alias in node.names}
            for node in ast.walk(tree):
                if not (isinstance(node, ast.Attribute) and node.attr.startswith("_")
                        and not node.attr.startswith("__")):
                    continue
                owner = node.value
                if isinstance(owner, ast.Name) and (owner.id in ("self", "cls") or owner.id in modules):
                    continue
                found.add((path.relative_to(root).as_posix(), ast.unparse(node)))
    return found


def test_no_object_reads_another_objects_private_attributes() -> None:
    assert private_reads(ROOT) - ALLOWED == set()


def test_the_allowances_are_still_needed() -> None:
    assert ALLOWED - private_reads(ROOT) == set()


def test_the_scan_finds_a_private_read(tmp_path) -> None:
    (tmp_path / "agents").mkdir()
    (tmp_path / "agents" / "a.py").write_text("import numpy as np\n\ndef f(shape):\n    return shape._knobs, "
                                              "np._core\n\nclass A:\n    def g(self):\n        return self._x\n")
    assert private_reads(tmp_path, ("agents",)) == {("agents/a.py", "shape._knobs")}
