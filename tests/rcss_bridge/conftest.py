"""Fixtures shared by the bridge's tests."""

from __future__ import annotations

import pytest

from rcss_bridge.params import ServerParameters
from tests.rcss_bridge.recorded import received


@pytest.fixture(scope="module")
def parameters() -> ServerParameters:
    """The server's parameters as the recorded exchange ``BRIDGE-1`` gave them."""
    texts = received("BRIDGE-1")[-1]
    return ServerParameters.from_messages(
        next(t for t in texts if t.startswith("(server_param")), next(t for t in texts if t.startswith("(player_param")),
        [t for t in texts if t.startswith("(player_type")])
