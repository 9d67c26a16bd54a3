"""A translational joint in the animation: the guide's two surfaces and the slider's block.

With clearance, the gap, the slider's lateral offset and its tilt are magnified ``scale``
times (the tilt as an angle, so the corners meet the drawn surfaces about when they meet the
true ones, for small angles); the slider's body follows the drawn slider. An ideal joint,
which has no size of its own, is drawn as a block of ``IDEAL_SLIDER_SHARE`` of the
mechanism's size between its guide's surfaces.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.patches import Rectangle

from ...figures.tracks import angle, track
from ...model import Model
from ..kind import Actor

IDEAL_SLIDER_SHARE = 0.08  # an ideal translational joint's block: this share of the mechanism long
IDEAL_SLIDER_ASPECT = 0.5  # and this share of its length high


class SliderPose(NamedTuple):
    """A translational joint as drawn over the frames (a clearance's gap, offset, tilt scaled)."""

    centre: np.ndarray  # (frames, 2) slider's drawn centre [m]
    angle: np.ndarray  # (frames,) slider axis' drawn angle from the global x axis [rad]
    guide: np.ndarray  # (frames, 2 surfaces, 2 ends, 2) guide surfaces' drawn ends [m]
    corners: np.ndarray  # (frames, 4, 2) slider rectangle's drawn corners [m]
    size: tuple[float, float]  # the drawn slider's length and height [m]


class _Guide(NamedTuple):
    """A translational joint's guide over the frames: point, axis, normal, slide along it."""

    point: np.ndarray  # (frames, 2) the guide body's joint point [m]
    theta: np.ndarray  # (frames,) the guide axis' angle from the global x axis [rad]
    u: np.ndarray  # (frames, 2) unit vector along the axis
    v: np.ndarray  # (frames, 2) unit normal, u turned by +90 degrees
    along: np.ndarray  # (frames,) the slider's joint point along the axis from the guide's [m]


def _guide(model: Model, rows: pd.DataFrame, joint: object) -> _Guide:
    guide, slider = joint.bodies
    g = track(model, rows, guide, joint.points[0])
    axis = np.asarray(joint.axis, dtype=float)
    theta = angle(rows, guide) + math.atan2(axis[1], axis[0])
    u = np.column_stack([np.cos(theta), np.sin(theta)])
    v = np.column_stack([-u[:, 1], u[:, 0]])
    along = np.einsum("ij,ij->i", track(model, rows, slider, joint.points[1]) - g, u)
    return _Guide(g, theta, u, v, along)


def _pose(
    frame: _Guide, centre: np.ndarray, tilt: np.ndarray, size: tuple[float, float],
    half_width: float, ends: np.ndarray,
) -> SliderPose:  # fmt: skip
    """A slider of ``size`` at ``centre`` and angle ``tilt``, between two guide surfaces.

    The surfaces lie ``half_width`` off the guide's centreline, from ``ends[0]`` to
    ``ends[1]`` along it [m].
    """
    g, u, v = frame.point, frame.u, frame.v
    guide_ends = np.stack(
        [np.stack([g + e * u + side * half_width * v for e in ends], axis=1) for side in (1, -1)],
        axis=1,
    )
    a, b = 0.5 * size[0], 0.5 * size[1]
    cos, sin = np.cos(tilt)[:, None], np.sin(tilt)[:, None]
    corner = np.array([(-a, -b), (a, -b), (a, b), (-a, b)])
    corners = np.stack(
        [centre[:, 0:1] + cos * corner[:, 0] - sin * corner[:, 1],
         centre[:, 1:2] + sin * corner[:, 0] + cos * corner[:, 1]], axis=2,
    )  # fmt: skip
    return SliderPose(centre, tilt, guide_ends, corners, size)


def _travel(frame: _Guide, length: float) -> np.ndarray:
    """The ends [m] of an unbounded guide: the slider's travel over the frames."""
    return np.array([frame.along.min() - 0.5 * length, frame.along.max() + 0.5 * length])


def _drawn(pose: SliderPose, moved: dict) -> Actor:
    """The actor that draws ``pose``: two guide lines and the slider's block."""

    def setup(ax: Axes) -> object:
        lines = [ax.plot([], [], "k-", lw=1.5, zorder=3)[0] for _ in range(2)]
        block = ax.add_patch(
            Rectangle(
                (0, 0), *pose.size, rotation_point="center",
                fc="mistyrose", ec="tab:red", lw=1.5, alpha=0.8, zorder=1.5,
            )
        )  # fmt: skip
        half = 0.5 * np.array(pose.size)

        def draw(frame: int) -> None:
            for surface, line in enumerate(lines):
                line.set_data(pose.guide[frame, surface, :, 0], pose.guide[frame, surface, :, 1])
            block.set_xy(pose.centre[frame] - half)
            block.set_angle(math.degrees(pose.angle[frame]))

        return draw

    extent = np.concatenate([pose.guide.reshape(-1, 2), pose.corners.reshape(-1, 2)])
    return Actor(moved, extent, setup)


def slider_pose(
    model: Model, rows: pd.DataFrame, joint: object, scale: float
) -> tuple[SliderPose, dict]:
    """The drawn slider and guide of a clearance ``joint``, and the slider body's points.

    The slider's centre lies at its true position along the guide and ``scale`` times its
    lateral offset off the centreline; its axis at ``scale`` times its tilt to the guide's. The
    guide's surfaces lie ``b + scale c`` off its centreline, over its length, or if unbounded
    over the slider's travel in ``rows``. Returns the pose and {(body, point): track}.
    """
    slider = joint.bodies[1]
    c = joint.clearance
    frame = _guide(model, rows, joint)
    lateral = rows[f"{joint.name}_lateral"].to_numpy()
    tilt = rows[f"{joint.name}_tilt"].to_numpy()
    centre = frame.point + frame.along[:, None] * frame.u + scale * lateral[:, None] * frame.v
    size = (c.slider_length, c.slider_height)
    ends = np.array([-0.5, 0.5]) * c.guide_length if c.guide_length else _travel(frame, size[0])
    half_width = 0.5 * c.slider_height + scale * c.clearance_gap
    pose = _pose(frame, centre, frame.theta + scale * tilt, size, half_width, ends)
    # The slider body as drawn: turned by (scale - 1) tilt about its centre, moved with it.
    centre_local = np.asarray(model.point(slider, joint.points[1]), dtype=float)
    phi = angle(rows, slider) + (scale - 1.0) * tilt
    moved = {}
    for name, local in model.body(slider).points.items():
        dx, dy = np.asarray(local, dtype=float) - centre_local
        moved[(slider, name)] = centre + np.column_stack(
            [np.cos(phi) * dx - np.sin(phi) * dy, np.sin(phi) * dx + np.cos(phi) * dy]
        )
    return pose, moved


def actor(model: Model, rows: pd.DataFrame, joint: object, scale: float, size: float) -> Actor:
    """The clearance joint as drawn over ``rows``, magnified ``scale`` times."""
    return _drawn(*slider_pose(model, rows, joint, scale))


def ideal_actor(model: Model, rows: pd.DataFrame, joint: object, size: float) -> Actor:
    """An ideal joint: a block ``IDEAL_SLIDER_SHARE`` of ``size`` [m] long on the centreline.

    Between guide surfaces over the block's travel in ``rows``: an ideal joint has no size of
    its own.
    """
    length = IDEAL_SLIDER_SHARE * size
    frame = _guide(model, rows, joint)
    block = (length, IDEAL_SLIDER_ASPECT * length)
    centre = frame.point + frame.along[:, None] * frame.u
    pose = _pose(frame, centre, frame.theta, block, 0.5 * block[1], _travel(frame, length))
    return _drawn(pose, {})


def title(joints: tuple, scale: float) -> str:
    """The animation's line on these joints' magnification."""
    gap_mm = max(j.clearance.clearance_gap for j in joints) * 1e3
    return (
        f"sliders: gap, offset and tilt × {scale:.3g} "
        f"(gap {gap_mm:.3g} mm drawn as {gap_mm * scale:.3g} mm)"
    )
