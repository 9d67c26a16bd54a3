"""The compiled step loop: integrate a chunk, locate events, write output rows.

``advance`` runs until the chunk's stop time, the end of the run, a full output buffer or a
failure, and returns a ``Status`` and the number of rows written. The Python side calls it
chunk after chunk (progress, Ctrl-C and saving happen in between); all persistent state lives
in the arrays passed in, so a chunk can stop and the next one goes on exactly where it was.

Minimum step (SPEC sec. 2): when the error test fails at ``min_step`` the step is accepted
anyway and counted in ``Counter.MIN_STEP_HITS``.
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from . import abm, dopri5
from .codes import Counter, EventDirection, Method, Status
from .dynamics import constraint_norm, rhs
from .outputs import write_row

ACCEPTED = 0
REJECTED = 1
EVENT_TIME_TOLERANCE = 1e-13  # relative bracket width at which a crossing is located [-]
MAX_EVENT_ITERATIONS = 100


class Control(NamedTuple):
    """Solver settings (SI)."""

    method: int  # Method
    rtol: float
    atol: float
    min_step: float  # [s]
    max_step: float  # [s]
    t_end: float  # [s]
    max_steps: int
    output_times: np.ndarray  # (rows,) times of the output rows [s], increasing
    rows_per_step: int  # most rows one step can produce (buffer reserve)


class LoopState(NamedTuple):
    """Persistent loop state besides the integrator's own (updated in place)."""

    counters: np.ndarray  # (N_COUNTERS,) int64, see Counter
    max_violation: np.ndarray  # (1,) largest 2-norm of Phi after an accepted step
    y_pred: np.ndarray  # (N,) ABM prediction
    yp_pred: np.ndarray  # (N,)
    y_corr: np.ndarray  # (N,) ABM correction
    yp_corr: np.ndarray  # (N,)
    y_scratch: np.ndarray  # (N,) interpolated states (events, output rows)
    yp_scratch: np.ndarray  # (N,)
    event_prev: np.ndarray  # (ne,) event function values at the current time
    event_time: np.ndarray  # (cap,) crossings logged during this chunk [s]
    event_index: np.ndarray  # (cap,) int64 event number
    event_rising: np.ndarray  # (cap,) int64 1 rising, 0 falling


@njit(cache=True)
def current_time(ctl, dp, ab):
    """Time reached by the integrator [s]."""
    if ctl.method == Method.DOPRI5:
        return dp.scal[dopri5.S_T]
    return ab.scal[abm.S_T]


@njit(cache=True)
def current_state(ctl, dp, ab):
    """State (q, q') reached by the integrator (a view)."""
    if ctl.method == Method.DOPRI5:
        return dp.y
    return ab.y


@njit(cache=True)
def interpolate(ctl, dp, ab, t, out):
    """Dense output of the last accepted step at time t [s] into out."""
    if t == current_time(ctl, dp, ab):
        out[:] = current_state(ctl, dp, ab)
    elif ctl.method == Method.DOPRI5:
        dopri5.dopri5_interpolate(dp, t, out)
    else:
        abm.abm_interpolate(ab, t, out)


@njit(cache=True)
def event_value(sys, e, y):
    """Event function e: the watched coordinate minus its value."""
    return y[3 * sys.event_body[e] + sys.event_coordinate[e]] - sys.event_value[e]


@njit(cache=True)
def start(sys, ctl, ls, dp, ab, wk, t0, y0, h0):
    """Begin a run at (t0, y0) with first step h0 [s]; returns False if the solve fails."""
    ok = rhs(t0, y0, sys, wk, ls.yp_scratch)
    ls.counters[Counter.RHS_EVALS] += 1
    dopri5.dopri5_start(dp, t0, y0, ls.yp_scratch, h0)
    abm.abm_start(ab, t0, y0, ls.yp_scratch, h0)
    for e in range(ls.event_prev.shape[0]):
        ls.event_prev[e] = event_value(sys, e, y0)
    return ok


@njit(cache=True)
def _at_min_step(h, ctl):
    return h <= ctl.min_step * (1.0 + 1e-12)


@njit(cache=True)
def _forced(h, err, ctl, ls):
    """Whether a failed error test is accepted anyway because h is at the minimum step."""
    if _at_min_step(h, ctl) and math.isfinite(err):
        ls.counters[Counter.MIN_STEP_HITS] += 1
        return True
    return False


@njit(cache=True)
def _step_dopri5(sys, ctl, ls, dp, wk, t_stop):
    h = dopri5.dopri5_begin(dp, ctl.max_step, ctl.min_step, t_stop)
    for s in range(1, 7):
        ts = dopri5.dopri5_stage(dp, s)
        ls.counters[Counter.RHS_EVALS] += 1
        if not rhs(ts, dp.ystage, sys, wk, dp.k[s]):
            if _at_min_step(h, ctl):
                return -Status.SINGULAR
            dopri5.dopri5_reject(dp, math.inf)  # a trial state near a dead centre: shorten
            return REJECTED
    err = dopri5.dopri5_error(dp, ctl.rtol, ctl.atol)
    if err <= 1.0 or _forced(h, err, ctl, ls):
        dopri5.dopri5_accept(dp, err)
        return ACCEPTED
    if _at_min_step(h, ctl):
        return -Status.NON_FINITE
    dopri5.dopri5_reject(dp, err)
    return REJECTED


