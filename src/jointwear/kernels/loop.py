"""The compiled step loop: integrate a chunk, locate events, write output rows.

``advance`` runs until the chunk's stop time, the end of the run, a full buffer or a
failure, and returns a ``Status`` and the number of rows written. The Python side calls it
chunk after chunk (progress, Ctrl-C and saving happen in between); all persistent state lives
in the arrays passed in, so the next chunk goes on exactly where the last one stopped.

The loop knows three things, each behind its interface: the constrained system
(``dynamics.rhs`` on a ``Problem``), the integrator (``integrate``) and the contact elements
(``elements``), through their contact slots:

- Onset: when a step ends with a slot in free flight penetrating past its contact tolerance,
  the onset is located on the interpolant exact at the step's ends (to within the tolerance
  in penetration), the step is cut there, the element opens its contact period, and the
  integrator restarts from the cut.
- Rebound: a slot in contact with no penetration at the step's midpoint but penetrating again
  at its end: the separation is located where the penetration reaches zero, so that the
  period closes there and the new impact is located as an onset. A rebound that misses the
  midpoint goes unseen; steps are short in contact.
- After every accepted step the elements accumulate wear and totals from the step's midpoint.

Constraints: after every accepted step ``dynamics.project`` reports the constraint violation
the step ended with (and, in the augmented Lagrangian formulation, projects the state back
onto the constraints). A violation above ``Control.max_violation`` ends the run with
``Status.CONSTRAINT_DRIFT``: the motion may have left its assembly branch.

Output rows: each evaluates the right-hand side at its state interpolated in the step, so it
reports the accelerations, multipliers and forces there. Without contact slots, and with rows
at least ``max_step`` apart, steps are cut to end on the rows' times when that is cheap
(``stepsize.clip_step``), and a row due exactly at a step's end, with no row due before it
in the step, is written before the projection from the step's own last evaluation. With
contact slots the steps are left alone: in contact they are far shorter than the rows' interval.

Minimum step (SPEC sec. 2): when the error test fails at ``min_step`` the step is accepted
anyway and counted in ``Counter.MIN_STEP_HITS``.
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from . import elements, integrate
from .codes import Counter, EventDirection, Status
from .dynamics import project, rhs, row_multipliers
from .outputs import fill_row, write_row

EVENT_TIME_TOLERANCE = 1e-13  # relative bracket width at which a crossing is located [-]
MAX_EVENT_ITERATIONS = 100


class Control(NamedTuple):
    """Solver settings (SI)."""

    rtol: float
    atol: float
    min_step: float  # [s]
    max_step: float  # [s]
    t_end: float  # [s]
    max_steps: int
    output_times: np.ndarray  # (rows,) times of the output rows [s], increasing
    rows_per_step: int  # most rows one step can produce (buffer reserve)
    snapshot_times: np.ndarray  # (ns,) times of the wear snapshots [s], increasing
    max_violation: float  # a step ending with a larger 2-norm of Phi stops the run [m, rad]


class UserEvents(NamedTuple):
    """Crossings of a body coordinate through a value, logged with their times."""

    body: np.ndarray  # (ne,) int64
    coordinate: np.ndarray  # (ne,) int64: 0 x, 1 y, 2 phi
    value: np.ndarray  # (ne,) [m or rad]
    direction: np.ndarray  # (ne,) int64 EventDirection


class Log(NamedTuple):
    """What a run records besides its state: counters, crossings, onsets, element totals.

    The crossing and onset buffers are emptied by the caller after every chunk.
    """

    counters: np.ndarray  # (N_COUNTERS,) int64, see Counter
    max_violation: np.ndarray  # (1,) largest 2-norm of Phi at a step's end, before projection
    event_time: np.ndarray  # (cap,) crossings logged during this chunk [s]
    event_index: np.ndarray  # (cap,) int64 event number
    event_rising: np.ndarray  # (cap,) int64 1 rising, 0 falling
    impact_time: np.ndarray  # (cap,) contact onsets logged during this chunk [s]
    impact_owner: np.ndarray  # (cap, 2) int64 the slot's kind and element within the kind
    impact_info: np.ndarray  # (cap, 4) what the element reports of each onset
    elements: elements.ElementLog


class Scratch(NamedTuple):
    """Work arrays of the loop (n state components, ne user events)."""

    y: np.ndarray  # (n,) interpolated states (events, output rows)
    yp: np.ndarray  # (n,) derivatives of output rows
    y_cut: np.ndarray  # (n,) state where a step is cut at a contact change
    y_mid: np.ndarray  # (n,) state at the middle of the step (or of its part before a cut)
    event_prev: np.ndarray  # (ne,) user event values at the current time


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def event_value(events, e, y):
    """User event e: the watched coordinate minus its value."""
    return y[3 * events.body[e] + events.coordinate[e]] - events.value[e]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _begin_periods(problem, log, t, y):
    """Open or close every slot's contact period at the step end (t [s], y); log onsets."""
    n = problem.mech.inv_mass.shape[0]
    for slot in range(elements.slot_count(problem.elements)):
        i = log.counters[Counter.IMPACTS]
        info = log.impact_info[min(i, log.impact_info.shape[0] - 1)]
        opened = elements.begin_period(
            problem.elements, problem.state, problem.scratch, log.elements, slot,
            y[:n], y[n:], info,
        )  # fmt: skip
        if opened and i < log.impact_time.shape[0]:
            log.impact_time[i] = t
            log.impact_owner[i, 0], log.impact_owner[i, 1] = elements.owner(problem.elements, slot)
            log.counters[Counter.IMPACTS] = i + 1


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def start(problem, integ, events, log, scratch, t0, y0, h0):
    """Begin a run at (t0 [s], y0) with first step h0 [s]; False if the first solve fails."""
    _begin_periods(problem, log, t0, y0)
    ok = rhs(t0, y0, problem, scratch.yp)
    log.counters[Counter.RHS_EVALS] += 1
    integrate.start(integ, t0, y0, scratch.yp, h0)
    for e in range(scratch.event_prev.shape[0]):
        scratch.event_prev[e] = event_value(events, e, y0)
    return ok


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _excess(problem, slot, y):
    """Penetration of a slot beyond its tolerance at state y [m]."""
    n = problem.mech.inv_mass.shape[0]
    return elements.penetration_excess(
        problem.elements, problem.state, problem.scratch, slot, y[:n], y[n:]
    )


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _crossing(problem, events, integ, scratch, kind, index, t):
    """Value at t [s] of a user event (kind 0), a slot's onset (1) or its separation (2)."""
    if kind == 0:
        integrate.interpolate(integ, t, scratch.y)
        return event_value(events, index, scratch.y)
    integrate.interpolate_ends(integ, t, scratch.y)
    excess = _excess(problem, index, scratch.y)
    if kind == 2:
        return excess + elements.tolerance(problem.elements, index)
    return excess


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _locate(problem, events, integ, scratch, kind, index, ta, ga, tb, gb, g_tol):
    """Crossing time in [ta, tb] [s] by the Illinois method on the step's interpolant.

    Stops when the bracket is at the time tolerance or abs(g(tb)) <= g_tol; returns tb, the
    end on the far side of the crossing: g > 0 there for a rising crossing, g <= 0 for a
    falling one. With g_tol = 0 an exact zero is returned at once.
    """
    rising = gb > 0.0
    g_far = gb  # g at tb; gb itself may be halved by the Illinois modification
    side = 0
    for _ in range(MAX_EVENT_ITERATIONS):
        if tb - ta <= EVENT_TIME_TOLERANCE * max(1.0, abs(tb)) or abs(g_far) <= g_tol:
            break
        tc = tb - gb * (tb - ta) / (gb - ga)
        tc = min(max(tc, ta), tb)
        gc = _crossing(problem, events, integ, scratch, kind, index, tc)
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


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _log_events(problem, events, integ, log, scratch, t_old, t_new, y_new):
    for e in range(scratch.event_prev.shape[0]):
        g0 = scratch.event_prev[e]
        g1 = event_value(events, e, y_new)
        scratch.event_prev[e] = g1
        rising = g0 < 0.0 <= g1
        falling = g0 > 0.0 >= g1
        wanted = events.direction[e]
        if (rising and wanted != EventDirection.FALLING) or (
            falling and wanted != EventDirection.RISING
        ):
            i = log.counters[Counter.EVENTS]
            log.event_time[i] = _locate(
                problem, events, integ, scratch, 0, e, t_old, g0, t_new, g1, 0.0
            )
            log.event_index[i] = e
            log.event_rising[i] = 1 if rising else 0
            log.counters[Counter.EVENTS] += 1


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _contact_cut(problem, events, integ, scratch, t_old, y_old, t_new, y_new):
    """Earliest change of contact inside the step just accepted [s], or t_new if none.

    Also returns whether scratch.y_mid now holds the state at the step's midpoint.
    """
    t_mid = 0.5 * (t_old + t_new)
    t_first = t_new
    midpoint_known = False
    for slot in range(elements.slot_count(problem.elements)):
        tol = elements.tolerance(problem.elements, slot)
        g1 = _excess(problem, slot, y_new)
        if not elements.in_contact(problem.elements, problem.state, slot):
            if g1 > 0.0:
                g0 = min(_excess(problem, slot, y_old), 0.0)  # periods open above tol
                t_hit = _locate(problem, events, integ, scratch, 1, slot, t_old, g0, t_new, g1, tol)
                t_first = min(t_first, t_hit)
            continue
        if g1 + tol <= 0.0:
            continue  # the period ends at the step end
        if not midpoint_known:
            integrate.interpolate_ends(integ, t_mid, scratch.y_mid)
            midpoint_known = True
        depth_mid = _excess(problem, slot, scratch.y_mid) + tol
        if depth_mid <= 0.0:
            depth_old = _excess(problem, slot, y_old) + tol  # > 0 in a period
            t_gap = _locate(
                problem, events, integ, scratch, 2, slot, t_old, depth_old, t_mid, depth_mid, tol
            )
            t_first = min(t_first, t_gap)
    return t_first, midpoint_known


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _write_rows(problem, integ, ctl, log, scratch, out, rows, t):
    """Write the output rows due by time t [s]; return (row count, False if singular)."""
    k = log.counters[Counter.OUTPUT_ROWS]
    while k < ctl.output_times.shape[0] and ctl.output_times[k] <= t:
        integrate.interpolate(integ, ctl.output_times[k], scratch.y)
        log.counters[Counter.RHS_EVALS] += 1
        if not write_row(ctl.output_times[k], scratch.y, problem, scratch.yp, out[rows]):
            return rows, False
        rows += 1
        k += 1
        log.counters[Counter.OUTPUT_ROWS] = k
    return rows, True


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _write_end_row(problem, integ, ctl, log, out, rows):
    """Write the next output row if it is due exactly at the end of the step just accepted.

    It is filled from the step's last evaluation, which was at that state, so it costs none
    of its own. Returns the row count.
    """
    k = log.counters[Counter.OUTPUT_ROWS]
    t = integrate.current_time(integ)
    if k < ctl.output_times.shape[0] and ctl.output_times[k] == t:
        row_multipliers(problem)
        y = integrate.current_state(integ)
        fill_row(t, y, problem, integrate.current_derivative(integ), out[rows])
        log.counters[Counter.OUTPUT_ROWS] = k + 1
        rows += 1
    return rows


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _landing(ctl, k):
    """Time the next step should end on if cheap [s]: row k's, when rows are a step apart."""
    times = ctl.output_times
    if 0 < k < times.shape[0] and times[k] - times[k - 1] >= ctl.max_step:
        return times[k]
    return ctl.t_end


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _copy(source, target):
    for i in range(source.shape[0]):
        target[i] = source[i]


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _after_step(problem, integ, events, ctl, log, scratch, out, rows, h):
    """Contact changes, wear, events and rows of the step just accepted.

    Returns (rows, False if singular). At a contact change the step is cut there: the rows
    and events up to it come from this step's interpolant, and the integrator restarts from
    the cut.
    """
    t_new = integrate.current_time(integ)
    y_new = integrate.current_state(integ)
    t_old, y_old = integrate.step_start(integ)
    n = problem.mech.inv_mass.shape[0]
    slots = elements.slot_count(problem.elements)
    t_cut, midpoint_known = t_new, False
    if slots:
        t_cut, midpoint_known = _contact_cut(
            problem, events, integ, scratch, t_old, y_old, t_new, y_new
        )
    if t_cut < t_new:
        integrate.interpolate_ends(integ, t_cut, scratch.y_cut)
    else:
        _copy(y_new, scratch.y_cut)
    if slots:
        if t_cut < t_new or not midpoint_known:
            integrate.interpolate_ends(integ, 0.5 * (t_old + t_cut), scratch.y_mid)
        elements.accumulate(
            problem.elements, problem.state, problem.scratch, log.elements, t_old, t_cut,
            scratch.y_mid[:n], scratch.y_mid[n:], ctl.snapshot_times,
            log.counters[Counter.SNAPSHOTS],
        )  # fmt: skip
        snapshots = log.counters[Counter.SNAPSHOTS]
        while snapshots < ctl.snapshot_times.shape[0] and ctl.snapshot_times[snapshots] <= t_cut:
            snapshots += 1
        log.counters[Counter.SNAPSHOTS] = snapshots
    _log_events(problem, events, integ, log, scratch, t_old, t_cut, scratch.y_cut)
    # The step's rows see the contact periods as the step did, before they open or close.
    rows, ok = _write_rows(problem, integ, ctl, log, scratch, out, rows, t_cut)
    if not ok:
        return rows, False
    if t_cut == t_new:
        if slots:
            _begin_periods(problem, log, t_new, y_new)
        return rows, True
    _begin_periods(problem, log, t_cut, scratch.y_cut)
    log.counters[Counter.RHS_EVALS] += 1
    if not rhs(t_cut, scratch.y_cut, problem, scratch.yp):
        return rows, False
    integrate.restart(integ, t_cut, scratch.y_cut, scratch.yp, h, ctl.min_step)
    return rows, True


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def advance(problem, integ, events, ctl, log, scratch, out, t_stop, step_stop):
    """Integrate past t_stop [s] (or to the end); return (Status, rows written into out).

    The chunk also hands back once the step count (accepted + rejected) reaches step_stop,
    and before its event, impact or output buffers could overflow. Steps are never shortened
    to land on t_stop, only on the end time, so the solution does not depend on the chunks.
    """
    rows = 0
    n_events = scratch.event_prev.shape[0]
    slots = elements.slot_count(problem.elements)
    counters = log.counters
    while True:
        t = integrate.current_time(integ)
        rows, ok = _write_rows(problem, integ, ctl, log, scratch, out, rows, t)
        if not ok:
            return Status.SINGULAR, rows
        if t >= ctl.t_end:
            return Status.SUCCESS, rows
        if t >= t_stop:
            return Status.RUNNING, rows
        full = rows + ctl.rows_per_step > out.shape[0]
        full |= counters[Counter.EVENTS] + n_events > log.event_time.shape[0]
        full |= counters[Counter.IMPACTS] + slots > log.impact_time.shape[0]
        if full:
            return Status.RUNNING, rows
        steps = counters[Counter.ACCEPTED] + counters[Counter.REJECTED]
        if steps >= ctl.max_steps:
            return Status.MAX_STEPS, rows
        if steps >= step_stop:
            return Status.RUNNING, rows
        t_land = _landing(ctl, counters[Counter.OUTPUT_ROWS]) if not slots else ctl.t_end
        outcome = integrate.attempt(integ, problem, ctl, counters, t_land)
        if outcome == integrate.REJECTED:
            counters[Counter.REJECTED] += 1
            continue
        if outcome < 0:
            return -outcome, rows
        counters[Counter.ACCEPTED] += 1
        y_new = integrate.current_state(integ)
        for i in range(y_new.shape[0]):
            if not math.isfinite(y_new[i]):
                return Status.NON_FINITE, rows
        if not slots:  # no contact change can cut the step short of its end
            rows = _write_end_row(problem, integ, ctl, log, out, rows)
        violation = project(integrate.current_time(integ), y_new, problem)
        if violation < 0.0:
            return Status.SINGULAR, rows
        log.max_violation[0] = max(log.max_violation[0], violation)
        if violation > ctl.max_violation:
            return Status.CONSTRAINT_DRIFT, rows
        h = integrate.current_time(integ) - t
        rows, ok = _after_step(problem, integ, events, ctl, log, scratch, out, rows, h)
        if not ok:
            return Status.SINGULAR, rows
