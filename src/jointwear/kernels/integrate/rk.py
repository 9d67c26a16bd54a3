"""Explicit embedded Runge-Kutta pairs with dense output, driven by a tableau (phase API).

A method is its ``Tableau``: nodes c, matrix a, propagated weights b, error weights
e = b - b_hat, dense-output weights P (``b_i(theta) = sum_p P[i, p] theta^(p+1)``, so that
``y(t + theta h) = y + h sum_i b_i(theta) k_i``), the order of the embedded solution and the
integral gain of the PI step control. Pairs must be FSAL (the last stage is evaluated at the
new solution, c[-1] = 1 and a[-1] = b), as Dormand-Prince 5(4) is.

| symbol | meaning | unit |
|---|---|---|
| y, k[i] | solution; stage derivatives f(t + c_i h, Y_i) | units of y; per second |
| h, theta | step; fraction of the last accepted step | s; - |
| err | weighted RMS norm of h sum_i e_i k_i (accept when <= 1) | - |

The right-hand side is evaluated by the caller between phases (``st = make_rk_state(n)``)::

    rk_start(st, t0, y0, f(t0, y0), h0)          # also: restart after a discontinuity
    h = rk_begin(st, h_max, h_min, t_stop, t_land)  # ends on t_stop (t_land if cheap) exactly
    for s in range(1, stages):
        ts = rk_stage(st, s)                     # writes st.ystage
        f(ts, st.ystage) -> st.k[s]              # last stage: the new solution at t + h
    err = rk_error(st, rtol, atol)
    rk_accept(st, err) or rk_reject(st, err)     # NaN err must be rejected
    rk_interpolate(st, t_out, out)               # any t_out in the last accepted step

References
----------
J.R. Dormand, P.J. Prince, "A family of embedded Runge-Kutta formulae", J. Comput. Appl.
Math. 6 (1980) 19-26. E. Hairer, S.P. Norsett, G. Wanner, *Solving Ordinary Differential
Equations I*, 2nd ed., Springer (1993): sec. II.4 (PI control), sec. II.6 (dense output).
"""

from typing import NamedTuple

import numpy as np
from numba import njit

from .stepsize import ERR_PREV_MIN, clip_step, error_norm, pi_factor, reject_factor, step_end


class Tableau(NamedTuple):
    """Coefficients of an FSAL embedded explicit Runge-Kutta pair (``stages`` stages)."""

    c: np.ndarray  # (stages,) nodes
    a: np.ndarray  # (stages, stages) strictly lower triangular
    b: np.ndarray  # (stages,) weights of the propagated solution
    e: np.ndarray  # (stages,) b - b_hat: the error estimate's weights
    p: np.ndarray  # (stages, degree) dense output: b_i(theta) = sum_p p[i, p] theta^(p+1)
    order_embedded: int  # order of the error estimate's solution (controller exponent)
    beta: float  # integral gain of the PI controller


def make_dopri5_tableau() -> Tableau:
    """Dormand & Prince (1980), Table 2; dense output of HNW I sec. II.6."""
    a = np.zeros((7, 7))
    a[1, 0] = 1.0 / 5.0
    a[2, :2] = [3.0 / 40.0, 9.0 / 40.0]
    a[3, :3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0]
    a[4, :4] = [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0]
    a[5, :5] = [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0]
    a[6, :6] = [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0]
    b = a[6].copy()
    b_hat = np.array(
        [5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40]
    )
    # HNW's continuous extension: u(theta) = (1 - theta) y0 + theta y1 + theta (1 - theta)
    # [(1 - theta)(h k_1 - dy) + theta (dy - h k_7) + theta (1 - theta) h sum_i d_i k_i],
    # dy = h sum_i b_i k_i. As b_i(theta), a polynomial in theta without constant term:
    # theta b_i + theta (1 - theta) [(1 - theta)(delta_i1 - b_i) + theta (b_i - delta_i7)
    # + theta (1 - theta) d_i].
    d = np.array(
        [
            -12715105075.0 / 11282082432.0,
            0.0,
            87487479700.0 / 32700410799.0,
            -10690763975.0 / 1880347072.0,
            701980252875.0 / 199316789632.0,
            -1453857185.0 / 822651844.0,
            69997945.0 / 29380423.0,
        ]
    )
    first = np.eye(7)[0]
    last = np.eye(7)[6]
    u = first - b  # coefficient of theta (1 - theta)^2
    v = b - last  # coefficient of theta^2 (1 - theta)
    # theta b + u (theta - 2 theta^2 + theta^3) + v (theta^2 - theta^3)
    # + d (theta^2 - 2 theta^3 + theta^4)
    p = np.column_stack([b + u, -2.0 * u + v + d, u - v - 2.0 * d, d])
    c = np.array([0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0])
    return Tableau(c, a, b, b - b_hat, p, 4, 0.04)


