"""Dormand-Prince 5(4) explicit Runge-Kutta kernels with dense output (phase API).

Method: the 7-stage, FSAL, embedded pair of Dormand & Prince, "A family of embedded
Runge-Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19-26. The 5th-order solution is
propagated, the 4th-order one only estimates the error. Step size: PI control (Hairer,
Norsett & Wanner, *Solving ODEs I*, 2nd ed., sec. II.4; see ``stepsize``). Dense output:
the 4th-order continuous extension of HNW I sec. II.6 (cubic Hermite through the step's end
values and slopes plus ``theta**2 (1-theta)**2 h sum_i D_i k_i``).

The right-hand side ``f(t, y)`` is evaluated by the caller between phases. Call sequence
(``st = make_dopri5_state(n)``; ``S_T`` etc. index ``st.scal``)::

    f(t0, y0) -> f0
    dopri5_start(st, t0, y0, f0, h0)             # also: restart after a discontinuity
    while st.scal[S_T] < t_end:
        h = dopri5_begin(st, h_max, h_min, t_stop)   # step to try; ends on t_stop exactly
        for s in range(1, 7):
            ts = dopri5_stage(st, s)             # writes st.ystage
            f(ts, st.ystage) -> st.k[s]          # stage 6: st.ystage is y_new, ts is t_new
        err = dopri5_error(st, rtol, atol)       # normalised: accept when err <= 1
        if err <= 1.0:                           # (or forced, e.g. h at h_min)
            dopri5_accept(st, err)               # y, t, k[0] (FSAL) advance; dense output
        else:                                    # NaN err lands here too
            dopri5_reject(st, err)               # st.scal[S_HNEXT] shrinks
    dopri5_interpolate(st, t_out, out)           # any t_out in the last accepted step

The step-by-step pieces (``stage_input``, ``error_estimate``, ``dense_prepare``,
``dense_eval``, ``dense_eval_derivative``) work on plain arrays and can be used without the
state.
"""

from typing import NamedTuple

import numpy as np
from numba import njit

from jointwear.kernels.stepsize import (
    BETA_DOPRI5,
    ERR_PREV_MIN,
    clip_step,
    error_norm,
    hits_stop,
    pi_factor,
    reject_factor,
)

