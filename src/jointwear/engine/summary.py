"""What a finished run reports: its tables and ``summary.json``."""

from __future__ import annotations

import numpy as np
import pandas as pd

from .._version import __version__
from ..kernels.codes import Counter, Status
from ..model import Model
from ..results.clearance import impact_columns, joint_summaries, snapshot_table, wear_table
from ..results.cycles import CycleWindows, Settling, lead_with_steady_state
from .contacts import Contacts
from .status import status_message

DRIVER_EFFORTS = {"torque": "n_m", "force": "n"}  # time-series <kind>_<driver>: summary suffix


def run_stats(log: object, wall: float, t_reached: float, assembly: object, dof: int) -> dict:
    """The run's counts: wall time [s], steps, evaluations, constraint violation, ..."""
    return {
        "simulation_wall_s": wall,
        "t_reached": t_reached,
        "accepted_steps": int(log.counters[Counter.ACCEPTED]),
        "rejected_steps": int(log.counters[Counter.REJECTED]),
        "rhs_evaluations": int(log.counters[Counter.RHS_EVALS]),
        "min_step_hits": int(log.counters[Counter.MIN_STEP_HITS]),
        "max_constraint_violation": float(log.max_violation[0]),
        "assembly_iterations": assembly.iterations,
        "degrees_of_freedom": dof,
    }


def clearance_tables(
    model: Model,
    contacts: Contacts,
    snapshot_times: np.ndarray,
    taken: int,
    impacts: list[dict],
    windows: CycleWindows,
) -> dict[str, pd.DataFrame]:
    """The clearance joints' tables: wear, its snapshots, impacts, cycles."""
    return {
        "wear": wear_table(model, contacts.wear()),
        "wear_snapshots": snapshot_table(model, snapshot_times, contacts.snapshots(), taken),
        "impacts": pd.DataFrame.from_records(impacts, columns=impact_columns(model)),
        "cycles": windows.table(model),
    }


def summary(
    model: Model,
    status: Status,
    detail: str,
    stats: dict,
    redundant: int,
    energy: dict,
) -> dict:
    """``summary.json`` of a run, before its clearance joints and provenance."""
    solver = model.solver
    return {
        "jointwear_version": __version__,
        "model": model.name,
        "status": status.name.lower(),
        "message": detail or status_message(status),
        "settings": solver.model_dump(mode="json"),
        "stats": stats,
        "constraints": {
            "formulation": solver.formulation,
            "max_violation": stats["max_constraint_violation"],
            "bound": solver.max_constraint_violation,
            "redundant_equations": redundant,
        },
        "energy": energy,
    }


def clearance_summary(
    model: Model,
    contacts: Contacts,
    windows: CycleWindows,
    settle: Settling,
    span: tuple[float, float],
) -> dict:
    """The summary's ``steady_state`` and ``clearance_joints`` over the run ``span`` [s]."""
    t0, t_reached = span
    wear = contacts.wear()
    whole = joint_summaries(model, contacts.totals(), wear, t_reached - t0)
    steady = windows.steady()
    settled = None if steady is None else joint_summaries(model, steady[0], wear, steady[1])
    return {
        "steady_state": settle.summary(t0, t_reached, steady[2] if steady else 0),
        "clearance_joints": lead_with_steady_state(whole, settled),
    }


def driver_summary(model: Model, timeseries: pd.DataFrame, steady_state: dict | None) -> dict:
    """Per driver, the torque [N m] (or force [N]) it applies: largest, smallest and range.

    Over the steady state where the run reached it (``steady_state``'s ``from_s``), else over
    the whole run; what sizes the drive (a motor's rating, a gearbox's torque range).
    """
    from_s = (steady_state or {}).get("from_s")
    rows = timeseries if from_s is None else timeseries[timeseries["time"] >= from_s]
    drivers = {}
    for driver in model.drivers:
        for kind, suffix in DRIVER_EFFORTS.items():
            column = f"{kind}_{driver.name}"
            if column not in rows or not len(rows):
                continue
            values = rows[column].to_numpy()
            drivers[driver.name] = {
                f"max_{kind}_{suffix}": float(np.max(values)),
                f"min_{kind}_{suffix}": float(np.min(values)),
                f"{kind}_range_{suffix}": float(np.ptp(values)),
            }
    return drivers
