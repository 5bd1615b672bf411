"""dense_to_graph: each row's finite pairs sorted by length, ties by target index, whatever
the row's size (small rows are insertion-sorted, long ones merge-sorted)."""

import numpy as np
import pytest

from agents.assignment.graphs import _INSERTION_MAX, dense_to_graph


def _reference(lengths: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    indptr, indices, values = [0], [], []
    for row in lengths:
        for j in np.argsort(row, kind="stable"):
            if row[j] < np.inf:
                indices.append(j)
                values.append(row[j])
        indptr.append(len(indices))
    return np.array(indptr), np.array(indices, dtype=np.int64), np.array(values, dtype=np.float64)


@pytest.mark.parametrize("cols", [1, 7, 10, _INSERTION_MAX, _INSERTION_MAX + 1, 60])
def test_rows_sorted_by_length_then_target(cols: int) -> None:
    rng = np.random.default_rng(cols)
    for trial in range(20):
        rows = int(rng.integers(1, min(cols, 12) + 1))
        # Few distinct values (many ties), forbidden pairs and -inf padding.
        lengths = rng.integers(0, 4, (rows, cols)).astype(np.float64) if trial % 2 else rng.uniform(0, 5, (rows, cols))
        lengths[rng.random((rows, cols)) < 0.2] = np.inf
        lengths[rng.random((rows, cols)) < 0.05] = -np.inf
        got = dense_to_graph(lengths)
        for a, b in zip(got, _reference(lengths)):
            np.testing.assert_array_equal(a, b)


def test_example_ties_keep_target_order() -> None:
    lengths = np.array([[2.0, 1.0, np.inf, 1.0, 0.5]])
    indptr, indices, values = dense_to_graph(lengths)
    assert indptr.tolist() == [0, 4]
    assert indices.tolist() == [4, 1, 3, 0]
    assert values.tolist() == [0.5, 1.0, 1.0, 2.0]
