"""One stored match: what the runner keeps of it, whether it was played or forfeited."""

from __future__ import annotations

import json
from dataclasses import dataclass, field

FORFEIT_NONE = -1
"""``MatchRecord.forfeit`` when no team is at fault (played normally, or a failure of the run)."""


@dataclass
class MatchRecord:
    """One match (home first): the key, the outcome, every per-team figure and the failure, if any.

    A match whose team raised, sent a malformed command or overran the time budget is
    *forfeited* by that team: ``error`` holds the message, ``traceback`` the worker's traceback,
    ``forfeit`` the side at fault (0 home, 1 away) and the goals are None.
    """

    home: str
    away: str
    seed: int
    config_hash: str
    code_version: str = ""
    home_goals: int | None = None
    away_goals: int | None = None
    cycles: int = 0
    wall_time: float = 0.0
    """Seconds spent playing the match in the worker (or until it was stopped)."""
    home_stats: dict[str, float] = field(default_factory=dict)
    """Every figure of :meth:`soccer_sim.TeamStatistics.as_dict` (the team's reported ones included)."""
    away_stats: dict[str, float] = field(default_factory=dict)
    error: str | None = None
    traceback: str | None = None
    forfeit: int = FORFEIT_NONE
    report: object = field(default=None, compare=False, repr=False)
    """What the run's ``report`` function made of the finished match in its worker (``soccer-sim
    play``'s :class:`~experiments.match_report.MatchReport`), carried back with the record and
    never stored: not one of :meth:`to_row`'s columns."""

    @property
    def key(self) -> tuple[str, str, int]:
        return (self.home, self.away, self.seed)

    @property
    def played(self) -> bool:
        """True when the match was played to its end (it has a score)."""
        return self.error is None

    def names(self) -> tuple[str, str]:
        return (self.home, self.away)

    def goals(self) -> tuple[int, int]:
        if self.home_goals is None or self.away_goals is None:
            raise ValueError(f"match {self.key} has no score: {self.error}")
        return (self.home_goals, self.away_goals)

    def stats(self, side: int) -> dict[str, float]:
        return self.home_stats if side == 0 else self.away_stats

    def to_row(self) -> dict[str, object]:
        """The SQL row (statistics as JSON text)."""
        return {"home": self.home, "away": self.away, "seed": self.seed, "config_hash": self.config_hash,
                "code_version": self.code_version, "home_goals": self.home_goals, "away_goals": self.away_goals,
                "cycles": self.cycles, "wall_time": self.wall_time,
                "home_stats": json.dumps(self.home_stats, sort_keys=True),
                "away_stats": json.dumps(self.away_stats, sort_keys=True),
                "error": self.error, "traceback": self.traceback, "forfeit": self.forfeit}

    @classmethod
    def from_row(cls, row: dict[str, object]) -> MatchRecord:
        """The record of a stored row; ValueError naming the field when a value is not what the
        runner stores (a row edited by hand or damaged: goals that are no integer, a played
        match without a score, statistics that are not a JSON object)."""
        values = dict(row)
        for side in ("home_stats", "away_stats"):
            values[side] = json.loads(values.get(side) or "{}")
            if not isinstance(values[side], dict):
                raise ValueError(f"{side} of {_key(values)} is not a JSON object")
        record = cls(**{name: values[name] for name in cls.__dataclass_fields__ if name in values})
        record._check()
        return record

    def _check(self) -> None:
        """ValueError naming the first field of this record that no run would store."""
        for name in ("home", "away", "config_hash"):
            if not isinstance(getattr(self, name), str):
                raise ValueError(f"{name} of {self.key} is {getattr(self, name)!r}, not text")
        for name in ("seed", "cycles", "forfeit"):
            if not _is_integer(getattr(self, name)):
                raise ValueError(f"{name} of {self.key} is {getattr(self, name)!r}, not an integer")
        for name in ("home_goals", "away_goals"):
            value = getattr(self, name)
            if value is None and self.played:
                raise ValueError(f"{name} of {self.key} is missing, though the match was played to its end")
            if value is not None and not (_is_integer(value) and value >= 0):
                raise ValueError(f"{name} of {self.key} is {value!r}, not a number of goals")


def _is_integer(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _key(values: dict[str, object]) -> tuple[object, object, object]:
    return (values.get("home"), values.get("away"), values.get("seed"))
