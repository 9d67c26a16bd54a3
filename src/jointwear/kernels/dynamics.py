"""The right-hand side: accelerations and multipliers of the constrained mechanism.

| symbol | meaning | unit |
|---|---|---|
| y | state (q, q') | m, rad, m/s, rad/s |
| M | diagonal mass matrix (m, m, J per body) | kg, kg m^2 |
| lam | Lagrange multipliers lambda (paper Eq. 5: g_c = -Phi_q^T lambda) | N, N m |
| c | acceleration target | m/s^2, rad/s^2 |
| alpha, beta | Baumgarte parameters | 1/s |

Two formulations (``Formulation``):

- Baumgarte, the paper's Eq. (7), with c = gamma - 2 alpha Phi' - beta^2 Phi:
  [[M, Phi_q^T], [Phi_q, 0]] [q''; lam] = [g; c], solved by
  its Schur complement, M being diagonal: (Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - c, then
  q'' = M^-1 (g - Phi_q^T lam). Baumgarte (1972), Nikravesh (1988) sec. 13. It fails where
  Phi_q loses rank: dead-centre positions and redundant constraints.
- Index-1 augmented Lagrangian (Bayo, Garcia de Jalon and Serna 1988; Garcia de Jalon and
  Bayo 1994, sec. 5.3), with c = gamma:
  (M + Phi_q^T W Phi_q) q''_k+1 = g - Phi_q^T (lam_k - W c), then
  lam_k+1 = lam_k + W (Phi_q q''_k+1 - c), from lam_0 = 0, until q'' settles. The leading
  matrix is positive definite whatever the rank of Phi_q, so singular positions and
  redundant constraints pass. W is diagonal, w_r = penalty / (Phi_q,r M^-1 Phi_q,r^T): each
  row's penalty relative to its own effective mass. M q'' = g - Phi_q^T lam holds at every
  iterate. After each step ``project`` moves positions and velocities back onto the
  constraints along M-orthogonal directions (Bayo and Ledesma 1996); no Baumgarte terms are
  needed. With redundant rows the multipliers are not unique: ``least_norm_multipliers``
  gives the set of least Euclidean norm with the same forces on the bodies.

The contact elements' forces are part of g (``kernels.elements``). Matrices are sparse, in
envelope storage (``kernels.linalg``, index tables from ``pattern.py``).
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from . import elements
from .codes import Formulation
from .constraints import evaluate_constraints
from .forces import applied_forces
from .linalg import envelope_factor, envelope_solve

ENTRIES = 6  # Jacobian entries per row (pattern.ENTRIES)
MAX_ITERATIONS = 30  # augmented Lagrangian iterations per evaluation
SETTLED = 1e-10  # iterations stop when q'' changes by less than this fraction of its size
GRAM_SHIFT = 1e-10  # regularisation of Phi_q^T Phi_q in least_norm_multipliers [-]
MAX_PROJECTIONS = 5  # corrections per projection of positions, and of velocities


class DynamicsScratch(NamedTuple):
    """Arrays of one right-hand-side evaluation (m constraint rows, n coordinates)."""

    g: np.ndarray  # (n,) generalised applied forces
    phi: np.ndarray  # (m,)
    cq: np.ndarray  # (m, 6) Jacobian entries (pattern.Pattern.row_coord gives the columns)
    gamma: np.ndarray  # (m,)
    phi_t: np.ndarray  # (m,)
    target: np.ndarray  # (m,) acceleration target c
    weight: np.ndarray  # (m,) augmented Lagrangian penalties w_r
    lam: np.ndarray  # (m,) Lagrange multipliers
    force: np.ndarray  # (n,) g - Phi_q^T lam
    qdd: np.ndarray  # (n,) accelerations of the last iterate
    x_rows: np.ndarray  # (m,) a row vector in envelope order
    x_coords: np.ndarray  # (n,) a coordinate vector in envelope order
    schur: np.ndarray  # Phi_q M^-1 Phi_q^T in envelope storage
    lead: np.ndarray  # M + Phi_q^T W Phi_q in envelope storage
    evaluated: np.ndarray  # (1 + 2n,) time [s] and state of the last evaluation (its factor)


class Problem(NamedTuple):
    """What the right-hand side reads: the mechanism, its contact elements, and scratch."""

    mech: NamedTuple  # system.Mechanism
    elements: elements.Elements
    state: elements.ElementState  # updated by the loop between steps
    scratch: elements.ElementScratch
    dyn: DynamicsScratch


def make_dynamics_scratch(mech: NamedTuple) -> DynamicsScratch:
    """Allocate the scratch of a ``system.Mechanism`` (Python)."""
    n = mech.inv_mass.shape[0]
    m = mech.row_coord.shape[0]
    return DynamicsScratch(
        g=np.zeros(n),
        phi=np.zeros(m),
        cq=np.zeros((m, ENTRIES)),
        gamma=np.zeros(m),
        phi_t=np.zeros(m),
        target=np.zeros(m),
        weight=np.zeros(m),
        lam=np.zeros(m),
        force=np.zeros(n),
        qdd=np.zeros(n),
        x_rows=np.zeros(m),
        x_coords=np.zeros(n),
        schur=np.zeros(mech.row_ptr[-1]),
        lead=np.zeros(mech.coord_ptr[-1]),
        evaluated=np.full(1 + 2 * n, np.nan),
    )


@njit(cache=True, no_cpython_wrapper=True)
def _row_dot(mech, cq, r, v):
    """Phi_q,r . v for a coordinate vector v."""
    total = 0.0
    for e in range(ENTRIES):
        col = mech.row_coord[r, e]
        if col >= 0:
            total += cq[r, e] * v[col]
    return total


@njit(cache=True, no_cpython_wrapper=True)
def _targets(mech, wk, qd):
    """Acceleration targets c = gamma - 2 alpha Phi' - beta^2 Phi (Baumgarte), or gamma."""
    a2 = 0.0
    b2 = 0.0
    if mech.formulation == Formulation.BAUMGARTE:
        a2 = 2.0 * mech.baumgarte_alpha
        b2 = mech.baumgarte_beta * mech.baumgarte_beta
    for r in range(wk.phi.shape[0]):
        phi_dot = wk.phi_t[r] + _row_dot(mech, wk.cq, r, qd)
        wk.target[r] = wk.gamma[r] - a2 * phi_dot - b2 * wk.phi[r]


