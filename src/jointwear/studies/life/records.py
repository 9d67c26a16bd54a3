"""What a long-life wear run records after every update, and its summary.

Every clearance joint of a kind that life runs support (``ClearanceKind.life_runs``) is
recorded alike: per mapped surface its deepest cell, the effective clearance growth (the
kind's measure, ``ClearanceKind.clearance_growth``), the volume the profiles hold, the
largest wear per cycle, the peak contact force and the largest penetration against the gap.
Cycles are also given as hours of operation (``hours``: cycles times the driver's period).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..._version import __version__
from ...joints import ClearanceKind, joints_by_kind
from ...joints.kind import deepest
from ...model import Model
from ...results import Results
from ...results.clearance import wear_columns, wear_table
from ...results.cycles import cycles_at

GROWTH_MARK = 0.5  # the summary reports the cycles at which the growth reached this share of c
PENETRATION_KEY = "max_penetration_over_gap"  # life.csv: the measured cycles' largest [-]
HOUR_S = 3600.0
Profiles = dict[str, NDArray[np.float64]]  # per joint type, (joints, surfaces, cells) [m]


def cells(kind: ClearanceKind, joint: object, values: NDArray[np.float64]) -> NDArray[np.float64]:
    """The joint's mapped cells of ``values`` (an array shaped as its wear), flat."""
    return np.array([row[3] for row in kind.wear_rows(joint, values)])


def deepest_cells(
    kind: ClearanceKind, joint: object, wear: NDArray[np.float64]
) -> dict[str, tuple[float, object]]:
    """Per mapped surface: its deepest cell's depth [m] and position (None if unworn)."""
    rows = kind.wear_rows(joint, wear)
    found = {}
    for surface in kind.mapped_surfaces(joint):
        mine = [row for row in rows if row[0] == surface]
        depth, peak = deepest(np.array([row[3] for row in mine]))
        found[surface] = (depth, None if peak is None else float(mine[peak][2]))
    return found


def clearance_growths(
    model: Model, wear: Profiles, timeseries: Sequence[pd.DataFrame]
) -> dict[str, float]:
    """Effective clearance growth [m] of every clearance joint by name, for profiles ``wear``.

    ``timeseries``: the measured cycles, whose motion the growth is judged at.
    """
    return {
        joint.name: kind.clearance_growth(joint, wear[kind.name][k], timeseries)
        for kind, k, joint in joints_by_kind(model)
    }


def hours(cycles: float | None, period: float) -> float | None:
    """Hours of operation of ``cycles`` cycles of ``period`` [s]; None for None (never)."""
    return None if cycles is None else cycles * period / HOUR_S


def figure_options(model: Model, driver: str, period: float) -> dict:
    """What the life figures take of the study: growth mark, driver's range column, period."""
    return {
        "growth_mark": GROWTH_MARK,
        "range_column": driver_columns(model, driver)[1],
        "period_s": period,
    }


def driver_columns(model: Model, driver: str) -> tuple[str, str]:
    """The time-series column of ``driver``'s torque or force, and the life table's of its range.

    ``torque_<driver>`` and ``torque_range_<driver>_n_m`` for an angle driver [N m],
    ``force_<driver>`` and ``force_range_<driver>_n`` for a distance driver [N].
    """
    if next(d.type for d in model.drivers if d.name == driver) == "angle":
        return f"torque_{driver}", f"torque_range_{driver}_n_m"
    return f"force_{driver}", f"force_range_{driver}_n"


def depth_keys(kind: ClearanceKind, joint: object) -> list[str]:
    """The keys of the joint's deepest cell per mapped surface, ``max_wear_depth_<surface>_m``."""
    return [f"max_wear_depth_{surface}_m" for surface in kind.mapped_surfaces(joint)]


def table_columns(model: Model, driver: str) -> list[str]:
    """The columns of life.csv, in order."""
    columns = ["update", "cycles", "hours", "simulated_cycles", "extrapolated_cycles", "steady"]
    for kind, _, joint in joints_by_kind(model):
        keys = [*depth_keys(kind, joint), *_JOINT_KEYS]
        columns += [f"{joint.name}.{key}" for key in keys]
    return [*columns, driver_columns(model, driver)[1], "wall_s"]


def profile_columns(model: Model) -> list[str]:
    """The columns of profiles.csv: the wear table's, after the update and its cycles."""
    return ["update", "cycles", *wear_columns(model)]


_JOINT_KEYS = (
    "clearance_growth_m",
    "worn_volume_m3",
    "wear_rate_m_per_cycle",
    "max_contact_force_n",
    PENETRATION_KEY,
)


