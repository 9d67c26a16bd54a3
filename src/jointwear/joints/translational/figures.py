"""Figures of the translational clearance joints: a slider in a guide with a gap.

Functions ``Results -> matplotlib Figure`` and ``save_figures`` that writes them all;
``draw_life_profiles`` draws a joint's profiles in a life run's figure (``figures.life``).
As in the time series (``results.slider``): the lateral offset is the slider centre's from
the guide's centreline along the guide's normal, the tilt the slider's angle relative to the
guide's from the initial pose; "front" is the guide's +axis side, "top" its +normal side.
Wear positions run along each surface from its middle, in its body's frame.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch
from matplotlib.gridspec import SubplotSpec

from ...figures.crank import crank_abscissa, set_abscissa
from ...figures.files import save_pngs
from ...figures.legends import LEGEND_ROOM, legend_beside
from ...figures.plan import kind_drawings
from ...figures.scaling import length_unit
from ...results import Results
from . import KIND
from .schema import TranslationalClearance, TranslationalJoint

MM = 1e3  # [mm/m]
MRAD = 1e3  # [mrad/rad]
NEAR_LIMIT = 0.25  # the tilt limits are drawn when the tilt comes within this share of them
# The corner panels as the slider is seen with its guide's axis to the right.
CORNER_GRID = (("rear_top", "front_top"), ("rear_bottom", "front_bottom"))
CORNER_COLOR = "tab:blue"
EDGE_COLOR = "tab:red"
SURFACE_COLORS = {"top": "tab:blue", "bottom": "tab:orange"}
SNAPSHOT_ALPHA = 0.35


def _joints(results: Results) -> tuple[TranslationalJoint, ...]:
    joints = results.model.joints_of("translational")
    if not joints:
        raise ValueError(f"model '{results.model.name}' has no translational clearance joints")
    return joints


def tilt_limit(clearance: TranslationalClearance) -> float:
    """Tilt [rad] at which two opposite corners touch both guide surfaces, slider centred.

    Rigid slider with sharp corners, no wear: a sin(t) + b cos(t) = b + c with a, b the
    slider's half-length and half-height and c the gap, so
    t = asin((b + c) / sqrt(a^2 + b^2)) - atan(b / a), about 2 c / L for a small gap.
    """
    a, b = 0.5 * clearance.slider_length, 0.5 * clearance.slider_height
    reach = min(clearance.guide_half_height / math.hypot(a, b), 1.0)
    return math.asin(reach) - math.atan2(b, a)


def plot_slider_motion(results: Results) -> Figure:
    """Each slider's lateral offset [mm] and tilt [mrad] against the crank angle [deg].

    Against time [s] without a crank (``crank_abscissa``). Dashed: the gap ±c (a level
    slider on a guide surface) and, when the tilt comes within ``NEAR_LIMIT`` of it, the
    tilt limit ±``tilt_limit`` (two opposite corners touching; else its value is noted).
    """
    joints = _joints(results)
    df = results.timeseries
    x = crank_abscissa(results)
    fig = Figure(figsize=(8.0 + LEGEND_ROOM, 4.6 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(2 * len(joints), 1, sharex=True, squeeze=False)[:, 0]
    for k, joint in enumerate(joints):
        lateral, tilt = axes[2 * k], axes[2 * k + 1]
        guide, slider = joint.bodies
        gap = joint.clearance.clearance_gap * MM
        lateral.plot(x.values, df[f"{joint.name}_lateral"].to_numpy() * MM, lw=0.9)
        for sign in (1.0, -1.0):
            label = f"gap ±c = ±{gap:.3g} mm" if sign > 0 else None
            lateral.axhline(sign * gap, ls="--", color="k", lw=0.8, label=label)
        lateral.set_ylabel("lateral offset [mm]")
        lateral.set_title(
            f"{joint.name}: slider ({slider}) centre from the guide ({guide}) centreline",
            loc="left",
            fontsize="medium",
        )
        legend_beside(lateral)
        angle = df[f"{joint.name}_tilt"].to_numpy() * MRAD
        tilt.plot(x.values, angle, lw=0.9, color="tab:purple")
        limit = tilt_limit(joint.clearance) * MRAD
        if np.max(np.abs(angle), initial=0.0) >= NEAR_LIMIT * limit:
            for sign in (1.0, -1.0):
                label = f"opposite corners touch: ±{limit:.3g} mrad" if sign > 0 else None
                tilt.axhline(sign * limit, ls="--", color="k", lw=0.8, label=label)
            legend_beside(tilt)
        else:
            tilt.text(
                0.99,
                0.95,
                f"opposite corners touch at ±{limit:.3g} mrad (off scale)",
                transform=tilt.transAxes,
                ha="right",
                va="top",
                fontsize="small",
                color="0.3",
            )
        tilt.set_ylabel("tilt [mrad]")
        tilt.set_title(f"{joint.name}: slider tilt in the guide", loc="left", fontsize="medium")
    for ax in axes:
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.grid(alpha=0.3)
    set_abscissa(axes[-1], x)
    fig.suptitle(f"{results.model.name}: slider motion in the guide")
    return fig


def plot_corner_forces(results: Results) -> Figure:
    """Normal force [N] at each slider corner against the crank angle [deg] (or time [s]).

    Per joint a 2 x 2 grid as the slider is seen with its guide's axis to the right (top
    corners above, front on the right); a finite guide's end edge that pushed on the slider's
    face near a corner is drawn in that corner's panel.

    The titles give the largest force among the time-series rows (the summary's maximum is
    over every step, so it can be larger).
    """
    joints = _joints(results)
    df = results.timeseries
    x = crank_abscissa(results)
    fig = Figure(figsize=(10.0 + LEGEND_ROOM, 4.8 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(2 * len(joints), 2, sharex=True, sharey=True, squeeze=False)
    for k, joint in enumerate(joints):
        for r, row in enumerate(CORNER_GRID):
            for ax, corner in zip(axes[2 * k + r], row, strict=True):
                force = df[f"{joint.name}_fn_{corner}"].to_numpy()
                ax.plot(x.values, force, lw=0.9, color=CORNER_COLOR, label=f"corner {corner}")
                peak = np.max(force, initial=0.0)
                title = f"{joint.name}: {corner} corner (largest row {peak:.4g} N)"
                edge = df.get(f"{joint.name}_fn_edge_{corner}")
                if edge is not None and edge.to_numpy().any():
                    ax.plot(
                        x.values, edge.to_numpy(), lw=0.9, color=EDGE_COLOR,
                        label=f"guide edge {corner}",
                    )  # fmt: skip
                    legend_beside(ax)
                ax.set_title(title, loc="left", fontsize="medium")
                ax.grid(alpha=0.3)
            axes[2 * k + r, 0].set_ylabel("normal force [N]")
    for ax in axes[-1]:
        set_abscissa(ax, x)
    fig.suptitle(f"{results.model.name}: normal contact forces on the slider")
    return fig


def _depths(table: pd.DataFrame, joint: str, surface: str) -> tuple[np.ndarray, np.ndarray]:
    """(segment centres [m], wear depths [m]) of one surface, in segment order."""
    rows = table[(table["joint"] == joint) & (table["surface"] == surface)].sort_values("sector")
    return rows["position_m"].to_numpy(), rows["depth_m"].to_numpy()


def _snapshots(results: Results) -> list[tuple[float, pd.DataFrame]]:
    """(time [s], wear table) of each snapshot before the end of the run."""
    snaps = results.wear_snapshots
    if not len(snaps):
        return []
    t_end = float(results.timeseries["time"].iloc[-1])
    half_row = 0.5 * results.model.solver.output_interval
    return [(float(t), table) for t, table in snaps.groupby("time_s") if t < t_end - half_row]


def _wear_panel(
    ax: Axes, results: Results, joint: TranslationalJoint, part: str, length: float
) -> None:
    """Wear depth along the ``part`` ("guide", "slider") surfaces: snapshots, then the end.

    Depths in nm, µm or mm, as the deepest of the run reads (``scaling.length_unit``).
    """
    unit, per_m = length_unit(results.wear["depth_m"])
    snapshots = _snapshots(results)
    times = [f"{t:.3g}" for t, _ in snapshots]
    times = times if len(times) <= 4 else [times[0], "…", times[-1]]
    for side, color in SURFACE_COLORS.items():
        surface = f"{part}_{side}"
        for n, (_, table) in enumerate(snapshots):
            position, depth = _depths(table, joint.name, surface)
            label = f"t = {', '.join(times)} s (lighter)" if n == 0 and side == "top" else None
            ax.plot(position * MM, depth * per_m, lw=0.8, color=color, alpha=SNAPSHOT_ALPHA,
                    label=label)  # fmt: skip
        position, depth = _depths(results.wear, joint.name, surface)
        ax.plot(position * MM, depth * per_m, "o-", ms=3, lw=1.2, color=color, label=surface)
    body = joint.bodies[0] if part == "guide" else joint.bodies[1]
    where = "its middle" if part == "guide" else "its centre"
    ax.set_xlabel(f"position along the {part} from {where} ({body} frame) [mm]")
    ax.set_ylabel(f"wear depth [{unit}]")
    ax.set_xlim(-0.5 * length * MM, 0.5 * length * MM)
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    legend_beside(ax)


def plot_guide_wear(results: Results) -> Figure:
    """Wear depth along the guide's and the slider's surfaces [mm] at the end of the run.

    Earlier wear snapshots as lighter lines. An unbounded guide keeps no map of its wear:
    its joint shows the slider's surfaces only (said in the titles).
    """
    joints = _joints(results)
    t_end = float(results.timeseries["time"].iloc[-1])
    columns = 2 if any(j.clearance.guide_length for j in joints) else 1
    fig = Figure(
        figsize=(5.5 * columns + 1.0 + LEGEND_ROOM, 4.2 * len(joints) + 0.6), layout="constrained"
    )
    axes = fig.subplots(len(joints), columns, squeeze=False)
    for row, joint in zip(axes, joints, strict=True):
        c = joint.clearance
        guide, slider = joint.bodies
        _wear_panel(row[-1], results, joint, "slider", c.slider_length)
        if c.guide_length:
            _wear_panel(row[0], results, joint, "guide", c.guide_length)
            row[0].set_title(f"{joint.name}: guide ({guide})")
            row[-1].set_title(f"{joint.name}: slider ({slider})")
        else:
            row[-1].set_title(f"{joint.name}: slider ({slider}) only: unbounded guide, not mapped")
            if columns == 2:
                row[0].set_axis_off()
                note = f"{joint.name}: the guide is unbounded;\nits wear is not mapped"
                row[0].text(0.5, 0.5, note, ha="center", va="center", transform=row[0].transAxes)
    unbounded = [j.name for j in joints if not j.clearance.guide_length]
    note = f" (unbounded guide of {', '.join(unbounded)}: slider only)" if unbounded else ""
    fig.suptitle(f"{results.model.name}: wear depth at t = {t_end:.4g} s{note}")
    return fig


def draw_life_profiles(
    fig: Figure, place: SubplotSpec, joint: TranslationalJoint, profiles: pd.DataFrame,
    updates: dict,
) -> None:  # fmt: skip
    """Wear depth along the guide's and the slider's surfaces at a few updates.

    Top surfaces solid, bottom ones dashed. ``profiles``: the joint's rows of a life run's
    profiles.csv; ``updates``: the updates drawn, each with its colour.
    """
    unit, per_m = length_unit(profiles["depth_m"])
    c = joint.clearance
    cells = place.subgridspec(1, 2)
    parts = (("guide", c.guide_length, "its middle"), ("slider", c.slider_length, "its centre"))
    for n, (part, length, origin) in enumerate(parts):
        ax = fig.add_subplot(cells[0, n])
        if not length:
            ax.set_axis_off()
            note = f"{joint.name}: the guide is unbounded;\nits wear is not mapped"
            ax.text(0.5, 0.5, note, ha="center", va="center", transform=ax.transAxes)
            continue
        for update, colour in updates.items():
            rows = profiles[profiles["update"] == update]
            for side, style in (("top", "-"), ("bottom", "--")):
                position, depth = _depths(rows, joint.name, f"{part}_{side}")
                label = f"{int(rows['cycles'].iloc[0]):,} cycles" if side == "top" else None
                ax.plot(position * MM, depth * per_m, ls=style, color=colour, lw=1.2, label=label)
        ax.set_title(f"{joint.name}: {part} ({joint.bodies[n]}), top solid, bottom dashed")
        ax.set_xlabel(f"position along the {part} from {origin} [mm]")
        ax.set_ylabel(f"wear depth [{unit}]")
        ax.set_xlim(-0.5 * length * MM, 0.5 * length * MM)
        ax.set_ylim(bottom=0.0)
        ax.grid(alpha=0.3)
        if n == 1:
            ax.legend(fontsize="small")


def save_figures(results: Results, folder: str | Path) -> list[Path]:
    """Write the slider figures into ``folder`` as PNG; return the paths (none without sliders)."""
    return save_pngs(kind_drawings(KIND, results), Path(folder))
