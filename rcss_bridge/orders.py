"""One player's order for one step: what the client layer sends and the command translation
makes (:mod:`rcss_bridge.client`, :mod:`rcss_bridge.commands`)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PlayerOrder:
    """One player's commands for one step: ``commands`` as the server reads them (``(dash 80)
    (turn_neck 10)``; empty for none) and a message to ``say`` (None: nothing)."""

    commands: str = ""
    say: str | None = None
