"""The experiments core (runner, results store, configuration, statistics) does not lean on
the command line, a study or a benchmark: none of its modules imports them, at module level
or inside a function."""

from __future__ import annotations

import ast
from pathlib import Path

import experiments

PACKAGE = Path(experiments.__file__).parent
CORE = ["runner", "results", "errors.py", "configuration.py", "limits.py", "stats.py"]
OUTER = ("experiments.commands", "experiments.studies", "experiments.benchmarks", "experiments.cli")


def imported_modules(path: Path) -> set[str]:
    """Every module ``path`` imports, anywhere in its code (functions included)."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


def core_files() -> list[Path]:
    files: list[Path] = []
    for part in CORE:
        path = PACKAGE / part
        files.extend(sorted(path.rglob("*.py")) if path.is_dir() else [path])
    return files


def test_the_core_imports_no_command_study_or_benchmark() -> None:
    files = core_files()
    assert len(files) > 10
    wrong = {f"{path.relative_to(PACKAGE)} imports {name}"
             for path in files for name in imported_modules(path)
             if name == "experiments" or name.startswith(OUTER) or name in ("experiments.commands",)}
    assert not wrong, sorted(wrong)


def test_the_walk_sees_function_level_imports(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    module.write_text("def f():\n    from experiments.commands.errors import fail\n    return fail\n")
    assert "experiments.commands.errors" in imported_modules(module)
