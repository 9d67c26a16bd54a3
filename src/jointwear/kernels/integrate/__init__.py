"""The integrator interface the step loop sees: one set of functions, whatever the method.

An integrator is its state (``RkState`` of a tableau, or ``AbmState``); each function below
is chosen by the state's type when the loop is compiled, so the loop never branches on the
method and a run compiles only the method it uses. The contract, for a method module:

1. ``start(st, t, y, f0, h)``: begin at (t, y) with f0 = f(t, y) and first step h [s].
2. ``restart(st, t, y, f0, h_last, h_min)``: begin again after a discontinuity at t (a
   contact onset), knowing the last step h_last [s].
3. ``attempt(st, problem, ctl, counters, t_land)``: try one step, evaluating the right-hand
   side ``dynamics.rhs`` on ``problem``; return ``ACCEPTED``, ``REJECTED`` or minus a
   ``Status``. The step never passes ``ctl.t_end``, and ends exactly on ``t_land`` (the
   next output row) when that shortens it a little (``stepsize.clip_step``). A failed error
   test at ``ctl.min_step`` is accepted and counted.
4. ``current_time(st)``, ``current_state(st)``: where the last accepted step ended;
   ``current_derivative(st)``: f there, from the step's last evaluation of the right-hand
   side, which was at that state (before ``dynamics.project`` moves it).
5. ``step_start(st)``: time [s] and state where the last accepted step began.
6. ``interpolate(st, t, out)``: dense output inside the last accepted step;
   ``interpolate_ends(st, t, out)``: an interpolant exact at both ends of that step (for
   the contact logic).
"""

import math

from numba import njit

from ..codes import Counter, Status
from ..dynamics import rhs
from ..structs import by_kind
from .abm import (
    S_H,
    S_HOLD,
    AbmState,
    abm_accept,
    abm_correct,
    abm_interpolate,
    abm_interpolate_ends,
    abm_predict,
    abm_reject,
    abm_start,
)
from .rk import (
    S_T,
    S_TOLD,
    RkState,
    rk_accept,
    rk_begin,
    rk_error,
    rk_interpolate,
    rk_reject,
    rk_stage,
    rk_start,
)

ACCEPTED = 0
REJECTED = 1
ABM_RESTART_FRACTION = 0.25  # first Adams step after an onset, of the step cut there (order 1)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _forced(h, err, ctl, counters):
    """Whether a failed error test is accepted anyway because h is at the minimum step."""
    if h <= ctl.min_step * (1.0 + 1e-12) and err <= 1e300:
        counters[Counter.MIN_STEP_HITS] += 1
        return True
    return False


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _rk_attempt(st, problem, ctl, counters, t_land):
    h = rk_begin(st, ctl.max_step, ctl.min_step, ctl.t_end, t_land)
    min_step = h <= ctl.min_step * (1.0 + 1e-12)
    for s in range(1, st.k.shape[0]):
        ts = rk_stage(st, s)
        counters[Counter.RHS_EVALS] += 1
        if not rhs(ts, st.ystage, problem, st.k[s]):
            if min_step:
                return -Status.SINGULAR
            rk_reject(st, math.inf)  # a trial state near a dead centre: shorten
            return REJECTED
    err = rk_error(st, ctl.rtol, ctl.atol)
    if err <= 1.0 or _forced(h, err, ctl, counters):
        rk_accept(st, err)
        return ACCEPTED
    if min_step:
        return -Status.NON_FINITE
    rk_reject(st, err)
    return REJECTED


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _abm_attempt(st, problem, ctl, counters, t_land):
    t_new = abm_predict(st, ctl.max_step, ctl.min_step, ctl.t_end, t_land, st.p)
    h = st.scal[S_H]
    min_step = h <= ctl.min_step * (1.0 + 1e-12)
    counters[Counter.RHS_EVALS] += 1
    if not rhs(t_new, st.p, problem, st.fp):
        if min_step:
            return -Status.SINGULAR
        abm_reject(st)  # a predicted state near a dead centre: shorten
        return REJECTED
    err = abm_correct(st, st.fp, ctl.rtol, ctl.atol, st.y_corr)
    if err <= 1.0 or _forced(h, err, ctl, counters):
        counters[Counter.RHS_EVALS] += 1
        if not rhs(t_new, st.y_corr, problem, st.yp_corr):
            return -Status.SINGULAR
        abm_accept(st, st.y_corr, st.yp_corr)
        return ACCEPTED
    if min_step:
        return -Status.NON_FINITE
    abm_reject(st)
    return REJECTED


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _rk_restart(st, t, y, f0, h_last, h_min):
    rk_start(st, t, y, f0, h_last)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _abm_restart(st, t, y, f0, h_last, h_min):
    abm_start(st, t, y, f0, max(ABM_RESTART_FRACTION * h_last, h_min))


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _rk_step_start(st):
    return st.scal[S_TOLD], st.y_old


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _abm_step_start(st):
    return st.scal[S_T] - st.scal[S_HOLD], st.y_old


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _time(st):
    return st.scal[S_T]  # the same slot in both methods


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _state(st):
    return st.y


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _rk_derivative(st):
    return st.k[0]  # FSAL: the last stage, moved to the first by rk_accept


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _abm_derivative(st):
    return st.yp


_METHODS = {
    RkState.__name__: {
        "start": rk_start,
        "restart": _rk_restart,
        "attempt": _rk_attempt,
        "step_start": _rk_step_start,
        "current_derivative": _rk_derivative,
        "interpolate": rk_interpolate,
        "interpolate_ends": rk_interpolate,  # passes through both ends already
    },
    AbmState.__name__: {
        "start": abm_start,
        "restart": _abm_restart,
        "attempt": _abm_attempt,
        "step_start": _abm_step_start,
        "current_derivative": _abm_derivative,
        "interpolate": abm_interpolate,
        "interpolate_ends": abm_interpolate_ends,
    },
}


def start(st, t, y, f0, h):
    """Begin at (t [s], y), f0 = f(t, y), first step h [s]."""


def restart(st, t, y, f0, h_last, h_min):
    """Begin again at (t [s], y) after a discontinuity; h_last, h_min [s]."""


def attempt(st, problem, ctl, counters, t_land):
    """Try one step (landing on t_land [s] when cheap); ACCEPTED, REJECTED, or minus a Status."""


def step_start(st):
    """(time [s], state) where the last accepted step began."""


def interpolate(st, t, out):
    """Dense output at t [s] inside the last accepted step, into out."""


def interpolate_ends(st, t, out):
    """An interpolant at t [s] exact at both ends of the last accepted step, into out."""


def current_time(st):
    """Time reached [s]."""


def current_state(st):
    """State reached (a view of the integrator's array)."""


def current_derivative(st):
    """Derivative at the state reached, as the step evaluated it (the integrator's array)."""


for _methods in _METHODS.values():
    _methods["current_time"] = _time
    _methods["current_state"] = _state
for _stub in (
    start, restart, attempt, step_start, interpolate, interpolate_ends, current_time,
    current_state, current_derivative,
):  # fmt: skip
    by_kind(_stub, {kind: methods[_stub.__name__] for kind, methods in _METHODS.items()})
