"""numba's on-disk cache kept in step with the code a compiled kernel takes from other files.

numba stamps each cached function with a hash of its own source file only. A kernel that
calls a kernel of another module, or reads another module's constants, has that code or those
values compiled in; when only the other module changes, numba loads the old machine code
(after a ``git pull``, a branch switch or an edit, a match would quietly run code that is
gone). Importing this package (the packages that define kernels, ``soccer_sim``, ``agents``
and ``formations``, do it first thing) gives the
project's kernels a stamp over their own file and the project modules they import from,
following the imports further through every module that itself defines kernels (its code is
compiled in too) but not through plain modules (only their values are). A change to any of
those files sends the kernel back to the compiler; a change elsewhere does not.

It works through numba's cache locators (``numba.core.caching.CacheImpl``): a locator is
chosen when a kernel is decorated, so this must be imported before any kernel module of the
project, which each package's ``__init__`` does. Functions outside the project keep numba's
own locators. If numba's internals differ from what this expects, nothing is installed and
numba behaves as it always does.
"""

from __future__ import annotations

import ast
import hashlib
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
"""The directory holding the project's packages."""
PACKAGES = ("soccer_sim", "agents", "formations", "experiments", "kernel_cache")
"""The project's packages, whose kernels get the stamp."""

_roots: list[tuple[Path, tuple[str, ...]]] = []
_stamps: dict[Path, bytes] = {}
_files: dict[Path, tuple[bytes, list[Path]]] = {}


def install(root: Path = ROOT, packages: Sequence[str] = PACKAGES) -> bool:
    """Give the kernels of ``packages`` (directories under ``root``) decorated from now on the
    stamp of the module docstring; returns whether numba's locators could be extended (once is
    enough; again with other packages adds them)."""
    try:
        from numba.core import caching

        bases = (caching.UserProvidedCacheLocator, caching.InTreeCacheLocator, caching.UserWideCacheLocator)
        locators = caching.CacheImpl._locator_classes
    except (ImportError, AttributeError):
        return False
    entry = (Path(root).resolve(), tuple(packages))
    if entry not in _roots:
        _roots.append(entry)
    if not any(getattr(cls, "_project_stamp", False) for cls in locators):
        caching.CacheImpl._locator_classes = [_project_locator(base) for base in bases] + list(locators)
    return True


def _project_locator(base: type) -> type:
    """``base`` (one of numba's file-backed locators) for the project's files, with their stamp."""

    def from_function(cls, py_func, py_file):
        if _module_of(Path(py_file)) is None:
            return None
        return super(cls, cls).from_function(py_func, py_file)

    def get_source_stamp(self):
        return dependency_stamp(Path(self._py_file))

    return type(f"Project{base.__name__}", (base,), {"_project_stamp": True, "from_function": classmethod(
        from_function), "get_source_stamp": get_source_stamp})


def _module_of(path: Path) -> tuple[Path, str] | None:
    """(root, dotted name) of ``path`` when it is a module of an installed package, else None."""
    path = path.resolve()
    for root, packages in _roots:
        try:
            parts = path.relative_to(root).with_suffix("").parts
        except ValueError:
            continue
        if parts and parts[0] in packages:
            return root, ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
    return None


def _file_of(root: Path, module: str) -> Path | None:
    """The file of ``module`` under ``root`` (a module or a package's ``__init__``), if any."""
    base = root.joinpath(*module.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def dependency_stamp(path: Path) -> bytes:
    """The hash of ``path`` and of the project modules its compiled code depends on (module
    docstring): the files' names and contents, so touching a file without changing it keeps
    the stamp."""
    path = path.resolve()
    if path not in _stamps:
        _stamps[path] = hashlib.sha256(b"".join(
            name.encode() + b"\0" + hashlib.sha256(text).digest() for name, text in sorted(dependencies(path).items())
        )).digest()
    return _stamps[path]


def dependencies(path: Path) -> dict[str, bytes]:
    """``path``'s contents and those of the project modules it depends on, by file path
    relative to its root (module docstring)."""
    path = path.resolve()
    found = _module_of(path)
    if found is None:
        return {path.name: path.read_bytes()}
    root = found[0]
    texts: dict[str, bytes] = {}
    waiting = [path]
    while waiting:
        current = waiting.pop()
        name = str(current.relative_to(root))
        if name in texts:
            continue
        texts[name], imported = _read(root, current)
        waiting += imported
    return texts


def _read(root: Path, path: Path) -> tuple[bytes, list[Path]]:
    """``path``'s contents and the files of the project modules it imports, read once; none
    for a plain module (no kernels): its values count, its own imports do not."""
    if path not in _files:
        text = path.read_bytes()
        module = _module_of(path)
        imported = _imported_files(root, module[1], path, text) if module is not None and b"njit" in text else []
        _files[path] = text, [file for file in imported if _module_of(file) is not None]
    return _files[path]


def _imported_files(root: Path, module: str, path: Path, text: bytes) -> list[Path]:
    """The files of the project modules ``text`` (module ``module`` at ``path``) imports at
    module level: ``import a.b``, ``from a.b import c`` (``a.b.c`` when it is a module) and
    relative forms."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    files = []
    for node in ast.parse(text).body:
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, *([base] if base else [])])
            names = [base, *(f"{base}.{alias.name}" for alias in node.names)]
        else:
            continue
        files += [file for file in (_file_of(root, name) for name in names if name) if file is not None]
    return files


install()