# Butcher tableau, Dormand & Prince (1980), Table 2 (also HNW I, Table II.5.2).
C = np.array([0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0])
A = np.zeros((7, 7))
A[1, 0] = 1.0 / 5.0
A[2, :2] = [3.0 / 40.0, 9.0 / 40.0]
A[3, :3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0]
A[4, :4] = [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0]
A[5, :5] = [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0]
A[6, :6] = [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0]
# 5th-order weights (= last row of A: first same as last).
B = A[6].copy()
# 4th-order (embedded) weights.
BHAT = np.array(
    [
        5179.0 / 57600.0,
        0.0,
        7571.0 / 16695.0,
        393.0 / 640.0,
        -92097.0 / 339200.0,
        187.0 / 2100.0,
        1.0 / 40.0,
    ]
)
# Error weights: err = h * sum_j E_j k_j estimates the error of the 4th-order solution.
E = B - BHAT
# Dense-output weights D_i of the 4th-order continuous extension, HNW I sec. II.6 (as
# published with the authors' DOPRI5 code). The extension is
#   u(theta) = (1-theta) y0 + theta y1
#              + theta (1-theta) [(1-theta) (h k_1 - dy) + theta (dy - h k_7)
#                                 + theta (1-theta) h sum_i D_i k_i],   dy = y1 - y0.
D = np.array(
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

ORDER_EMBEDDED = 4  # order of the error estimate's solution (controller exponent 1/5)

# Indices into Dopri5State.scal (float64).
S_T = 0  # current time t [s]
S_H = 1  # step being tried [s] (set by dopri5_begin)
S_TNEW = 2  # end time of the step being tried [s] (== t_stop exactly when it hits)
S_HNEXT = 3  # proposed next step [s]
S_ERRPREV = 4  # error norm of the last accepted step
S_TOLD = 5  # start time of the last accepted step [s]
S_HOLD = 6  # length of the last accepted step [s] (0: none yet, no dense output)
N_SCAL = 7
# Indices into Dopri5State.count (int64).
C_NACCEPT = 0  # accepted steps
C_NREJECT = 1  # rejected steps
C_REJECTED = 2  # 1 if the last attempt was rejected (next accept may not grow h)
C_HIT = 3  # 1 if the step being tried ends on t_stop
N_COUNT = 4


class Dopri5State(NamedTuple):
    """Work arrays of the Dormand-Prince kernel (``n`` equations).

    Attributes
    ----------
    y : ndarray, shape (n,)
        Solution at ``scal[S_T]``.
    k : ndarray, shape (7, n)
        Stage derivatives; ``k[0] = f(t, y)``; the caller writes ``k[s]``.
    ystage : ndarray, shape (n,)
        Stage input written by ``dopri5_stage``; after stage 6, the new solution.
    err : ndarray, shape (n,)
        Local error vector of the last step tried.
    rcont : ndarray, shape (5, n)
        Dense output coefficients of the last accepted step.
    scal : ndarray, shape (N_SCAL,)
        Float scalars, see the ``S_*`` indices.
    count : ndarray, shape (N_COUNT,)
        Integer counters and flags, see the ``C_*`` indices.
    """

    y: np.ndarray
    k: np.ndarray
    ystage: np.ndarray
    err: np.ndarray
    rcont: np.ndarray
    scal: np.ndarray
    count: np.ndarray


def make_dopri5_state(n: int) -> Dopri5State:
    """Allocate the work arrays for ``n`` equations (plain Python)."""
    return Dopri5State(
        y=np.zeros(n),
        k=np.zeros((7, n)),
        ystage=np.zeros(n),
        err=np.zeros(n),
        rcont=np.zeros((5, n)),
        scal=np.zeros(N_SCAL),
        count=np.zeros(N_COUNT, dtype=np.int64),
    )


# --------------------------------------------------------------------------- array kernels


@njit(cache=True)
def stage_input(y: np.ndarray, k: np.ndarray, h: float, s: int, out: np.ndarray) -> None:
    """Input of stage ``s`` (1..6): ``out = y + h * sum_{j<s} A[s, j] k[j]``.

    ``y`` (n,) is the solution at the step start, ``k`` (7, n) the stage derivatives
    (``k[0] = f(t, y)``), ``h`` the step [s]; ``out`` must not alias ``y``. The caller then
    evaluates ``k[s] = f(t + C[s] h, out)``. For ``s = 6``, ``out`` is the 5th-order solution
    at ``t + h`` (FSAL: ``k[6]`` is ``f`` there and becomes the next step's ``k[0]``).
    """
    n = y.shape[0]
    for i in range(n):
        out[i] = 0.0
    for j in range(s):
        a = A[s, j]
        if a != 0.0:
            for i in range(n):
                out[i] += a * k[j, i]
    for i in range(n):
        out[i] = y[i] + h * out[i]


@njit(cache=True)
def error_estimate(k: np.ndarray, h: float, out: np.ndarray) -> None:
    """Local error vector ``out = h * sum_j E[j] k[j]`` (5th minus 4th order), units of y.

    ``k`` (7, n) holds all seven stage derivatives of the step, ``h`` is the step [s].
    """
    n = out.shape[0]
    for i in range(n):
        acc = 0.0
        for j in range(7):
            acc += E[j] * k[j, i]
        out[i] = h * acc


@njit(cache=True)
def dense_prepare(
    y0: np.ndarray, y1: np.ndarray, k: np.ndarray, h: float, rcont: np.ndarray
) -> None:
    """Coefficients of the continuous extension over an accepted step of length ``h`` [s].

    ``y0``, ``y1`` (n,) are the solution at the start and end, ``k`` (7, n) the stage
    derivatives with ``k[6] = f(t + h, y1)``. ``rcont`` (5, n) receives the rows
    ``y0, y1, h k_1 - dy, dy - h k_7, h sum_i D_i k_i`` with ``dy = y1 - y0``.
    """
    n = y0.shape[0]
    for i in range(n):
        dy = y1[i] - y0[i]
        acc = 0.0
        for j in range(7):
            acc += D[j] * k[j, i]
        rcont[0, i] = y0[i]
        rcont[1, i] = y1[i]
        rcont[2, i] = h * k[0, i] - dy
        rcont[3, i] = dy - h * k[6, i]
        rcont[4, i] = h * acc


@njit(cache=True)
def dense_eval(rcont: np.ndarray, theta: float, out: np.ndarray) -> None:
    """Continuous extension at ``t0 + theta h`` into ``out`` (n,), from ``rcont``.

    ``theta`` in [0, 1] (outside: extrapolation); the result is exactly ``y0`` at 0 and
    exactly ``y1`` at 1.
    """
    s = 1.0 - theta
    ts = theta * s
    for i in range(out.shape[0]):
        bracket = s * rcont[2, i] + theta * rcont[3, i] + ts * rcont[4, i]
        out[i] = s * rcont[0, i] + theta * rcont[1, i] + ts * bracket


@njit(cache=True)
def dense_eval_derivative(rcont: np.ndarray, theta: float, h: float, out: np.ndarray) -> None:
    """Time derivative ``du/dt`` (units of y per second) at ``t0 + theta h`` into ``out``.

    ``h`` [s] is the step the coefficients ``rcont`` were prepared with. Local error
    O(h**4); equals ``f`` exactly at ``theta = 0`` and 1 (Hermite conditions).
    """
    s = 1.0 - theta
    ts = theta * s
    dts = 1.0 - 2.0 * theta  # d(theta s)/d theta
    inv_h = 1.0 / h
    for i in range(out.shape[0]):
        a = rcont[2, i]
        b = rcont[3, i]
        c = rcont[4, i]
        bracket = s * a + theta * b + ts * c
        dbracket = b - a + dts * c
        du = rcont[1, i] - rcont[0, i] + dts * bracket + ts * dbracket
        out[i] = du * inv_h


# --------------------------------------------------------------------------- stateful phases


@njit(cache=True)
def dopri5_start(st: Dopri5State, t: float, y: np.ndarray, f0: np.ndarray, h: float) -> None:
    """Start, or restart after a discontinuity, from ``(t, y)``; forget all history.

    ``f0 = f(t, y)`` is evaluated by the caller (it becomes ``k[0]``); ``h`` [s] is the
    first step to try. Dense output is unavailable until the next accepted step.
    """
    st.y[:] = y
    st.k[0, :] = f0
    st.scal[S_T] = t
    st.scal[S_H] = h
    st.scal[S_TNEW] = t
    st.scal[S_HNEXT] = h
    st.scal[S_ERRPREV] = ERR_PREV_MIN
    st.scal[S_TOLD] = t
    st.scal[S_HOLD] = 0.0
    st.count[C_REJECTED] = 0
    st.count[C_HIT] = 0


@njit(cache=True)
def dopri5_begin(st: Dopri5State, h_max: float, h_min: float, t_stop: float) -> float:
    """Choose the step to try from the proposal ``scal[S_HNEXT]``; return it [s].

    The proposal is bounded by ``h_min`` and ``h_max`` [s] and cut (or stretched by at most
    1 %) to end on ``t_stop`` (> t) [s], in which case ``scal[S_TNEW]`` is ``t_stop``
    exactly. The step is stored in ``scal[S_H]``.
    """
    t = st.scal[S_T]
    h = clip_step(t, st.scal[S_HNEXT], h_min, h_max, t_stop)
    st.scal[S_H] = h
    if hits_stop(t, h, t_stop):
        st.scal[S_TNEW] = t_stop
        st.count[C_HIT] = 1
    else:
        st.scal[S_TNEW] = t + h
        st.count[C_HIT] = 0
    return h


@njit(cache=True)
def dopri5_stage(st: Dopri5State, s: int) -> float:
    """Form the input of stage ``s`` (1..6) in ``st.ystage``; return its time [s].

    The caller then writes ``f(ts, st.ystage)`` into ``st.k[s]``. At ``s = 6`` the input is
    the new solution and the time is ``scal[S_TNEW]`` exactly.
    """
    stage_input(st.y, st.k, st.scal[S_H], s, st.ystage)
    if s == 6:
        return st.scal[S_TNEW]
    return st.scal[S_T] + C[s] * st.scal[S_H]


@njit(cache=True)
def dopri5_error(st: Dopri5State, rtol: float, atol: float) -> float:
    """Error norm of the step just computed (all of ``k[0..6]`` filled).

    ``rtol`` [-] and ``atol`` (units of y) as in ``stepsize.error_norm``. Accept the step
    when the result is <= 1; it is NaN or inf when a stage was not finite.
    """
    error_estimate(st.k, st.scal[S_H], st.err)
    return error_norm(st.err, st.y, st.ystage, rtol, atol)


@njit(cache=True)
def dopri5_accept(st: Dopri5State, err: float) -> None:
    """Accept the step: dense output, advance ``t`` and ``y``, FSAL, propose next step.

    ``err`` is the norm from ``dopri5_error`` (it may exceed 1 when the caller forces the
    acceptance, e.g. at ``h_min``).
    """
    h = st.scal[S_H]
    dense_prepare(st.y, st.ystage, st.k, h, st.rcont)
    fac = pi_factor(err, st.scal[S_ERRPREV], ORDER_EMBEDDED, BETA_DOPRI5)
    if st.count[C_REJECTED] == 1:
        fac = min(fac, 1.0)
    h_next = h * fac
    # A step shortened to land on t_stop says nothing against the earlier proposal.
    if st.count[C_HIT] == 1 and fac >= 1.0:
        h_next = max(h_next, st.scal[S_HNEXT])
    st.scal[S_TOLD] = st.scal[S_T]
    st.scal[S_HOLD] = h
    st.scal[S_T] = st.scal[S_TNEW]
    st.scal[S_HNEXT] = h_next
    st.scal[S_ERRPREV] = max(err, ERR_PREV_MIN)
    st.y[:] = st.ystage
    st.k[0, :] = st.k[6]
    st.count[C_NACCEPT] += 1
    st.count[C_REJECTED] = 0
    st.count[C_HIT] = 0


@njit(cache=True)
def dopri5_reject(st: Dopri5State, err: float) -> float:
    """Reject the step (``t``, ``y``, ``k[0]`` unchanged); return the new proposal [s]."""
    h_next = st.scal[S_H] * reject_factor(err, ORDER_EMBEDDED)
    st.scal[S_HNEXT] = h_next
    st.count[C_NREJECT] += 1
    st.count[C_REJECTED] = 1
    st.count[C_HIT] = 0
    return h_next


@njit(cache=True)
def _theta(st: Dopri5State, t_out: float) -> float:
    """Fraction of the last accepted step at ``t_out`` (exactly 1 at its end)."""
    if t_out == st.scal[S_T]:
        return 1.0
    return (t_out - st.scal[S_TOLD]) / st.scal[S_HOLD]


@njit(cache=True)
def dopri5_interpolate(st: Dopri5State, t_out: float, out: np.ndarray) -> None:
    """Dense output at ``t_out`` [s] in the last accepted step ``[scal[S_TOLD], scal[S_T]]``.

    Exact at both ends; valid until the next accept (begin, stages and reject do not disturb
    it). Before any accepted step (``scal[S_HOLD] == 0``) ``out`` is the current ``y``.
    """
    if st.scal[S_HOLD] == 0.0:
        out[:] = st.y
    else:
        dense_eval(st.rcont, _theta(st, t_out), out)


@njit(cache=True)
def dopri5_interpolate_derivative(st: Dopri5State, t_out: float, out: np.ndarray) -> None:
    """Time derivative of the dense output at ``t_out`` (``k[0]`` before any step)."""
    if st.scal[S_HOLD] == 0.0:
        out[:] = st.k[0]
    else:
        dense_eval_derivative(st.rcont, _theta(st, t_out), st.scal[S_HOLD], out)
