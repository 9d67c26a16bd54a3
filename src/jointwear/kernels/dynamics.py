"""The right-hand side: paper Eq. (7) with Baumgarte stabilisation, solved for q'' and lambda.

| symbol | meaning | unit |
|---|---|---|
| y | state (q, q') | m, rad, m/s, rad/s |
| M | diagonal mass matrix (m, m, J per body) | kg, kg m^2 |
| lam | Lagrange multipliers lambda (paper Eq. 5: g_c = -Phi_q^T lambda) | N, N m |
| alpha, beta | Baumgarte parameters | 1/s |

[[M, Phi_q^T], [Phi_q, 0]] [q''; lam] = [g; gamma - 2 alpha Phi' - beta^2 Phi] is solved by
its Schur complement, M being diagonal: (Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - gamma_s,
then q'' = M^-1 (g - Phi_q^T lam). Baumgarte (1972), Nikravesh (1988) sec. 13. The contact
elements' forces are part of g (``kernels.elements``).
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from . import elements
from .constraints import evaluate_constraints
from .forces import applied_forces
from .linalg import cholesky_solve


class DynamicsScratch(NamedTuple):
    """Arrays of one right-hand-side evaluation (m constraint rows, n coordinates)."""

    g: np.ndarray  # (n,) generalised applied forces
    phi: np.ndarray  # (m,)
    cq: np.ndarray  # (m, n)
    gamma: np.ndarray  # (m,)
    phi_t: np.ndarray  # (m,)
    b: np.ndarray  # (m,) right side of the Schur system
    schur: np.ndarray  # (m, m)
    lam: np.ndarray  # (m,) Lagrange multipliers


class Problem(NamedTuple):
    """What the right-hand side reads: the mechanism, its contact elements, and scratch."""

    mech: NamedTuple  # system.Mechanism
    elements: elements.Elements
    state: elements.ElementState  # updated by the loop between steps
    scratch: elements.ElementScratch
    dyn: DynamicsScratch


def make_dynamics_scratch(n: int, m: int) -> DynamicsScratch:
    """Allocate the scratch of n coordinates and m constraint rows (Python)."""
    return DynamicsScratch(
        g=np.zeros(n),
        phi=np.zeros(m),
        cq=np.zeros((m, n)),
        gamma=np.zeros(m),
        phi_t=np.zeros(m),
        b=np.zeros(m),
        schur=np.zeros((m, m)),
        lam=np.zeros(m),
    )


@njit(cache=True, no_cpython_wrapper=True)
def rhs(t, y, problem, ydot):
    """Write y' = (q', q'') into ydot; lambda is left in problem.dyn.lam. False if singular."""
    mech = problem.mech
    wk = problem.dyn
    n = mech.inv_mass.shape[0]
    m = wk.phi.shape[0]
    q = y[:n]
    qd = y[n:]
    g = wk.g
    applied_forces(t, q, qd, mech, g)
    elements.add_forces(problem.elements, problem.state, problem.scratch, q, qd, g)
    evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    cq = wk.cq
    a2 = 2.0 * mech.baumgarte_alpha
    b2 = mech.baumgarte_beta * mech.baumgarte_beta
    for r in range(m):
        phi_dot = wk.phi_t[r]
        rhs_r = 0.0
        for c in range(n):
            phi_dot += cq[r, c] * qd[c]
            rhs_r += cq[r, c] * mech.inv_mass[c] * g[c]
        wk.b[r] = rhs_r - (wk.gamma[r] - a2 * phi_dot - b2 * wk.phi[r])
        for s in range(r + 1):
            acc = 0.0
            for c in range(n):
                acc += cq[r, c] * mech.inv_mass[c] * cq[s, c]
            wk.schur[r, s] = acc
            wk.schur[s, r] = acc
    if not cholesky_solve(wk.schur, wk.b, wk.lam):
        return False
    for c in range(n):
        force = g[c]
        for r in range(m):
            force -= cq[r, c] * wk.lam[r]
        ydot[c] = qd[c]
        ydot[n + c] = mech.inv_mass[c] * force
    return True


@njit(cache=True, no_cpython_wrapper=True)
def constraint_norm(dyn):
    """2-norm of Phi from the last evaluation [m, rad]."""
    total = 0.0
    for r in range(dyn.phi.shape[0]):
        total += dyn.phi[r] * dyn.phi[r]
    return math.sqrt(total)