@njit(cache=True, no_cpython_wrapper=True)
def _multipliers(mech, wk):
    """Baumgarte: lam from (Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - c. False if singular."""
    cq = wk.cq
    wk.schur[:] = 0.0
    pairs = mech.row_pairs
    for p in range(pairs.shape[0]):
        r1, e1, r2, e2, col = pairs[p, 1], pairs[p, 2], pairs[p, 3], pairs[p, 4], pairs[p, 5]
        wk.schur[pairs[p, 0]] += cq[r1, e1] * mech.inv_mass[col] * cq[r2, e2]
    for r in range(wk.phi.shape[0]):
        b = -wk.target[r]
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                b += cq[r, e] * mech.inv_mass[col] * wk.g[col]
        wk.x_rows[mech.row_order[r]] = b
    if not envelope_factor(mech.row_first, mech.row_ptr, wk.schur):
        return False
    envelope_solve(mech.row_first, mech.row_ptr, wk.schur, wk.x_rows)
    for r in range(wk.phi.shape[0]):
        wk.lam[r] = wk.x_rows[mech.row_order[r]]
    return True


@njit(cache=True, no_cpython_wrapper=True)
def _factor_rows(mech, wk):
    """Add Phi_q^T W Phi_q (W = wk.weight) to the diagonal in wk.lead, and factor it."""
    cq = wk.cq
    lead = wk.lead
    for r in range(wk.phi.shape[0]):
        w = wk.weight[r]
        for e1 in range(ENTRIES):
            for e2 in range(ENTRIES):
                at = mech.row_entry_pairs[r, ENTRIES * e1 + e2]
                if at >= 0:
                    lead[at] += w * cq[r, e1] * cq[r, e2]
    return envelope_factor(mech.coord_first, mech.coord_ptr, lead)


@njit(cache=True, no_cpython_wrapper=True)
def _diagonal(mech, c):
    """Flat index in lead of coordinate c's diagonal entry."""
    i = mech.coord_order[c]
    return mech.coord_ptr[i] + i - mech.coord_first[i]


@njit(cache=True, no_cpython_wrapper=True)
def _factor_lead(mech, wk):
    """Penalties w_r and the factor of M + Phi_q^T W Phi_q. False if not positive definite."""
    wk.lead[:] = 0.0
    for c in range(mech.inv_mass.shape[0]):
        wk.lead[_diagonal(mech, c)] = 1.0 / mech.inv_mass[c]
    for r in range(wk.phi.shape[0]):
        inverse_mass = 0.0
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                inverse_mass += wk.cq[r, e] * wk.cq[r, e] * mech.inv_mass[col]
        wk.weight[r] = mech.penalty / inverse_mass if inverse_mass > 0.0 else 0.0
    return _factor_rows(mech, wk)


