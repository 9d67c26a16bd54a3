"""Driving the compiled loop chunk by chunk, and watching each chunk.

Between chunks (about ``CHUNK_WALL_S`` of wall time each) the rows computed so far are kept,
the crossings and contact onsets the chunk logged are read, the rows are checked for
non-finite values and for energy drift, the progress callback is called, and Ctrl-C or
SIGTERM end the run cleanly with status ``interrupted``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from ..kernels import loop
from ..kernels.codes import Counter, Status
from ..model import Model
from ..results.clearance import impact_rows
from ..results.cycles import CycleWindows
from . import integrators
from .contacts import Contacts
from .energy import EnergyMonitor
from .finite import first_non_finite
from .interrupts import stop_requests

CHUNK_WALL_S = 0.2  # target wall time of one compiled chunk [s]
MIN_CHUNK_STEPS = 100  # the first chunk: this many maximum steps, and at least this many steps
Progress = Callable[[float, float], None]  # (simulated time reached, end time) [s]


class LoopArrays(NamedTuple):
    """The compiled loop's arrays for one run."""

    args: tuple  # its tables as structs, by reference: problem, integrator, events, ...
    log: loop.Log
    integ: object  # the integrator's state (``integrators``)
    buffer: np.ndarray  # rows of one chunk
    columns: list[str]  # the time series' columns


@dataclass
class Drive:
    """What the chunks gave: rows, crossings, onsets, the status and why."""

    status: Status = Status.RUNNING
    detail: str = ""  # what a non-finite status found, and when
    blocks: list[np.ndarray] = field(default_factory=list)
    events: list[tuple[float, str, str]] = field(default_factory=list)
    impacts: list[dict] = field(default_factory=list)


def drive(
    model: Model,
    arrays: LoopArrays,
    contacts: Contacts,
    watch: tuple[CycleWindows, EnergyMonitor],
    t0: float,
    progress: Progress | None,
    status: Status,
) -> Drive:
    """Advance the loop from ``t0`` [s] until it stops; ``watch``: the cycles and the energy."""
    solver = model.solver
    args, log, integ, buffer, columns = arrays
    windows, energy = watch
    done = Drive(status=status)
    chunk = min(solver.t_end, MIN_CHUNK_STEPS * solver.max_step)
    budget = MIN_CHUNK_STEPS  # steps a chunk may take, so a stalled run still hands back
    with stop_requests() as stop_requested:
        while done.status == Status.RUNNING:
            t_before = integrators.time(integ)
            chunk_start = time.perf_counter()
            steps_before = log.counters[Counter.ACCEPTED] + log.counters[Counter.REJECTED]
            try:
                t_stop = min(t_before + chunk, windows.next_end)
                code, rows = loop.advance(*args, buffer, t_stop, steps_before + budget)
            except ArithmeticError as error:  # a kernel divided by zero: values at float's edges
                code, rows = Status.NON_FINITE, 0
                done.detail = (
                    f"{type(error).__name__} in the compiled step loop between t = "
                    f"{t_before:.6g} and {integrators.time(integ):.6g} s (the chunk's rows are "
                    "lost); check the model's sizes and coefficients against their units"
                )
            done.status = Status(code)
            _keep(
                done, buffer[:rows].copy(), columns, contacts, (t_before, integrators.time(integ))
            )
            if energy.update(done.blocks[-1]) and done.status in (Status.RUNNING, Status.SUCCESS):
                done.status = Status.ENERGY_DRIFT
            _read_logs(done, model, log)
            t_now = integrators.time(integ)
            windows.passed(t_now)
            if progress is not None:
                progress(t_now - t0, solver.t_end)
            if stop_requested[0] and done.status == Status.RUNNING:
                done.status = Status.INTERRUPTED
            elapsed = time.perf_counter() - chunk_start
            steps = log.counters[Counter.ACCEPTED] + log.counters[Counter.REJECTED] - steps_before
            if elapsed > 0:  # aim the next chunk at CHUNK_WALL_S, in time and in steps
                budget = max(MIN_CHUNK_STEPS, min(int(steps / elapsed * CHUNK_WALL_S), 10 * budget))
                if t_now > t_before:
                    rate = (t_now - t_before) / elapsed
                    chunk = min(max(rate * CHUNK_WALL_S, 1e-9 * solver.t_end), 10 * chunk)
    return done


def _keep(
    done: Drive, block: np.ndarray, columns: list[str], contacts: Contacts, span: tuple
) -> None:
    """Keep a chunk's rows up to the first non-finite value (which ends the run)."""
    done.blocks.append(block)
    broken = first_non_finite(block, columns, contacts.accumulated(), span)
    if broken is not None and done.status in (Status.RUNNING, Status.SUCCESS):
        quantity, when, keep = broken
        done.blocks[-1] = block[:keep]  # the rows before it are kept
        done.status = Status.NON_FINITE
        done.detail = (
            f"{quantity} became non-finite (NaN or inf) {when}; check the model's "
            "coefficients (wear, stiffness, forces) against their units"
        )


def _read_logs(done: Drive, model: Model, log: loop.Log) -> None:
    """Move the chunk's crossings and contact onsets out of the loop's log."""
    for i in range(log.counters[Counter.EVENTS]):
        direction = "rising" if log.event_rising[i] else "falling"
        name = model.events[log.event_index[i]].name
        done.events.append((log.event_time[i], name, direction))
    log.counters[Counter.EVENTS] = 0
    done.impacts += impact_rows(
        model, log.impact_time, log.impact_owner, log.impact_info,
        log.counters[Counter.IMPACTS],
    )  # fmt: skip
    log.counters[Counter.IMPACTS] = 0
