"""Run a model: prepare it, drive the compiled loop chunk by chunk, and report.

``prepare`` builds and assembles the model (as ``jointwear check`` does), ``drive`` runs the
chunks and watches them, ``summary`` turns what they gave into ``Results``. Set-up and
compiling lose nothing when cut short; during the run, Ctrl-C or SIGTERM end it cleanly:
the ``Results`` then hold everything computed up to that point, with status ``interrupted``.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pandas as pd

from ..kernels import loop
from ..kernels.codes import N_COUNTERS, Counter, Status
from ..kernels.dynamics import Problem, make_dynamics_scratch
from ..kernels.structs import StructProxy, to_struct
from ..mechanism.system import column_names, freed_degrees_of_freedom
from ..model import Model
from ..model.sections import FORMULATIONS
from ..results import Results
from ..results.cycles import CycleWindows, settling
from ..results.derived import with_derived_columns
from ..results.run_state import RunState
from . import integrators
from .contacts import Contacts
from .drive import LoopArrays, Progress, drive
from .energy import EnergyMonitor
from .interrupts import interruptible
from .prepare import prepare
from .provenance import provenance
from .state_tables import left_tables
from .status import status_message
from .summary import clearance_summary, clearance_tables, driver_summary, run_stats, summary
from .user_laws import user_tables

# A run that reaches its lock-up time, or fails past this share of it, ends ``lock_up``.
LOCK_NEAR = 0.9
LOCK_FAILURES = (Status.SUCCESS, Status.SINGULAR, Status.NON_FINITE, Status.CONSTRAINT_DRIFT,
                 Status.MAX_STEPS)  # fmt: skip
EVENT_CAPACITY = 4096  # crossings (and contact onsets) one chunk may log before it hands back
SNAPSHOTS_BY_DEFAULT = 5  # wear snapshots over the run unless wear_snapshot_interval is set
__all__ = ["Progress", "simulate"]


def _output_times(t0: float, duration: float, interval: float) -> np.ndarray:
    count = math.floor(duration / interval * (1.0 + 1e-12)) + 1
    times = np.minimum(np.arange(count) * interval, duration)  # 3 * 0.1 must not pass 0.3
    if duration - times[-1] > 1e-9 * interval:
        times = np.append(times, duration)
    return t0 + times


def _snapshot_times(t0: float, duration: float, interval: float | None) -> np.ndarray:
    interval = interval or duration / SNAPSHOTS_BY_DEFAULT
    count = math.floor(duration / interval * (1.0 + 1e-12))
    return t0 + np.minimum(np.arange(1, count + 1) * interval, duration)


def _control(model: Model, t0: float, t_end: float) -> loop.Control:
    """The loop's settings from the model's solver section, for a run from t0 to t_end [s]."""
    solver = model.solver
    output_times = _output_times(t0, solver.t_end, solver.output_interval)
    return loop.Control(
        rtol=solver.rtol,
        atol=solver.atol,
        min_step=solver.min_step,
        max_step=solver.max_step,
        t_end=t_end,
        max_steps=solver.max_steps,
        output_times=output_times,
        rows_per_step=min(math.ceil(solver.max_step / solver.output_interval), len(output_times))
        + 2,
        snapshot_times=_snapshot_times(t0, solver.t_end, solver.wear_snapshot_interval),
        max_violation=solver.max_constraint_violation,
    )


def _loop_log(contacts: Contacts, n_events: int, element_logs: object) -> loop.Log:
    """The loop's log, with room for many steps' crossings and onsets in one chunk."""
    events = max(EVENT_CAPACITY, 16 * n_events)  # a step logs one crossing per event at most
    impacts = max(EVENT_CAPACITY, 16 * contacts.slots())  # and one onset per slot
    return loop.Log(
        counters=np.zeros(N_COUNTERS, dtype=np.int64),
        max_violation=np.zeros(1),
        event_time=np.zeros(events),
        event_index=np.zeros(events, dtype=np.int64),
        event_rising=np.zeros(events, dtype=np.int64),
        impact_time=np.zeros(impacts),
        impact_owner=np.zeros((impacts, 2), dtype=np.int64),
        impact_info=np.zeros((impacts, contacts.impact_info_width())),
        elements=element_logs,
    )


def _by_reference(*tables: object) -> tuple[StructProxy, ...]:
    """The loop's tables as structs (sharing their arrays), so each call passes a pointer."""
    nested = {"mech", "dyn"}  # Problem's fields that are tables themselves
    return tuple(
        to_struct(t._replace(**{f: to_struct(getattr(t, f)) for f in nested & set(t._fields)}))
        for t in tables
    )