@njit(cache=True, no_cpython_wrapper=True)
def _solve_lead(mech, wk, force, coef, out):
    """Out = (M + Phi_q^T W Phi_q)^-1 (force + Phi_q^T coef), with the factored lead."""
    x = wk.x_coords
    for c in range(force.shape[0]):
        x[mech.coord_order[c]] = force[c]
    for r in range(coef.shape[0]):
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                x[mech.coord_order[col]] += wk.cq[r, e] * coef[r]
    envelope_solve(mech.coord_first, mech.coord_ptr, wk.lead, x)
    for c in range(force.shape[0]):
        out[c] = x[mech.coord_order[c]]


@njit(cache=True, no_cpython_wrapper=True)
def _augmented(mech, wk):
    """Augmented Lagrangian iterations for lam (and q'' in wk.qdd). False if they fail."""
    if not _factor_lead(mech, wk):
        return False
    m = wk.phi.shape[0]
    coef = wk.x_rows  # W c - lam, row by row
    for r in range(m):
        wk.lam[r] = 0.0
    for _ in range(MAX_ITERATIONS):
        for r in range(m):
            coef[r] = wk.weight[r] * wk.target[r] - wk.lam[r]
        change = 0.0
        size = 0.0
        for c in range(wk.qdd.shape[0]):
            wk.force[c] = wk.qdd[c]  # the previous iterate, to measure the change
        _solve_lead(mech, wk, wk.g, coef, wk.qdd)
        for c in range(wk.qdd.shape[0]):
            change = max(change, abs(wk.qdd[c] - wk.force[c]))
            size = max(size, abs(wk.qdd[c]))
        for r in range(m):
            wk.lam[r] += wk.weight[r] * (_row_dot(mech, wk.cq, r, wk.qdd) - wk.target[r])
        if change <= SETTLED * size:
            break
    return True


@njit(cache=True, no_cpython_wrapper=True)
def rhs(t, y, problem, ydot):
    """Write y' = (q', q'') into ydot; lambda is left in problem.dyn.lam. False if singular."""
    mech = problem.mech
    wk = problem.dyn
    n = mech.inv_mass.shape[0]
    q = y[:n]
    qd = y[n:]
    g = wk.g
    applied_forces(t, q, qd, mech, g)
    elements.add_forces(problem.elements, problem.state, problem.scratch, q, qd, g)
    evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    _targets(mech, wk, qd)
    if mech.formulation == Formulation.BAUMGARTE:
        ok = _multipliers(mech, wk)
    else:
        ok = _augmented(mech, wk)
    if not ok:
        return False
    wk.evaluated[0] = t
    wk.evaluated[1:] = y
    for c in range(n):
        wk.force[c] = g[c]
    for r in range(wk.phi.shape[0]):
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                wk.force[col] -= wk.cq[r, e] * wk.lam[r]
    for c in range(n):
        ydot[c] = qd[c]
        ydot[n + c] = mech.inv_mass[c] * wk.force[c]
    return True


@njit(cache=True, no_cpython_wrapper=True)
def least_norm_multipliers(mech, wk):
    """Replace lam by the multipliers of least Euclidean norm with the same Phi_q^T lam.

    With redundant constraints only Phi_q^T lam, the force on the bodies, is determined; the
    iterations leave lam with an arbitrary part that applies none (round-off inconsistencies
    of c, times w). The least-norm set (Moore-Penrose) is lam = Phi_q z with
    (Phi_q^T Phi_q) z = Phi_q^T lam, found by iterations preconditioned with the factor of
    Phi_q^T Phi_q + eps I, eps = GRAM_SHIFT of its largest diagonal. The evaluation's factor
    is overwritten.
    """
    n = mech.inv_mass.shape[0]
    m = wk.phi.shape[0]
    f = wk.g  # the evaluation is done with g: it holds the target force Phi_q^T lam
    f[:] = 0.0
    wk.lead[:] = 0.0
    for r in range(m):
        wk.weight[r] = 1.0
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                f[col] += wk.cq[r, e] * wk.lam[r]
                wk.lead[_diagonal(mech, col)] += wk.cq[r, e] * wk.cq[r, e]
    shift = 0.0
    for c in range(n):
        shift = max(shift, GRAM_SHIFT * wk.lead[_diagonal(mech, c)])
    wk.lead[:] = 0.0
    for c in range(n):
        wk.lead[_diagonal(mech, c)] = max(shift, 1e-300)
    wk.evaluated[0] = np.nan  # the factor is no longer the evaluation's
    if not _factor_rows(mech, wk):
        return
    z = wk.force
    z[:] = 0.0
    for _ in range(MAX_ITERATIONS):
        for r in range(m):  # residual f - Phi_q^T Phi_q z
            wk.x_rows[r] = -_row_dot(mech, wk.cq, r, z)
        _solve_lead(mech, wk, f, wk.x_rows, wk.qdd)
        change = 0.0
        size = 0.0
        for c in range(n):
            z[c] += wk.qdd[c]
            change = max(change, abs(wk.qdd[c]))
            size = max(size, abs(z[c]))
        if change <= SETTLED * size:
            break
    for r in range(m):
        wk.lam[r] = _row_dot(mech, wk.cq, r, z)


