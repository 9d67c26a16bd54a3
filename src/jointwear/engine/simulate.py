"""Run a model: assemble, then integrate chunk by chunk in the compiled loop.

Between chunks (about ``CHUNK_WALL_S`` of wall time each) the rows computed so far are kept,
the progress callback is called, and Ctrl-C or SIGTERM end the run cleanly: the ``Results``
then hold everything computed up to that point, with status ``interrupted``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import pandas as pd

from .._version import __version__
from ..kernels import loop
from ..kernels.codes import N_COUNTERS, Counter, Formulation, Method, Status
from ..kernels.dynamics import Problem, make_dynamics_scratch
from ..kernels.elements import ElementLog, Elements, ElementScratch, ElementState, journal, slider
from ..kernels.integrate.abm import make_abm_state
from ..kernels.integrate.rk import DOPRI5, S_T, make_rk_state
from ..kernels.structs import StructProxy, to_struct
from ..mechanism.assembly import assemble, redundant_equations
from ..mechanism.lockup import find_lock_up, lock_up_span
from ..mechanism.system import (
    System,
    build_system,
    column_names,
    freed_degrees_of_freedom,
    sliders_outside_guides,
)
from ..model import Model, ModelError
from ..model.sections import FORMULATIONS
from ..results import Results
from ..results import slider as slider_results
from ..results.clearance import (
    impact_columns,
    impact_rows,
    joint_summaries,
    snapshot_table,
    wear_table,
)
from ..results.cycles import (
    JOURNAL_PEAKS,
    SLIDER_PEAKS,
    CycleWindows,
    lead_with_steady_state,
    settling,
)
from ..results.run_state import RunState
from ..results.tribology import with_tribology
from .energy import EnergyMonitor
from .finite import first_non_finite
from .interrupts import interruptible, stop_requests
from .provenance import provenance
from .status import status_message

CHUNK_WALL_S = 0.2  # target wall time of one compiled chunk [s]
# A run that reaches its lock-up time, or fails past this share of it, ends ``lock_up``.
LOCK_NEAR = 0.9
LOCK_FAILURES = (Status.SUCCESS, Status.SINGULAR, Status.NON_FINITE, Status.CONSTRAINT_DRIFT,
                 Status.MAX_STEPS)  # fmt: skip
MIN_CHUNK_STEPS = 100  # the first chunk: this many maximum steps, and at least this many steps
EVENT_CAPACITY = 4096  # crossings (and contact onsets) one chunk may log before it hands back
SNAPSHOTS_BY_DEFAULT = 5  # wear snapshots over the run unless wear_snapshot_interval is set
Progress = Callable[[float, float], None]  # (simulated time reached, end time) [s]


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


def _integrator(method: Method, n_state: int) -> object:
    """The integrator state of ``method`` for n_state equations."""
    if method == Method.DOPRI5:
        return make_rk_state(n_state, DOPRI5)
    return make_abm_state(n_state)


def _kernel_arrays(
    system: System, formulation: Formulation, n_state: int, n_events: int, n_snapshots: int
) -> tuple[Problem, loop.Log, loop.Scratch, ElementState, ElementLog]:
    """The problem the right-hand side reads, the run's log and the loop's scratch.

    Each element kind's tables go in as structs (one pointer per call, ``kernels.structs``);
    the last two returned are their states and logs as named tuples, for Python to read.
    """
    table, state, element_log, scratch = journal.make_journals(
        system.journal_ints, system.journal_params, n_snapshots
    )
    s_table, s_state, s_log, s_scratch = slider.make_sliders(
        system.slider_ints, system.slider_params, n_snapshots
    )
    states = ElementState(journal=state, slider=s_state)
    logs = ElementLog(journal=element_log, slider=s_log)
    problem = Problem(
        mech=system.mechanism,
        elements=Elements(journal=to_struct(table), slider=to_struct(s_table)),
        state=ElementState(journal=to_struct(state), slider=to_struct(s_state)),
        scratch=ElementScratch(journal=to_struct(scratch), slider=to_struct(s_scratch)),
        dyn=make_dynamics_scratch(system.mechanism, formulation),
    )
    slots = system.journal_ints.shape[0] + slider.SLOTS * system.slider_ints.shape[0]
    # A step logs at most one crossing per event and one onset per slot: room for many steps.
    events = max(EVENT_CAPACITY, 16 * n_events)
    impacts = max(EVENT_CAPACITY, 16 * slots)
    log = loop.Log(
        counters=np.zeros(N_COUNTERS, dtype=np.int64),
        max_violation=np.zeros(1),
        event_time=np.zeros(events),
        event_index=np.zeros(events, dtype=np.int64),
        event_rising=np.zeros(events, dtype=np.int64),
        impact_time=np.zeros(impacts),
        impact_slot=np.zeros(impacts, dtype=np.int64),
        impact_info=np.zeros((impacts, max(journal.N_IMPACT_INFO, slider.N_IMPACT_INFO))),
        elements=ElementLog(journal=to_struct(element_log), slider=to_struct(s_log)),
    )
    work = loop.Scratch(
        y=np.zeros(n_state),
        yp=np.zeros(n_state),
        y_cut=np.zeros(n_state),
        y_mid=np.zeros(n_state),
        event_prev=np.zeros(n_events),
    )
    return problem, log, work, states, logs


def _by_reference(*tables: NamedTuple) -> tuple[StructProxy, ...]:
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
        Where to start: by default the assembled initial pose at t = 0 with every journal
        and slider centred and unworn; or the state another run of the same model ended in
        (``Results.final``), possibly with other worn profiles (``RunState.with_wear``). The
        run then goes on from ``initial.time`` to ``initial.time + t_end``.
    check_lock_up
        Before a run from t = 0, solve the all-ideal mechanism over the drivers' first cycle
        and stop the run where it locks up (``jointwear.lockup``). False skips that check,
        for a model known to pass it: the ideal companion of a run that did.

    Returns
    -------
    Results
        Time series, events and summary; partial, with a non-success status, if the run
        failed or was interrupted.
    """
    origin = provenance()
    # Set-up and compiling lose nothing when cut short: a Ctrl-C there stops at once.
    with interruptible():
        solver = model.solver
        system = build_system(model)
        ideal = build_system(model, ideal=True)
        assembly = assemble(model, ideal)  # journals centred
        # of the system that runs, without the clearance joints' rows
        redundant = redundant_equations(system, assembly.y0) if assembly.redundant else 0
        if redundant:  # rows report the least-norm multipliers (kernels.formulations)
            system = system._replace(mechanism=system.mechanism._replace(redundant=True))
        outside = sliders_outside_guides(model, assembly.y0)
        if outside:
            raise ModelError(outside)
        n_state = assembly.y0.shape[0]
        t0 = 0.0 if initial is None else initial.time
        t_end = t0 + solver.t_end
        lock = None  # a driven mechanism's lock-up: the run stops there with its status
        if initial is None and check_lock_up:
            lock = find_lock_up(model, ideal, assembly, lock_up_span(model))
            t_end = t_end if lock is None else min(t_end, lock.time)
        output_times = _output_times(t0, solver.t_end, solver.output_interval)
        ctl = loop.Control(
            rtol=solver.rtol,
            atol=solver.atol,
            min_step=solver.min_step,
            max_step=solver.max_step,
            t_end=t_end,
            max_steps=solver.max_steps,
            output_times=output_times,
            rows_per_step=min(
                math.ceil(solver.max_step / solver.output_interval), len(output_times)
            )
            + 2,
            snapshot_times=_snapshot_times(t0, solver.t_end, solver.wear_snapshot_interval),
            max_violation=solver.max_constraint_violation,
        )
        integ = _integrator(solver.method, n_state)
        problem, log, scratch, states, element_logs = _kernel_arrays(
            system,
            FORMULATIONS[solver.formulation],
            n_state,
            len(model.events),
            ctl.snapshot_times.shape[0],
        )
        journals, sliders = states
        impacts: list[dict] = []
        columns = column_names(model)
        buffer = np.zeros((max(ctl.rows_per_step * 4, 1024), len(columns)))
        blocks: list[np.ndarray] = []
        events: list[tuple[float, str, str]] = []

        y0 = assembly.y0
        if initial is not None:
            _check_initial(initial, y0, journals, sliders)
            y0 = initial.y
            journals.wear[:] = initial.wear
            journals.contact_on[:] = initial.contact_on
            journals.impact_speed[:] = initial.impact_speed
            sliders.wear[:] = initial.slider_wear
            sliders.contact_on[:] = initial.slider_contact_on
            sliders.impact_speed[:] = initial.slider_impact_speed

        settle = settling(model, continuing=initial is not None)
        windows = CycleWindows(
            t0, t_end, settle, (element_logs.journal.totals, element_logs.slider.totals),
            (JOURNAL_PEAKS, SLIDER_PEAKS),
        )  # fmt: skip
        energy = EnergyMonitor(model, columns)
        wall_start = time.perf_counter()
        status = Status.RUNNING
        args = _by_reference(problem, integ, system.events, ctl, log, scratch)
        if not loop.start(*args[:3], *args[4:], t0, y0, solver.initial_step):
            status = Status.SINGULAR
    chunk = min(solver.t_end, MIN_CHUNK_STEPS * solver.max_step)
    detail = ""  # what a non-finite status found, and when
    budget = MIN_CHUNK_STEPS  # steps a chunk may take, so a stalled run still hands back
    with stop_requests() as stop_requested:
        while status == Status.RUNNING:
            t_before = float(integ.scal[S_T])
            chunk_start = time.perf_counter()
            steps_before = log.counters[Counter.ACCEPTED] + log.counters[Counter.REJECTED]
            try:
                t_stop = min(t_before + chunk, windows.next_end)
                code, rows = loop.advance(*args, buffer, t_stop, steps_before + budget)
            except ArithmeticError as error:  # a kernel divided by zero: values at float's edges
                code, rows = Status.NON_FINITE, 0
                detail = (
                    f"{type(error).__name__} in the compiled step loop between t = "
                    f"{t_before:.6g} and {float(integ.scal[S_T]):.6g} s (the chunk's rows are "
                    "lost); check the model's sizes and coefficients against their units"
                )
            status = Status(code)
            blocks.append(buffer[:rows].copy())
            broken = first_non_finite(
                blocks[-1], columns, _accumulated(journals, sliders, element_logs),
                (t_before, float(integ.scal[S_T])),
            )  # fmt: skip
            if broken is not None and status in (Status.RUNNING, Status.SUCCESS):
                quantity, when, keep = broken
                blocks[-1] = blocks[-1][:keep]  # the rows before it are kept
                status = Status.NON_FINITE
                detail = (
                    f"{quantity} became non-finite (NaN or inf) {when}; check the model's "
                    "coefficients (wear, stiffness, forces) against their units"
                )
            if energy.update(blocks[-1]) and status in (Status.RUNNING, Status.SUCCESS):
                status = Status.ENERGY_DRIFT
            for i in range(log.counters[Counter.EVENTS]):
                direction = "rising" if log.event_rising[i] else "falling"
                name = model.events[log.event_index[i]].name
                events.append((log.event_time[i], name, direction))
            log.counters[Counter.EVENTS] = 0
            impacts += impact_rows(
                model, log.impact_time, log.impact_slot, log.impact_info,
                log.counters[Counter.IMPACTS],
            )  # fmt: skip
            log.counters[Counter.IMPACTS] = 0
            t_now = float(integ.scal[S_T])
            windows.passed(t_now)
            if progress is not None:
                progress(t_now - t0, solver.t_end)
            if stop_requested[0] and status == Status.RUNNING:
                status = Status.INTERRUPTED
            elapsed = time.perf_counter() - chunk_start
            steps = log.counters[Counter.ACCEPTED] + log.counters[Counter.REJECTED] - steps_before
            if elapsed > 0:  # aim the next chunk at CHUNK_WALL_S, in time and in steps
                budget = max(MIN_CHUNK_STEPS, min(int(steps / elapsed * CHUNK_WALL_S), 10 * budget))
                if t_now > t_before:
                    rate = (t_now - t_before) / elapsed
                    chunk = min(max(rate * CHUNK_WALL_S, 1e-9 * solver.t_end), 10 * chunk)
    near_lock = lock is not None and float(integ.scal[S_T]) - t0 >= LOCK_NEAR * lock.time
    if near_lock and status in LOCK_FAILURES:  # how the dynamics meet the lock-up
        status, detail = Status.LOCK_UP, lock.message()
    wall = time.perf_counter() - wall_start
    t_reached = float(integ.scal[S_T])
    windows.finish(t_reached)
    final = RunState(
        time=t_reached,
        y=integ.y.copy(),
        wear=journals.wear.copy(),
        contact_on=journals.contact_on.copy(),
        impact_speed=journals.impact_speed.copy(),
        slider_wear=sliders.wear.copy(),
        slider_contact_on=sliders.contact_on.copy(),
        slider_impact_speed=sliders.impact_speed.copy(),
    )

    data = np.concatenate(blocks) if blocks else np.zeros((0, len(columns)))
    stats = {
        "simulation_wall_s": wall,
        "t_reached": t_reached,
        "accepted_steps": int(log.counters[Counter.ACCEPTED]),
        "rejected_steps": int(log.counters[Counter.REJECTED]),
        "rhs_evaluations": int(log.counters[Counter.RHS_EVALS]),
        "min_step_hits": int(log.counters[Counter.MIN_STEP_HITS]),
        "max_constraint_violation": float(log.max_violation[0]),
        "assembly_iterations": assembly.iterations,
        "degrees_of_freedom": assembly.dof + freed_degrees_of_freedom(model),
    }
    tables = {}
    if model.has_clearance:
        tables["wear"] = wear_table(model, journals.wear, sliders.wear)
        tables["wear_snapshots"] = snapshot_table(
            model, ctl.snapshot_times, element_logs.journal.snapshots,
            int(log.counters[Counter.SNAPSHOTS]), element_logs.slider.snapshots,
        )  # fmt: skip
        tables["impacts"] = pd.DataFrame.from_records(impacts, columns=impact_columns(model))
    summary = {
        "jointwear_version": __version__,
        "model": model.name,
        "status": status.name.lower(),
        "message": detail or status_message(status),
        "settings": model.solver.model_dump(mode="json"),
        "stats": stats,
        "constraints": {
            "formulation": solver.formulation,
            "max_violation": stats["max_constraint_violation"],
            "bound": solver.max_constraint_violation,
            "redundant_equations": redundant,
        },
        "energy": energy.summary(),
    }
    if model.has_clearance:
        totals = (element_logs.journal.totals, element_logs.slider.totals)
        whole = _joint_figures(model, journals.wear, sliders.wear, totals, t_reached - t0)
        steady = windows.steady()
        summary["steady_state"] = settle.summary(t0, t_reached, steady[2] if steady else 0)
        settled = None if steady is None else steady[:2]
        summary["clearance_joints"] = lead_with_steady_state(
            whole, settled and _joint_figures(model, journals.wear, sliders.wear, *settled)
        )
        tables["cycles"] = windows.table(model)
    summary["provenance"] = origin
    return Results(
        model=model,
        timeseries=with_tribology(model, pd.DataFrame(data, columns=columns)),
        events=pd.DataFrame(events, columns=["time", "event", "direction"]),
        summary=summary,
        final=final,
        **tables,
    )


