"""The manifest's argument types as text (:func:`experiments.warmup.signature_text`) read back
as the very same numba types (:func:`~experiments.warmup.signature_of`), named tuples included:
their numba ``repr`` is no expression, and a type read back differently never matches the
on-disk cache's index."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import typeof
from numba.core import types
from numba.experimental import structref

from experiments.warmup import Kernel, signature_of, signature_text


class Mixed(NamedTuple):
    grid: np.ndarray
    count: int


class Same(NamedTuple):
    first: np.ndarray
    second: np.ndarray


@structref.register
class HolderType(types.StructRef):
    """A compiled structure whose field is a named tuple."""


def _read_back(signature: tuple) -> tuple:
    return signature_of(Kernel("formations.interpolation_kernels", "value_kernel", signature_text(signature)))


def test_named_tuples_read_back_as_the_same_types() -> None:
    mixed = typeof(Mixed(np.zeros(3), 4))
    same = typeof(Same(np.zeros(2), np.ones(2)))
    assert isinstance(mixed, types.NamedTuple) and isinstance(same, types.NamedUniTuple)
    signature = (types.float64, mixed, same, types.Tuple((mixed, types.int64)), types.UniTuple(same, 2))
    assert signature_text(signature).count(f"named('{__name__}.Mixed')") == 2
    assert _read_back(signature) == signature


def test_a_structure_holding_a_named_tuple_reads_back_with_its_name() -> None:
    holder = HolderType([("tables", typeof(Mixed(np.zeros(3), 4))), ("n", types.int64)])
    back = _read_back((holder,))
    assert back == (holder,) and back[0].name == holder.name  # a structure's type is keyed by its name


def test_plain_types_are_written_as_numba_writes_them() -> None:
    signature = (types.float64, typeof(np.zeros((2, 2))), types.UniTuple(types.float64, 3))
    assert signature_text(signature) == repr(signature)
    assert signature_text((types.int64,)) == "(int64,)"