def update_row(
    model: Model,
    driver: str,
    counts: tuple[int, int, int, int, int],
    period: float,
    wear: Profiles,
    rate: Profiles,
    growth: dict[str, float],
    runs: Sequence[Results],
    wall_s: float,
) -> list:
    """One row of life.csv, in the order of ``table_columns``.

    Parameters
    ----------
    model, driver
        The model and the driver whose cycles are counted.
    counts
        Update number, cycles so far, cycles simulated so far, cycles extrapolated by it,
        and 1 if the measured cycles were steady (else 0).
    period
        The cycle [s].
    wear
        The profiles after the update [m].
    rate
        Wear per cycle of the update's measured cycles [m].
    growth
        Effective clearance growth of each joint with ``wear`` [m], by name.
    runs
        The update's measured cycles (contact forces and driver torque).
    wall_s
        Wall time of the whole run so far [s].
    """
    row: list = [counts[0], counts[1], hours(counts[1], period), *counts[2:]]
    for kind, k, joint in joints_by_kind(model):
        mine = wear[kind.name][k]
        figures = [r.summary["clearance_joints"][joint.name] for r in runs]
        ranges = [f.get("outside_law_ranges", {}).get(kind.penetration_range) for f in figures]
        row += [depth for depth, _ in deepest_cells(kind, joint, mine).values()]
        row += [
            growth[joint.name],
            kind.worn_volume(joint, mine),
            float(cells(kind, joint, rate[kind.name][k]).max()),
            max(f["max_contact_force_n"] for f in figures),
            max((r["largest"] for r in ranges if r is not None), default=float("nan")),
        ]
    column = driver_columns(model, driver)[0]
    torque = np.concatenate([r.timeseries[column].to_numpy() for r in runs])
    return [*row, float(torque.max() - torque.min()), wall_s]


def profile_rows(model: Model, update: int, cycles: int, wear: Profiles) -> list[list]:
    """Rows of profiles.csv, in the order of ``profile_columns``."""
    table = wear_table(model, wear)
    return [[update, cycles, *row] for row in table.itertuples(index=False, name=None)]


def life_summary(
    model: Model,
    table: pd.DataFrame,
    wear: Profiles | None,
    outcome: dict,
) -> dict:
    """``summary.json`` of a life run.

    Parameters
    ----------
    model
        The model as run (after overrides and the feedback setting).
    table
        The life table (life.csv).
    wear
        The final profiles [m], or None if no update was made.
    outcome
        status, message, cycles, period_s, driver, wall_s, settings (and ``runaway`` if the
        run ran away): written first, as given.
    """
    last = table.iloc[-1] if len(table) else None
    reached = int(last["cycles"]) if last is not None else 0
    summary = {
        "jointwear_version": __version__,
        "model": model.name,
        **outcome,
        "cycles_reached": reached,
        "hours_reached": hours(reached, outcome["period_s"]),
        "updates": int(last["update"]) if last is not None else 0,
        "simulated_cycles": int(last["simulated_cycles"]) if last is not None else 0,
        "unsteady_updates": int((table["steady"] == 0).sum()),
    }
    joints = {}
    for kind, k, joint in joints_by_kind(model):
        c = kind.gap(joint)
        entry: dict[str, object] = {"type": kind.name, kind.gap_key: c}
        if last is not None:
            name = joint.name
            for key in depth_keys(kind, joint):
                entry[key] = float(last[f"{name}.{key}"])
            growth = float(last[f"{name}.clearance_growth_m"])
            entry["clearance_growth_m"] = growth
            entry["clearance_growth_fraction"] = growth / c
            entry["worn_volume_m3"] = float(last[f"{name}.worn_volume_m3"])
            entry["max_contact_force_n"] = float(table[f"{name}.max_contact_force_n"].max())
            half = cycles_at(table["cycles"], table[f"{name}.clearance_growth_m"], GROWTH_MARK * c)
            entry["cycles_to_clearance_growth_50pct"] = half
            entry["hours_to_clearance_growth_50pct"] = hours(half, outcome["period_s"])
            where, unit = kind.wear_position.rsplit("_", 1)  # angle_deg, position_m
            for surface, (_, place) in deepest_cells(kind, joint, wear[kind.name][k]).items():
                entry[f"max_wear_{where}_{surface}_{unit}"] = place
        joints[joint.name] = entry
    halves = [e["cycles_to_clearance_growth_50pct"] for e in joints.values()]
    first = min((half for half in halves if half is not None), default=None)
    summary["cycles_to_clearance_growth_50pct"] = first  # the mechanism's: its first joint's
    summary["hours_to_clearance_growth_50pct"] = hours(first, outcome["period_s"])
    summary["clearance_joints"] = joints
    return summary
