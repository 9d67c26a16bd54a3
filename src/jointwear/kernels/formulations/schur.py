"""Multipliers from the Schur complement of the diagonal mass matrix, in one sparse solve.

With M diagonal, [[M, Phi_q^T], [Phi_q, 0]] [q''; lam] = [g; c] reduces to
(Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - c, an envelope of a few entries per row for
mechanisms numbered as ``mechanism.pattern`` numbers them: its factorisation and solve cost
linear time in the number of rows. The Baumgarte formulation solves it with
c = gamma - 2 alpha Phi' - beta^2 Phi, the augmented Lagrangian tries it with c = gamma.
The complement loses rank with Phi_q (dead centres, redundant constraints).
"""

from numba import njit

from ..jacobian import ENTRIES
from ..linalg import envelope_factor, envelope_solve


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def schur_factor(wk, mech):
    """Phi_q M^-1 Phi_q^T of wk.cq into wk.schur, and its factor; False if singular."""
    inv_mass = mech.inv_mass
    cq = wk.cq
    schur = wk.schur
    schur[:] = 0.0
    pairs = mech.row_pairs
    for p in range(pairs.shape[0]):
        r1, e1, r2, e2, col = pairs[p, 1], pairs[p, 2], pairs[p, 3], pairs[p, 4], pairs[p, 5]
        schur[pairs[p, 0]] += cq[r1, e1] * inv_mass[col] * cq[r2, e2]
    return envelope_factor(mech.row_first, mech.row_ptr, schur, False)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def schur_solve(wk, mech, x):
    """Solve (Phi_q M^-1 Phi_q^T) x = b in place (x holds b on entry), with wk.schur factored.

    x is in row order; wk.x_rows is overwritten.
    """
    order = mech.row_order
    for r in range(x.shape[0]):
        wk.x_rows[order[r]] = x[r]
    envelope_solve(mech.row_first, mech.row_ptr, wk.schur, wk.x_rows)
    for r in range(x.shape[0]):
        x[r] = wk.x_rows[order[r]]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def schur_multipliers(wk, mech, qd, alpha, beta):
    """Lam into wk.lam for c = gamma - 2 alpha Phi' - beta^2 Phi [1/s]; False if singular.

    Reads wk.g, wk.phi, wk.cq, wk.gamma and wk.phi_t (Phi' = Phi_q q' + Phi_t); leaves the
    complement's factor in wk.schur.
    """
    inv_mass = mech.inv_mass
    row_coord = mech.row_coord
    cq = wk.cq
    g = wk.g
    a2 = 2.0 * alpha
    b2 = beta * beta
    if not schur_factor(wk, mech):
        return False
    for r in range(wk.phi.shape[0]):
        b = b2 * wk.phi[r] - wk.gamma[r] + a2 * wk.phi_t[r]
        for e in range(ENTRIES):
            col = row_coord[r, e]
            if col >= 0:
                b += cq[r, e] * (inv_mass[col] * g[col] + a2 * qd[col])
        wk.lam[r] = b
    schur_solve(wk, mech, wk.lam)
    return True
