"""Playing many matches: specifications, a local process pool or Ray, progress, and the
run loop that stores every finished match (see :func:`experiments.runner.run.run_matches`)."""

from experiments.runner.run import DEFAULT_MATCH_TIMEOUT, RunSummary, run_matches
from experiments.runner.spec import MatchSpec, config_for, config_hash, paired_specs

__all__ = ["DEFAULT_MATCH_TIMEOUT", "MatchSpec", "RunSummary", "config_for", "config_hash", "paired_specs",
           "run_matches"]
