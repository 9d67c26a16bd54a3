"""Minimum-norm least-squares solutions of Phi_q x = b: the set-up's Newton steps and velocities.

Small Jacobians (``Jacobian.small``) go to LAPACK (``numpy.linalg.lstsq``). Larger ones are
solved in x = Phi_q^T y, with y from the normal equations of the second kind,
(Phi_q Phi_q^T + delta I) y = b, factorised sparse (SuperLU, through scipy), then corrected
with the residual until the corrections stop shrinking: iterated regularisation (Riley
1956), whose every x lies in the row space of Phi_q and whose limit is the minimum-norm
least-squares solution, as lstsq's. A correction shrinks the error along a singular value s
of Phi_q by delta / (s^2 + delta), delta a 1e-12 share of the largest diagonal entry: the
2,000-link chain (s^2 down to 3e-7 of it) settles in three corrections, one of 20,000 links
in five. The shift keeps the factorisation definite where rows depend on each other
(redundant constraints, a singular pose), and there it costs accuracy where they contradict
each other: their share of b, amplified by 1/delta in rounding, moves x by up to 1e-3 of its
size (the residual by 1e-7 of its own); where b is consistent, x agrees with lstsq to 1e-13.
What this cannot resolve is a pose within s^2 < delta of a singular one (s below 1e-6 of the
largest, where lstsq resolves 1e-13): there the corrections stop before the minimum-norm
answer. scipy has no sparse rank-revealing QR, which would give the same without them.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .background import off_main_thread
from .jacobian import Jacobian

REGULARISATION = 1e-12  # delta, of the largest diagonal entry of Phi_q Phi_q^T
CORRECTIONS = 50  # at most, after the first solution
SETTLED = 1e-15  # a correction this share of the solution's size ends the iteration


def least_norm(jacobian: Jacobian, b: NDArray[np.float64]) -> NDArray[np.float64]:
    """The minimum-norm x among those minimising |Phi_q x - b| (2-norms)."""
    if jacobian.small:
        return np.linalg.lstsq(jacobian.dense(), b, rcond=None)[0]
    return sparse_least_norm(jacobian, b)


def sparse_least_norm(jacobian: Jacobian, b: NDArray[np.float64]) -> NDArray[np.float64]:
    """``least_norm`` by sparse factorisation and iterated regularisation, at any size."""
    from scipy.sparse import identity
    from scipy.sparse.linalg import splu

    x = np.zeros(jacobian.columns)
    if jacobian.rows == 0:
        return x
    if not (np.all(np.isfinite(jacobian.entries)) and np.all(np.isfinite(b))):
        return np.full(jacobian.columns, np.nan)
    cq = jacobian.csr()
    gram = (cq @ cq.T).tocsc()
    shift = REGULARISATION * max(float(gram.diagonal().max()), np.finfo(float).tiny)
    shifted = gram + shift * identity(jacobian.rows, format="csc")
    factor = off_main_thread(  # a Ctrl-C is answered during a long one
        lambda: splu(
            shifted,
            permc_spec="MMD_AT_PLUS_A",  # a symmetric ordering, diagonal pivots: definite
            diag_pivot_thresh=0.0,
            options={"SymmetricMode": True},
        )
    )
    residual, last = b, np.inf
    for _ in range(1 + CORRECTIONS):
        step = cq.T @ factor.solve(residual)
        x += step
        size = float(np.linalg.norm(step))
        if not size > SETTLED * np.linalg.norm(x) or size >= last:  # or rounding reached
            break
        residual, last = b - cq @ x, size
    return x
