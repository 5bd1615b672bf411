"""A whole agent2d ``formations-dt`` directory as one :class:`FormationSet`.

agent2d-based teams keep one file per game situation in a directory. The
files whose meaning matches one of our situations are placed there:

==============================  =====================
agent2d file                    situation
==============================  =====================
``normal-formation.conf``       ``normal`` (required)
``offense-formation.conf``      ``attack``
``defense-formation.conf``      ``defend``
``setplay-our-formation.conf``  ``our_set_play``
``setplay-opp-formation.conf``  ``their_set_play``
==============================  =====================

Every other file is left out and reported with the reason: agent2d's
``before-kick-off.conf`` is a fixed line-up taken only before kick-offs, and
our sets have no situation of that kind (a kick-off is one of the set plays);
the more specific set plays (``kickin-our-formation.conf``,
``goal-kick-opp.conf``, ``goalie-catch-our.conf``,
``indirect-freekick-*-formation.conf``, ...) would all compete for the one
set-play situation of each side. ``mapping`` overrides or extends the table,
e.g. ``{"before-kick-off": "our_set_play"}``.

A set needs the same roles in every formation, so every member takes the
roles (names, kinds, partners) of the normal formation; a file whose role
names or pairs differ is noted in the report. Files may be in any layout
:func:`formations.files.load_helios` reads: agent2d's text layouts,
helios-base's comma-separated layout or its JSON layout, static or not.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from dataclasses import field as default_of
from pathlib import Path

from formations.errors import FormationError
from formations.field import FieldDimensions
from formations.files import load_helios
from formations.formation import Formation
from formations.formation_set import FormationSet, Situation, parse_situation

AGENT2D_SITUATIONS: dict[str, Situation] = {
    "normal-formation": Situation.NORMAL,
    "offense-formation": Situation.ATTACK,
    "defense-formation": Situation.DEFEND,
    "setplay-our-formation": Situation.OUR_SET_PLAY,
    "setplay-opp-formation": Situation.THEIR_SET_PLAY,
}
"""agent2d file name (without ``.conf``) -> our situation."""

LEFT_OUT_REASONS: dict[str, str] = {
    "before-kick-off": "the line-up before kick-offs; our sets have no situation for it (kick-offs are set plays)",
    "kickin-our-formation": "our kick-ins only; our_set_play takes setplay-our-formation.conf",
    "indirect-freekick-our-formation": "our indirect free kicks only; our_set_play takes setplay-our-formation.conf",
    "indirect-freekick-opp-formation": "their indirect free kicks only; their_set_play takes setplay-opp-formation.conf",
    "goal-kick-our": "our goal kicks only; our_set_play takes setplay-our-formation.conf",
    "goal-kick-opp": "their goal kicks only; their_set_play takes setplay-opp-formation.conf",
    "goalie-catch-our": "after our goalkeeper's catches only; our sets have no situation for it",
    "goalie-catch-opp": "after their goalkeeper's catches only; our sets have no situation for it",
    "goalie-formation": "helios-base's players never load it (their strategy reads no goalie-formation.conf)",
}
"""Reasons given for agent2d's other known files."""

FORMATION_SUFFIXES = (".conf", ".json")
"""Files of a directory considered as formations."""


@dataclass
class DirectoryImport:
    """The set made of a directory, and what happened to each file."""

    formation_set: FormationSet
    placed: dict[Situation, Path]
    """Situation -> the file that supplied it."""
    left_out: dict[Path, str] = default_of(default_factory=dict)
    """File -> why it was not placed."""
    notes: list[str] = default_of(default_factory=list)
    """Other things the user should know (roles taken from the normal formation, ...)."""


def import_helios_directory(
    directory: str | os.PathLike[str],
    *,
    field: FieldDimensions,
    name: str | None = None,
    mapping: Mapping[str, str | Situation] | None = None,
) -> DirectoryImport:
    """Read an agent2d formation directory into a :class:`FormationSet` on *field* (the server's
    pitch its files were written for; see :func:`formations.files.read_any`).

    *mapping* maps file names (with or without ``.conf``) to situation names
    and takes precedence over :data:`AGENT2D_SITUATIONS`. Raises
    :class:`FormationError` if the directory has no normal formation, two
    files claim one situation, or a placed file is malformed (the error names
    the file and line); ``OSError`` if the directory cannot be read.
    """
    root = Path(directory)
    files = sorted(p for p in root.iterdir() if p.is_file() and p.suffix in FORMATION_SUFFIXES)
    table, displaced = _situation_table(mapping, str(root))
    placed: dict[Situation, Path] = {}
    left_out: dict[Path, str] = {}
    for path in files:
        situation = table.get(path.stem)
        if situation is None:
            left_out[path] = displaced.get(path.stem) or LEFT_OUT_REASONS.get(
                path.stem, "not an agent2d file name this importer knows"
            )
            continue
        if situation in placed:
            raise FormationError(
                str(path), f"situation {situation.value!r} is already taken by {placed[situation].name}"
            )
        placed[situation] = path
    if Situation.NORMAL not in placed:
        found = ", ".join(p.name for p in files) or "no .conf or .json files"
        raise FormationError(str(root), f"no normal formation (normal-formation.conf) in the directory (found: {found})")
    formations: dict[Situation, Formation] = {}
    for situation, path in placed.items():
        formations[situation] = load_helios(path, field=field)
    notes = []
    normal = formations[Situation.NORMAL]
    for situation, formation in formations.items():
        if formation.roles != normal.roles:
            formations[situation] = _with_roles(formation, normal)
            notes.append(
                f"{placed[situation].name}: roles (names, kinds, pairs) differ from "
                f"{placed[Situation.NORMAL].name}'s; {situation.value} uses those of the normal formation"
            )
    set_name = name if name is not None else root.resolve().name
    description = f"imported from the agent2d formation directory {root}"
    formation_set = FormationSet(set_name, formations, description=description, source=str(root))
    return DirectoryImport(formation_set, placed, left_out, notes)


def _situation_table(
    mapping: Mapping[str, str | Situation] | None, source: str
) -> tuple[dict[str, Situation], dict[str, str]]:
    """File stem -> situation, and the reason of each default file the mapping displaced."""
    table = dict(AGENT2D_SITUATIONS)
    displaced: dict[str, str] = {}
    for key, value in (mapping or {}).items():
        stem = key[: -len(".conf")] if key.endswith(".conf") else key
        try:
            situation = parse_situation(value)
        except ValueError as error:
            raise FormationError(source, f"mapping of {key!r}: {error}") from None
        for other, taken in list(table.items()):
            if taken == situation and other != stem and other in AGENT2D_SITUATIONS:
                del table[other]  # an explicit mapping replaces the default file of that situation
                displaced[other] = f"{situation.value} was given to {stem} by the mapping"
        table[stem] = situation
        displaced.pop(stem, None)
    return table, displaced


def _with_roles(formation: Formation, model: Formation) -> Formation:
    """*formation*'s samples with *model*'s roles (matched by number)."""
    if sorted(formation.role_numbers) != sorted(model.role_numbers):
        raise FormationError(
            formation.source, f"role numbers {list(formation.role_numbers)} differ from {list(model.role_numbers)}"
        )
    order = [formation.index_of(role.number) for role in model.roles]
    return Formation(
        model.roles,
        formation.balls,
        formation.sample_positions[:, order],
        name=formation.name,
        description=formation.description,
        source=formation.source,
    )
