"""A pin-in-slot clearance joint in the animation: the slot's outline and the pin's circle.

As for the other kinds, the motion inside the joint is magnified ``scale`` times: the pin's
centre is drawn at the point of the slot's centre segment nearest to it plus ``scale`` times
its offset from there, and the slot's half-width grows to R_p + ``scale`` c to match, so the
drawn pin touches the drawn slot when the true one touches. The slot moves with its body; the
pin body's point is drawn at the drawn pin.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.patches import Circle, Polygon

from ...figures.tracks import angle, track
from ...model import Model
from ..kind import Actor

OUTLINE_POINTS = 40  # per end of the drawn slot


def _stadium(half_length: float, half_width: float) -> np.ndarray:
    """(n, 2) outline of a slot, (along, across) from its point [m]: sides and round ends."""
    turn = np.linspace(-0.5 * math.pi, 0.5 * math.pi, OUTLINE_POINTS)
    front = np.column_stack([half_length + half_width * np.cos(turn), half_width * np.sin(turn)])
    return np.concatenate([front, -front])


def actor(model: Model, rows: pd.DataFrame, joint: object, scale: float, size: float) -> Actor:
    """The joint as drawn over ``rows`` with its gap magnified ``scale`` times."""
    c = joint.clearance
    slot, pin = joint.bodies
    point = track(model, rows, slot, joint.points[0])
    theta = angle(rows, slot) + math.atan2(joint.axis[1], joint.axis[0])
    u = np.column_stack([np.cos(theta), np.sin(theta)])
    v = np.column_stack([-u[:, 1], u[:, 0]])
    along = rows[f"{joint.name}_along"].to_numpy()
    across = rows[f"{joint.name}_across"].to_numpy()
    half = 0.5 * c.slot_length
    nearest = np.clip(along, -half, half)  # the centre segment's point nearest the pin
    drawn_along = nearest + scale * (along - nearest)
    centre = point + drawn_along[:, None] * u + scale * across[:, None] * v
    local = _stadium(half, c.pin_radius + scale * c.gap)
    outline = point[:, None, :] + local[None, :, :1] * u[:, None] + local[None, :, 1:] * v[:, None]

    def setup(ax: Axes) -> object:
        wall = ax.add_patch(Polygon(outline[0], closed=True, fill=False, lw=1.5, ec="k", zorder=3))
        circle = ax.add_patch(Circle((0, 0), c.pin_radius, fc="w", lw=1.5, ec="tab:red", zorder=4))

        def draw(frame: int) -> None:
            wall.set_xy(outline[frame])
            circle.set_center(centre[frame])

        return draw

    return Actor({(pin, joint.points[1]): centre}, outline.reshape(-1, 2), setup)


def title(joints: tuple, scale: float) -> str:
    """The animation's line on these joints' magnification."""
    c_mm = max(j.clearance.gap for j in joints) * 1e3
    return (
        f"pins in slots: offset from the slot's centre line × {scale:.3g} "
        f"(gap {c_mm:.3g} mm drawn as {c_mm * scale:.3g} mm)"
    )
