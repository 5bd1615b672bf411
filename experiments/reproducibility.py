"""The exact library versions a set of figures was measured with.

README's figures depend on more than the code: numba compiles for the installed LLVM,
numpy and scipy choose their kernels, pymunk's stepping changes between releases. This
module walks the installed distribution's requirements (with the extras named) and pins
every package of that closure to the version installed here, in pip's constraints format,
so that someone reproducing a figure installs the same versions::

    python -m experiments.reproducibility > constraints.txt
    pip install -c constraints.txt -e ".[test]"

Only the project's own dependency closure is written, never unrelated packages that happen
to be installed in the same environment.
"""

from __future__ import annotations

import re
import sys
from importlib import metadata

from packaging.requirements import Requirement

DISTRIBUTION = "soccer-sim"
"""The project's distribution name, whose requirements are walked."""

EXTRAS: tuple[str, ...] = ("test", "ray", "parquet")
"""The project's extras whose requirements are pinned too."""


def canonical(name: str) -> str:
    """A package name as pip compares them (PEP 503: lower case, runs of ``-_.`` as ``-``)."""
    return re.sub(r"[-_.]+", "-", name).lower()


def dependency_closure(distribution: str = DISTRIBUTION, extras: tuple[str, ...] = EXTRAS) -> dict[str, str]:
    """Canonical name -> installed version of every package *distribution* needs, with
    *extras*, on this interpreter (environment markers evaluated here); the distribution
    itself is left out. A requirement that is not installed raises ``PackageNotFoundError``
    naming it, since pins for a partial environment would mislead."""
    pins: dict[str, str] = {}
    pending: list[tuple[str, tuple[str, ...]]] = [(distribution, extras)]
    seen: set[tuple[str, str]] = set()
    while pending:
        name, wanted = pending.pop()
        dist = metadata.distribution(name)
        for text in dist.requires or ():
            requirement = Requirement(text)
            if requirement.marker is not None and not any(
                    requirement.marker.evaluate({"extra": extra}) for extra in ("", *wanted)):
                continue
            key = canonical(requirement.name)
            for extra in ("", *sorted(requirement.extras)):
                if (key, extra) in seen:
                    continue
                seen.add((key, extra))
                try:
                    pins[key] = metadata.version(requirement.name)
                except metadata.PackageNotFoundError:
                    raise metadata.PackageNotFoundError(
                        f"{requirement.name} (required by {name}) is not installed") from None
                pending.append((requirement.name, tuple(sorted(requirement.extras))))
    pins.pop(canonical(distribution), None)
    return pins


def constraints_text(pins: dict[str, str]) -> str:
    """*pins* in pip's constraints format, one ``name==version`` a line, sorted by name, under
    a header naming the Python version they were taken from."""
    header = (f"# Versions of soccer-sim's dependencies (extras: {', '.join(EXTRAS)}) in the environment "
              f"that measured README's figures.\n# Python {sys.version.split()[0]}; regenerate with "
              "`python -m experiments.reproducibility > constraints.txt`.\n")
    return header + "".join(f"{name}=={version}\n" for name, version in sorted(pins.items()))


if __name__ == "__main__":
    sys.stdout.write(constraints_text(dependency_closure()))
