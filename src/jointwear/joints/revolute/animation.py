"""A revolute clearance joint in the animation: a bearing circle and a journal circle.

The journal's centre is drawn at the bearing's plus ``scale`` times its eccentricity, and the
bearing circle grows to match, so the motion inside the joint shows (the paper's Fig. 6 does
the same with an exaggerated clearance); the journal body's outline goes through it.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.patches import Circle

from ...figures.tracks import track
from ...model import Model
from ..kind import Actor


def actor(model: Model, rows: pd.DataFrame, joint: object, scale: float, size: float) -> Actor:
    """The joint as drawn over ``rows`` with its clearance magnified ``scale`` times."""
    c = joint.clearance
    bearing = track(model, rows, joint.bodies[0], joint.points[0])
    journal = bearing + scale * rows[[f"{joint.name}_ex", f"{joint.name}_ey"]].to_numpy()

    def setup(ax: Axes) -> object:
        radius = c.journal_radius + scale * c.radial_clearance
        outer = ax.add_patch(Circle((0, 0), radius, fill=False, lw=1.5, ec="k", zorder=3))
        inner = ax.add_patch(
            Circle((0, 0), c.journal_radius, fc="w", lw=1.5, ec="tab:red", zorder=4)
        )

        def draw(frame: int) -> None:
            outer.set_center(bearing[frame])
            inner.set_center(journal[frame])

        return draw

    moved = {(joint.bodies[1], joint.points[1]): journal}
    return Actor(moved, np.empty((0, 2)), setup)


def title(joints: tuple, scale: float) -> str:
    """The animation's line on these joints' magnification."""
    c_mm = max(j.clearance.radial_clearance for j in joints) * 1e3
    return (
        f"clearance joints: journal offset × {scale:.3g} "
        f"(c = {c_mm:.3g} mm drawn as {c_mm * scale:.3g} mm)"
    )
