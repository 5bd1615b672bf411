"""The default pairings of ``bench soccer``: which built-in teams play whom.

Eight pairings that between them field all nine assigner variants of the built-in team
(the same team apart from its role assigner) and each of the three reference opponents
(``counter-442``, ``press-433``, ``possession``, distinct in style) twice, so that the
figures describe the built-in play as a whole rather than one team's. ``bench soccer``
plays each pairing on both sides with the same seeds (the side a team starts on then
cancels out of the figures).
"""

from __future__ import annotations

PAIRINGS: tuple[tuple[str, str], ...] = (
    ("mmdr", "counter-442"),
    ("mmd+msd2", "press-433"),
    ("static", "possession"),
    ("greedy", "mmd+msd2"),
    ("bidding", "counter-442"),
    ("msd", "press-433"),
    ("msd2", "possession"),
    ("greedy-offense", "random"),
)
"""(team, opponent) of each default pairing."""
