"""The named parameter records of the core's kernels: every field set by name, nothing else,
and laid out packed (numba types an aligned record's array far more slowly on each call)."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import kernels
from soccer_sim.env.partial_kernel import OBSERVATION_PARAMS
from soccer_sim.kernels import OVERLAP_PARAMS, make_record
from soccer_sim.perception.kernels import SEE_PARAMS, see_record
from soccer_sim.perception.params import SeeParams

RECORDS = [kernels.DASH_PARAMS, kernels.DECAY_PARAMS, kernels.KICK_PARAMS, kernels.MARGIN_PARAMS, kernels.SUBSTEP_PARAMS,
           kernels.BALL_CONTACT_PARAMS, kernels.OVERLAP_PARAMS, SEE_PARAMS, OBSERVATION_PARAMS]


def test_a_record_holds_each_value_under_its_name() -> None:
    record = make_record(OVERLAP_PARAMS, contact=0.385, factor=-0.1, rounds=10)
    assert record.shape == (1,)
    assert (record[0]["contact"], record[0]["factor"], record[0]["rounds"]) == (0.385, -0.1, 10)


def test_a_record_refuses_missing_and_unknown_fields() -> None:
    with pytest.raises(TypeError, match=r"missing \['rounds'\], unknown \['loops'\]"):
        make_record(OVERLAP_PARAMS, contact=0.385, factor=-0.1, loops=10)


@pytest.mark.parametrize("dtype", RECORDS, ids=lambda d: ",".join(d.names[:2]))
def test_records_are_packed(dtype: np.dtype) -> None:
    assert not dtype.isalignedstruct
    assert dtype.itemsize == sum(dtype.fields[name][0].itemsize for name in dtype.names)


def test_the_see_record_holds_the_see_parameters_under_their_names() -> None:
    params = SeeParams(visible_angle=120.0, omnidirectional=True, exact_self=True, unum_far_length=15.0)
    record = see_record(params)[0]
    assert record["half_angle"] == 60.0
    assert record["omnidirectional"] and record["exact_self"] and record["omnidirectional"].dtype == np.bool_
    for name in set(SEE_PARAMS.names) - {"half_angle", "omnidirectional", "exact_self"}:
        assert record[name] == getattr(params, name), name
