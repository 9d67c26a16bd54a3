"""Index-1 augmented Lagrangian with mass-orthogonal projections.

Bayo, Garcia de Jalon and Serna (1988); Garcia de Jalon and Bayo (1994), sec. 5.3:

    (M + Phi_q^T W Phi_q) q''_k+1 = g - Phi_q^T (lam_k - W gamma),
    lam_k+1 = lam_k + W (Phi_q q''_k+1 - gamma),  lam_0 = 0,

until every row's residual, or the change of q'' still to come, is below SETTLED of its size.
Near a singular position the iterations settle slowly in the directions the rows nearly share;
there residuals below UNSETTLED of the largest row's terms are accepted after MAX_ITERATIONS,
and larger ones fail the solve (a badly conditioned system: masses and inertias of very
different sizes). M q'' = g - Phi_q^T lam holds at every iterate. The leading matrix is
positive definite whatever the rank of Phi_q, so singular positions and redundant
constraints pass. W is diagonal, w_r = penalty / (Phi_q,r M^-1 Phi_q,r^T): each row's penalty
relative to its own effective mass. After every step ``project`` moves the positions, then
the velocities, back onto the constraints by M-orthogonal corrections
(M + Phi_q^T W Phi_q) dq = -Phi_q^T W Phi (Bayo and Ledesma 1996), to the mechanism's
projection tolerance; no Baumgarte terms are needed. Near singular positions a residue of
1e-10 m grows, crossing after crossing, into a jump of assembly branch; one of 1e-13 m of the
mechanism's size does not (tests/test_singular_redundant.py).

Where the joints close no loop (an open chain or tree of bodies: every body hangs from the
ground by one path of joints, or floats) Phi_q keeps full rank at every pose: no singular
position, no redundancy. There the iterations converge to the solution of
(Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - gamma, and ``solve`` takes it from that sparse
system directly (``schur``): the iterations' contraction, 1 / (1 + penalty mu) with mu the
smallest eigenvalue of that matrix scaled to a unit diagonal, slows with the size of a chain
(mu about 0.6 / N^2 for N straight links: 25 iterations at N = 640, more than MAX_ITERATIONS
past N = 1,000), while the direct solve costs the same per body at every size. Mechanisms
with loops keep the iterations, whose penalty regularises their singular positions.
"""

from typing import NamedTuple

import numpy as np
from numba import njit

from ..constraints import evaluate_constraints
from ..jacobian import ENTRIES, add_transpose_product, norm, row_dot
from ..linalg import envelope_factor, envelope_solve
from . import shared_arrays
from .schur import schur_factor, schur_multipliers, schur_solve

MAX_ITERATIONS = 50  # iterations per evaluation
UNSETTLED = 1e-3  # at MAX_ITERATIONS, residuals below this of the largest row's terms pass
CLEAN_AFTER = 10  # more iterations than this: near a singular position, rows take least norm
SETTLED = 1e-10  # iterations stop at residuals, or changes of q'', this fraction of their size
GRAM_SHIFT = 1e-10  # regularisation of Phi_q^T Phi_q in row_multipliers [-]
MAX_PROJECTIONS = 5  # corrections per projection of positions, and of velocities


class AugmentedScratch(NamedTuple):
    """Arrays of one evaluation (m constraint rows, n coordinates)."""

    g: np.ndarray  # (n,) generalised applied forces [N, N m]
    phi: np.ndarray  # (m,) Phi [m, rad]
    cq: np.ndarray  # (m, 6) Jacobian entries (jacobian.py)
    gamma: np.ndarray  # (m,) right side of Phi_q q'' = gamma
    phi_t: np.ndarray  # (m,) partial time derivative of Phi
    lam: np.ndarray  # (m,) Lagrange multipliers [N, N m]
    force: np.ndarray  # (n,) Phi_q^T lam after an evaluation; scratch within one
    x_rows: np.ndarray  # (m,) a row vector
    weight: np.ndarray  # (m,) penalties w_r
    qdd: np.ndarray  # (n,) accelerations of the last iterate
    x_coords: np.ndarray  # (n,) a coordinate vector in envelope order
    lead: np.ndarray  # M + Phi_q^T W Phi_q in envelope storage, or its factor
    evaluated: np.ndarray  # (1 + 2n,) time [s] and state the factor below belongs to
    by_schur: np.ndarray  # (1,) bool: that factor is schur's (else lead's)
    iterations: np.ndarray  # (1,) int64 iterations of the last evaluation (0: direct)
    schur: np.ndarray  # Phi_q M^-1 Phi_q^T in envelope storage, or its factor
    z_rows: np.ndarray  # (m,) a row vector
    direct: bool  # an open tree of joints: lam from the Schur complement (``_direct``)


