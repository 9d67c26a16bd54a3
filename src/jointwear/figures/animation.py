"""Animation of a mechanism from its results: bodies, ground points and clearance joints.

Each body is drawn as a thick line through its points (closed for three or more), ground
points as triangles, and each revolute clearance joint as a bearing circle and a journal
circle whose offset from the bearing centre is magnified, so that the motion inside the joint
shows (the paper's Fig. 6 does the same with an exaggerated clearance). Each translational
clearance joint is drawn as its guide's two surfaces and the slider as a rectangle, the gap,
the slider's lateral offset and its tilt magnified by the same factor (the tilt as an angle,
so the corners meet the drawn surfaces about when they meet the true ones, for small
angles); the slider's body, and the points of bodies pinned to it by ideal revolute joints,
follow the drawn slider. An ideal translational joint, which has no size of its own, is drawn
as a block of a set share of the mechanism's size between its guide's surfaces.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from io import BytesIO
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.animation import AbstractMovieWriter, FuncAnimation
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch
from matplotlib.patches import Circle, Rectangle
from PIL import Image

from ..io import make_folder, write_atomic
from ..model import Model
from ..model.sections import RevoluteJoint, TranslationalJoint
from ..results import Results
from .plan import crank_driver
from .slider import crank_body

NO_CRANK_SPAN = 0.04  # [s] the time animated when no constant-speed driver turns a crank
CLEARANCE_SHARE = 0.04  # default: a radial clearance or a gap drawn as this share of the mechanism
IDEAL_SLIDER_SHARE = 0.08  # an ideal translational joint's block: this share of the mechanism long
IDEAL_SLIDER_ASPECT = 0.5  # and this share of its length high


class _GifWriter(AbstractMovieWriter):
    """Like matplotlib's ``PillowWriter``, but each frame is reduced to 256 colours when grabbed.

    The fast octree reduction takes a fifth of the time Pillow's default one does at saving.
    """

    def setup(self, fig: Figure, outfile: str | Path, dpi: float | None = None) -> None:
        super().setup(fig, outfile, dpi=dpi)
        self._images: list[Image.Image] = []

    def grab_frame(self, **savefig_kwargs: object) -> None:
        buffer = BytesIO()
        self.fig.savefig(buffer, **{**savefig_kwargs, "format": "rgba", "dpi": self.dpi})
        rgba = Image.frombuffer("RGBA", self.frame_size, buffer.getbuffer(), "raw", "RGBA", 0, 1)
        self._images.append(rgba.convert("RGB").quantize(method=Image.Quantize.FASTOCTREE))

    def finish(self) -> None:
        first, *rest = self._images
        duration = round(1000 / self.fps)  # [ms] per frame
        first.save(
            self.outfile, format="GIF", save_all=True, append_images=rest, duration=duration,
            loop=0,
        )  # fmt: skip


def _frames(results: Results, turns: float, frames: int) -> pd.DataFrame:
    """Rows of the last ``turns`` crank turns (or ``NO_CRANK_SPAN``), ``frames`` of them at most.

    The crank: a constant-speed driver's body, else a free crank (``slider.crank_body``).
    """
    df = results.timeseries
    crank = crank_driver(results)
    free = crank_body(results) if crank is None else None
    if free is not None:
        phi = df[f"phi_{free}"].to_numpy()
        before = np.flatnonzero(np.abs(phi - phi[-1]) > turns * 2.0 * math.pi * (1.0 + 1e-9))
        window = df.iloc[before[-1] + 1 if len(before) else 0 :]
    else:
        span = turns * 2.0 * math.pi / abs(crank[2]) if crank else NO_CRANK_SPAN
        window = df[df["time"] >= df["time"].iloc[-1] - span * (1.0 + 1e-9)]
    rows = np.unique(np.linspace(0, len(window) - 1, min(frames, len(window))).round())
    return window.iloc[rows.astype(int)]


def _track(model: Model, rows: pd.DataFrame, body: str, point: str) -> np.ndarray:
    """Global positions [m] of ``point`` of ``body`` over ``rows``, shape (rows, 2)."""
    local = np.asarray(model.point(body, point), dtype=float)
    if body == "ground":
        return np.tile(local, (len(rows), 1))
    phi = rows[f"phi_{body}"].to_numpy()
    cos, sin = np.cos(phi), np.sin(phi)
    x = rows[f"x_{body}"].to_numpy() + cos * local[0] - sin * local[1]
    y = rows[f"y_{body}"].to_numpy() + sin * local[0] + cos * local[1]
    return np.column_stack([x, y])


def _outlines(model: Model, rows: pd.DataFrame, moved: dict) -> dict[str, np.ndarray]:
    """Per body, its points over ``rows``, shape (rows, points, 2); ``moved`` replaces some."""
    outlines = {}
    for body in model.bodies:
        tracks = [moved.get((body.name, p), _track(model, rows, body.name, p)) for p in body.points]
        if not tracks:  # a body without points: its centre of mass
            tracks = [rows[[f"x_{body.name}", f"y_{body.name}"]].to_numpy()]
        if len(tracks) > 2:
            tracks.append(tracks[0])
        outlines[body.name] = np.stack(tracks, axis=1)
    return outlines


def _angle(rows: pd.DataFrame, body: str) -> np.ndarray:
    """Angle [rad] of ``body`` over ``rows`` (0 for the ground)."""
    return np.zeros(len(rows)) if body == "ground" else rows[f"phi_{body}"].to_numpy()


def _scale(model: Model, rows: pd.DataFrame, clearance_scale: float | None) -> float:
    """Magnification of the clearances [-]: ``clearance_scale`` if given.

    By default the factor that draws the largest radial clearance or gap as
    ``CLEARANCE_SHARE`` of the mechanism's size (1 without clearance joints).
    """
    if clearance_scale is not None:
        return clearance_scale
    gaps = [j.clearance.radial_clearance for j in model.joints_of("revolute")]
    gaps += [j.clearance.clearance_gap for j in model.joints_of("translational")]
    if not gaps:
        return 1.0
    return CLEARANCE_SHARE * _size(_outlines(model, rows, {})) / max(gaps)


def _size(outlines: dict[str, np.ndarray]) -> float:
    """The mechanism's size [m]: the larger side of the box its drawn points sweep."""
    points = np.concatenate([o.reshape(-1, 2) for o in outlines.values()])
    return float(max(np.ptp(points, axis=0)))


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


