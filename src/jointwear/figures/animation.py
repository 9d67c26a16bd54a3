"""Animation of a mechanism from its results: bodies, ground points and joints.

Each body is drawn as a thick line through its points (closed for three or more), ground
points as triangles, and each joint type draws its joints (``ClearanceKind.animation_module``:
a revolute clearance joint as a bearing and a journal circle, a translational one as its
guide's surfaces and the slider's block). Every clearance is magnified by one factor, so that
the motion inside the joints shows (the paper's Fig. 6 does the same with an exaggerated
clearance); the points a joint's drawing moves, and those of bodies pinned to them by ideal
joints, are drawn where it moves them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from importlib import import_module
from io import BytesIO
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.animation import AbstractMovieWriter, FuncAnimation
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch
from PIL import Image

from ..io import make_folder, write_atomic
from ..joints import BY_NAME, KINDS
from ..joints.kind import Actor
from ..model import Model
from ..results import Results
from .crank import crank_body
from .plan import crank_driver
from .tracks import track

NO_CRANK_SPAN = 0.04  # [s] the time animated when no constant-speed driver turns a crank
CLEARANCE_SHARE = 0.04  # default: a radial clearance or a gap drawn as this share of the mechanism


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

    The crank: a constant-speed driver's body, else a free crank (``crank.crank_body``).
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


def _outlines(model: Model, rows: pd.DataFrame, moved: dict) -> dict[str, np.ndarray]:
    """Per body, its points over ``rows``, shape (rows, points, 2); ``moved`` replaces some."""
    outlines = {}
    for body in model.bodies:
        tracks = [moved.get((body.name, p), track(model, rows, body.name, p)) for p in body.points]
        if not tracks:  # a body without points: its centre of mass
            tracks = [rows[[f"x_{body.name}", f"y_{body.name}"]].to_numpy()]
        if len(tracks) > 2:
            tracks.append(tracks[0])
        outlines[body.name] = np.stack(tracks, axis=1)
    return outlines


def _scale(model: Model, rows: pd.DataFrame, clearance_scale: float | None) -> float:
    """Magnification of the clearances [-]: ``clearance_scale`` if given.

    By default the factor that draws the largest clearance (``ClearanceKind.gap``) as
    ``CLEARANCE_SHARE`` of the mechanism's size (1 without clearance joints).
    """
    if clearance_scale is not None:
        return clearance_scale
    gaps = [kind.gap(joint) for kind in KINDS for joint in kind.joints(model)]
    if not gaps:
        return 1.0
    return CLEARANCE_SHARE * _size(_outlines(model, rows, {})) / max(gaps)


def _size(outlines: dict[str, np.ndarray]) -> float:
    """The mechanism's size [m]: the larger side of the box its drawn points sweep."""
    points = np.concatenate([o.reshape(-1, 2) for o in outlines.values()])
    return float(max(np.ptp(points, axis=0)))


def _pinned(model: Model, moved: dict) -> dict:
    """Points of other bodies pinned by ideal joints to a moved point: moved alike."""
    pinned = {}
    for joint in model.joints:
        if joint.clearance is not None or not BY_NAME[joint.type].pins_points:
            continue
        ends = list(zip(joint.bodies, joint.points, strict=True))
        for here, there in (ends, ends[::-1]):
            if here in moved and there not in moved and there[0] != "ground":
                pinned[there] = moved[here]
    return pinned


def _actors(
    model: Model, rows: pd.DataFrame, clearance_scale: float | None
) -> tuple[list[Actor], list[str], float]:
    """Every joint's drawing over ``rows``, the title's lines, and the magnification."""
    scale = _scale(model, rows, clearance_scale)
    size = _size(_outlines(model, rows, {}))
    actors, titles = [], []
    for kind in KINDS:
        if not kind.animation_module:
            continue
        drawing = import_module(kind.animation_module)
        joints = kind.joints(model)
        actors += [drawing.actor(model, rows, joint, scale, size) for joint in joints]
        if joints:
            titles.append(drawing.title(joints, scale))
        if hasattr(drawing, "ideal_actor"):
            ideal = [j for j in model.joints if j.type == kind.name and j.clearance is None]
            actors += [drawing.ideal_actor(model, rows, joint, size) for joint in ideal]
    return actors, titles, scale


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
    actors, titles, scale = _actors(model, rows, clearance_scale)
    moved = {}
    for drawn_joint in actors:
        moved |= drawn_joint.moved
    outlines = _outlines(model, rows, moved | _pinned(model, moved))
    drawn = [o.reshape(-1, 2) for o in outlines.values()] + [a.extent for a in actors]
    fig, ax = _stage(model, np.concatenate(drawn))
    lines = {
        name: ax.plot([], [], "-o", lw=5, ms=5, solid_capstyle="round", label=name, zorder=2)[0]
        for name in outlines
    }
    draws = [drawn_joint.setup(ax) for drawn_joint in actors]
    if titles:
        ax.set_title("\n".join(titles), fontsize="small")
    ax.legend(loc="upper right", fontsize="small")
    clock = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top")
    times = rows["time"].to_numpy()

    def draw(frame: int) -> None:
        for name, line in lines.items():
            line.set_data(outlines[name][frame, :, 0], outlines[name][frame, :, 1])
        for draw_joint in draws:
            draw_joint(frame)
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

    Without a crank (a constant-speed driver's body or a free crank, ``crank.crank_body``),
    the last ``NO_CRANK_SPAN`` seconds. ``frames``: at most this many, evenly spaced in time.
    ``clearance_scale`` [-]: factor on each clearance joint's motion inside its gap (a
    journal's offset from its bearing centre, bearing circles growing to match; a slider's
    gap, lateral offset and tilt); by default the largest clearance shows as
    ``CLEARANCE_SHARE`` of the mechanism's size.
    """
    scene = mechanism_scene(results, turns=turns, frames=frames, clearance_scale=clearance_scale)
    out = Path(path)
    make_folder(out.parent)
    animation = FuncAnimation(scene.figure, scene.draw, frames=len(scene.times))
    return write_atomic(
        out, lambda temporary: animation.save(temporary, writer=_GifWriter(fps=fps))
    )