DOPRI5 = make_dopri5_tableau()

# Indices into RkState.scal (float64).
S_T = 0  # current time t [s]
S_H = 1  # step being tried [s]
S_TNEW = 2  # end time of the step being tried [s] (== t_stop exactly when it hits)
S_HNEXT = 3  # proposed next step [s]
S_ERRPREV = 4  # error norm of the last accepted step
S_TOLD = 5  # start time of the last accepted step [s]
S_HOLD = 6  # length of the last accepted step [s] (0: none yet, no dense output)
N_SCAL = 7
# Indices into RkState.count (int64).
C_NACCEPT = 0
C_NREJECT = 1
C_REJECTED = 2  # 1 if the last attempt was rejected (the next accept may not grow h)
C_HIT = 3  # 1 if the step being tried was cut to end on t_stop or t_land
N_COUNT = 4


class RkState(NamedTuple):
    """Work arrays of an explicit Runge-Kutta pair for ``n`` equations."""

    tableau: Tableau
    y: np.ndarray  # (n,) solution at scal[S_T]
    k: np.ndarray  # (stages, n) stage derivatives; k[0] = f(t, y)
    ystage: np.ndarray  # (n,) stage input; after the last stage, the new solution
    err: np.ndarray  # (n,) local error vector of the last step tried
    y_old: np.ndarray  # (n,) solution at the start of the last accepted step
    dense: np.ndarray  # (degree, n) h sum_i p[i, p] k_i of the last accepted step
    scal: np.ndarray  # (N_SCAL,) see S_*
    count: np.ndarray  # (N_COUNT,) int64, see C_*


