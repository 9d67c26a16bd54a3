"""Animation of a mechanism from its results: bodies, ground points and clearance joints.

Each body is drawn as a thick line through its points (closed for three or more), ground
points as triangles, and each clearance joint as a bearing circle and a journal circle whose
offset from the bearing centre is magnified, so that the motion inside the joint shows (the
paper's Fig. 6 does the same with an exaggerated clearance).
"""

from __future__ import annotations

import math
from io import BytesIO
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.animation import AbstractMovieWriter, FuncAnimation
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch
from matplotlib.patches import Circle
from PIL import Image

from ..model import Model
from ..results import Results
from .run import crank_driver

NO_CRANK_SPAN = 0.04  # [s] the time animated when no constant-speed driver turns a crank
CLEARANCE_SHARE = 0.04  # default: a radial clearance is drawn as this share of the mechanism


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
        first.save(self.outfile, save_all=True, append_images=rest, duration=duration, loop=0)


def _frames(results: Results, turns: float, frames: int) -> pd.DataFrame:
    """Rows of the last ``turns`` crank turns (or ``NO_CRANK_SPAN``), ``frames`` of them at most."""
    df = results.timeseries
    crank = crank_driver(results)
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


def _positions(
    results: Results, rows: pd.DataFrame, clearance_scale: float | None
) -> tuple[dict, dict, dict, float]:
    """Drawn positions over ``rows``: body outlines, bearing and journal centres [m], scale.

    A journal centre is drawn at the bearing centre plus ``clearance_scale`` times its
    offset; its body's outline goes through it.
    """
    model = results.model
    joints = model.clearance_joints
    bearings = {j.name: _track(model, rows, j.bodies[0], j.points[0]) for j in joints}
    if clearance_scale is None and joints:
        points = np.concatenate([o.reshape(-1, 2) for o in _outlines(model, rows, {}).values()])
        size = max(np.ptp(points, axis=0))
        clearance_scale = CLEARANCE_SHARE * size / max(j.clearance.radial_clearance for j in joints)
    journals = {
        j.name: bearings[j.name]
        + clearance_scale * rows[[f"{j.name}_ex", f"{j.name}_ey"]].to_numpy()
        for j in joints
    }
    moved = {(j.bodies[1], j.points[1]): journals[j.name] for j in joints}
    return _outlines(model, rows, moved), bearings, journals, clearance_scale


def _stage(model: Model, outlines: dict[str, np.ndarray]) -> tuple[Figure, Axes]:
    """Figure and axes that hold every drawn position, with the ground points as triangles."""
    ground = np.array(list(model.ground.points.values())).reshape(-1, 2)
    points = np.concatenate([ground, *(o.reshape(-1, 2) for o in outlines.values())])
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

    Without a crank, the last ``NO_CRANK_SPAN`` seconds. ``frames``: at most this many,
    evenly spaced in time. ``clearance_scale`` [-]: factor on each journal's offset from its
    bearing centre (bearing circles grow to match); by default the largest radial clearance
    shows as ``CLEARANCE_SHARE`` of the mechanism's size.
    """
    model = results.model
    rows = _frames(results, turns, frames)
    outlines, bearings, journals, scale = _positions(results, rows, clearance_scale)
    fig, ax = _stage(model, outlines)
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
    if circles:
        c_mm = max(model.joint(name).clearance.radial_clearance for name in circles) * 1e3
        ax.set_title(
            f"clearance joints: journal offset × {scale:.3g} "
            f"(c = {c_mm:.3g} mm drawn as {c_mm * scale:.3g} mm)",
            fontsize="small",
        )
    ax.legend(loc="upper right", fontsize="small")
    clock = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top")
    times = rows["time"].to_numpy()

    def draw(frame: int) -> None:
        for name, line in lines.items():
            line.set_data(outlines[name][frame, :, 0], outlines[name][frame, :, 1])
        for name, (bearing, journal) in circles.items():
            bearing.set_center(bearings[name][frame])
            journal.set_center(journals[name][frame])
        clock.set_text(f"t = {times[frame]:.4f} s")

    out = Path(path)
    out.parent.mkdir(parents=True, exist_ok=True)
    FuncAnimation(fig, draw, frames=len(rows)).save(out, writer=_GifWriter(fps=fps))
    return out