def _guide(model: Model, rows: pd.DataFrame, joint: TranslationalJoint) -> _Guide:
    guide, slider = joint.bodies
    g = _track(model, rows, guide, joint.points[0])
    axis = np.asarray(joint.axis, dtype=float)
    theta = _angle(rows, guide) + math.atan2(axis[1], axis[0])
    u = np.column_stack([np.cos(theta), np.sin(theta)])
    v = np.column_stack([-u[:, 1], u[:, 0]])
    along = np.einsum("ij,ij->i", _track(model, rows, slider, joint.points[1]) - g, u)
    return _Guide(g, theta, u, v, along)


def _pose(
    frame: _Guide, centre: np.ndarray, angle: np.ndarray, size: tuple[float, float],
    half_width: float, ends: np.ndarray,
) -> SliderPose:  # fmt: skip
    """A slider of ``size`` at ``centre`` and ``angle``, between two guide surfaces.

    The surfaces lie ``half_width`` off the guide's centreline, from ``ends[0]`` to
    ``ends[1]`` along it [m].
    """
    g, u, v = frame.point, frame.u, frame.v
    guide_ends = np.stack(
        [np.stack([g + e * u + side * half_width * v for e in ends], axis=1) for side in (1, -1)],
        axis=1,
    )
    a, b = 0.5 * size[0], 0.5 * size[1]
    cos, sin = np.cos(angle)[:, None], np.sin(angle)[:, None]
    corner = np.array([(-a, -b), (a, -b), (a, b), (-a, b)])
    corners = np.stack(
        [centre[:, 0:1] + cos * corner[:, 0] - sin * corner[:, 1],
         centre[:, 1:2] + sin * corner[:, 0] + cos * corner[:, 1]], axis=2,
    )  # fmt: skip
    return SliderPose(centre, angle, guide_ends, corners, size)


def _travel(frame: _Guide, length: float) -> np.ndarray:
    """The ends [m] of an unbounded guide: the slider's travel over the frames."""
    return np.array([frame.along.min() - 0.5 * length, frame.along.max() + 0.5 * length])


