"""Tables and summary figures of a run's translational clearance joints (sliders).

- wear profiles, one row per joint, surface and segment: ``joint, surface, sector,
  position_m, depth_m`` (``position_m`` is the segment's centre along its surface, from the
  surface's middle, in its body's frame: the guide's from the joint's first point, the
  slider's from its centre, positive along the axis); an unbounded guide keeps no map of its
  wear, so its surfaces have no rows;
- impacts (contact onsets): ``time_s, joint, penetration_velocity_m_s, contact,
  guide_position_m, penetration_m`` (``contact`` names the corner or guide edge,
  ``kernels.elements.slider.CONTACT_NAMES``);
- per joint, the figures ``summary.json`` reports under ``clearance_joints``.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..kernels.elements import slider as ks
from ..model import Model
from ..model.sections import TranslationalJoint

WEAR_COLUMNS = ["joint", "surface", "sector", "position_m", "depth_m"]
IMPACT_COLUMNS = [
    "time_s", "joint", "penetration_velocity_m_s", "contact", "guide_position_m", "penetration_m",
]  # fmt: skip


def surfaces(joint: TranslationalJoint) -> dict[str, float]:
    """{mapped surface: its length [m]}, in the order of the kernel's wear array."""
    c = joint.clearance
    guide = c.guide_length
    lengths = (guide, guide, c.slider_length, c.slider_length)
    return {name: length for name, length in zip(ks.SURFACES, lengths, strict=True) if length}


def segment_centres(length: float, segments: int) -> NDArray[np.float64]:
    """Centres of a surface's segments from its middle [m]."""
    return (np.arange(segments) + 0.5) * length / segments - 0.5 * length


def wear_table(model: Model, wear: NDArray[np.float64]) -> pd.DataFrame:
    """Long table of the wear depths ``wear[k, surface, segment]`` [m]."""
    rows = []
    for k, joint in enumerate(model.slider_joints):
        n = joint.clearance.segments
        for surface, length in surfaces(joint).items():
            s = ks.SURFACES.index(surface)
            centres = segment_centres(length, n)
            rows += [(joint.name, surface, i, centres[i], wear[k, s, i]) for i in range(n)]
    return pd.DataFrame(rows, columns=WEAR_COLUMNS)


def impact_rows(model: Model, time: float, slot: int, info: NDArray) -> tuple:
    """One row of the impact table from a slider slot's onset (slot counted among sliders)."""
    return (
        float(time),
        model.slider_joints[slot // ks.SLOTS].name,
        float(info[ks.IMPACT_SPEED]),
        ks.CONTACT_NAMES[int(info[ks.IMPACT_CONTACT])],
        float(info[ks.IMPACT_X_GUIDE]),
        float(info[ks.IMPACT_DELTA]),
    )


def joint_summaries(
    model: Model, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
) -> dict[str, dict]:
    """Per slider: contact, impact, wear and energy figures (SI units in the keys).

    ``duration`` [s] is the simulated time the totals were gathered over.
    """
    summaries = {}
    for k, joint in enumerate(model.slider_joints):
        c = joint.clearance
        row = totals[k]
        entry: dict[str, object] = {
            "type": "translational",
            "gap_m": c.clearance_gap,
            "max_contact_force_n": float(row[ks.T_MAX_FN]),
            "contact_time_fraction": (
                min(1.0, float(row[ks.T_CONTACT_TIME] / duration)) if duration else 0.0
            ),
            "impacts": int(row[ks.T_IMPACTS]),
            "max_penetration_m": float(row[ks.T_MAX_DELTA]),
            "worn_volume_m3": float(row[ks.T_WORN_VOLUME]),
            "sliding_distance_m": float(row[ks.T_SLIDING]),
            "energy_dissipated_damping_j": float(row[ks.T_DAMPING_ENERGY]),
            "energy_dissipated_friction_j": float(row[ks.T_FRICTION_ENERGY]),
        }
        for surface, length in surfaces(joint).items():
            depths = wear[k, ks.SURFACES.index(surface), : c.segments]
            peak = int(np.argmax(depths))
            worn = depths[peak] > 0.0
            entry[f"max_wear_depth_{surface}_m"] = float(depths[peak])
            where = segment_centres(length, c.segments)[peak]
            entry[f"max_wear_position_{surface}_m"] = float(where) if worn else None
        summaries[joint.name] = entry
    return summaries
