"""``soccer-sim formation ...``: check, draw and import formation files.

* ``validate FILE``: read a formation or formation set and report what it
  holds (samples, triangles, symmetry); with ``--require-symmetry`` exit 1 if
  it is not mirror-symmetric.
* ``show FILE --ball X Y --out picture.png``: draw the field, triangulation,
  samples and the interpolated positions for one ball position, and print the
  positions.
* ``import helios FILE OUT``: convert a helios-base / agent2d formation (their
  JSON layout or agent2d's text layouts) into this project's layout;
  ``import helios DIR OUT`` converts a whole ``formations-dt`` directory into
  one formation set and lists the files it could not place.

FILE may also be the name of a built-in formation set (e.g. ``4-3-3``).
``validate`` and ``show`` take ``--json`` to print what they report as one JSON
object. Errors print one line on stderr naming the file and the problem (see
:mod:`experiments.commands.errors`): exit status 2 for bad input (a malformed
formation, a file that cannot be read or written, a bad option), 1 when
``validate --require-symmetry`` finds asymmetries, 130 after Ctrl-C.
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

from experiments.commands.errors import BAD_INPUT, FAILED, fail as _fail, guarded


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("formation", help="validate, draw or import formation files")
    actions = parser.add_subparsers(dest="formation_action", metavar="ACTION", required=True)

    validate = actions.add_parser("validate", help="check a formation or formation-set file")
    validate.add_argument(
        "file", metavar="FILE", help="formation file (ours, helios-base JSON or agent2d text) or built-in name"
    )
    validate.add_argument(
        "--require-symmetry", action="store_true", help="also fail (exit 1) if the samples are not mirror-symmetric"
    )
    validate.add_argument("--json", action="store_true", help="print the report as one JSON object")
    validate.set_defaults(func=guarded(run_validate))

    show = actions.add_parser("show", help="draw a formation for one ball position")
    show.add_argument("file", metavar="FILE", help="formation file (any layout validate reads) or built-in name")
    show.add_argument(
        "--ball",
        nargs=2,
        type=float,
        metavar=("X", "Y"),
        default=(0.0, 0.0),
        help="ball position in metres, team-relative frame (default: 0 0)",
    )
    show.add_argument(
        "--situation",
        default="normal",
        help="which formation of a set to draw (normal, attack, defend, our_set_play, their_set_play)",
    )
    show.add_argument(
        "--out",
        required=True,
        metavar="PICTURE",
        help="output picture, e.g. picture.png (.png is added to a name without extension; "
        "an existing directory receives NAME-SITUATION.png)",
    )
    show.add_argument("--json", action="store_true", help="print the picture's path and the positions as one JSON object")
    show.set_defaults(func=guarded(run_show))

    imports = actions.add_parser("import", help="convert another program's formation file")
    imports.add_argument("layout", choices=["helios"], help="layout of the input file")
    imports.add_argument("file", metavar="FILE", help="input file, or an agent2d formations-dt directory")
    imports.add_argument(
        "out", metavar="OUT", help="output file (this project's JSON layout; a formation set for a directory)"
    )
    imports.add_argument(
        "--map",
        action="append",
        default=[],
        metavar="FILE=SITUATION",
        help="with a directory: place FILE (e.g. before-kick-off) in SITUATION (e.g. our_set_play); repeatable",
    )
    imports.add_argument("--name", default=None, help="with a directory: name of the set (default: the directory's)")
    imports.set_defaults(func=guarded(run_import))


def run_validate(args: argparse.Namespace) -> int:
    import json

    from formations import Formation
    from formations.symmetry import asymmetries

    item = _read(args.file)
    if isinstance(item, int):
        return item
    formations = (
        [(None, item)]
        if isinstance(item, Formation)
        else [(situation.value, formation) for situation, formation in item.own_formations().items()]
    )
    report = []
    for situation, formation in formations:
        problems = asymmetries(formation, tolerance=1e-6)
        report.append({"situation": situation, "name": formation.name or "formation", "roles": len(formation.roles),
                       "samples": formation.n_samples, "triangles": len(formation.triangles),
                       "asymmetries": [problem.describe() for problem in problems]})
    broken = sum(bool(entry["asymmetries"]) for entry in report) if args.require_symmetry else 0
    if args.json:
        print(json.dumps({"file": args.file, "set": None if isinstance(item, Formation) else item.name,
                          "formations": report, "ok": not broken}, indent=2))
    else:
        if not isinstance(item, Formation):
            print(f"{args.file}: formation set {item.name!r} with {len(formations)} situations")
        for entry in report:
            problems = entry["asymmetries"]
            label = f"[{entry['situation']}] " if entry["situation"] else ""
            symmetry = "mirror-symmetric" if not problems else f"{len(problems)} asymmetries"
            print(f"{args.file}: {label}{entry['name']}: {entry['roles']} roles, {entry['samples']} samples, "
                  f"{entry['triangles']} triangles, {symmetry}")
            for problem in problems[:5]:
                print(f"    {problem}")
    if broken:
        return _fail(f"{args.file}: {broken} formation(s) are not mirror-symmetric", FAILED)
    if not args.json:
        print(f"{args.file}: OK")
    return 0


def run_show(args: argparse.Namespace) -> int:
    import json

    from experiments.reporting import Table
    from formations import Formation, FormationError
    from experiments.results.files import atomic_output, describe, file_problem, is_directory_name
    from formations.validation import check_ball_position
    from formations.plotting import save_picture
    from soccer_sim.config import STANDARD_FIELD

    item = _read(args.file)
    if isinstance(item, int):
        return item
    if isinstance(item, Formation):
        formation = item
    else:
        try:
            formation = item.formation(args.situation)
        except ValueError as error:
            return _fail(f"{args.file}: {error}")
    ball = (float(args.ball[0]), float(args.ball[1]))
    if not all(math.isfinite(v) for v in ball):
        return _fail(f"--ball must be two finite numbers (metres), got {ball[0]:g} {ball[1]:g}")
    try:
        check_ball_position(ball, "--ball", STANDARD_FIELD)
    except FormationError as error:
        return _fail(str(error))
    label = (formation.name if isinstance(item, Formation) else item.name) or Path(args.file).stem
    given = file_problem(args.out) if not is_directory_name(args.out) else None
    if given and not given.startswith("directory"):    # an empty name, a device, a FIFO: refused as given
        return _fail(f"--out {args.out!r}: {given}")
    out = _picture_path(args.out, label, args.situation, isinstance(item, Formation))
    problem = file_problem(out, inputs=[args.file])
    if problem:
        return _fail(f"--out {out}: {problem}")
    try:
        with atomic_output(out) as temporary:
            positions = save_picture(formation, ball, temporary, field=STANDARD_FIELD)
    except OSError as error:                 # a write that started and failed (a full disk): exit 1
        return _fail(f"--out: cannot write {describe(error)}; nothing was written", FAILED)
    except ValueError as error:              # a format matplotlib does not know
        return _fail(f"{out}: {error}")
    rows = [(role.number, role.name, float(x), float(y)) for role, (x, y) in zip(formation.roles, positions)]
    if args.json:
        print(json.dumps({"file": args.file, "situation": None if isinstance(item, Formation) else args.situation,
                          "ball": list(ball), "picture": str(out),
                          "positions": [{"number": n, "role": name, "x": x, "y": y} for n, name, x, y in rows]},
                         indent=2))
        return 0
    print(f"wrote {out}")
    table = Table(f"positions for the ball at ({ball[0]:g}, {ball[1]:g})", ["number", "role", "x (m)", "y (m)"],
                  labels=2)
    table.rows = [[str(n), name, f"{x:.2f}", f"{y:.2f}"] for n, name, x, y in rows]
    table.print()
    return 0


def run_import(args: argparse.Namespace) -> int:
    from experiments.results.files import file_problem
    from formations import FormationError
    from formations.files import load_helios
    from soccer_sim.config import STANDARD_FIELD

    if os.path.isdir(args.file):
        return _import_directory(args)
    if args.map or args.name is not None:
        return _fail("--map and --name apply to a directory import only")
    problem = file_problem(args.out, inputs=[args.file])
    if problem:
        return _fail(f"{args.out}: {problem}")
    try:
        formation = load_helios(args.file, field=STANDARD_FIELD)
    except FormationError as error:
        return _fail(str(error))
    except OSError as error:
        return _fail(_os_message(args.file, error))
    status = _save(formation, args.out)
    if status:
        return status
    print(f"wrote {args.out}: {len(formation.roles)} roles, {formation.n_samples} samples")
    return 0


def _import_directory(args: argparse.Namespace) -> int:
    from experiments.results.files import file_problem, is_directory_name
    from formations import FormationError
    from formations.formation_set import Situation
    from formations.helios_dir import import_helios_directory
    from soccer_sim.config import STANDARD_FIELD

    mapping = {}
    for entry in args.map:
        key, sep, value = entry.partition("=")
        if not sep or not key or not value:
            return _fail(f"--map takes FILE=SITUATION (e.g. before-kick-off=our_set_play), got {entry!r}")
        mapping[key] = value
    problem = file_problem(args.out, inputs=[args.file]) if not is_directory_name(args.out) else None
    if problem:
        return _fail(f"{args.out}: {problem}")
    try:
        result = import_helios_directory(args.file, field=STANDARD_FIELD, name=args.name, mapping=mapping)
    except FormationError as error:
        return _fail(str(error))
    except OSError as error:
        return _fail(_os_message(args.file, error))
    out = Path(args.out)
    if is_directory_name(args.out):
        out = out / f"{result.formation_set.name}.json"
        problem = file_problem(out, inputs=[args.file])
        if problem:
            return _fail(f"{out}: {problem}")
    status = _save(result.formation_set, out)
    if status:
        return status
    print(f"wrote {out}: formation set {result.formation_set.name!r}")
    for situation in Situation:
        if situation not in result.placed:
            continue
        path = result.placed[situation]
        formation = result.formation_set.formation(situation)
        print(f"  {situation.value:<15} <- {path.name} ({formation.n_samples} samples)")
    missing = [s.value for s in Situation if s not in result.placed]
    if missing:
        print(f"  {', '.join(missing)}: no file; the normal formation is used")
    for note in result.notes:
        print(f"  note: {note}")
    if result.left_out:
        count = len(result.left_out)
        print(f"not placed ({count} file{'s' if count > 1 else ''}):")
        for path, reason in result.left_out.items():
            print(f"  {path.name}: {reason}")
    return 0


def _save(item, out: str | Path) -> int:
    """Write a formation or set to ``out`` whole or not at all; 0, or the exit status after
    saying why it could not be written (1: the write started and failed, e.g. a full disk)."""
    from experiments.results.files import atomic_output, describe
    from formations.files import save

    try:
        with atomic_output(out) as temporary:
            save(item, temporary)
    except OSError as error:
        return _fail(f"cannot write {describe(error)}; nothing was written", FAILED)
    return 0


def _picture_path(out: str, name: str, situation: str, single: bool) -> Path:
    """Where ``show --out`` writes: into an existing directory as NAME[-SITUATION].png, and
    with ``.png`` added to a name without extension (what matplotlib would write anyway)."""
    from experiments.results.files import is_directory_name

    path = Path(out)
    if is_directory_name(out):
        stem = name if single else f"{name}-{situation}"
        return path / f"{stem}.png"
    return path if path.suffix else path.with_name(path.name + ".png")


def _read(name: str):
    """The formation or set in FILE (or the built-in set of that name if no
    such file exists), or the exit status (2: bad input) after printing why it
    cannot be read: a malformed formation or an unreadable file."""
    from formations import FormationError, builtin_names, load_builtin, read_any
    from soccer_sim.config import STANDARD_FIELD

    try:
        if not os.path.exists(name) and name in builtin_names():
            return load_builtin(name)
        return read_any(name, field=STANDARD_FIELD)
    except FormationError as error:
        return _fail(str(error), BAD_INPUT)
    except OSError as error:
        return _fail(_os_message(name, error), BAD_INPUT)


def _os_message(path: str, error: OSError) -> str:
    return f"{path}: {error.strerror or error}"
