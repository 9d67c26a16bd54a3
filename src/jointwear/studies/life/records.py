"""What a long-life wear run records after every update, and its summary.

The effective clearance growth of a joint is the largest increase of the gap between journal
and bearing over every direction, at every relative orientation the two bodies pass through
in the measured cycles: with psi the journal body's angle relative to the bearing body's,
the gap in the direction at angle theta of the bearing's frame grows by
``w_B(theta) + w_J(theta - psi)`` (the worn profiles interpolated as the contact model does,
``kernels.laws.wear.depth_at``), maximised over theta and over psi between its smallest and largest
value in the measured cycles (psi is continuous, so it takes every value in between). When
the bodies turn fully relative to each other it is the sum of the two deepest sectors.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..._version import __version__
from ...joints.revolute import SURFACES
from ...joints.revolute.schema import RevoluteJoint
from ...model import Model
from ...results import Results
from ...results.clearance import wear_table

GRID_CELLS = 2**20  # evaluations per block of the clearance-growth search
GROWTH_MARK = 0.5  # the summary reports the cycles at which the growth reached this share of c


def relative_angle_range(joint: RevoluteJoint, runs: Sequence[Results]) -> tuple[float, float]:
    """Smallest and largest angle psi [rad] of the journal's body relative to the bearing's.

    Over the output rows of ``runs``.
    """
    psi = np.concatenate(
        [
            _angle(r.timeseries, joint.bodies[1]) - _angle(r.timeseries, joint.bodies[0])
            for r in runs
        ]
    )
    return float(psi.min()), float(psi.max())


def _angle(timeseries: pd.DataFrame, body: str) -> NDArray[np.float64]:
    if body == "ground":
        return np.zeros(len(timeseries))
    return timeseries[f"phi_{body}"].to_numpy()


def clearance_growth(
    bearing: NDArray[np.float64], journal: NDArray[np.float64], psi: tuple[float, float]
) -> float:
    """Largest gap increase [m] over directions and relative angles ``psi`` (module docstring).

    Parameters
    ----------
    bearing, journal
        Sector depths of the two surfaces [m], the same number of sectors.
    psi
        Smallest and largest relative angle of the journal's body [rad].
    """
    lo, hi = psi
    if hi - lo >= 2.0 * math.pi:
        return float(bearing.max() + journal.max())
    n = bearing.shape[0]
    sector = 2.0 * math.pi / n
    centres = (np.arange(n) + 0.5) * sector
    # In (theta, phi = theta - psi) the sum is linear on every cell between sector centres,
    # so its largest value on the strip lo <= psi <= hi lies on a vertex of a cell cut by
    # the strip: a pair of centres (psi a whole number of sectors) or a cell edge on the
    # strip's border (psi = lo or hi). For each such psi, it lies on a centre of either
    # surface.
    psis = np.concatenate([[lo, hi], np.arange(math.ceil(lo / sector), hi / sector) * sector])
    largest = 0.0
    for block in np.array_split(psis, math.ceil(psis.size * 2 * n / GRID_CELLS)):
        theta = np.concatenate(
            [np.broadcast_to(centres, (block.size, n)), centres + block[:, None]], 1
        )
        gap = np.interp(theta, centres, bearing, period=2.0 * math.pi)
        gap += np.interp(theta - block[:, None], centres, journal, period=2.0 * math.pi)
        largest = max(largest, float(gap.max()))
    return largest


def clearance_growths(
    model: Model, wear: NDArray[np.float64], psi: Sequence[tuple[float, float]]
) -> NDArray[np.float64]:
    """Effective clearance growth [m] of every clearance joint, for profiles ``wear``."""
    growths = []
    for k, joint in enumerate(model.joints_of("revolute")):
        n = joint.clearance.sectors
        growths.append(clearance_growth(wear[k, 0, :n], wear[k, 1, :n], psi[k]))
    return np.array(growths)


def worn_volume(joint: RevoluteJoint, wear: NDArray[np.float64]) -> float:
    """Volume [m^3] the profiles ``wear[surface, sector]`` hold: depth x R x 2 pi / N x L."""
    c = joint.clearance
    arc = 2.0 * math.pi / c.sectors * c.width
    bearing, journal = wear[0, : c.sectors].sum(), wear[1, : c.sectors].sum()
    return float((bearing * c.bearing_radius + journal * c.journal_radius) * arc)


def driver_columns(model: Model, driver: str) -> tuple[str, str]:
    """The time-series column of ``driver``'s torque or force, and the life table's of its range.

    ``torque_<driver>`` and ``torque_range_<driver>_n_m`` for an angle driver [N m],
    ``force_<driver>`` and ``force_range_<driver>_n`` for a distance driver [N].
    """
    if next(d.type for d in model.drivers if d.name == driver) == "angle":
        return f"torque_{driver}", f"torque_range_{driver}_n_m"
    return f"force_{driver}", f"force_range_{driver}_n"


def table_columns(model: Model, driver: str) -> list[str]:
    """The columns of life.csv, in order."""
    columns = ["update", "cycles", "simulated_cycles", "extrapolated_cycles", "steady"]
    for joint in model.joints_of("revolute"):
        columns += [f"{joint.name}.{key}" for key in _JOINT_KEYS]
    return [*columns, driver_columns(model, driver)[1], "wall_s"]


_JOINT_KEYS = (
    "max_wear_depth_bearing_m",
    "max_wear_depth_journal_m",
    "clearance_growth_m",
    "worn_volume_m3",
    "wear_rate_m_per_cycle",
    "max_contact_force_n",
)


def update_row(
    model: Model,
    driver: str,
    counts: tuple[int, int, int, int, int],
    wear: NDArray[np.float64],
    rate: NDArray[np.float64],
    growth: NDArray[np.float64],
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
    wear
        The profiles after the update [m], (joints, 2, sectors).
    rate
        Wear per cycle of the update's measured cycles [m].
    growth
        Effective clearance growth of each joint with ``wear`` [m].
    runs
        The update's measured cycles (contact forces and driver torque).
    wall_s
        Wall time of the whole run so far [s].
    """
    row: list = list(counts)
    for k, joint in enumerate(model.joints_of("revolute")):
        n = joint.clearance.sectors
        row += [
            float(wear[k, 0, :n].max()),
            float(wear[k, 1, :n].max()),
            float(growth[k]),
            worn_volume(joint, wear[k]),
            float(rate[k, :, :n].max()),
            max(r.summary["clearance_joints"][joint.name]["max_contact_force_n"] for r in runs),
        ]
    column = driver_columns(model, driver)[0]
    torque = np.concatenate([r.timeseries[column].to_numpy() for r in runs])
    return [*row, float(torque.max() - torque.min()), wall_s]