@njit(cache=True)
def _step_abm(sys, ctl, ls, ab, wk, t_stop):
    t_new = abm.abm_predict(ab, ctl.max_step, ctl.min_step, t_stop, ls.y_pred)
    h = ab.scal[abm.S_H]
    ls.counters[Counter.RHS_EVALS] += 1
    if not rhs(t_new, ls.y_pred, sys, wk, ls.yp_pred):
        if _at_min_step(h, ctl):
            return -Status.SINGULAR
        abm.abm_reject(ab)  # a predicted state near a dead centre: shorten
        return REJECTED
    err = abm.abm_correct(ab, ls.yp_pred, ctl.rtol, ctl.atol, ls.y_corr)
    if err <= 1.0 or _forced(h, err, ctl, ls):
        ls.counters[Counter.RHS_EVALS] += 1
        if not rhs(t_new, ls.y_corr, sys, wk, ls.yp_corr):
            return -Status.SINGULAR
        abm.abm_accept(ab, ls.y_corr, ls.yp_corr)
        return ACCEPTED
    if _at_min_step(h, ctl):
        return -Status.NON_FINITE
    abm.abm_reject(ab)
    return REJECTED


@njit(cache=True)
def _locate(sys, ctl, ls, dp, ab, e, ta, ga, tb, gb):
    """Crossing time of event e in [ta, tb] by the Illinois method on the dense output."""
    side = 0
    for _ in range(MAX_EVENT_ITERATIONS):
        if tb - ta <= EVENT_TIME_TOLERANCE * max(1.0, abs(tb)):
            break
        tc = tb - gb * (tb - ta) / (gb - ga)
        tc = min(max(tc, ta), tb)
        interpolate(ctl, dp, ab, tc, ls.y_scratch)
        gc = event_value(sys, e, ls.y_scratch)
        if gc == 0.0:
            return tc
        if (gc < 0.0) == (gb < 0.0):
            tb, gb = tc, gc
            if side == 1:
                ga *= 0.5
            side = 1
        else:
            ta, ga = tc, gc
            if side == -1:
                gb *= 0.5
            side = -1
    return tb


@njit(cache=True)
def _log_events(sys, ctl, ls, dp, ab, t_old, t_new, y_new):
    for e in range(ls.event_prev.shape[0]):
        g0 = ls.event_prev[e]
        g1 = event_value(sys, e, y_new)
        ls.event_prev[e] = g1
        rising = g0 < 0.0 <= g1
        falling = g0 > 0.0 >= g1
        wanted = sys.event_direction[e]
        if (rising and wanted != EventDirection.FALLING) or (
            falling and wanted != EventDirection.RISING
        ):
            slot = ls.counters[Counter.EVENTS]
            ls.event_time[slot] = _locate(sys, ctl, ls, dp, ab, e, t_old, g0, t_new, g1)
            ls.event_index[slot] = e
            ls.event_rising[slot] = 1 if rising else 0
            ls.counters[Counter.EVENTS] += 1


@njit(cache=True)
def advance(sys, ctl, ls, dp, ab, wk, out, t_stop, step_stop):
    """Integrate past t_stop [s] (or to the end); return (Status, rows written into out).

    The chunk also hands back once the step count (accepted + rejected) reaches step_stop.

    Steps are never shortened to land on t_stop, only on the end time, so the solution does
    not depend on how the run is cut into chunks.
    """
    rows = 0
    n_out = ctl.output_times.shape[0]
    n_events = ls.event_prev.shape[0]
    while True:
        t = current_time(ctl, dp, ab)
        k = ls.counters[Counter.OUTPUT_ROWS]
        while k < n_out and ctl.output_times[k] <= t:
            interpolate(ctl, dp, ab, ctl.output_times[k], ls.y_scratch)
            if not write_row(ctl.output_times[k], ls.y_scratch, sys, wk, ls.yp_scratch, out[rows]):
                return Status.SINGULAR, rows
            rows += 1
            k += 1
            ls.counters[Counter.OUTPUT_ROWS] = k
        if t >= ctl.t_end:
            return Status.SUCCESS, rows
        if t >= t_stop:
            return Status.RUNNING, rows
        full = rows + ctl.rows_per_step > out.shape[0]
        if full or ls.counters[Counter.EVENTS] + n_events > ls.event_time.shape[0]:
            return Status.RUNNING, rows
        steps = ls.counters[Counter.ACCEPTED] + ls.counters[Counter.REJECTED]
        if steps >= ctl.max_steps:
            return Status.MAX_STEPS, rows
        if steps >= step_stop:
            return Status.RUNNING, rows
        if ctl.method == Method.DOPRI5:
            outcome = _step_dopri5(sys, ctl, ls, dp, wk, ctl.t_end)
        else:
            outcome = _step_abm(sys, ctl, ls, ab, wk, ctl.t_end)
        if outcome == REJECTED:
            ls.counters[Counter.REJECTED] += 1
            continue
        if outcome < 0:
            return -outcome, rows
        ls.counters[Counter.ACCEPTED] += 1
        ls.max_violation[0] = max(ls.max_violation[0], constraint_norm(wk))
        y_new = current_state(ctl, dp, ab)
        for i in range(y_new.shape[0]):
            if not math.isfinite(y_new[i]):
                return Status.NON_FINITE, rows
        _log_events(sys, ctl, ls, dp, ab, t, current_time(ctl, dp, ab), y_new)
