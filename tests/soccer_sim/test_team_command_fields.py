"""A team's command refuses fields it does not have, so a misspelt field is an error rather
than a silently ignored attribute."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import TeamCommand


def test_a_misspelt_command_field_is_an_error() -> None:
    command = TeamCommand(dash=np.zeros((11, 2)), kick=np.zeros((11, 2)))
    command.catch = True  # a real field
    with pytest.raises(AttributeError, match="kik"):
        command.kik = np.zeros((11, 2))
