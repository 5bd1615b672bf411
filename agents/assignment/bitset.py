"""Rows of bits over a cyclic index range, packed 64 to a word (numba kernels).

ETSP ASSGMT ("Monotonic Target Assignment for Robotic Networks") keeps, per
agent, one availability bit per target and repeatedly clears whole stretches
of the target ring and searches for the next set bit around it. Packed rows
make both cost O(stretch / 64) instead of O(stretch), which keeps 1000 agents x
1000 targets fast. Each row lives in a 2-D ``uint64`` array ``bits[row, word]``;
``counts[row]`` is kept equal to the number of set bits of the row.
"""

from __future__ import annotations

import numpy as np
from numba import njit, uint64

_ONE = uint64(1)
_ALL = uint64(0xFFFFFFFFFFFFFFFF)


def full_rows(rows: int, width: int) -> tuple[np.ndarray, np.ndarray]:
    """``rows`` rows of ``width`` set bits (bits past ``width`` stay clear) and their counts."""
    words = max(1, (width + 63) // 64)
    bits = np.zeros((rows, words), dtype=np.uint64)
    if width:
        bits[:, : width // 64] = np.uint64(0xFFFFFFFFFFFFFFFF)
        if width % 64:
            bits[:, width // 64] = np.uint64((1 << (width % 64)) - 1)
    return bits, np.full(rows, width, dtype=np.int64)


@njit(cache=True, nogil=True, inline="always")
def _popcount(x: np.uint64) -> int:
    x = x - ((x >> uint64(1)) & uint64(0x5555555555555555))
    x = (x & uint64(0x3333333333333333)) + ((x >> uint64(2)) & uint64(0x3333333333333333))
    x = (x + (x >> uint64(4))) & uint64(0x0F0F0F0F0F0F0F0F)
    return int((x * uint64(0x0101010101010101)) >> uint64(56))


@njit(cache=True, nogil=True)
def test_bit(bits: np.ndarray, row: int, j: int) -> bool:
    """Whether bit ``j`` of ``row`` is set."""
    return (bits[row, j >> 6] >> uint64(j & 63)) & _ONE == _ONE


@njit(cache=True, nogil=True)
def set_bit(bits: np.ndarray, counts: np.ndarray, row: int, j: int) -> None:
    """Set bit ``j`` of ``row``."""
    mask = _ONE << uint64(j & 63)
    if bits[row, j >> 6] & mask == uint64(0):
        bits[row, j >> 6] |= mask
        counts[row] += 1


@njit(cache=True, nogil=True)
def clear_bit(bits: np.ndarray, counts: np.ndarray, row: int, j: int) -> None:
    """Clear bit ``j`` of ``row``."""
    mask = _ONE << uint64(j & 63)
    if bits[row, j >> 6] & mask != uint64(0):
        bits[row, j >> 6] &= ~mask
        counts[row] -= 1


@njit(cache=True, nogil=True)
def _clear_span(bits: np.ndarray, counts: np.ndarray, row: int, lo: int, hi: int) -> None:
    """Clear bits ``lo <= j < hi`` of ``row`` (no wrap-around)."""
    if lo >= hi:
        return
    first = lo >> 6
    last = (hi - 1) >> 6
    for w in range(first, last + 1):
        mask = _ALL
        if w == first:
            mask &= _ALL << uint64(lo & 63)
        if w == last and (hi & 63) != 0:
            mask &= _ALL >> uint64(64 - (hi & 63))
        hit = bits[row, w] & mask
        if hit != uint64(0):
            counts[row] -= _popcount(hit)
            bits[row, w] &= ~mask


@njit(cache=True, nogil=True)
def clear_cyclic(bits: np.ndarray, counts: np.ndarray, row: int, start: int, length: int, width: int) -> None:
    """Clear ``length`` bits of ``row`` from ``start`` going forward around ``0 .. width - 1``."""
    if length <= 0:
        return
    if length >= width:
        _clear_span(bits, counts, row, 0, width)
        return
    end = start + length
    if end <= width:
        _clear_span(bits, counts, row, start, end)
    else:
        _clear_span(bits, counts, row, start, width)
        _clear_span(bits, counts, row, 0, end - width)


@njit(cache=True, nogil=True)
def _lowest_bit(x: np.uint64) -> int:
    """Index of the lowest set bit of a non-zero word."""
    k = 0
    while (x >> uint64(k)) & _ONE == uint64(0):
        k += 1
    return k


@njit(cache=True, nogil=True)
def _highest_bit(x: np.uint64) -> int:
    """Index of the highest set bit of a non-zero word."""
    k = 63
    while (x >> uint64(k)) & _ONE == uint64(0):
        k -= 1
    return k


@njit(cache=True, nogil=True)
def _first_set_from(bits: np.ndarray, row: int, lo: int, width: int) -> int:
    """Smallest set bit ``j >= lo`` (``j < width``), or -1."""
    if lo >= width:
        return -1
    w = lo >> 6
    word = bits[row, w] & (_ALL << uint64(lo & 63))
    words = (width + 63) >> 6
    while True:
        if word != uint64(0):
            return (w << 6) + _lowest_bit(word)
        w += 1
        if w >= words:
            return -1
        word = bits[row, w]


@njit(cache=True, nogil=True)
def _last_set_upto(bits: np.ndarray, row: int, hi: int) -> int:
    """Largest set bit ``j <= hi``, or -1."""
    if hi < 0:
        return -1
    w = hi >> 6
    shift = 63 - (hi & 63)
    word = bits[row, w] & (_ALL >> uint64(shift))
    while True:
        if word != uint64(0):
            return (w << 6) + _highest_bit(word)
        w -= 1
        if w < 0:
            return -1
        word = bits[row, w]


@njit(cache=True, nogil=True)
def next_set_cyclic(bits: np.ndarray, row: int, start: int, width: int) -> int:
    """First set bit at or after ``start`` going forward around the ring (-1 if the row is empty)."""
    j = _first_set_from(bits, row, start, width)
    if j < 0:
        j = _first_set_from(bits, row, 0, width)
    return j


@njit(cache=True, nogil=True)
def prev_set_cyclic(bits: np.ndarray, row: int, start: int, width: int) -> int:
    """First set bit at or before ``start`` going backward around the ring (-1 if the row is empty)."""
    j = _last_set_upto(bits, row, start)
    if j < 0:
        j = _last_set_upto(bits, row, width - 1)
    return j
