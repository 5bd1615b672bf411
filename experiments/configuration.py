"""The match configuration a command, study or benchmark plays with, from its cycle count.

One rule for every caller (``soccer-sim play``, the runner's specs, benchmarks, the kernel
record): a regulation match, stopped early at ``cycles``, or, for more cycles than a
regulation match, two halves of ``ceil(cycles / 2)`` so half time stays in the middle.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # annotations only: importing the simulator is left to what plays matches
    from soccer_sim import MatchConfig


def match_config(cycles: int | None, observation: str = "full") -> MatchConfig:
    """The MatchConfig for a cycle count (None: a regulation match of two halves) and an
    observation mode (``"full"`` or ``"partial"``: ``--observation``)."""
    from dataclasses import replace

    from soccer_sim import MatchConfig, RuleConfig
    from soccer_sim.perception.config import ObservationConfig

    rules = RuleConfig()
    if cycles is not None and cycles > 2 * rules.half_cycles:
        rules = replace(rules, half_cycles=(cycles + 1) // 2)
    return MatchConfig(rules=rules, max_cycles=cycles, observation=ObservationConfig(observation))