@njit(cache=True, no_cpython_wrapper=True)
def constraint_norm(dyn):
    """2-norm of Phi from the last evaluation [m, rad]."""
    total = 0.0
    for r in range(dyn.phi.shape[0]):
        total += dyn.phi[r] * dyn.phi[r]
    return math.sqrt(total)


@njit(cache=True, no_cpython_wrapper=True)
def _velocity_violation(mech, wk, qd):
    """Phi' = Phi_q q' + Phi_t into wk.target; returns its 2-norm [m/s, rad/s]."""
    total = 0.0
    for r in range(wk.phi.shape[0]):
        v = wk.phi_t[r] + _row_dot(mech, wk.cq, r, qd)
        wk.target[r] = v
        total += v * v
    return math.sqrt(total)


@njit(cache=True, no_cpython_wrapper=True)
def _correct(mech, wk, v, violation):
    """V += dv, the M-orthogonal correction toward Phi_q dv = -violation (lead factored)."""
    coef = wk.x_rows
    for r in range(coef.shape[0]):
        coef[r] = -wk.weight[r] * violation[r]
    wk.force[:] = 0.0
    _solve_lead(mech, wk, wk.force, coef, wk.qdd)
    for c in range(v.shape[0]):
        v[c] += wk.qdd[c]


@njit(cache=True, no_cpython_wrapper=True)
def _evaluated_at(wk, t, y):
    """Whether the last evaluation (and its factor) was at time t [s] and state y."""
    return wk.evaluated[0] == t and np.array_equal(wk.evaluated[1:], y)


@njit(cache=True, no_cpython_wrapper=True)
def project(t, y, problem):
    """After a step: the position constraint 2-norm [m, rad] it ended with.

    The augmented Lagrangian formulation then moves positions, and then velocities, back onto
    the constraints (to the projection tolerance; near singular positions a residue of
    1e-10 m grows into a jump of assembly branch, one of 1e-13 m does not), each by
    M-orthogonal corrections
    (M + Phi_q^T W Phi_q) dq = -Phi_q^T W Phi (Bayo and Ledesma 1996). The factor of the
    step's last evaluation serves all corrections when that was at y, as the integrators'
    last evaluation is. Returns -1 if a correction could not be factorised.
    """
    mech = problem.mech
    wk = problem.dyn
    if mech.formulation == Formulation.BAUMGARTE:
        return constraint_norm(wk)  # of the step's last evaluation, at its end
    n = mech.inv_mass.shape[0]
    q = y[:n]
    qd = y[n:]
    factored = _evaluated_at(wk, t, y)
    if not factored:
        evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    before = constraint_norm(wk)
    tol = mech.projection_tolerance
    violation = before
    for _ in range(MAX_PROJECTIONS):
        if violation <= tol:
            break
        if not factored:
            if not _factor_lead(mech, wk):
                return -1.0
            factored = True
        _correct(mech, wk, q, wk.phi)
        wk.evaluated[0] = np.nan
        evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
        violation = constraint_norm(wk)
    for _ in range(MAX_PROJECTIONS):
        if _velocity_violation(mech, wk, qd) <= tol:  # the same number in m/s and rad/s
            break
        if not factored:
            if not _factor_lead(mech, wk):
                return -1.0
            factored = True
        _correct(mech, wk, qd, wk.target)
        wk.evaluated[0] = np.nan
    return before
