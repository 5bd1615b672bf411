"""Extreme numbers for the fuzz tests (not a test module): the values every numeric option and
configuration field must refuse in one line, or take and still finish within the bound."""

from __future__ import annotations

from hypothesis import strategies as st

EXTREMES = ["-1", "0", "-0", "1e308", "-1e308", "1e-308", "99999999999", "-99999999999", "9" * 30, "-" + "9" * 30,
            "nan", "inf", "-inf", "2147483648", "18446744073709551616", "1e-6"]
"""Huge, tiny, negative and non-finite numbers as a command line spells them."""


def extreme_arguments():
    """:data:`EXTREMES` and :func:`extreme_numbers` as command-line arguments."""
    return st.one_of(st.sampled_from(EXTREMES), extreme_numbers().map(str))


def extreme_numbers():
    """Numbers no option should take without a word: 1e9 or more in magnitude, negative, zero,
    tiny or not finite (moderate values are valid and may simply take long)."""
    huge = st.integers(10**9, 10**40)
    floats = st.floats(allow_nan=True, allow_infinity=True).filter(lambda x: not 1e-6 < abs(x) < 1e9 or x < 0)
    return st.one_of(huge, huge.map(lambda n: -n), st.integers(-(10**6), 0), floats)
