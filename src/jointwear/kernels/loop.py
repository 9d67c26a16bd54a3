"""The compiled step loop: integrate a chunk, locate events, write output rows.

``advance`` runs until the chunk's stop time, the end of the run, a full output buffer or a
failure, and returns a ``Status`` and the number of rows written. The Python side calls it
chunk after chunk (progress, Ctrl-C and saving happen in between); all persistent state lives
in the arrays passed in, so a chunk can stop and the next one goes on exactly where it was.

Minimum step (SPEC sec. 2): when the error test fails at ``min_step`` the step is accepted
anyway and counted in ``Counter.MIN_STEP_HITS``.

Clearance joints (``kernels.contact_steps``): when a step ends with a joint in free flight
penetrating past the contact tolerance, the onset is located on the dense output (to within
the tolerance in penetration), the step is cut there, the contact period begins with the
penetration rate of that instant, and the integrator restarts from it. After every accepted
step the wear of the step is added to the surfaces.
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from . import abm, dopri5
from .borrow import borrow
from .codes import Counter, EventDirection, Method, Status
from .contact_steps import accumulate_step, begin_periods, penetration_excess
from .dynamics import constraint_norm, rhs
from .joint_contact import P_TOL
from .outputs import write_row

ACCEPTED = 0
REJECTED = 1
EVENT_TIME_TOLERANCE = 1e-13  # relative bracket width at which a crossing is located [-]
MAX_EVENT_ITERATIONS = 100
ABM_RESTART_FRACTION = 0.25  # first step after a contact onset, of the step cut there (order 1)


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
    snapshot_times: np.ndarray  # (ns,) times of the wear snapshots [s], increasing


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
    y_cut: np.ndarray  # (N,) state where a step is cut at a contact onset or separation
    y_mid: np.ndarray  # (N,) state at the middle of the step (or of its part before a cut)
    t_old: np.ndarray  # (1,) start of the step being taken [s] (with clearance joints)
    y_old: np.ndarray  # (N,) state there
    yp_old: np.ndarray  # (N,) its derivative
    contact_totals: np.ndarray  # (nc, N_TOTALS) per clearance joint, contact_steps.T_*
    impact_time: np.ndarray  # (cap,) contact onsets logged during this chunk [s]
    impact_joint: np.ndarray  # (cap,) int64 clearance joint
    impact_info: np.ndarray  # (cap, N_IMPACT_INFO) contact_steps.I_* of each onset
    wear_snapshots: np.ndarray  # (ns, nc, 2, max sectors) wear depths at snapshot_times [m]


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
def contact_state(ctl, ls, dp, ab, t, out):
    """State at time t [s] inside the last accepted step, for the contact logic.

    The Dormand-Prince dense output passes through both ends of its step; the Adams
    interpolant is not exact at the start of its step (it integrates the corrected
    derivative), which can put a penetration on the wrong side of an onset. For ``abm`` the
    cubic Hermite interpolant of (y, y') at the step's two ends is used instead.
    """
    t_new = current_time(ctl, dp, ab)
    if ctl.method == Method.DOPRI5 or t == t_new:
        interpolate(ctl, dp, ab, t, out)
        return
    t_old = ls.t_old[0]
    h = t_new - t_old
    s = (t - t_old) / h
    s2 = s * s
    s3 = s2 * s
    w_y0 = 2.0 * s3 - 3.0 * s2 + 1.0
    w_f0 = (s3 - 2.0 * s2 + s) * h
    w_y1 = 3.0 * s2 - 2.0 * s3
    w_f1 = (s3 - s2) * h
    for i in range(out.shape[0]):
        out[i] = w_y0 * ls.y_old[i] + w_f0 * ls.yp_old[i] + w_y1 * ab.y[i] + w_f1 * ab.yp[i]


@njit(cache=True)
def current_derivative(ctl, dp, ab):
    """Derivative y' at the time reached (a view)."""
    if ctl.method == Method.DOPRI5:
        return dp.k[0]
    return ab.yp


@njit(cache=True)
def event_value(sys, e, y):
    """Event function e: the watched coordinate minus its value."""
    return y[3 * sys.event_body[e] + sys.event_coordinate[e]] - sys.event_value[e]


@njit(cache=True)
def start(sys, ctl, ls, dp, ab, wk, t0, y0, h0):
    """Begin a run at (t0, y0) with first step h0 [s]; returns False if the solve fails."""
    begin_periods(sys, ls, wk, t0, y0)
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
def _crossing_value(sys, wk, e, y):
    """Event function e: user events, then per clearance joint its onset, then its separation.

    Onset of joint k: penetration minus the contact tolerance; separation: the penetration.
    """
    n_user = sys.event_body.shape[0]
    nc = sys.clearance_body.shape[0]
    if e < n_user:
        return event_value(sys, e, y)
    if e < n_user + nc:
        return penetration_excess(sys, wk, e - n_user, y)
    k = e - n_user - nc
    return penetration_excess(sys, wk, k, y) + sys.clearance_param[k, P_TOL]


@njit(cache=True)
def _locate(sys, ctl, ls, dp, ab, wk, e, ta, ga, tb, gb, g_tol):
    """Crossing time of event e in [ta, tb] by the Illinois method on the dense output.

    Stops when the bracket is at the time tolerance or abs(g(tb)) <= g_tol; returns tb, the
    end on the far side of the crossing: g > 0 there for a rising crossing (g(tb) > 0), g <= 0
    for a falling one. With g_tol = 0 an exact zero is returned at once.
    """
    rising = gb > 0.0
    g_far = gb  # g at tb; gb itself may be halved by the Illinois modification
    side = 0
    for _ in range(MAX_EVENT_ITERATIONS):
        if tb - ta <= EVENT_TIME_TOLERANCE * max(1.0, abs(tb)) or abs(g_far) <= g_tol:
            break
        tc = tb - gb * (tb - ta) / (gb - ga)
        tc = min(max(tc, ta), tb)
        if e < sys.event_body.shape[0]:
            interpolate(ctl, dp, ab, tc, ls.y_scratch)
        else:
            contact_state(ctl, ls, dp, ab, tc, ls.y_scratch)
        gc = _crossing_value(sys, wk, e, ls.y_scratch)
        if gc == 0.0 and g_tol == 0.0:
            return tc
        if (gc > 0.0) == rising:
            tb, gb, g_far = tc, gc, gc
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
def _log_events(sys, ctl, ls, dp, ab, wk, t_old, t_new, y_new):
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
            ls.event_time[slot] = _locate(sys, ctl, ls, dp, ab, wk, e, t_old, g0, t_new, g1, 0.0)
            ls.event_index[slot] = e
            ls.event_rising[slot] = 1 if rising else 0
            ls.counters[Counter.EVENTS] += 1


@njit(cache=True)
def _contact_cut(sys, ctl, ls, dp, ab, wk, t_old, t_new, y_new):
    """Earliest change of contact inside the step just accepted [s], or t_new if there is none.

    Also returns whether ls.y_mid now holds the state at the step's midpoint.

    - Onset: a joint in free flight penetrates past the tolerance at the step end; located to
      within the tolerance in penetration, from the state before the step (ls.y_old: the
      Adams interpolant is not exact at the start of its step).
    - Rebound: a joint in contact has no penetration at the step's midpoint but has it again
      at the end; the separation is located where the penetration reaches zero (to within
      the tolerance), so that the period closes there and the new impact is located as an
      onset. A rebound that misses the midpoint goes unseen; steps are short in contact.
    """
    n_user = sys.event_body.shape[0]
    nc = sys.clearance_body.shape[0]
    t_mid = 0.5 * (t_old + t_new)
    t_first = t_new
    midpoint_known = False
    for k in range(nc):
        tol = sys.clearance_param[k, P_TOL]
        g1 = penetration_excess(sys, wk, k, y_new)
        if not wk.contact_on[k]:
            if g1 > 0.0:
                g0 = min(penetration_excess(sys, wk, k, ls.y_old), 0.0)  # periods open above tol
                t_hit = _locate(sys, ctl, ls, dp, ab, wk, n_user + k, t_old, g0, t_new, g1, tol)
                t_first = min(t_first, t_hit)
            continue
        if g1 + tol <= 0.0:
            continue  # the period ends at the step end
        if not midpoint_known:
            contact_state(ctl, ls, dp, ab, t_mid, ls.y_mid)
            midpoint_known = True
        depth_mid = penetration_excess(sys, wk, k, ls.y_mid) + tol
        if depth_mid <= 0.0:
            depth_old = penetration_excess(sys, wk, k, ls.y_old) + tol  # > 0 in a period
            e = n_user + nc + k
            t_gap = _locate(sys, ctl, ls, dp, ab, wk, e, t_old, depth_old, t_mid, depth_mid, tol)
            t_first = min(t_first, t_gap)
    return t_first, midpoint_known


@njit(cache=True)
def _write_rows(sys, ctl, ls, dp, ab, wk, out, rows, t):
    """Write the output rows due by time t [s]; return (row count, False if singular)."""
    k = ls.counters[Counter.OUTPUT_ROWS]
    while k < ctl.output_times.shape[0] and ctl.output_times[k] <= t:
        interpolate(ctl, dp, ab, ctl.output_times[k], ls.y_scratch)
        if not write_row(ctl.output_times[k], ls.y_scratch, sys, wk, ls.yp_scratch, out[rows]):
            return rows, False
        rows += 1
        k += 1
        ls.counters[Counter.OUTPUT_ROWS] = k
    return rows, True


@njit(cache=True)
def _after_step(sys, ctl, ls, dp, ab, wk, out, rows, t_old, h):
    """Contact onsets, wear, events and rows of the step just accepted.

    Returns (rows, False if singular). At an onset the step is cut there: the rows and events
    up to it are written from this step's dense output, and the integrator restarts from the
    cut.
    """
    t_new = current_time(ctl, dp, ab)
    y_new = current_state(ctl, dp, ab)
    nc = sys.clearance_body.shape[0]
    t_cut, midpoint_known = t_new, False
    if nc:
        t_cut, midpoint_known = _contact_cut(sys, ctl, ls, dp, ab, wk, t_old, t_new, y_new)
    if t_cut < t_new:
        contact_state(ctl, ls, dp, ab, t_cut, ls.y_cut)
    else:
        ls.y_cut[:] = y_new
    if nc:
        if t_cut < t_new or not midpoint_known:
            contact_state(ctl, ls, dp, ab, 0.5 * (t_old + t_cut), ls.y_mid)
        accumulate_step(sys, ctl, ls, wk, t_old, t_cut, ls.y_mid)
    _log_events(sys, ctl, ls, dp, ab, wk, t_old, t_cut, ls.y_cut)
    # The step's rows see the contact periods as the step did, before they open or close.
    rows, ok = _write_rows(sys, ctl, ls, dp, ab, wk, out, rows, t_cut)
    if not ok:
        return rows, False
    if t_cut == t_new:
        if nc:
            begin_periods(sys, ls, wk, t_new, y_new)
        return rows, True
    begin_periods(sys, ls, wk, t_cut, ls.y_cut)
    ls.counters[Counter.RHS_EVALS] += 1
    if not rhs(t_cut, ls.y_cut, sys, wk, ls.yp_scratch):
        return rows, False
    if ctl.method == Method.DOPRI5:
        dopri5.dopri5_start(dp, t_cut, ls.y_cut, ls.yp_scratch, h)
    else:
        h_abm = max(ABM_RESTART_FRACTION * h, ctl.min_step)
        abm.abm_start(ab, t_cut, ls.y_cut, ls.yp_scratch, h_abm)
    return rows, True


@njit(cache=True)
def advance(sys, ctl, ls, dp, ab, wk, out, t_stop, step_stop):
    """Integrate past t_stop [s] (or to the end); return (Status, rows written into out).

    The chunk also hands back once the step count (accepted + rejected) reaches step_stop,
    and before its event, impact or output buffers could overflow.

    Steps are never shortened to land on t_stop, only on the end time, so the solution does
    not depend on how the run is cut into chunks.
    """
    sys, ctl, ls, wk = borrow(sys), borrow(ctl), borrow(ls), borrow(wk)  # kernels.borrow
    dp, ab = borrow(dp), borrow(ab)
    rows = 0
    n_events = ls.event_prev.shape[0]
    nc = sys.clearance_body.shape[0]
    while True:
        t = current_time(ctl, dp, ab)
        rows, ok = _write_rows(sys, ctl, ls, dp, ab, wk, out, rows, t)
        if not ok:
            return Status.SINGULAR, rows
        if t >= ctl.t_end:
            return Status.SUCCESS, rows
        if t >= t_stop:
            return Status.RUNNING, rows
        full = rows + ctl.rows_per_step > out.shape[0]
        full |= ls.counters[Counter.EVENTS] + n_events > ls.event_time.shape[0]
        full |= ls.counters[Counter.IMPACTS] + nc > ls.impact_time.shape[0]
        if full:
            return Status.RUNNING, rows
        steps = ls.counters[Counter.ACCEPTED] + ls.counters[Counter.REJECTED]
        if steps >= ctl.max_steps:
            return Status.MAX_STEPS, rows
        if steps >= step_stop:
            return Status.RUNNING, rows
        if nc:
            ls.t_old[0] = t
            ls.y_old[:] = current_state(ctl, dp, ab)
            ls.yp_old[:] = current_derivative(ctl, dp, ab)
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
        h = current_time(ctl, dp, ab) - t
        rows, ok = _after_step(sys, ctl, ls, dp, ab, wk, out, rows, t, h)
        if not ok:
            return Status.SINGULAR, rows
