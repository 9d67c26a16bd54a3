"""Small dense symmetric positive-definite solves, allocation-free.

For the few-by-few systems of planar mechanisms a hand-written Cholesky factorisation in
place beats a LAPACK call, whose overhead dominates at these sizes, and it allocates nothing.
"""

import math

from numba import njit


@njit(cache=True)
def cholesky_solve(a, b, x):
    """Solve a x = b for symmetric positive-definite a (m x m), overwriting a.

    Returns False if a pivot is not positive relative to the diagonal (singular or redundant
    constraints), True otherwise.
    """
    m = b.shape[0]
    scale = 0.0
    for i in range(m):
        scale = max(scale, abs(a[i, i]))
    tiny = 1e-13 * scale
    for j in range(m):
        d = a[j, j]
        for k in range(j):
            d -= a[j, k] * a[j, k]
        if not d > tiny:
            return False
        d = math.sqrt(d)
        a[j, j] = d
        for i in range(j + 1, m):
            s = a[i, j]
            for k in range(j):
                s -= a[i, k] * a[j, k]
            a[i, j] = s / d
    for i in range(m):  # forward: L z = b
        s = b[i]
        for k in range(i):
            s -= a[i, k] * x[k]
        x[i] = s / a[i, i]
    for i in range(m - 1, -1, -1):  # backward: L^T x = z
        s = x[i]
        for k in range(i + 1, m):
            s -= a[k, i] * x[k]
        x[i] = s / a[i, i]
    return True
