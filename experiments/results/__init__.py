"""Stored results of runs: one SQLite file per run, one row per match, and its exports."""

from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.results.store import ResultsError, ResultStore

__all__ = ["FORFEIT_NONE", "MatchRecord", "ResultStore", "ResultsError"]