def profile_rows(model: Model, update: int, cycles: int, wear: NDArray[np.float64]) -> list[list]:
    """Rows of profiles.csv: ``update, cycles, joint, surface, sector, angle_deg, depth_m``."""
    table = wear_table(model, {"revolute": wear})
    return [[update, cycles, *row] for row in table.itertuples(index=False, name=None)]


def cycles_at(cycles: pd.Series, values: pd.Series, level: float) -> float | None:
    """Cycles at which ``values`` first reach ``level`` (linear between rows); None if never."""
    reached = np.flatnonzero(values.to_numpy() >= level)
    if reached.size == 0:
        return None
    i = int(reached[0])
    if i == 0:
        return float(cycles.iloc[0])
    x0, x1 = cycles.iloc[i - 1], cycles.iloc[i]
    y0, y1 = values.iloc[i - 1], values.iloc[i]
    return float(x0 + (level - y0) / (y1 - y0) * (x1 - x0))


def life_summary(
    model: Model,
    table: pd.DataFrame,
    wear: NDArray[np.float64] | None,
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
        status, message, cycles, period_s, driver, wall_s, settings: written first, as given.
    """
    last = table.iloc[-1] if len(table) else None
    summary = {
        "jointwear_version": __version__,
        "model": model.name,
        **outcome,
        "cycles_reached": int(last["cycles"]) if last is not None else 0,
        "updates": int(last["update"]) if last is not None else 0,
        "simulated_cycles": int(last["simulated_cycles"]) if last is not None else 0,
        "unsteady_updates": int((table["steady"] == 0).sum()),
    }
    joints = {}
    for k, joint in enumerate(model.joints_of("revolute")):
        c = joint.clearance.radial_clearance
        entry: dict[str, float | None] = {"radial_clearance_m": c}
        if last is not None:
            for key in ("max_wear_depth_bearing_m", "max_wear_depth_journal_m"):
                entry[key] = float(last[f"{joint.name}.{key}"])
            growth = float(last[f"{joint.name}.clearance_growth_m"])
            entry["clearance_growth_m"] = growth
            entry["clearance_growth_fraction"] = growth / c
            entry["worn_volume_m3"] = float(last[f"{joint.name}.worn_volume_m3"])
            entry["max_contact_force_n"] = float(table[f"{joint.name}.max_contact_force_n"].max())
            entry["cycles_to_clearance_growth_50pct"] = cycles_at(
                table["cycles"], table[f"{joint.name}.clearance_growth_m"], GROWTH_MARK * c
            )
            for s, surface in enumerate(SURFACES):
                depths = wear[k, s, : joint.clearance.sectors]
                peak = int(np.argmax(depths))
                angle = (peak + 0.5) * 360.0 / depths.shape[0]
                entry[f"max_wear_angle_{surface}_deg"] = angle if depths[peak] > 0 else None
        joints[joint.name] = entry
    summary["clearance_joints"] = joints
    return summary