def make_rk_state(n: int, tableau: Tableau = DOPRI5) -> RkState:
    """Allocate the work arrays for ``n`` equations (plain Python)."""
    stages, degree = tableau.p.shape
    return RkState(
        tableau=tableau,
        y=np.zeros(n),
        k=np.zeros((stages, n)),
        ystage=np.zeros(n),
        err=np.zeros(n),
        y_old=np.zeros(n),
        dense=np.zeros((degree, n)),
        scal=np.zeros(N_SCAL),
        count=np.zeros(N_COUNT, dtype=np.int64),
    )


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_start(st, t, y, f0, h):
    """Start, or restart after a discontinuity, from (t [s], y); forget all history.

    ``f0 = f(t, y)`` becomes ``k[0]``; ``h`` [s] is the first step to try. No dense output
    until the next accepted step.
    """
    for i in range(y.shape[0]):
        st.y[i] = y[i]
        st.k[0, i] = f0[i]
    st.scal[S_T] = t
    st.scal[S_H] = h
    st.scal[S_TNEW] = t
    st.scal[S_HNEXT] = h
    st.scal[S_ERRPREV] = ERR_PREV_MIN
    st.scal[S_TOLD] = t
    st.scal[S_HOLD] = 0.0
    st.count[C_REJECTED] = 0
    st.count[C_HIT] = 0


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_begin(st, h_max, h_min, t_stop, t_land):
    """Choose the step to try [s] within [h_min, h_max]; it lands on t_stop, or t_land if cheap.

    See ``stepsize.clip_step``.
    """
    t = st.scal[S_T]
    h = clip_step(t, st.scal[S_HNEXT], h_min, h_max, t_stop, t_land)
    st.scal[S_H] = h
    st.scal[S_TNEW] = step_end(t, h, t_stop, t_land)
    st.count[C_HIT] = 0 if st.scal[S_TNEW] == t + h else 1
    return h


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_stage(st, s):
    """Form the input of stage s (1 .. stages-1) in st.ystage; return its time [s]."""
    a = st.tableau.a
    h = st.scal[S_H]
    n = st.y.shape[0]
    for i in range(n):
        acc = 0.0
        for j in range(s):
            acc += a[s, j] * st.k[j, i]
        st.ystage[i] = st.y[i] + h * acc
    if s == st.k.shape[0] - 1:
        return st.scal[S_TNEW]
    return st.scal[S_T] + st.tableau.c[s] * h


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_error(st, rtol, atol):
    """Error norm of the step just computed (all stages filled); accept when <= 1."""
    e = st.tableau.e
    h = st.scal[S_H]
    for i in range(st.y.shape[0]):
        acc = 0.0
        for j in range(e.shape[0]):
            acc += e[j] * st.k[j, i]
        st.err[i] = h * acc
    return error_norm(st.err, st.y, st.ystage, rtol, atol)


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_accept(st, err):
    """Accept the step: dense output, advance t and y, FSAL, propose the next step.

    ``err`` may exceed 1 when the caller forces the acceptance (h at h_min).
    """
    tab = st.tableau
    h = st.scal[S_H]
    last = st.k.shape[0] - 1
    n = st.y.shape[0]
    for i in range(n):
        for d in range(tab.p.shape[1]):
            acc = 0.0
            for j in range(last + 1):
                acc += tab.p[j, d] * st.k[j, i]
            st.dense[d, i] = h * acc
        st.y_old[i] = st.y[i]
        st.y[i] = st.ystage[i]
        st.k[0, i] = st.k[last, i]
    fac = pi_factor(err, st.scal[S_ERRPREV], tab.order_embedded, tab.beta)
    if st.count[C_REJECTED] == 1:
        fac = min(fac, 1.0)
    h_next = h * fac
    if st.count[C_HIT] == 1 and fac >= 1.0:  # a step cut to land on t_stop proves nothing
        h_next = max(h_next, st.scal[S_HNEXT])
    st.scal[S_TOLD] = st.scal[S_T]
    st.scal[S_HOLD] = h
    st.scal[S_T] = st.scal[S_TNEW]
    st.scal[S_HNEXT] = h_next
    st.scal[S_ERRPREV] = max(err, ERR_PREV_MIN)
    st.count[C_NACCEPT] += 1
    st.count[C_REJECTED] = 0
    st.count[C_HIT] = 0


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_reject(st, err):
    """Reject the step (t, y, k[0] unchanged); return the new proposal [s]."""
    h_next = st.scal[S_H] * reject_factor(err, st.tableau.order_embedded)
    st.scal[S_HNEXT] = h_next
    st.count[C_NREJECT] += 1
    st.count[C_REJECTED] = 1
    st.count[C_HIT] = 0
    return h_next


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_interpolate(st, t_out, out):
    """Dense output at t_out [s] in the last accepted step (its end exactly: y).

    Before any accepted step since the (re)start, ``out`` is the current y.
    """
    n = st.y.shape[0]
    if st.scal[S_HOLD] == 0.0 or t_out == st.scal[S_T]:
        for i in range(n):
            out[i] = st.y[i]
        return
    theta = (t_out - st.scal[S_TOLD]) / st.scal[S_HOLD]
    degree = st.dense.shape[0]
    for i in range(n):
        acc = 0.0
        for d in range(degree - 1, -1, -1):  # Horner: sum_p dense[p] theta^(p+1)
            acc = (acc + st.dense[d, i]) * theta
        out[i] = st.y_old[i] + acc


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rk_interpolate_derivative(st, t_out, out):
    """Time derivative of the dense output at t_out [s] (k[0] before any step)."""
    n = st.y.shape[0]
    if st.scal[S_HOLD] == 0.0:
        for i in range(n):
            out[i] = st.k[0, i]
        return
    theta = (t_out - st.scal[S_TOLD]) / st.scal[S_HOLD]
    degree = st.dense.shape[0]
    for i in range(n):
        acc = 0.0
        for d in range(degree - 1, -1, -1):  # sum_p (p+1) dense[p] theta^p
            acc = acc * theta + (d + 1.0) * st.dense[d, i]
        out[i] = acc / st.scal[S_HOLD]
