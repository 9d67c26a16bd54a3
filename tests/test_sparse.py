"""The sparse linear algebra against dense numpy: envelope Cholesky and the index tables."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear.kernels.linalg import envelope_factor, envelope_solve
from jointwear.mechanism.pattern import ENTRIES, build_pattern


def _envelope(dense: np.ndarray, first: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row starts and the flat envelope of a symmetric matrix."""
    ptr = np.concatenate([[0], np.cumsum(np.arange(len(first)) - first + 1)]).astype(np.int64)
    flat = np.concatenate([dense[i, first[i] : i + 1] for i in range(len(first))])
    return ptr, flat


@settings(max_examples=60, deadline=None)
@given(size=st.integers(1, 12), seed=st.integers(0, 2**31 - 1))
def test_envelope_cholesky_solves_as_numpy(size, seed):
    # A random band-limited SPD matrix (each row's first column random): the solution of
    # L L^T x = b against numpy's dense solve, to rounding of a matrix of condition <= 1e3.
    rng = np.random.default_rng(seed)
    first = np.array([rng.integers(0, i + 1) for i in range(size)], dtype=np.int64)
    dense = np.zeros((size, size))
    for i in range(size):
        dense[i, first[i] : i] = rng.uniform(-1.0, 1.0, i - first[i])
    dense = dense + dense.T  # then diagonally dominant: positive definite
    dense += np.diag(np.abs(dense).sum(axis=1) + rng.uniform(0.5, 2.0, size))
    b = rng.uniform(-1.0, 1.0, size)
    for per_row in (False, True):
        ptr, flat = _envelope(dense, first)
        assert envelope_factor(first, ptr, flat, per_row)
        x = b.copy()
        envelope_solve(first, ptr, flat, x)
        np.testing.assert_allclose(x, np.linalg.solve(dense, b), rtol=1e-10, atol=1e-12)


def test_envelope_cholesky_reports_a_singular_matrix():
    dense = np.array([[1.0, 1.0], [1.0, 1.0]])
    first = np.zeros(2, dtype=np.int64)
    ptr, flat = _envelope(dense, first)
    assert not envelope_factor(first, ptr, flat, False)


@pytest.mark.parametrize("seed", range(5))
def test_pattern_covers_both_matrices(seed):
    # Random joints between 8 bodies and the ground, bodies numbered at random: every
    # non-zero of Phi_q^T Phi_q and of Phi_q Phi_q^T lies inside its envelope, and the index
    # tables address exactly those entries.
    rng = np.random.default_rng(seed)
    bodies = 8
    rows = np.array(
        [rng.choice(np.arange(-1, bodies), size=2, replace=False) for _ in range(14)],
        dtype=np.int64,
    )
    pattern = build_pattern(rows, bodies)
    n = 3 * bodies
    jacobian = np.zeros((len(rows), n))
    for r in range(len(rows)):
        for e in range(ENTRIES):
            if pattern.row_coord[r, e] >= 0:
                jacobian[r, pattern.row_coord[r, e]] = rng.uniform(0.5, 1.5)
    for order, first, product in (
        (pattern.coord_order, pattern.coord_first, jacobian.T @ jacobian),
        (pattern.row_order, pattern.row_first, jacobian @ jacobian.T),
    ):
        permuted = np.zeros_like(product)
        permuted[np.ix_(order, order)] = product
        for i in range(len(first)):
            assert not permuted[i, : first[i]].any(), (i, first[i])
    # The Schur terms: summed through the tables, Phi_q Phi_q^T in envelope storage.
    ptr = pattern.row_ptr
    schur = np.zeros(ptr[-1])
    coord = pattern.row_coord
    for at, r1, e1, r2, e2, _ in pattern.row_pairs:
        schur[at] += jacobian[r1, coord[r1, e1]] * jacobian[r2, coord[r2, e2]]
    permuted = np.zeros((len(rows), len(rows)))
    permuted[np.ix_(pattern.row_order, pattern.row_order)] = jacobian @ jacobian.T
    _, expected = _envelope(permuted, pattern.row_first)
    np.testing.assert_allclose(schur, expected, rtol=1e-14, atol=1e-14)


GROUND = -1
OPEN_TREES = {  # bodies, joints (body pairs, two rows each), whether they close no loop
    "pendulum chain": (3, [(GROUND, 0), (0, 1), (1, 2)], True),
    "branched tree": (4, [(GROUND, 0), (0, 1), (0, 2), (2, 3)], True),
    "floating pair": (2, [(0, 1)], True),
    "four-bar": (3, [(GROUND, 0), (0, 1), (1, 2), (2, GROUND)], False),
    "four-bar with a clearance joint": (3, [(GROUND, 0), (0, 1), (2, GROUND)], True),
    "floating triangle": (3, [(0, 1), (1, 2), (2, 0)], False),
}


@pytest.mark.parametrize("case", OPEN_TREES)
def test_open_tree_finds_the_loops(case):
    # The closed loops of each graph are known by construction: a joint between bodies
    # already connected through the others (or the ground) closes one.
    bodies, joints, expected = OPEN_TREES[case]
    rows = [pair for pair in joints for _ in range(2)] + [joints[0][::-1]]  # and a driver on one
    pattern = build_pattern(np.array(rows, dtype=np.int64), bodies)
    assert pattern.open_tree is expected
