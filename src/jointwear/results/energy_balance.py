"""The energy balance of a run, from its time series.

The drivers' work against what the mechanism stores and its clearance joints dissipate:
stored (kinetic + potential + the contacts' elastic energy) + dissipated (contact damping,
friction, lubricant film) - driver work stays at its initial value; its drift shows how well
the rows, integrated with the trapezoidal rule, and the motion account for the energy.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..model import Model

DISSIPATION = ("damping_power", "friction_power", "film_power")  # per joint, [W]


def unaccounted(model: Model) -> str | None:
    """What moves energy in ``model`` that the time series does not hold, or None."""
    for driver in model.drivers:
        if driver.type != "angle":
            return f"driver '{driver.name}' moves a distance: its work is not in the time series"
    for force in model.forces:
        if force.does_work:
            kind = force.type.replace("_", " ")
            return f"the work of an applied {kind} is not in the time series"
        if getattr(force, "damping", 0.0) > 0.0:
            return "a damper's dissipation is not in the time series"
    return None


def energy_balance(model: Model, timeseries: pd.DataFrame) -> pd.DataFrame:
    """Per row: ``time``, ``stored``, ``dissipated``, ``driver_work`` and ``balance`` [J].

    ``dissipated`` and ``driver_work`` are integrals from the first row (trapezoidal rule),
    ``balance`` = stored + dissipated - driver_work, minus its first value. Call only when
    ``unaccounted(model)`` is None.
    """
    df = timeseries
    time = df["time"].to_numpy()
    stored = df["energy_kinetic"].to_numpy() + df["energy_potential"].to_numpy()
    if "energy_contact" in df:
        stored = stored + df["energy_contact"].to_numpy()
    power_in = np.zeros_like(time)
    for driver in model.drivers:
        speed = df[f"omega_{driver.body}"].to_numpy()
        if driver.relative_to != "ground":
            speed = speed - df[f"omega_{driver.relative_to}"].to_numpy()
        power_in += df[f"torque_{driver.name}"].to_numpy() * speed
    power_lost = np.zeros_like(time)
    for joint in model.clearance_joints:
        for quantity in DISSIPATION:
            column = f"{joint.name}_{quantity}"
            if column in df:
                power_lost += df[column].to_numpy()
    work, dissipated = _integral(power_in, time), _integral(power_lost, time)
    balance = stored + dissipated - work
    return pd.DataFrame(
        {
            "time": time,
            "stored": stored,
            "dissipated": dissipated,
            "driver_work": work,
            "balance": balance - balance[0],
        }
    )


def _integral(values: np.ndarray, time: np.ndarray) -> np.ndarray:
    """Cumulative trapezoidal integral from the first sample (scipy's is not a runtime need)."""
    steps = 0.5 * (values[1:] + values[:-1]) * np.diff(time)
    return np.concatenate([[0.0], np.cumsum(steps)])