def _slider_pose(
    model: Model, rows: pd.DataFrame, joint: TranslationalJoint, scale: float
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
    phi = _angle(rows, slider) + (scale - 1.0) * tilt
    moved = {}
    for name, local in model.body(slider).points.items():
        dx, dy = np.asarray(local, dtype=float) - centre_local
        moved[(slider, name)] = centre + np.column_stack(
            [np.cos(phi) * dx - np.sin(phi) * dy, np.sin(phi) * dx + np.cos(phi) * dy]
        )
    return pose, moved


def _ideal_slider_pose(
    model: Model, rows: pd.DataFrame, joint: TranslationalJoint, length: float
) -> SliderPose:
    """An ideal translational joint: a block ``length`` [m] long on its guide's centreline.

    Between guide surfaces over the block's travel in ``rows``: an ideal joint has no size of
    its own.
    """
    frame = _guide(model, rows, joint)
    size = (length, IDEAL_SLIDER_ASPECT * length)
    centre = frame.point + frame.along[:, None] * frame.u
    return _pose(frame, centre, frame.theta, size, 0.5 * size[1], _travel(frame, length))


def _pinned(model: Model, moved: dict) -> dict:
    """Points of other bodies pinned by ideal revolute joints to a moved point: moved alike."""
    pinned = {}
    for joint in model.joints:
        if not isinstance(joint, RevoluteJoint) or joint.clearance is not None:
            continue
        ends = list(zip(joint.bodies, joint.points, strict=True))
        for here, there in (ends, ends[::-1]):
            if here in moved and there not in moved and there[0] != "ground":
                pinned[there] = moved[here]
    return pinned


def _positions(
    results: Results, rows: pd.DataFrame, clearance_scale: float | None
) -> tuple[dict, dict, dict, dict, float]:
    """Drawn positions over ``rows``: outlines, bearing and journal centres [m], sliders, scale.

    A journal centre is drawn at the bearing centre plus ``scale`` times its offset; its
    body's outline goes through it. Sliders: ``_slider_pose``.
    """
    model = results.model
    joints = model.joints_of("revolute")
    scale = _scale(model, rows, clearance_scale)
    bearings = {j.name: _track(model, rows, j.bodies[0], j.points[0]) for j in joints}
    journals = {
        j.name: bearings[j.name] + scale * rows[[f"{j.name}_ex", f"{j.name}_ey"]].to_numpy()
        for j in joints
    }
    sliders, moved = {}, {}
    for joint in model.joints_of("translational"):
        sliders[joint.name], points = _slider_pose(model, rows, joint, scale)
        moved |= points
    ideal = [j for j in model.joints if isinstance(j, TranslationalJoint) and j.clearance is None]
    if ideal:
        length = IDEAL_SLIDER_SHARE * _size(_outlines(model, rows, {}))
        sliders |= {j.name: _ideal_slider_pose(model, rows, j, length) for j in ideal}
    moved |= _pinned(model, moved)
    moved |= {(j.bodies[1], j.points[1]): journals[j.name] for j in joints}
    return _outlines(model, rows, moved), bearings, journals, sliders, scale


def _stage(model: Model, points: np.ndarray) -> tuple[Figure, Axes]:
    """Figure and axes that hold the drawn ``points`` (n, 2) and the ground points (triangles)."""
    ground = np.array(list(model.ground.points.values())).reshape(-1, 2)
    points = np.concatenate([ground, points])
    low, high = points.min(axis=0), points.max(axis=0)
    margin = 0.08 * max(high - low)
    fig = Figure(figsize=(6.4, 6.0), dpi=100)  # fixed margins: a layout engine redraws each frame
    fig.subplots_adjust(left=0.13, right=0.97, bottom=0.09, top=0.89)
    ax = fig.add_subplot()
    ax.set_xlim(low[0] - margin, high[0] + margin)
    ax.set_ylim(low[1] - margin, high[1] + margin)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(alpha=0.3)
    ax.plot(ground[:, 0], ground[:, 1], "^", color="0.3", ms=12, zorder=1)
    fig.suptitle(model.name)
    return fig, ax


class Scene(NamedTuple):
    """The animation's figure, its ``draw(frame)``, the frames' times [s], the magnification."""

    figure: Figure
    draw: Callable[[int], None]
    times: np.ndarray
    scale: float


def mechanism_scene(
    results: Results,
    *,
    turns: float = 1.0,
    frames: int = 80,
    clearance_scale: float | None = None,
) -> Scene:
    """The figure of ``save_animation`` and the function that draws its frames (same keys)."""
    model = results.model
    rows = _frames(results, turns, frames)
    outlines, bearings, journals, sliders, scale = _positions(results, rows, clearance_scale)
    drawn = [o.reshape(-1, 2) for o in outlines.values()]
    drawn += [p.reshape(-1, 2) for s in sliders.values() for p in (s.guide, s.corners)]
    fig, ax = _stage(model, np.concatenate(drawn))
    lines = {
        name: ax.plot([], [], "-o", lw=5, ms=5, solid_capstyle="round", label=name, zorder=2)[0]
        for name in outlines
    }
    circles = {}
    for name in bearings:
        c = model.joint(name).clearance
        bearing_radius = c.journal_radius + scale * c.radial_clearance
        circles[name] = (
            ax.add_patch(Circle((0, 0), bearing_radius, fill=False, lw=1.5, ec="k", zorder=3)),
            ax.add_patch(Circle((0, 0), c.journal_radius, fc="w", lw=1.5, ec="tab:red", zorder=4)),
        )
    guides, blocks = {}, {}
    for name, pose in sliders.items():
        guides[name] = [ax.plot([], [], "k-", lw=1.5, zorder=3)[0] for _ in range(2)]
        blocks[name] = ax.add_patch(
            Rectangle(
                (0, 0), *pose.size, rotation_point="center",
                fc="mistyrose", ec="tab:red", lw=1.5, alpha=0.8, zorder=1.5,
            )
        )  # fmt: skip
    titles = []
    if circles:
        c_mm = max(model.joint(name).clearance.radial_clearance for name in circles) * 1e3
        titles.append(
            f"clearance joints: journal offset × {scale:.3g} "
            f"(c = {c_mm:.3g} mm drawn as {c_mm * scale:.3g} mm)"
        )
    if model.joints_of("translational"):
        gap_mm = max(j.clearance.clearance_gap for j in model.joints_of("translational")) * 1e3
        titles.append(
            f"sliders: gap, offset and tilt × {scale:.3g} "
            f"(gap {gap_mm:.3g} mm drawn as {gap_mm * scale:.3g} mm)"
        )
    if titles:
        ax.set_title("\n".join(titles), fontsize="small")
    ax.legend(loc="upper right", fontsize="small")
    clock = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top")
    times = rows["time"].to_numpy()

    def draw(frame: int) -> None:
        for name, line in lines.items():
            line.set_data(outlines[name][frame, :, 0], outlines[name][frame, :, 1])
        for name, (bearing, journal) in circles.items():
            bearing.set_center(bearings[name][frame])
            journal.set_center(journals[name][frame])
        for name, pose in sliders.items():
            for surface, line in enumerate(guides[name]):
                line.set_data(pose.guide[frame, surface, :, 0], pose.guide[frame, surface, :, 1])
            block = blocks[name]
            half = 0.5 * np.array([block.get_width(), block.get_height()])
            block.set_xy(pose.centre[frame] - half)
            block.set_angle(math.degrees(pose.angle[frame]))
        clock.set_text(f"t = {times[frame]:.4f} s")

    return Scene(fig, draw, times, scale)


def save_animation(
    results: Results,
    path: str | Path,
    *,
    turns: float = 1.0,
    fps: int = 25,
    frames: int = 80,
    clearance_scale: float | None = None,
) -> Path:
    """Write a GIF of the mechanism over the last ``turns`` crank turns; return its path.

    Without a crank (a constant-speed driver's body or a free crank, ``slider.crank_body``),
    the last ``NO_CRANK_SPAN`` seconds. ``frames``: at most this many, evenly spaced in time.
    ``clearance_scale`` [-]: factor on each journal's offset from its bearing centre (bearing
    circles grow to match) and on each slider's gap, lateral offset and tilt; by default the
    largest radial clearance or gap shows as ``CLEARANCE_SHARE`` of the mechanism's size.
    """
    scene = mechanism_scene(results, turns=turns, frames=frames, clearance_scale=clearance_scale)
    out = Path(path)
    make_folder(out.parent)
    animation = FuncAnimation(scene.figure, scene.draw, frames=len(scene.times))
    return write_atomic(
        out, lambda temporary: animation.save(temporary, writer=_GifWriter(fps=fps))
    )
