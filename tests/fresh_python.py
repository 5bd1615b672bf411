"""Running a script in a fresh Python process, for tests of what happens at start-up (imports,
numba's on-disk cache)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
"""The checkout under test."""


def run_python(script: str, tmp_path: Path, cache: Path | None = None) -> subprocess.CompletedProcess:
    """Run ``script`` in a fresh Python with this checkout and ``tmp_path`` importable and the
    numba cache in ``cache`` (None: numba's default, beside the sources), in ``tmp_path``;
    fails the test if it fails."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), str(tmp_path)]))
    env.pop("NUMBA_CACHE_DIR", None)
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = str(cache)
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(script)], env=env, cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done
