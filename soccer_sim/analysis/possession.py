"""Possession: which team has the ball, counted the same way by match statistics and replays.

**Definition.** A team has possession in a cycle when, at the end of that cycle, the last
player to touch the ball (kick, body touch or catch: ``WorldState.last_touch``) is one of
its players. Cycles are counted in every play mode, so a team keeps possession while the
opponents wait to take the restart after it put the ball out; a kick-off forgets the last
toucher, so until somebody plays the ball nobody has it. A team's possession share is its
possession cycles over the cycles in which either team had possession: the two shares add
up to 1, and both are 0 while nobody has touched the ball.

The state a match starts from is not a cycle played: recorders count from the first cycle
after it (``on_cycle``), not at ``on_start``.
"""

from __future__ import annotations

from soccer_sim.state import HOME


class Possession:
    """Possession cycles of both teams so far; ``home_players``: rows below it are home's."""

    def __init__(self, home_players: int) -> None:
        self._n = home_players
        self.cycles = [0, 0]
        """Possession cycles of home and away."""

    def add(self, last_touch: int) -> None:
        """Count one cycle whose last toucher (a player row, or negative for nobody) is ``last_touch``."""
        if last_touch >= 0:
            self.cycles[0 if last_touch < self._n else 1] += 1

    def share(self, team: int = HOME) -> float:
        """``team``'s possession share so far, in [0, 1] (0 while nobody has had the ball)."""
        total = self.cycles[0] + self.cycles[1]
        return self.cycles[team] / total if total else 0.0
