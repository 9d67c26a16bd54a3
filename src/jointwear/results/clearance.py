"""Tables and summary figures of a run's clearance joints, from the loop's arrays.

Revolute joints here, translational ones in ``results.slider``; the tables join both kinds
(each row leaves the other kind's columns empty).

- wear profiles, one row per joint, surface and sector: ``joint, surface, sector,
  angle_deg, depth_m`` (``angle_deg`` is the sector's centre in the surface's body frame);
  the snapshots add the time they were taken, ``time_s``, in front;
- impacts (contact onsets): ``time_s, joint, penetration_velocity_m_s, bearing_angle_deg,
  journal_angle_deg, penetration_m`` (the last shows how closely the onset was located: it
  lies between the contact tolerance and twice that);
- per joint, the figures ``summary.json`` reports under ``clearance_joints``.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..kernels.elements import journal as cs
from ..model import Model
from ..model.clearance import Clearance
from ..model.laws.record import ECCENTRICITY, HERTZ_PATCH, PENETRATION
from . import slider

SURFACES = ("bearing", "journal")
UM = 1e6  # micrometres per metre, for messages and figures
WEAR_COLUMNS = ["joint", "surface", "sector", "angle_deg", "depth_m"]
IMPACT_COLUMNS = [
    "time_s",
    "joint",
    "penetration_velocity_m_s",
    "bearing_angle_deg",
    "journal_angle_deg",
    "penetration_m",
]


def wear_table(
    model: Model, wear: NDArray[np.float64], slider_wear: NDArray[np.float64] | None = None
) -> pd.DataFrame:
    """Long table of the wear depths ``wear[k, surface, sector]`` [m] (and the sliders')."""
    rows = []
    for k, joint in enumerate(model.clearance_joints):
        n = joint.clearance.sectors
        centres = (np.arange(n) + 0.5) * 360.0 / n
        for s, surface in enumerate(SURFACES):
            for i in range(n):
                rows.append((joint.name, surface, i, centres[i], wear[k, s, i]))
    table = pd.DataFrame(rows, columns=WEAR_COLUMNS)
    if slider_wear is None or not model.slider_joints:
        return table
    slides = slider.wear_table(model, slider_wear)
    if not model.clearance_joints:
        return slides
    return pd.concat([table, slides], ignore_index=True)[wear_columns(model)]


def wear_columns(model: Model) -> list[str]:
    """The wear table's columns for the clearance joint kinds of ``model``."""
    angle = ["angle_deg"] if model.clearance_joints else []
    position = ["position_m"] if model.slider_joints else []
    return [*WEAR_COLUMNS[:3], *angle, *position, "depth_m"]


def snapshot_table(
    model: Model,
    times: NDArray[np.float64],
    snapshots: NDArray[np.float64],
    taken: int,
    slider_snapshots: NDArray[np.float64] | None = None,
) -> pd.DataFrame:
    """The wear snapshots taken so far, each with its time ``time_s`` [s]."""
    tables = [
        wear_table(
            model, snapshots[i], None if slider_snapshots is None else slider_snapshots[i]
        ).assign(time_s=times[i])
        for i in range(taken)
    ]
    if not tables:
        return pd.DataFrame(columns=["time_s", *wear_columns(model)])
    table = pd.concat(tables, ignore_index=True)
    return table[["time_s", *table.columns[:-1]]]


def impact_columns(model: Model) -> list[str]:
    """The impact table's columns for the clearance joint kinds of ``model``."""
    kinds = []
    if model.clearance_joints:
        kinds += IMPACT_COLUMNS[3:5]
    if model.slider_joints:
        kinds += slider.IMPACT_COLUMNS[3:5]
    return [*IMPACT_COLUMNS[:3], *kinds, IMPACT_COLUMNS[-1]]


def impact_rows(
    model: Model, time: NDArray, slot: NDArray, info: NDArray, count: int
) -> list[dict]:
    """Rows of the impact table from the loop's impact log (``count`` entries)."""
    journals = len(model.clearance_joints)
    rows = []
    for i in range(count):
        if slot[i] >= journals:
            row = slider.impact_rows(model, time[i], slot[i] - journals, info[i])
            rows.append(dict(zip(slider.IMPACT_COLUMNS, row, strict=True)))
            continue
        row = (
            float(time[i]),
            model.clearance_joints[slot[i]].name,
            float(info[i, cs.IMPACT_SPEED]),
            math.degrees(info[i, cs.IMPACT_THETA_B]),
            math.degrees(info[i, cs.IMPACT_THETA_J]),
            float(info[i, cs.IMPACT_DELTA]),
        )
        rows.append(dict(zip(IMPACT_COLUMNS, row, strict=True)))
    return rows


def joint_summaries(
    model: Model, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
) -> dict[str, dict]:
    """Per clearance joint: contact, impact, wear and energy figures (SI units in the keys).

    ``duration`` [s] is the simulated time the totals were gathered over.
    """
    summaries = {}
    for k, joint in enumerate(model.clearance_joints):
        c = joint.clearance
        row = totals[k]
        entry = {
            "type": "revolute",
            "radial_clearance_m": c.radial_clearance,
            "max_contact_force_n": row[cs.T_MAX_FN],
            "contact_time_fraction": min(1.0, row[cs.T_CONTACT_TIME] / duration)
            if duration
            else 0.0,
            "impacts": int(row[cs.T_IMPACTS]),
            "max_penetration_m": row[cs.T_MAX_DELTA],
            "worn_volume_m3": row[cs.T_WORN_VOLUME],
            "sliding_distance_m": row[cs.T_SLIDING],
            "energy_dissipated_damping_j": row[cs.T_DAMPING_ENERGY],
            "energy_dissipated_friction_j": row[cs.T_FRICTION_ENERGY],
            "outside_law_ranges": _outside_ranges(c, row, duration),
        }
        if c.lubricated:
            entry["energy_dissipated_film_j"] = row[cs.T_FILM_ENERGY]
        for s, surface in enumerate(SURFACES):
            depths = wear[k, s, : c.sectors]
            peak = int(np.argmax(depths))
            worn = depths[peak] > 0.0
            entry[f"max_wear_depth_{surface}_m"] = float(depths[peak])
            entry[f"max_wear_angle_{surface}_deg"] = (
                (peak + 0.5) * 360.0 / c.sectors if worn else None
            )
        summaries[joint.name] = {key: _plain(value) for key, value in entry.items()}
    return summaries


def _outside_ranges(c: Clearance, row: NDArray[np.float64], duration: float) -> dict:
    """Per checked assumption of the joint's laws: its limit, the largest value, the time beyond.

    Only the ranges of the laws this joint uses (their records: ``Clearance.law_ranges``).
    """
    checks = {name: (*_RANGE_TOTALS[name], limit) for name, limit in c.law_ranges().items()}
    return {
        name: {
            "limit": float(limit),
            "largest": float(row[largest]),
            "time_beyond_s": float(row[time]),
            "time_fraction_beyond": float(row[time] / duration) if duration else 0.0,
        }
        for name, (time, largest, limit) in checks.items()
    }


# The journal's totals (time beyond, largest value) of each range a law may have.
_RANGE_TOTALS = {
    PENETRATION: (cs.T_DEPTH_TIME, cs.T_DEPTH_MAX),
    HERTZ_PATCH: (cs.T_PATCH_TIME, cs.T_PATCH_MAX),
    ECCENTRICITY: (cs.T_FILM_TIME, cs.T_FILM_MAX),
}


def _plain(value: object) -> object:
    return float(value) if isinstance(value, np.floating) else value
