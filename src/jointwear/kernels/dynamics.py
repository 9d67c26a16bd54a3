"""The right-hand side: paper Eq. (7) with Baumgarte stabilisation, solved for q'' and lambda.

| symbol | meaning | unit |
|---|---|---|
| y | state (q, q') | m, rad, m/s, rad/s |
| M | diagonal mass matrix (m, m, J per body) | kg, kg m^2 |
| lam | Lagrange multipliers lambda (paper Eq. 5: g_c = -Phi_q^T lambda) | N, N m |
| alpha, beta | Baumgarte parameters | 1/s |

[[M, Phi_q^T], [Phi_q, 0]] [q''; lam] = [g; gamma - 2 alpha Phi' - beta^2 Phi] is solved by
its Schur complement, M being diagonal: (Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - gamma_s,
then q'' = M^-1 (g - Phi_q^T lam). Baumgarte (1972), Nikravesh (1988) sec. 13. The
clearance joints' contact forces are part of g (``kernels.joint_contact``).
"""

import math

from numba import njit

from .constraints import evaluate_constraints
from .forces import applied_forces
from .joint_contact import contact_forces
from .linalg import cholesky_solve


@njit(cache=True)
def rhs(t, y, sys, wk, ydot):
    """Write y' = (q', q'') into ydot; lam is left in wk.lam. Returns False if singular."""
    n = sys.inv_mass.shape[0]
    m = wk.phi.shape[0]
    q = y[:n]
    qd = y[n:]
    g = wk.g
    applied_forces(t, q, qd, sys, g)
    contact_forces(q, qd, sys, wk, g)
    evaluate_constraints(t, q, qd, sys, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    cq = wk.cq
    a2 = 2.0 * sys.baumgarte_alpha
    b2 = sys.baumgarte_beta * sys.baumgarte_beta
    for r in range(m):
        phi_dot = wk.phi_t[r]
        rhs_r = 0.0
        for c in range(n):
            phi_dot += cq[r, c] * qd[c]
            rhs_r += cq[r, c] * sys.inv_mass[c] * g[c]
        wk.b[r] = rhs_r - (wk.gamma[r] - a2 * phi_dot - b2 * wk.phi[r])
        for s in range(r + 1):
            acc = 0.0
            for c in range(n):
                acc += cq[r, c] * sys.inv_mass[c] * cq[s, c]
            wk.schur[r, s] = acc
            wk.schur[s, r] = acc
    if not cholesky_solve(wk.schur, wk.b, wk.lam):
        return False
    for c in range(n):
        force = g[c]
        for r in range(m):
            force -= cq[r, c] * wk.lam[r]
        ydot[c] = qd[c]
        ydot[n + c] = sys.inv_mass[c] * force
    return True


@njit(cache=True)
def constraint_norm(wk):
    """2-norm of Phi from the last evaluation [m, rad]."""
    total = 0.0
    for r in range(wk.phi.shape[0]):
        total += wk.phi[r] * wk.phi[r]
    return math.sqrt(total)
