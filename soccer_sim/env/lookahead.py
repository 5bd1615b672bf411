"""Seeing a partially observed cycle before the match plays it: :class:`LookaheadObserver`.

Under partial observation a match builds its players' views at the start of each cycle
(:meth:`soccer_sim.perception.observer.Observer.observe`, inside :meth:`Match.step`) and hands
them straight to the teams. The environment's agents must see those views one call earlier:
a step returns the observations of the next cycle, and the agents' answers are the external
team's command when the match then plays it. :class:`LookaheadObserver` takes the match
observer's place: the environment calls :meth:`observe` after a step (or at the start), and
when the match asks for the same cycle's views it gets those, not a second perception. Each
cycle is perceived exactly once, in the same order relative to the channel's ``say`` as
without the environment (the state does not change between the end of a step and the start
of the next), so the match stays the pure function of its inputs it always is: the same
views, the same random draws, the same messages.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from soccer_sim.perception.observer import Observer
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import WorldState


class LookaheadObserver:
    """The match's :class:`Observer` perceiving each cycle once, on the first request
    (see the module docstring); every other attribute is the observer's."""

    def __init__(self, observer: Observer) -> None:
        self.observer = observer
        self._cycle: int | None = None
        self._views: tuple[PlayerViews, PlayerViews] | None = None

    def observe(self, state: WorldState) -> tuple[PlayerViews, PlayerViews]:
        """Both teams' views of ``state.cycle``: perceived on the first call of the cycle, the
        same views on the next calls of the same cycle."""
        if self._cycle != state.cycle or self._views is None:
            self._views = self.observer.observe(state)
            self._cycle = state.cycle
        return self._views

    def say(self, cycle: int, messages: Sequence[Sequence[str | None]], positions: np.ndarray,
            checked: bool = False) -> None:
        """The teams' messages of ``cycle`` into the channel (the observer's :meth:`~Observer.say`)."""
        self.observer.say(cycle, messages, positions, checked)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.observer, name)
