"""The named parameter records of the core's kernels: every field set by name, nothing else,
and laid out packed (numba types an aligned record's array far more slowly on each call)."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import kernels
from soccer_sim.kernels import DECAY_PARAMS, make_record

RECORDS = [kernels.DASH_PARAMS, kernels.DECAY_PARAMS, kernels.MARGIN_PARAMS, kernels.SUBSTEP_PARAMS,
           kernels.BALL_CONTACT_PARAMS]


def test_a_record_holds_each_value_under_its_name() -> None:
    record = make_record(DECAY_PARAMS, player_decay=0.4, ball_decay=0.94, ball_noise=0.05, ball_speed_max=3.0)
    assert record.shape == (1,)
    assert (record[0]["player_decay"], record[0]["ball_decay"], record[0]["ball_noise"],
            record[0]["ball_speed_max"]) == (0.4, 0.94, 0.05, 3.0)


def test_a_record_refuses_missing_and_unknown_fields() -> None:
    with pytest.raises(TypeError, match=r"missing \['ball_speed_max'\], unknown \['speed'\]"):
        make_record(DECAY_PARAMS, player_decay=0.4, ball_decay=0.94, ball_noise=0.05, speed=3.0)


@pytest.mark.parametrize("dtype", RECORDS, ids=lambda d: ",".join(d.names[:2]))
def test_records_are_packed(dtype: np.dtype) -> None:
    assert not dtype.isalignedstruct
    assert dtype.itemsize == sum(dtype.fields[name][0].itemsize for name in dtype.names)