def make_scratch(n: int, m: int, mech: NamedTuple) -> AugmentedScratch:
    """Allocate the scratch of n coordinates and m rows of ``system.Mechanism`` (Python)."""
    return AugmentedScratch(
        **shared_arrays(n, m),
        weight=np.zeros(m),
        qdd=np.zeros(n),
        x_coords=np.zeros(n),
        lead=np.zeros(mech.coord_ptr[-1]),
        evaluated=np.full(1 + 2 * n, np.nan),
        by_schur=np.zeros(1, dtype=np.bool_),
        iterations=np.zeros(1, dtype=np.int64),
        schur=np.zeros(mech.row_ptr[-1]),
        z_rows=np.zeros(m),
        direct=mech.open_tree and not mech.redundant,
    )


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _factor_rows(mech, wk):
    """Add Phi_q^T W Phi_q (W = wk.weight) to the diagonal in wk.lead, and factor it."""
    cq = wk.cq
    lead = wk.lead
    weight = wk.weight
    pairs = mech.row_entry_pairs
    for r in range(weight.shape[0]):
        w = weight[r]
        for e1 in range(ENTRIES):
            for e2 in range(ENTRIES):
                at = pairs[r, ENTRIES * e1 + e2]
                if at >= 0:
                    lead[at] += w * cq[r, e1] * cq[r, e2]
    return envelope_factor(mech.coord_first, mech.coord_ptr, lead, True)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _factor_lead(mech, wk):
    """Penalties w_r and the factor of M + Phi_q^T W Phi_q. False if not positive definite."""
    inv_mass = mech.inv_mass
    row_coord = mech.row_coord
    diagonal = mech.coord_diagonal
    cq = wk.cq
    wk.lead[:] = 0.0
    for c in range(inv_mass.shape[0]):
        wk.lead[diagonal[c]] = 1.0 / inv_mass[c]
    for r in range(wk.weight.shape[0]):
        inverse_mass = 0.0
        for e in range(ENTRIES):
            col = row_coord[r, e]
            if col >= 0:
                inverse_mass += cq[r, e] * cq[r, e] * inv_mass[col]
        wk.weight[r] = mech.penalty / inverse_mass if inverse_mass > 0.0 else 0.0
    return _factor_rows(mech, wk)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _solve_lead(mech, wk, force, coef, out):
    """Out = (M + Phi_q^T W Phi_q)^-1 (force + Phi_q^T coef), with the factored lead."""
    x = wk.x_coords
    order = mech.coord_order
    row_coord = mech.row_coord
    cq = wk.cq
    for c in range(force.shape[0]):
        x[order[c]] = force[c]
    for r in range(coef.shape[0]):
        for e in range(ENTRIES):
            col = row_coord[r, e]
            if col >= 0:
                x[order[col]] += cq[r, e] * coef[r]
    envelope_solve(mech.coord_first, mech.coord_ptr, wk.lead, x)
    for c in range(force.shape[0]):
        out[c] = x[order[c]]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _residual(mech, wk, r, qdd):
    """Row r's residual Phi_q,r q'' - gamma_r, and the sum of its terms' sizes."""
    residual = -wk.gamma[r]
    terms = abs(wk.gamma[r])
    for e in range(ENTRIES):
        col = mech.row_coord[r, e]
        if col >= 0:
            term = wk.cq[r, e] * qdd[col]
            residual += term
            terms += abs(term)
    return residual, terms


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _direct(wk, y, mech):
    """Lam (and q'') from the Schur complement if it factors and meets the rows to SETTLED.

    The residuals are measured against the largest row's terms: rounding leaves residuals
    of that size in rows of small terms beside large multipliers (the root of a long chain).
    The leading matrix is not factored.
    """
    n = mech.inv_mass.shape[0]
    if not schur_multipliers(wk, mech, y[n:], 0.0, 0.0):
        return False
    qdd = wk.force  # M^-1 (g - Phi_q^T lam), wk.qdd kept for the iterations if this fails
    qdd[:] = 0.0
    add_transpose_product(mech, wk.cq, wk.lam, qdd)
    for c in range(n):
        qdd[c] = mech.inv_mass[c] * (wk.g[c] - qdd[c])
    worst = 0.0  # the largest residual, and the largest row's terms
    largest = 0.0
    for r in range(wk.phi.shape[0]):
        residual, terms = _residual(mech, wk, r, qdd)
        worst = max(worst, abs(residual))
        largest = max(largest, terms)
    if not worst <= SETTLED * largest:
        return False
    wk.qdd[:] = qdd
    return True


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def solve(wk, t, y, mech):
    """Lam (and q'' in wk.qdd) for the target c = gamma. False if the iterations fail.

    An open tree of joints takes the Schur complement's solve (``_direct``), unless it fails
    its checks; any other mechanism the iterations from lam = 0.
    """
    if wk.direct and _direct(wk, y, mech):
        wk.iterations[0] = 0
        _factored_at(wk, t, y, True)
        return True
    return _iterate(wk, t, y, mech)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _iterate(wk, t, y, mech):
    """The iterations from lam = 0, to SETTLED (or UNSETTLED at MAX_ITERATIONS)."""
    if not _factor_lead(mech, wk):
        return False
    m = wk.phi.shape[0]
    n = wk.qdd.shape[0]
    coef = wk.x_rows  # W c - lam, row by row
    previous = wk.force
    for r in range(m):
        wk.lam[r] = 0.0
    last_change = np.inf
    settled = False
    for k in range(MAX_ITERATIONS):
        for r in range(m):
            coef[r] = wk.weight[r] * wk.gamma[r] - wk.lam[r]
        for c in range(n):
            previous[c] = wk.qdd[c]
        _solve_lead(mech, wk, wk.g, coef, wk.qdd)
        change = 0.0
        size = 0.0
        for c in range(n):
            change = max(change, abs(wk.qdd[c] - previous[c]))
            size = max(size, abs(wk.qdd[c]))
        met = True  # every row's residual Phi_q,r q'' - gamma_r within SETTLED of its terms
        worst = 0.0  # the largest residual, and the largest row's terms
        largest = 0.0
        for r in range(m):
            residual, terms = _residual(mech, wk, r, wk.qdd)
            wk.lam[r] += wk.weight[r] * residual
            met &= abs(residual) <= SETTLED * terms
            worst = max(worst, abs(residual))
            largest = max(largest, terms)
        # Or q'' has settled where the residuals cannot (redundant rows with gamma inconsistent
        # at rounding level): the remaining change, estimated from the contraction of the last
        # two changes, is below SETTLED of q''. The first change is from the last evaluation.
        ratio = change / last_change if k > 1 and last_change > 0.0 else 1.0
        if met or (ratio < 0.5 and change * ratio / (1.0 - ratio) <= SETTLED * size):
            settled = True
            break
        if change == 0.0 and k > 0:  # nothing moves any more: rounding level everywhere
            settled = True
            break
        last_change = change
    wk.iterations[0] = k + 1
    if not settled and worst > UNSETTLED * largest:
        return False  # not near a singular position: a badly conditioned system
    _factored_at(wk, t, y, False)
    return True


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _factored_at(wk, t, y, by_schur):
    """Record that the factor of schur (by_schur) or of lead belongs to time t [s], state y."""
    wk.evaluated[0] = t
    wk.evaluated[1:] = y
    wk.by_schur[0] = by_schur


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def row_multipliers(wk, mech):
    """With redundant constraints, or near a singular position, lam becomes the least-norm set.

    With redundant constraints only Phi_q^T lam, the force on the bodies, is determined; the
    iterations leave lam with an arbitrary part that applies none (round-off inconsistencies
    of c, times w). The least-norm set (Moore-Penrose) is lam = Phi_q z with
    (Phi_q^T Phi_q) z = Phi_q^T lam, found by iterations preconditioned with the factor of
    Phi_q^T Phi_q + eps I, eps = GRAM_SHIFT of its largest diagonal. The evaluation's factor
    is overwritten.
    """
    if not mech.redundant and wk.iterations[0] <= CLEAN_AFTER:
        return
    n = mech.inv_mass.shape[0]
    m = wk.phi.shape[0]
    f = wk.g  # the evaluation is done with g: it holds the target force Phi_q^T lam
    f[:] = 0.0
    add_transpose_product(mech, wk.cq, wk.lam, f)
    wk.lead[:] = 0.0
    for r in range(m):
        wk.weight[r] = 1.0
        for e in range(ENTRIES):
            col = mech.row_coord[r, e]
            if col >= 0:
                wk.lead[mech.coord_diagonal[col]] += wk.cq[r, e] * wk.cq[r, e]
    shift = 0.0
    for c in range(n):
        shift = max(shift, GRAM_SHIFT * wk.lead[mech.coord_diagonal[c]])
    wk.lead[:] = 0.0
    for c in range(n):
        wk.lead[mech.coord_diagonal[c]] = max(shift, 1e-300)
    wk.evaluated[0] = np.nan  # the factor is no longer the evaluation's
    if not _factor_rows(mech, wk):
        return
    z = wk.force
    z[:] = 0.0
    for _ in range(MAX_ITERATIONS):
        for r in range(m):  # residual f - Phi_q^T Phi_q z
            wk.x_rows[r] = -row_dot(mech, wk.cq, r, z)
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
        wk.lam[r] = row_dot(mech, wk.cq, r, z)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _evaluated_at(wk, t, y):
    """Whether the last evaluation (and its factor) was at time t [s] and state y."""
    return wk.evaluated[0] == t and np.array_equal(wk.evaluated[1:], y)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _velocity_violation(mech, wk, qd):
    """Phi' = Phi_q q' + Phi_t into wk.x_rows; returns its 2-norm [m/s, rad/s]."""
    for r in range(wk.phi.shape[0]):
        wk.x_rows[r] = wk.phi_t[r] + row_dot(mech, wk.cq, r, qd)
    return norm(wk.x_rows)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _factor_projection(mech, wk):
    """Factor the matrix the corrections solve with; False if neither can be factored.

    An open tree of joints: the Schur complement (exact M-orthogonal corrections), else, or
    where that is singular, the leading matrix.
    """
    wk.by_schur[0] = wk.direct and schur_factor(wk, mech)
    return wk.by_schur[0] or _factor_lead(mech, wk)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _correct(mech, wk, v, violation):
    """Add to v the M-orthogonal correction toward Phi_q dv = -violation (factored).

    With the Schur complement S: dv = -M^-1 Phi_q^T S^-1 violation. With the leading matrix:
    (M + Phi_q^T W Phi_q) dv = -Phi_q^T W violation, the same as W grows.
    """
    if wk.by_schur[0]:
        coef = wk.z_rows
        coef[:] = violation
        schur_solve(wk, mech, coef)
        for r in range(coef.shape[0]):
            for e in range(ENTRIES):
                col = mech.row_coord[r, e]
                if col >= 0:
                    v[col] -= mech.inv_mass[col] * wk.cq[r, e] * coef[r]
        return
    coef = wk.x_rows
    for r in range(coef.shape[0]):
        coef[r] = -wk.weight[r] * violation[r]
    wk.force[:] = 0.0
    _solve_lead(mech, wk, wk.force, coef, wk.qdd)
    for c in range(v.shape[0]):
        v[c] += wk.qdd[c]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def project(wk, t, y, mech):
    """The 2-norm of Phi the step ended with [m, rad]; then y is moved onto Phi = 0, Phi' = 0.

    Positions, then velocities, take M-orthogonal corrections until their violation is below
    the projection tolerance (the same number in m/s and rad/s for the velocities). The
    factor of the step's last evaluation serves all corrections when that was at y, as the
    integrators' last evaluation is. Returns -1 if no matrix could be factored.
    """
    n = mech.inv_mass.shape[0]
    q = y[:n]
    qd = y[n:]
    factored = _evaluated_at(wk, t, y)
    if not factored:
        evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    before = norm(wk.phi)
    tol = mech.projection_tolerance
    violation = before
    for _ in range(MAX_PROJECTIONS):
        if violation <= tol:
            break
        if not factored:
            if not _factor_projection(mech, wk):
                return -1.0
            factored = True
        _correct(mech, wk, q, wk.phi)
        wk.evaluated[0] = np.nan
        evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
        violation = norm(wk.phi)
    for _ in range(MAX_PROJECTIONS):
        if _velocity_violation(mech, wk, qd) <= tol:  # the same number in m/s and rad/s
            break
        if not factored:
            if not _factor_projection(mech, wk):
                return -1.0
            factored = True
        _correct(mech, wk, qd, wk.x_rows)
        wk.evaluated[0] = np.nan
    return before
