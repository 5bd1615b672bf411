"""Delaunay-triangulated formations: where each player should stand for any ball position.

A :class:`Formation` holds samples (a ball position with one position per
role), triangulates the ball positions once, and interpolates role positions
for any ball position in microseconds. A :class:`FormationSet` holds one
formation per game :class:`Situation`. Coordinates are metres in the
team-relative frame: origin at the centre spot, attacking towards +x, y to the
left (see :mod:`formations.field`). The field itself is the simulator's
(``soccer_sim.config.FieldConfig``): readers of formation files take it as an argument.

This package is pure: it imports only numpy and scipy (matplotlib lazily, for
pictures) and the project's numba cache stamps (:mod:`kernel_cache`), never the
simulator. It reads helios-base / agent2d formation files
(their JSON layout and agent2d's text layouts) and whole agent2d
``formations-dt`` directories (:func:`import_helios_directory`).

>>> import formations
>>> team = formations.load_builtin("4-3-3")
>>> team.positions((10.0, -5.0), "attack").shape
(11, 2)
"""

import kernel_cache  # noqa: F401 - first of all: numba's cache stamps for the kernels below (see kernel_cache)

from formations.builtin import builtin_names, load_builtin
from formations.errors import FormationError, FormationInputError, UnknownRoleError
from formations.field import FieldDimensions
from formations.files import load, load_helios, load_set, read_any, save
from formations.formation import Formation
from formations.formation_set import FormationSet, Situation, parse_situation
from formations.helios_dir import DirectoryImport, import_helios_directory
from formations.roles import ROLE_KINDS, Role
from formations.symmetry import asymmetries, mirror_complete

__all__ = [
    "DirectoryImport",
    "Formation",
    "FormationError",
    "FormationInputError",
    "FormationSet",
    "FieldDimensions",
    "ROLE_KINDS",
    "Role",
    "Situation",
    "UnknownRoleError",
    "asymmetries",
    "builtin_names",
    "import_helios_directory",
    "load",
    "load_builtin",
    "load_helios",
    "load_set",
    "mirror_complete",
    "parse_situation",
    "read_any",
    "save",
]