def _joint_figures(
    model: Model,
    journal_wear: np.ndarray,
    slider_wear: np.ndarray,
    totals: tuple[np.ndarray, np.ndarray],
    duration: float,
) -> dict[str, dict]:
    """Per clearance joint, its summary figures from ``totals`` gathered over ``duration`` [s]."""
    journals = joint_summaries(model, totals[0], journal_wear, duration)
    return journals | slider_results.joint_summaries(model, totals[1], slider_wear, duration)


def _accumulated(
    journals: journal.JournalState, sliders: slider.SliderState, logs: ElementLog
) -> dict[str, np.ndarray]:
    """What the elements accumulate besides the rows, by name (for ``first_non_finite``)."""
    return {
        "the journal joints' wear": journals.wear,
        "the slider joints' wear": sliders.wear,
        "the journal joints' contact totals": logs.journal.totals,
        "the slider joints' contact totals": logs.slider.totals,
    }


def _check_initial(
    initial: RunState, y0: np.ndarray, journals: journal.JournalState, sliders: slider.SliderState
) -> None:
    """Refuse a starting state that does not fit the model."""
    pairs = (("y", initial.y, y0), ("wear", initial.wear, journals.wear),
             ("contact_on", initial.contact_on, journals.contact_on),
             ("slider_wear", initial.slider_wear, sliders.wear),
             ("slider_contact_on", initial.slider_contact_on, sliders.contact_on))  # fmt: skip
    for name, given, expected in pairs:
        if given.shape != expected.shape:
            raise ValueError(
                f"initial.{name} has shape {given.shape}; this model needs {expected.shape}"
            )
