"""The code version: a hash of the project's source files as this process imported them.

A stored result says which code played it. A package version or a git commit says what the
driver was built from, not what a worker on another machine imported; so the version is
computed in every process that plays a match, from the files of the packages it imported:
SHA-256 over the sorted relative paths and bytes of every ``.py`` file of the project's packages
and of the package data that changes play (formations and scenarios). Two processes print
the same version exactly when they run the same code.
"""

from __future__ import annotations

import functools
import hashlib
import importlib
from collections.abc import Mapping
from pathlib import Path

PACKAGES = ("soccer_sim", "agents", "formations", "experiments", "kernel_cache")
"""The project's packages: what a node must import, what the Ray backend ships."""

DATA_FILES: Mapping[str, tuple[str, ...]] = {
    "formations": ("data/*.json",),
    "soccer_sim": ("scenarios/data/*.toml",),
}
"""Package data read during play (glob patterns relative to the package directory)."""

DIGITS = 12
"""Hex digits of the hash kept in the version (48 bits: no accidental collisions between builds)."""


def package_dirs() -> dict[str, Path]:
    """The directory of each project package as imported by this process."""
    return {name: Path(importlib.import_module(name).__file__).resolve().parent for name in PACKAGES}


def source_files(dirs: Mapping[str, Path]) -> list[tuple[str, Path]]:
    """(relative path, file) of every file the version covers, sorted by relative path: every
    ``.py`` file under each package directory and the package data of :data:`DATA_FILES`."""
    files: dict[str, Path] = {}
    for name, root in dirs.items():
        found = list(root.rglob("*.py"))
        for pattern in DATA_FILES.get(name, ()):
            found.extend(root.glob(pattern))
        for path in found:
            if "__pycache__" not in path.parts and path.is_file():
                files[f"{name}/{path.relative_to(root).as_posix()}"] = path
    return sorted(files.items())


def source_digest(dirs: Mapping[str, Path]) -> str:
    """SHA-256 (hex) over the relative paths and contents of :func:`source_files` of ``dirs``."""
    digest = hashlib.sha256()
    for relative, path in source_files(dirs):
        data = path.read_bytes()
        digest.update(f"{relative}\0{len(data)}\0".encode())
        digest.update(data)
    return digest.hexdigest()


@functools.lru_cache(maxsize=1)
def code_version() -> str:
    """This process's code version: the first :data:`DIGITS` hex digits of
    :func:`source_digest` of the imported packages (computed once per process, a few ms)."""
    return source_digest(package_dirs())[:DIGITS]
