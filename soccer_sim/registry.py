"""Finding teams by name.

A team is named either by a registered name (a Python entry point in the group
``soccer_sim.teams``, which any installed package can declare) or by a path
``package.module:Attribute`` (the attribute may be dotted). The attribute may be a Team
instance, a class, or a factory called without arguments (or with the team options a caller
passes to :func:`resolve_team`). The two built-in teams
(``idle``, ``chaser``) resolve even from a plain checkout where the package's entry points
are not installed.
"""

from __future__ import annotations

import difflib
import functools
import importlib
from importlib import metadata
from collections.abc import Iterable, Mapping
from typing import Any

from soccer_sim.errors import SoccerSimError
from soccer_sim.team import Team

ENTRY_POINT_GROUP = "soccer_sim.teams"

BUILTIN_TEAMS: dict[str, str] = {
    "idle": "soccer_sim.trivial_teams:IdleTeam",
    "chaser": "soccer_sim.trivial_teams:ChaserTeam",
}
"""Teams shipped in soccer_sim itself (also declared as entry points in pyproject.toml)."""


class TeamNotFoundError(SoccerSimError, LookupError):
    """A team name or path could not be resolved; the message says why (for an unknown name: the
    closest registered names, see :func:`unknown_team_message`)."""


def available_teams(refresh: bool = False) -> dict[str, str]:
    """Registered team names -> ``module:attribute`` targets (entry points override built-ins).
    The installed packages' entry points are read once per process (reading them scans every
    installed distribution, some 10 ms); ``refresh`` reads them again."""
    if refresh:
        _registered.cache_clear()
    return dict(_registered())


@functools.lru_cache(maxsize=1)
def _registered() -> tuple[tuple[str, str], ...]:
    """The registered names and targets, sorted by name (made once, see :func:`available_teams`)."""
    teams = dict(BUILTIN_TEAMS)
    for entry_point in metadata.entry_points(group=ENTRY_POINT_GROUP):
        teams[entry_point.name] = entry_point.value
    return tuple(sorted(teams.items()))


LISTED_IN_FULL = 8
"""An unknown-team message lists every registered name when there are at most this many;
otherwise only the names closest to the one given, and where to see them all."""


def unknown_team_message(name: str, known: Iterable[str]) -> str:
    """One line saying that ``name`` is not one of the registered teams ``known``: all of them
    when few, else the closest ones (by spelling) and ``soccer-sim teams``, which lists them,
    so the line stays short however many teams are installed."""
    known = sorted(known)
    if len(known) <= LISTED_IN_FULL:
        names = f"registered teams: {', '.join(known) or '(none)'}"
    else:
        closest = difflib.get_close_matches(name, known, n=3, cutoff=0.6)
        names = f"did you mean {' or '.join(closest)}? " if closest else ""
        names += f"`soccer-sim teams` lists the {len(known)} registered teams"
    return f"unknown team {name!r}; {names}; or give a path 'package.module:Attribute'"


def _load_path(path: str, name: str | None = None) -> Any:
    """The object ``package.module:Attribute`` names. Whatever goes wrong on the way (no such
    module, a syntax error in it, an exception or ``sys.exit`` while it is imported, no such
    attribute) is a one-line :class:`TeamNotFoundError` naming the team, the module and the
    cause, so every caller (play, tournaments, the environment) reports it the same way."""
    module_name, _, attribute = path.partition(":")
    label = f"team path {path!r}" if name is None or name == path else f"team {name!r} ({path})"
    if not module_name or not attribute:
        raise TeamNotFoundError(f"{label} must look like 'package.module:Attribute'")
    try:
        target: Any = importlib.import_module(module_name)
    except ImportError as exc:
        raise TeamNotFoundError(f"{label}: cannot import module {module_name!r} ({_one_line(exc)})") from exc
    except SyntaxError as exc:
        where = f"{exc.filename}:{exc.lineno}" if exc.filename else f"line {exc.lineno}"
        raise TeamNotFoundError(f"{label}: module {module_name!r} has a syntax error at {where}: {exc.msg}") from exc
    except SystemExit as exc:
        raise TeamNotFoundError(f"{label}: importing module {module_name!r} called sys.exit({exc.code!r})") from exc
    except Exception as exc:
        raise TeamNotFoundError(f"{label}: importing module {module_name!r} raised {type(exc).__name__}: "
                                f"{_one_line(exc)}{_origin(exc)}") from exc
    for part in attribute.split("."):
        try:
            target = getattr(target, part)
        except AttributeError as exc:
            raise TeamNotFoundError(f"{label}: {module_name!r} has no attribute {attribute!r}") from exc
        except Exception as exc:
            raise TeamNotFoundError(f"{label}: reading {attribute!r} from {module_name!r} raised "
                                    f"{type(exc).__name__}: {_one_line(exc)}") from exc
    return target


