"""Tables and summary figures of a run's clearance joints, from the loop's arrays.

Every joint type with clearance (``jointwear.joints``) gives its own rows; the tables join
them, each row leaving the columns of other types empty.

- wear profiles, one row per joint, surface and cell: ``joint, surface, sector, <position>,
  depth_m`` (the position column is the kind's: ``angle_deg`` round a revolute joint's
  surfaces, ``position_m`` along a translational joint's); the snapshots add the time they
  were taken, ``time_s``, in front;
- impacts (contact onsets): ``time_s, joint, penetration_velocity_m_s, <the kinds' columns>,
  penetration_m`` (the last shows how closely the onset was located: it lies between the
  contact tolerance and twice that);
- per joint, the figures ``summary.json`` reports under ``clearance_joints``.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..joints import KINDS
from ..model import Model

UM = 1e6  # micrometres per metre, for messages and figures
WEAR_COLUMNS = ["joint", "surface", "sector", "depth_m"]  # with the kinds' position columns


def _present(model: Model) -> list:
    """The kinds ``model`` has joints of, in registry order."""
    return [kind for kind in KINDS if kind.joints(model)]


def wear_columns(model: Model) -> list[str]:
    """The wear table's columns for the clearance joint kinds of ``model``."""
    positions = list(dict.fromkeys(kind.wear_position for kind in _present(model)))
    return [*WEAR_COLUMNS[:3], *positions, "depth_m"]


def wear_table(model: Model, wear: dict[str, NDArray[np.float64]]) -> pd.DataFrame:
    """Long table of the wear depths, ``wear[kind][k, surface, cell]`` [m]."""
    frames = []
    for kind in _present(model):
        rows = [
            (joint.name, surface, cell, position, depth)
            for k, joint in enumerate(kind.joints(model))
            for surface, cell, position, depth in kind.wear_rows(joint, wear[kind.name][k])
        ]
        columns = [*WEAR_COLUMNS[:3], kind.wear_position, "depth_m"]
        frames.append(pd.DataFrame(rows, columns=columns))
    if not frames:
        return pd.DataFrame(columns=wear_columns(model))
    if len(frames) == 1:
        return frames[0]
    return pd.concat(frames, ignore_index=True)[wear_columns(model)]


def snapshot_table(
    model: Model, times: NDArray[np.float64], snapshots: dict[str, NDArray], taken: int
) -> pd.DataFrame:
    """The wear snapshots taken so far, each with its time ``time_s`` [s]."""
    tables = [
        wear_table(model, {name: s[i] for name, s in snapshots.items()}).assign(time_s=times[i])
        for i in range(taken)
    ]
    if not tables:
        return pd.DataFrame(columns=["time_s", *wear_columns(model)])
    table = pd.concat(tables, ignore_index=True)
    return table[["time_s", *table.columns[:-1]]]


def impact_columns(model: Model) -> list[str]:
    """The impact table's columns for the clearance joint kinds of ``model``."""
    own = dict.fromkeys(c for kind in _present(model) for c in kind.impact_columns)
    return ["time_s", "joint", "penetration_velocity_m_s", *own, "penetration_m"]


def impact_rows(
    model: Model, time: NDArray, owner: NDArray, info: NDArray, count: int
) -> list[dict]:
    """Rows of the impact table from the loop's impact log (``count`` entries).

    ``owner[i]``: the onset's kind (index in ``KINDS``) and its joint among that kind's.
    """
    joints = [kind.joints(model) for kind in KINDS]
    rows = []
    for i in range(count):
        kind, k = int(owner[i, 0]), int(owner[i, 1])
        figures = KINDS[kind].impact_row(info[i])
        rows.append({"time_s": float(time[i]), "joint": joints[kind][k].name, **figures})
    return rows


def joint_summaries(
    model: Model,
    totals: dict[str, NDArray[np.float64]],
    wear: dict[str, NDArray[np.float64]],
    duration: float,
) -> dict[str, dict]:
    """Per clearance joint, its figures (SI units in the keys), in registry then file order.

    ``totals`` and ``wear``: per kind, gathered over ``duration`` [s] of simulated time.
    """
    return {
        joint.name: kind.summary(joint, totals[kind.name][k], wear[kind.name][k], duration)
        for kind in KINDS
        for k, joint in enumerate(kind.joints(model))
    }
