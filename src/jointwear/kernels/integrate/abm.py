"""Variable-step, variable-order Adams-Bashforth-Moulton PECE kernels (phase API).

Method: Adams methods in modified divided differences after Shampine & Gordon, *Computer
Solution of Ordinary Differential Equations: the Initial Value Problem* (Freeman, 1975),
ch. 5-6 (the DE/STEP/INTRP design), written here from the mathematics:

- ``psi_i = t_{n+1} - t_{n+1-i}``, ``alpha_i = h / psi_i``,
  ``beta_i = prod_{m<i} psi_m(n+1) / psi_m(n)``, ``phi*_i(n) = beta_i phi_i(n)``, where
  ``phi_i(n) = psi_1(n)...psi_{i-1}(n) f[t_n, ..., t_{n-i+1}]``.
- ``g_i = int_0^1 c_i(s) ds``, ``c_1 = 1``, ``c_{i+1}(s) = c_i(s) (1 + (s - 1) alpha_i)``,
  computed exactly from the polynomial coefficients of ``c_i`` (all non-negative).
- Predict (Adams-Bashforth, order k): ``p = y_n + h sum_{i<=k} g_i phi*_i``; evaluate
  ``f_p = f(t_{n+1}, p)``; ``e = f_p - sum_{i<=k} phi*_i`` (``= phi_{k+1}(n+1)``).
- Correct (Adams-Moulton, order k+1, local extrapolation): ``y = p + h g_{k+1} e``.
- Local error of the order-q formula: ``LE_q = h |g_{q+1} - g_q| ||phi_{q+1}(n+1)||`` with
  ``phi_q(n+1) = phi_{q+1}(n+1) + phi*_q(n)``; ``q = k`` decides acceptance, ``q = k-2,
  k-1`` (and ``k+1`` after ``k+1`` equal steps) choose the order. Norm: RMS with weights
  ``atol + rtol |y_n,i|`` (cf. ``stepsize.error_norm``).
- Evaluate again at the corrected ``y`` (the final E), then update the differences.
- Policy (Shampine-Gordon): start at order 1, doubling ``h`` and raising the order each
  step until an order decrease is indicated, a step fails or k = 12; afterwards lower the
  order when the lower-order errors are no larger, raise it when the ``k+1`` estimate is
  smaller, and double ``h`` if ``2**(k+1) LE <= 1/2``, keep it if ``LE <= 1/2``, else scale it
  by ``max(1/2, min(0.9, (0.5/LE)**(1/(k+1))))``. On failures 1-2 halve ``h`` (possibly
  lowering the order), on failure 3 halve it at order 1, then shrink by
  ``min(1/2, sqrt(0.5/LE))`` at order 1.
- Interpolation over the last step integrates the order-(k+1) interpolant of ``f``
  backwards from ``t_{n+1}`` (exact at ``t_{n+1}``).

The right-hand side is evaluated by the caller. Call sequence (``st = make_abm_state(n)``;
``S_T`` etc. index ``st.scal``, ``I_K`` etc. ``st.ints``)::

    f(t0, y0) -> yp0
    abm_start(st, t0, y0, yp0, h0)               # also: restart (order 1) at any time
    while st.scal[S_T] < t_end:
        t_new = abm_predict(st, h_max, h_min, t_stop, t_land, y_pred)  # ends on t_stop exactly
        f(t_new, y_pred) -> yp_pred
        err = abm_correct(st, yp_pred, rtol, atol, y_corr)    # accept when err <= 1
        if err <= 1.0:                           # (or forced, e.g. h at h_min)
            f(t_new, y_corr) -> yp_corr
            abm_accept(st, y_corr, yp_corr)      # t, y, yp advance; next h and order
        else:                                    # NaN err lands here too
            abm_reject(st)                       # history untouched; h and order drop
    abm_interpolate(st, t_out, out)              # t_out in [t - h_last, t]
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from .stepsize import clip_step, step_end

KMAX = 12  # highest order
NW = KMAX + 3  # length of the difference tables (phi_1..phi_{KMAX+2}, 1-based i at i-1)

# Indices into AbmState.scal (float64).
S_T = 0  # current time t_n [s]
S_H = 1  # step being tried [s]
S_TNEW = 2  # end time of the step being tried [s] (== t_stop exactly when it hits)
S_HNEXT = 3  # proposed next step [s]
S_HOLD = 4  # last accepted step [s] (0: none since the (re)start, no interpolation)
S_ERK = 5  # error estimates of the step being tried: order k
S_ERKM1 = 6  # order k-1
S_ERKM2 = 7  # order k-2
S_HPROP = 8  # proposal the tried step was clipped from [s]
N_SCAL = 9
# Indices into AbmState.ints (int64).
I_K = 0  # order of the next (or current) step
I_KOLD = 1  # order of the last accepted step (0: none)
I_KNEW = 2  # order suggested by the lowering test of the step being tried
I_NS = 3  # number of trailing accepted steps of equal size
I_PHASE1 = 4  # 1 while in the start phase (order and step go up each step)
I_IFAIL = 5  # consecutive failures of the current step
I_HIT = 6  # 1 if the step being tried was cut to end on t_stop or t_land
I_NACCEPT = 7
I_NREJECT = 8
N_INTS = 9


class AbmState(NamedTuple):
    """Work arrays of the ABM kernel (``n`` equations); 1-based ``i`` is stored at ``i-1``."""

    y: np.ndarray  # (n,) solution at scal[S_T]
    yp: np.ndarray  # (n,) f(t, y)
    y_old: np.ndarray  # (n,) solution at the start of the last accepted step
    yp_old: np.ndarray  # (n,) f there
    phi: np.ndarray  # (NW, n) phi_i at the last accepted point
    phis: np.ndarray  # (NW, n) phi*_i for the step being tried
    psum: np.ndarray  # (n,) sum_{i<=k} phi*_i
    p: np.ndarray  # (n,) predicted solution
    fp: np.ndarray  # (n,) f at the prediction (the caller's E of PECE)
    y_corr: np.ndarray  # (n,) corrected solution
    yp_corr: np.ndarray  # (n,) f there (the final E)
    wt: np.ndarray  # (n,) error weights atol + rtol |y| of the step being tried
    psi: np.ndarray  # (NW,) psi_i at the last accepted point
    psi_new: np.ndarray  # (NW,) psi_i for the step being tried
    g: np.ndarray  # (NW,) g_i for the step being tried
    poly: np.ndarray  # (NW,) scratch: polynomial coefficients
    coef: np.ndarray  # (NW,) scratch: interpolation weights
    scal: np.ndarray  # (N_SCAL,) float64 scalars, see S_*
    ints: np.ndarray  # (N_INTS,) int64 scalars, see I_*


def make_abm_state(n: int) -> AbmState:
    """Allocate the work arrays for ``n`` equations (plain Python)."""
    return AbmState(
        y=np.zeros(n),
        yp=np.zeros(n),
        y_old=np.zeros(n),
        yp_old=np.zeros(n),
        phi=np.zeros((NW, n)),
        phis=np.zeros((NW, n)),
        psum=np.zeros(n),
        p=np.zeros(n),
        fp=np.zeros(n),
        y_corr=np.zeros(n),
        yp_corr=np.zeros(n),
        wt=np.ones(n),
        psi=np.zeros(NW),
        psi_new=np.zeros(NW),
        g=np.zeros(NW),
        poly=np.zeros(NW),
        coef=np.zeros(NW),
        scal=np.zeros(N_SCAL),
        ints=np.zeros(N_INTS, dtype=np.int64),
    )


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_start(st: AbmState, t: float, y: np.ndarray, yp: np.ndarray, h: float) -> None:
    """Start, or restart at order 1, from ``(t, y)``; all history is discarded.

    ``yp = f(t, y)`` is evaluated by the caller. ``h`` [s] is the first step to try; make
    it small, the start phase doubles it every step. No interpolation until the next accept.
    """
    for j in range(y.shape[0]):
        st.y[j] = y[j]
        st.yp[j] = yp[j]
        for i in range(NW):
            st.phi[i, j] = yp[j] if i == 0 else 0.0
            st.phis[i, j] = 0.0
    for i in range(NW):
        st.psi[i] = (i + 1) * h  # fictitious history: only multiplies zero differences
    for i in range(N_SCAL):
        st.scal[i] = 0.0
    st.scal[S_T] = t
    st.scal[S_TNEW] = t
    st.scal[S_H] = h
    st.scal[S_HNEXT] = h
    st.ints[I_K] = 1
    st.ints[I_KOLD] = 0
    st.ints[I_KNEW] = 1
    st.ints[I_NS] = 0
    st.ints[I_PHASE1] = 1
    st.ints[I_IFAIL] = 0
    st.ints[I_HIT] = 0


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def _coefficients(st: AbmState, h: float, k: int) -> None:
    """psi, beta, phi* and g_1..g_{k+2} for a step ``h`` at order ``k``."""
    n = st.y.shape[0]
    st.psi_new[0] = h
    for i in range(1, NW):
        st.psi_new[i] = h + st.psi[i - 1]
    # phi*_i = beta_i phi_i, i = 1..k+1 (beta_1 = 1)
    beta = 1.0
    for i in range(k + 1):
        if i > 0:
            beta *= st.psi_new[i - 1] / st.psi[i - 1]
        for j in range(n):
            st.phis[i, j] = beta * st.phi[i, j]
    # g_i = int_0^1 c_i(s) ds; st.poly holds the coefficients of c_i in powers of s
    for i in range(NW):
        st.poly[i] = 0.0
    st.poly[0] = 1.0
    st.g[0] = 1.0
    for i in range(1, k + 2):
        alpha = h / st.psi_new[i - 1]
        for d in range(i, 0, -1):  # c_{i+1} = c_i * ((1 - alpha) + alpha s)
            st.poly[d] = (1.0 - alpha) * st.poly[d] + alpha * st.poly[d - 1]
        st.poly[0] *= 1.0 - alpha
        acc = 0.0
        for d in range(i + 1):
            acc += st.poly[d] / (d + 1.0)
        st.g[i] = acc


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_predict(
    st: AbmState,
    h_max: float,
    h_min: float,
    t_stop: float,
    t_land: float,
    y_pred: np.ndarray,
) -> float:
    """Choose the step, compute its coefficients and the predicted solution ``y_pred``.

    The proposal ``scal[S_HNEXT]`` is bounded by ``h_min`` and ``h_max`` [s] and cut (or
    stretched by at most 1 %) to end on ``t_stop`` (> t) [s], or on ``t_land`` when cheap
    (``stepsize.clip_step``); the step is stored in ``scal[S_H]``. Returns ``t_new`` [s]
    (``t_stop`` or ``t_land`` exactly when the step lands there); the caller evaluates
    ``f(t_new, y_pred)``.
    """
    t = st.scal[S_T]
    h = clip_step(t, st.scal[S_HNEXT], h_min, h_max, t_stop, t_land)
    st.scal[S_HPROP] = st.scal[S_HNEXT]
    st.scal[S_H] = h
    st.scal[S_TNEW] = step_end(t, h, t_stop, t_land)
    st.ints[I_HIT] = 0 if st.scal[S_TNEW] == t + h else 1
    k = st.ints[I_K]
    _coefficients(st, h, k)
    n = st.y.shape[0]
    for j in range(n):
        acc = 0.0
        ps = 0.0
        for i in range(k):
            acc += st.g[i] * st.phis[i, j]
            ps += st.phis[i, j]
        st.psum[j] = ps
        st.p[j] = st.y[j] + h * acc
        y_pred[j] = st.p[j]
    return st.scal[S_TNEW]


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_correct(
    st: AbmState, yp_pred: np.ndarray, rtol: float, atol: float, y_corr: np.ndarray
) -> float:
    """Correct with the order-(k+1) Adams-Moulton formula into ``y_corr``; return the error.

    ``yp_pred = f(t_new, y_pred)``; ``rtol`` [-], ``atol`` (units of y). The returned local
    error estimate is normalised: accept when <= 1 (NaN or inf when not finite).
    """
    n = st.y.shape[0]
    k = st.ints[I_K]
    h = st.scal[S_H]
    gk1 = st.g[k]  # g_{k+1}
    s0 = 0.0
    s1 = 0.0
    s2 = 0.0
    for j in range(n):
        w = atol + rtol * abs(st.y[j])
        st.wt[j] = w
        e = yp_pred[j] - st.psum[j]  # phi_{k+1}(n+1), predicted
        y_corr[j] = st.p[j] + h * gk1 * e
        r = e / w
        s0 += r * r
        if k >= 2:
            e1 = e + st.phis[k - 1, j]  # phi_k(n+1)
            r = e1 / w
            s1 += r * r
            if k >= 3:
                r = (e1 + st.phis[k - 2, j]) / w  # phi_{k-1}(n+1)
                s2 += r * r
    nn = max(n, 1)
    erk = h * abs(st.g[k] - st.g[k - 1]) * math.sqrt(s0 / nn)
    erkm1 = 0.0
    erkm2 = 0.0
    if k >= 2:
        erkm1 = h * abs(st.g[k - 1] - st.g[k - 2]) * math.sqrt(s1 / nn)
    if k >= 3:
        erkm2 = h * abs(st.g[k - 2] - st.g[k - 3]) * math.sqrt(s2 / nn)
    knew = k
    if k == 2 and erkm1 <= 0.5 * erk:
        knew = 1
    elif k >= 3 and max(erkm1, erkm2) <= erk:
        knew = k - 1
    st.ints[I_KNEW] = knew
    st.scal[S_ERK] = erk
    st.scal[S_ERKM1] = erkm1
    st.scal[S_ERKM2] = erkm2
    return erk


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def _new_step(h: float, erk: float, k: int) -> float:
    """Shampine-Gordon step after success: double, keep or shrink (error target 1/2)."""
    if erk * 2.0 ** (k + 1) <= 0.5:
        return 2.0 * h
    if erk <= 0.5:
        return h
    r = (0.5 / erk) ** (1.0 / (k + 1))
    return h * max(0.5, min(0.9, r))


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_accept(st: AbmState, y_corr: np.ndarray, yp_corr: np.ndarray) -> None:
    """Accept the step: update the differences, advance, choose next order and step.

    ``y_corr`` is the corrected solution and ``yp_corr = f(t_new, y_corr)`` (the final E of
    PECE). Acceptance may be forced by the caller when the error exceeded 1.
    """
    n = st.y.shape[0]
    k = st.ints[I_K]
    h = st.scal[S_H]
    # phi_{k+1}(n+1), phi_{k+2}(n+1), then phi_i(n+1) = phi*_i(n) + phi_{i+1}(n+1)
    s3 = 0.0
    for j in range(n):
        e = yp_corr[j] - st.psum[j]
        st.phi[k, j] = e
        st.phi[k + 1, j] = e - st.phis[k, j]
        r = st.phi[k + 1, j] / st.wt[j]
        s3 += r * r
        for i in range(k - 1, -1, -1):
            st.phi[i, j] = st.phis[i, j] + st.phi[i + 1, j]
        st.y_old[j] = st.y[j]
        st.yp_old[j] = st.yp[j]
        st.y[j] = y_corr[j]
        st.yp[j] = yp_corr[j]
    for i in range(NW):
        st.psi[i] = st.psi_new[i]
    ns = st.ints[I_NS]
    ns = ns + 1 if h == st.scal[S_HOLD] else 1
    st.ints[I_NS] = min(ns, NW)
    # order
    erk = st.scal[S_ERK]
    erkm1 = st.scal[S_ERKM1]
    knew = st.ints[I_KNEW]
    phase1 = st.ints[I_PHASE1] == 1
    if knew < k or k == KMAX:
        phase1 = False
    if phase1:
        k_next = k + 1
        h_next = 2.0 * h
    else:
        k_next = k
        e_next = erk
        if knew < k:
            k_next = k - 1
            e_next = erkm1
        elif k + 1 <= ns:
            erkp1 = h * abs(st.g[k + 1] - st.g[k]) * math.sqrt(s3 / max(n, 1))
            if k == 1:
                if erkp1 < 0.5 * erk:
                    k_next = 2
                    e_next = erkp1
            elif erkm1 <= min(erk, erkp1):
                k_next = k - 1
                e_next = erkm1
            elif erkp1 < erk and k < KMAX:
                k_next = k + 1
                e_next = erkp1
        h_next = _new_step(h, e_next, k_next)
        # a step shortened to land on t_stop or t_land says nothing against the earlier proposal
        if st.ints[I_HIT] == 1 and h_next >= h:
            h_next = max(h_next, st.scal[S_HPROP])
    st.ints[I_PHASE1] = 1 if phase1 else 0
    st.ints[I_KOLD] = k
    st.ints[I_K] = k_next
    st.ints[I_IFAIL] = 0
    st.ints[I_HIT] = 0
    st.ints[I_NACCEPT] += 1
    st.scal[S_HOLD] = h
    st.scal[S_T] = st.scal[S_TNEW]
    st.scal[S_HNEXT] = h_next


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_reject(st: AbmState) -> float:
    """Reject the step (history untouched); the step and maybe the order drop.

    Returns the new proposal ``scal[S_HNEXT]`` [s].
    """
    st.ints[I_PHASE1] = 0
    st.ints[I_IFAIL] += 1
    st.ints[I_NREJECT] += 1
    st.ints[I_HIT] = 0
    ifail = st.ints[I_IFAIL]
    fac = 0.5
    if ifail < 3:
        st.ints[I_K] = st.ints[I_KNEW]
    else:
        st.ints[I_K] = 1
        erk = st.scal[S_ERK]
        if ifail > 3 and erk > 2.0 and erk <= 1.0e300:
            fac = math.sqrt(0.5 / erk)
    h_next = fac * st.scal[S_H]
    st.scal[S_HNEXT] = h_next
    return h_next


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def _interpolate(st: AbmState, t_out: float, out: np.ndarray, derivative: bool) -> None:
    """y(t_out) = y + h sum_i D_i(sigma) phi_i(n+1), or y'(t_out) = sum_i d_i(sigma) phi_i."""
    h = st.scal[S_HOLD]
    kk = st.ints[I_KOLD] + 1
    sigma = (t_out - st.scal[S_T]) / h
    # d_1 = 1, d_{i+1}(sigma) = d_i(sigma) (psi_{i-1} + h sigma) / psi_i, psi_0 = 0;
    # D_i(sigma) = int_0^sigma d_i; st.coef[i-1] receives D_i h (or d_i)
    for i in range(NW):
        st.poly[i] = 0.0
    st.poly[0] = 1.0
    for i in range(kk):
        if i > 0:
            c0 = (st.psi[i - 2] if i >= 2 else 0.0) / st.psi[i - 1]
            c1 = h / st.psi[i - 1]
            for d in range(i, 0, -1):
                st.poly[d] = c0 * st.poly[d] + c1 * st.poly[d - 1]
            st.poly[0] *= c0
        acc = 0.0
        for d in range(i, -1, -1):  # Horner in sigma
            acc = acc * sigma + (st.poly[d] if derivative else st.poly[d] / (d + 1.0))
        st.coef[i] = acc if derivative else h * sigma * acc
    for j in range(st.y.shape[0]):
        acc = 0.0
        for i in range(kk):
            acc += st.coef[i] * st.phi[i, j]
        out[j] = acc if derivative else st.y[j] + acc


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_interpolate(st: AbmState, t_out: float, out: np.ndarray) -> None:
    """Solution at ``t_out`` [s] in the last accepted step ``[t - scal[S_HOLD], t]``.

    Exact at ``t``; valid until the next ``abm_accept`` (predict, correct and reject do not
    disturb it). Before any step since the (re)start, ``out`` is the current ``y``.
    """
    if st.ints[I_KOLD] == 0:
        for j in range(out.shape[0]):
            out[j] = st.y[j]
    else:
        _interpolate(st, t_out, out, False)


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_interpolate_derivative(st: AbmState, t_out: float, out: np.ndarray) -> None:
    """Time derivative of the interpolant at ``t_out`` (``yp`` before any step)."""
    if st.ints[I_KOLD] == 0:
        for j in range(out.shape[0]):
            out[j] = st.yp[j]
    else:
        _interpolate(st, t_out, out, True)


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def abm_interpolate_ends(st: AbmState, t_out: float, out: np.ndarray) -> None:
    """Cubic Hermite interpolant of (y, y') at both ends of the last accepted step.

    Unlike ``abm_interpolate`` (which integrates the corrected derivative and so misses
    ``y_old`` at the step's start by the local error), it passes through both ends exactly,
    which the contact logic needs to put a penetration on the right side of an onset.
    """
    t_new = st.scal[S_T]
    h = st.scal[S_HOLD]
    if st.ints[I_KOLD] == 0 or t_out == t_new:
        for j in range(out.shape[0]):
            out[j] = st.y[j]
        return
    s = (t_out - (t_new - h)) / h
    s2 = s * s
    s3 = s2 * s
    w_y0 = 2.0 * s3 - 3.0 * s2 + 1.0
    w_f0 = (s3 - 2.0 * s2 + s) * h
    w_y1 = 3.0 * s2 - 2.0 * s3
    w_f1 = (s3 - s2) * h
    for j in range(out.shape[0]):
        out[j] = w_y0 * st.y_old[j] + w_f0 * st.yp_old[j] + w_y1 * st.y[j] + w_f1 * st.yp[j]