def _one_line(exc: BaseException) -> str:
    """An exception's message on one line (error messages of the commands are one line)."""
    return " ".join(str(exc).split())


def _origin(exc: BaseException) -> str:
    """`` (at FILE:LINE)``: where the exception was raised, or nothing if unknown."""
    frame = exc.__traceback__
    if frame is None:
        return ""
    while frame.tb_next is not None:
        frame = frame.tb_next
    return f" (at {frame.tb_frame.f_code.co_filename}:{frame.tb_lineno})"


def _instantiate(target: Any, name: str, options: Mapping[str, Any] | None = None) -> Team:
    """The team ``target`` (a Team, a class or a factory) names: the Team itself, or what
    calling it gives, with ``options`` as keyword arguments (None or empty: no arguments)."""
    how = "without arguments" if not options else "with " + ", ".join(f"{k}={v!r}" for k, v in options.items())
    if isinstance(target, Team) and not isinstance(target, type):
        if options:
            raise TeamNotFoundError(f"team {name!r} is a team object, not a class or factory: it takes no options "
                                    f"({', '.join(options)})")
        return target
    if callable(target):
        try:
            team = target(**(options or {}))
        except SystemExit as exc:
            raise TeamNotFoundError(f"team {name!r}: calling {target!r} {how} called "
                                    f"sys.exit({exc.code!r})") from exc
        except Exception as exc:
            raise TeamNotFoundError(f"team {name!r}: calling {target!r} {how} failed: "
                                    f"{type(exc).__name__}: {_one_line(exc)}") from exc
        if isinstance(team, Team):
            return team
        raise TeamNotFoundError(f"team {name!r}: calling {target!r} gave {type(team).__name__}, "
                                "which lacks reset(side_info, config, rng) and act(view)")
    raise TeamNotFoundError(f"team {name!r}: {target!r} is neither a Team nor a class/factory making one")


def resolve_team(spec: Team | str | type, options: Mapping[str, Any] | None = None) -> tuple[Team, str]:
    """Return (team instance, display name) for a Team object, a class, a registered name or a
    ``package.module:Attribute`` path. Unknown names raise :class:`TeamNotFoundError` naming
    the closest registered ones (:func:`unknown_team_message`). ``options``: keyword arguments
    for the class or factory (a team option such as a switch of a study; a
    TeamNotFoundError, naming them, when it does not take them or ``spec`` is a Team object)."""
    if isinstance(spec, str):
        if ":" in spec:
            return _instantiate(_load_path(spec), spec, options), spec
        teams = available_teams()
        if spec not in teams:  # (perhaps installed since the names were read)
            teams = available_teams(refresh=True)
        if spec not in teams:
            raise TeamNotFoundError(unknown_team_message(spec, teams))
        return _instantiate(_load_path(teams[spec], spec), spec, options), spec
    if isinstance(spec, type):
        return _instantiate(spec, spec.__name__, options), spec.__name__
    if isinstance(spec, Team):
        name = str(getattr(spec, "name", type(spec).__name__))
        return _instantiate(spec, name, options), name
    raise TeamNotFoundError(f"cannot use {spec!r} as a team: expected a team name, a path "
                            "'package.module:Attribute', a Team class or a Team object")
