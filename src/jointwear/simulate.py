"""Run a model: assemble, then integrate chunk by chunk in the compiled loop.

Between chunks (about ``CHUNK_WALL_S`` of wall time each) the rows computed so far are kept,
the progress callback is called, and Ctrl-C or SIGTERM end the run cleanly: the ``Results``
then hold everything computed up to that point, with status ``interrupted``.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

import numpy as np
import pandas as pd

from ._version import __version__
from .assembly import assemble
from .interrupts import stop_requests
from .kernels import loop
from .kernels.abm import make_abm_state
from .kernels.codes import N_COUNTERS, Counter, Status
from .kernels.contact_steps import N_IMPACT_INFO, N_TOTALS
from .kernels.dopri5 import make_dopri5_state
from .model import Model
from .results import Results
from .results.clearance import (
    IMPACT_COLUMNS,
    clearance_joint_names,
    impact_rows,
    joint_summaries,
    snapshot_table,
    wear_table,
)
from .results.run_state import RunState
from .status import status_message
from .system import System, build_system, column_names, make_work

CHUNK_WALL_S = 0.2  # target wall time of one compiled chunk [s]
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


def _loop_state(
    system: System, n_state: int, n_events: int, n_snapshots: int, sectors: int
) -> loop.LoopState:
    nc = system.clearance_body.shape[0]
    # A step logs at most one crossing per event and one onset per joint: room for many steps.
    events = max(EVENT_CAPACITY, 16 * n_events)
    impacts = max(EVENT_CAPACITY, 16 * nc)
    state = ("y_pred", "yp_pred", "y_corr", "yp_corr", "y_scratch", "yp_scratch", "y_cut", "y_mid")
    return loop.LoopState(
        counters=np.zeros(N_COUNTERS, dtype=np.int64),
        max_violation=np.zeros(1),
        t_old=np.zeros(1),
        y_old=np.zeros(n_state),
        yp_old=np.zeros(n_state),
        event_prev=np.zeros(n_events),
        event_time=np.zeros(events),
        event_index=np.zeros(events, dtype=np.int64),
        event_rising=np.zeros(events, dtype=np.int64),
        contact_totals=np.zeros((nc, N_TOTALS)),
        impact_time=np.zeros(impacts),
        impact_joint=np.zeros(impacts, dtype=np.int64),
        impact_info=np.zeros((impacts, N_IMPACT_INFO)),
        wear_snapshots=np.zeros((n_snapshots, nc, 2, sectors)),
        **{name: np.zeros(n_state) for name in state},
    )


def simulate(
    model: Model, *, progress: Progress | None = None, initial: RunState | None = None
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
        centred and unworn; or the state another run of the same model ended in
        (``Results.final``), possibly with other worn profiles (``RunState.with_wear``). The
        run then goes on from ``initial.time`` to ``initial.time + t_end``.

    Returns
    -------
    Results
        Time series, events and summary; partial, with a non-success status, if the run
        failed or was interrupted.
    """
    solver = model.solver
    system = build_system(model)
    assembly = assemble(model, build_system(model, ideal=True))  # journals centred
    n_state = assembly.y0.shape[0]
    t0 = 0.0 if initial is None else initial.time
    t_end = t0 + solver.t_end
    output_times = _output_times(t0, solver.t_end, solver.output_interval)
    ctl = loop.Control(
        method=int(solver.method),
        rtol=solver.rtol,
        atol=solver.atol,
        min_step=solver.min_step,
        max_step=solver.max_step,
        t_end=t_end,
        max_steps=solver.max_steps,
        output_times=output_times,
        rows_per_step=math.ceil(solver.max_step / solver.output_interval) + 2,
        snapshot_times=_snapshot_times(t0, solver.t_end, solver.wear_snapshot_interval),
    )
    dp, ab, wk = make_dopri5_state(n_state), make_abm_state(n_state), make_work(system)
    ls = _loop_state(
        system, n_state, len(model.events), ctl.snapshot_times.shape[0], wk.wear.shape[2]
    )
    joint_names = clearance_joint_names(model)
    impacts: list[tuple] = []
    columns = column_names(model)
    buffer = np.zeros((max(ctl.rows_per_step * 4, 1024), len(columns)))
    blocks: list[np.ndarray] = []
    events: list[tuple[float, str, str]] = []

    y0 = assembly.y0
    if initial is not None:
        _check_initial(initial, y0, wk.wear)
        y0 = initial.y
        wk.wear[:] = initial.wear
        wk.contact_on[:] = initial.contact_on
        wk.impact_speed[:] = initial.impact_speed

    wall_start = time.perf_counter()
    status = Status.RUNNING
    if not loop.start(system, ctl, ls, dp, ab, wk, t0, y0, solver.initial_step):
        status = Status.SINGULAR
    chunk = min(solver.t_end, MIN_CHUNK_STEPS * solver.max_step)
    budget = MIN_CHUNK_STEPS  # steps a chunk may take, so a stalled run still hands back
    with stop_requests() as stop_requested:
        while status == Status.RUNNING:
            t_before = loop.current_time(ctl, dp, ab)
            chunk_start = time.perf_counter()
            steps_before = ls.counters[Counter.ACCEPTED] + ls.counters[Counter.REJECTED]
            code, rows = loop.advance(
                system, ctl, ls, dp, ab, wk, buffer, t_before + chunk, steps_before + budget
            )
            status = Status(code)
            blocks.append(buffer[:rows].copy())
            for i in range(ls.counters[Counter.EVENTS]):
                direction = "rising" if ls.event_rising[i] else "falling"
                events.append((ls.event_time[i], model.events[ls.event_index[i]].name, direction))
            ls.counters[Counter.EVENTS] = 0
            impacts += impact_rows(
                joint_names, ls.impact_time, ls.impact_joint, ls.impact_info,
                ls.counters[Counter.IMPACTS],
            )  # fmt: skip
            ls.counters[Counter.IMPACTS] = 0
            t_now = loop.current_time(ctl, dp, ab)
            if progress is not None:
                progress(t_now - t0, solver.t_end)
            if stop_requested[0] and status == Status.RUNNING:
                status = Status.INTERRUPTED
            elapsed = time.perf_counter() - chunk_start
            steps = ls.counters[Counter.ACCEPTED] + ls.counters[Counter.REJECTED] - steps_before
            if elapsed > 0:  # aim the next chunk at CHUNK_WALL_S, in time and in steps
                budget = max(MIN_CHUNK_STEPS, min(int(steps / elapsed * CHUNK_WALL_S), 10 * budget))
                if t_now > t_before:
                    rate = (t_now - t_before) / elapsed
                    chunk = min(max(rate * CHUNK_WALL_S, 1e-9 * solver.t_end), 10 * chunk)
    wall = time.perf_counter() - wall_start
    t_reached = float(loop.current_time(ctl, dp, ab))
    final = RunState(
        time=t_reached,
        y=loop.current_state(ctl, dp, ab).copy(),
        wear=wk.wear.copy(),
        contact_on=wk.contact_on.copy(),
        impact_speed=wk.impact_speed.copy(),
    )

    data = np.concatenate(blocks) if blocks else np.zeros((0, len(columns)))
    stats = {
        "simulation_wall_s": wall,
        "t_reached": t_reached,
        "accepted_steps": int(ls.counters[Counter.ACCEPTED]),
        "rejected_steps": int(ls.counters[Counter.REJECTED]),
        "rhs_evaluations": int(ls.counters[Counter.RHS_EVALS]),
        "min_step_hits": int(ls.counters[Counter.MIN_STEP_HITS]),
        "max_constraint_violation": float(ls.max_violation[0]),
        "assembly_iterations": assembly.iterations,
        "degrees_of_freedom": assembly.dof + 2 * len(joint_names),
    }
    tables = {}
    if joint_names:
        tables["wear"] = wear_table(model, wk.wear)
        tables["wear_snapshots"] = snapshot_table(
            model, ctl.snapshot_times, ls.wear_snapshots, int(ls.counters[Counter.SNAPSHOTS])
        )
        tables["impacts"] = pd.DataFrame(impacts, columns=IMPACT_COLUMNS)
    summary = {
        "jointwear_version": __version__,
        "model": model.name,
        "status": status.name.lower(),
        "message": status_message(status),
        "settings": model.solver.model_dump(mode="json"),
        "stats": stats,
    }
    if joint_names:
        summary["clearance_joints"] = joint_summaries(
            model, ls.contact_totals, wk.wear, t_reached - t0
        )
    return Results(
        model=model,
        timeseries=pd.DataFrame(data, columns=columns),
        events=pd.DataFrame(events, columns=["time", "event", "direction"]),
        summary=summary,
        final=final,
        **tables,
    )


def _check_initial(initial: RunState, y0: np.ndarray, wear: np.ndarray) -> None:
    """Refuse a starting state that does not fit the model."""
    for name, given, expected in (("y", initial.y, y0), ("wear", initial.wear, wear)):
        if given.shape != expected.shape:
            raise ValueError(
                f"initial.{name} has shape {given.shape}; this model needs {expected.shape}"
            )