def simulate(
    model: Model,
    *,
    progress: Progress | None = None,
    initial: RunState | None = None,
    check_lock_up: bool = True,
) -> Results:
    """Simulate ``model`` for ``model.solver.t_end`` seconds.

    Parameters
    ----------
    model
        A validated model (``load_model``).
    progress
        Called after every chunk with the time reached and the end time [s].
    initial
        Where to start: by default the assembled initial pose at t = 0 with every clearance
        joint centred and unworn; or the state another run of the same model ended in
        (``Results.final``), possibly with other worn profiles (``RunState.with_wear``). The
        run then goes on from ``initial.time`` to ``initial.time + t_end``.
    check_lock_up
        Before a run from t = 0, solve the all-ideal mechanism over the drivers' first cycle
        and stop the run where it locks up (``mechanism.lockup``). False skips that check,
        for a model known to pass it: the ideal companion of a run that did.

    Returns
    -------
    Results
        Time series, events and summary; partial, with a non-success status, if the run
        failed or was interrupted.
    """
    origin = provenance()
    with interruptible():  # set-up and compiling lose nothing when cut short
        solver = model.solver
        ready = prepare(model, check_lock_up=initial is None and check_lock_up)
        assembly, lock = ready.assembly, ready.lock
        t0 = 0.0 if initial is None else initial.time
        t_end = t0 + solver.t_end if lock is None else min(t0 + solver.t_end, lock.time)
        ctl = _control(model, t0, t_end)
        n_state = assembly.y0.shape[0]
        integ = integrators.make_integrator(solver.method, n_state)
        contacts = Contacts(ready.system, ctl.snapshot_times.shape[0], user_tables(model))
        elements, states, scratches, element_logs = contacts.structs()
        problem = Problem(
            mech=ready.system.mechanism,
            elements=elements,
            state=states,
            scratch=scratches,
            dyn=make_dynamics_scratch(ready.system.mechanism, FORMULATIONS[solver.formulation]),
        )
        log = _loop_log(contacts, len(model.events), element_logs)
        scratch = loop.Scratch(
            y=np.zeros(n_state),
            yp=np.zeros(n_state),
            y_cut=np.zeros(n_state),
            y_mid=np.zeros(n_state),
            event_prev=np.zeros(len(model.events)),
        )
        columns = column_names(model)
        buffer = np.zeros((max(ctl.rows_per_step * 4, 1024), len(columns)))
        y0 = assembly.y0
        if initial is not None:
            if initial.y.shape != y0.shape:
                raise ValueError(
                    f"initial.y has shape {initial.y.shape}; this model needs {y0.shape}"
                )
            contacts.start_from(initial)
            y0 = initial.y
        settle = settling(model, continuing=initial is not None)
        windows = CycleWindows(t0, t_end, settle, contacts.totals())
        energy = EnergyMonitor(model, columns)
        wall_start = time.perf_counter()
        args = _by_reference(problem, integ, ready.system.events, ctl, log, scratch)
        started = loop.start(*args[:3], *args[4:], t0, y0, solver.initial_step)
    arrays = LoopArrays(args, log, integ, buffer, columns)
    status = Status.RUNNING if started else Status.SINGULAR
    done = drive(model, arrays, contacts, (windows, energy), t0, progress, status)
    t_reached = integrators.time(integ)
    status, detail = done.status, done.detail
    if status in (Status.NON_FINITE, Status.SINGULAR) and not detail:  # a table left gives a
        certain = status == Status.NON_FINITE  # NaN load, whose solve may fail as singular
        detail = status_message(status) + left_tables(model, integrators.state(integ), certain)
    if lock is not None and t_reached - t0 >= LOCK_NEAR * lock.time and status in LOCK_FAILURES:
        status, detail = Status.LOCK_UP, lock.message()  # how the dynamics meet the lock-up
    wall = time.perf_counter() - wall_start
    windows.finish(t_reached)
    final = RunState(time=t_reached, y=integrators.state(integ), contacts=contacts.restart())

    data = np.concatenate(done.blocks) if done.blocks else np.zeros((0, len(columns)))
    dof = assembly.dof + freed_degrees_of_freedom(model)
    stats = run_stats(log, wall, t_reached, assembly, dof)
    report = summary(model, status, detail, stats, ready.redundant, energy.summary())
    tables = {}
    if model.has_clearance:
        taken = int(log.counters[Counter.SNAPSHOTS])
        tables = clearance_tables(model, contacts, ctl.snapshot_times, taken, done.impacts, windows)
        report |= clearance_summary(model, contacts, windows, settle, (t0, t_reached))
    timeseries = with_derived_columns(model, pd.DataFrame(data, columns=columns))
    report["drivers"] = driver_summary(model, timeseries, report.get("steady_state"))
    report["provenance"] = origin
    return Results(
        model=model,
        timeseries=timeseries,
        events=pd.DataFrame(done.events, columns=["time", "event", "direction"]),
        summary=report,
        final=final,
        **tables,
    )
