"""Figures of the revolute clearance joints: P. Flores, Mech. Mach. Theory 44 (2009), section 6.

Functions ``Results -> matplotlib Figure``, one per figure of the paper (Figs. 7-10) and a
finite bearing's film pressure (``film_figure``), and ``save_figures`` that writes them all;
``draw_life_profiles`` draws a joint's profiles in a life run's figure (``figures.life``).
Angles on a joint surface are measured counter-clockwise in that surface's body frame from
the body's x axis, as in the wear table.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib import colormaps
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch
from matplotlib.gridspec import SubplotSpec

from ...figures.files import save_pngs
from ...figures.legends import LEGEND_ROOM, legend_beside
from ...figures.plan import crank_driver, kind_drawings
from ...figures.scaling import length_unit
from ...results import Results
from . import KIND
from .film_figure import plot_film_pressure as plot_film_pressure  # a kind's figure, drawn here
from .schema import RevoluteJoint

PROFILE_SHARE = 0.15  # Fig. 10: the largest wear depth is drawn as this share of the radius
STILL_ANGLE = 1e-6  # [rad] a body whose angle spans less does not rotate (a slider)
CLEARANCE_COLOR = "tab:red"
IDEAL_COLOR = "0.15"
MM = 1e3  # [mm/m]
PEAK_ROOM = 1.1  # Fig. 8's depth axes reach this share above their automatic top


PAPER_MODEL = "flores2009_fourbar"  # the paper's four-bar (examples/flores2009_fourbar*.toml)


def _paper(results: Results, figure: str) -> str:
    """The title's note " (paper Fig. N)" for the paper's own model; "" for any other."""
    return f" (paper Fig. {figure})" if results.model.name.startswith(PAPER_MODEL) else ""


def _require_joints(results: Results) -> tuple[RevoluteJoint, ...]:
    """The revolute clearance joints; ValueError if there are none to draw.

    Translational ones have figures of their own (slider.py).
    """
    joints = results.model.joints_of("revolute")
    if not joints:
        raise ValueError(f"model '{results.model.name}' has no revolute clearance joints")
    return joints


def _surface_body(joint: RevoluteJoint, surface: str) -> str:
    """The body that carries ``surface``: the bearing is in the first, the journal on the second."""
    return joint.bodies[0] if surface == "bearing" else joint.bodies[1]


def _radius(joint: RevoluteJoint, surface: str) -> float:
    c = joint.clearance
    return c.bearing_radius if surface == "bearing" else c.journal_radius


def _profile(table: pd.DataFrame, joint: str, surface: str) -> tuple[np.ndarray, np.ndarray]:
    """(sector centre angles [deg], wear depths [m]) of one surface, in sector order."""
    rows = table[(table["joint"] == joint) & (table["surface"] == surface)].sort_values("sector")
    return rows["angle_deg"].to_numpy(), rows["depth_m"].to_numpy()


def _turns_label(results: Results, time: float) -> str:
    """'after N turns' of the crank at ``time`` [s] (to 0.1 turn), or 't = x s' without one."""
    crank = crank_driver(results)
    if crank is None:
        return f"t = {time:.3g} s"
    turns = round(time * abs(crank[2]) / (2.0 * math.pi), 1)
    return f"after {turns:g} turn{'' if turns == 1 else 's'}"


def _window(results: Results, turns: float) -> tuple[pd.DataFrame, float, float]:
    """The rows of the last ``turns`` crank turns (all rows without a crank).

    Returns the rows, their first time [s] and the crank speed [rad/s] (0 without a crank).
    """
    df = results.timeseries
    crank = crank_driver(results)
    if crank is None:
        return df, float(df["time"].iloc[0]), 0.0
    speed = abs(crank[2])
    t_end = df["time"].iloc[-1]
    rows = df[df["time"] >= t_end - turns * 2.0 * math.pi / speed * (1.0 + 1e-9)]
    return rows, float(rows["time"].iloc[0]), speed


def _dynamics_panels(results: Results) -> list[tuple[str, str, str]]:
    """(column, title, y label) of Fig. 7 (a)-(c): output body, then the driver if any.

    The output body is the model's last body; its x motion if it does not rotate or is the
    slider of a translational clearance joint (which only tilts). The driver is the crank,
    else the first driver.
    """
    body = results.model.bodies[-1].name
    phi = results.timeseries[f"phi_{body}"]
    slides = any(joint.bodies[1] == body for joint in results.model.joints_of("translational"))
    if phi.max() - phi.min() >= STILL_ANGLE and not slides:
        panels = [
            (f"omega_{body}", f"{body} angular velocity", "angular velocity [rad/s]"),
            (f"alpha_{body}", f"{body} angular acceleration", "angular acceleration [rad/s²]"),
        ]
    else:
        panels = [
            (f"vx_{body}", f"{body} x velocity", "x velocity [m/s]"),
            (f"ax_{body}", f"{body} x acceleration", "x acceleration [m/s²]"),
        ]
    crank = crank_driver(results)
    drivers = [d for d in results.model.drivers if crank is None or d.name == crank[0]]
    if drivers:
        name = drivers[0].name
        if drivers[0].type == "angle":
            panels.append((f"torque_{name}", f"driving moment of '{name}'", "driving moment [N m]"))
        else:
            panels.append((f"force_{name}", f"driving force of '{name}'", "driving force [N]"))
    return panels


def plot_dynamics(results: Results, ideal: Results | None = None) -> Figure:
    """Output body velocity and acceleration, and the driving moment: paper Fig. 7 (a)-(c).

    Over the last two crank turns against the crank angle turned in that window [deg]
    (over the whole run against time [s] without a crank); ``ideal`` (same mechanism,
    ideal joints) dashed. Panels: see ``_dynamics_panels``.
    """
    panels = _dynamics_panels(results)
    rows, t0, speed = _window(results, 2.0)
    runs = [("clearance", rows, CLEARANCE_COLOR, "-", 0.9)]
    if ideal is not None:
        ts = ideal.timeseries
        ideal_rows = ts[(ts["time"] >= t0 - 1e-12) & (ts["time"] <= rows["time"].iloc[-1])]
        runs.append(("ideal joints", ideal_rows, IDEAL_COLOR, "--", 1.1))
    fig = Figure(figsize=(7.5 + LEGEND_ROOM, 2.6 * len(panels) + 0.6), layout="constrained")
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
    for ax, (column, title, ylabel), letter in zip(axes, panels, "abc", strict=False):
        for label, data, color, style, width in runs:
            t = data["time"].to_numpy()
            x = np.degrees(speed * (t - t0)) if speed else t
            ax.plot(x, data[column].to_numpy(), style, color=color, lw=width, label=label)
        ax.set_ylabel(ylabel)
        ax.set_title(f"({letter}) {title}", loc="left", fontsize="medium")
        ax.grid(alpha=0.3)
    legend_beside(axes[0])
    if speed:
        span = np.degrees(speed * (rows["time"].iloc[-1] - t0))
        axes[-1].set_xlim(0.0, span)
        axes[-1].set_xticks(np.arange(0.0, span + 1.0, 90.0))
        axes[-1].set_xlabel(f"crank angle turned since t = {t0:.4g} s [deg]")
        when = f"last {span / 360.0:.3g} crank turns"
    else:
        axes[-1].set_xlabel("time [s]")
        when = "whole run"
    fig.suptitle(
        f"{results.model.name}: {results.model.bodies[-1].name}, {when}{_paper(results, '7a-c')}"
    )
    return fig


def plot_orbit(results: Results) -> Figure:
    """Journal-centre orbit relative to the bearing centre [mm], paper Fig. 7 (d).

    One panel per clearance joint, with the clearance circle of radius c; the whole run
    thin and light, the last two crank turns dark.
    """
    joints = _require_joints(results)
    fig = Figure(figsize=(5.5 * len(joints) + LEGEND_ROOM, 5.8), layout="constrained")
    axes = fig.subplots(1, len(joints), squeeze=False)[0]
    last, _, speed = _window(results, 2.0)
    df = results.timeseries
    for ax, joint in zip(axes, joints, strict=True):
        name, c = joint.name, joint.clearance.radial_clearance * MM
        ex, ey = df[f"{name}_ex"] * MM, df[f"{name}_ey"] * MM
        ax.plot(ex, ey, color="tab:blue", lw=0.5, alpha=0.35, label="whole run")
        if speed:
            ax.plot(
                last[f"{name}_ex"] * MM,
                last[f"{name}_ey"] * MM,
                color="navy",
                lw=0.9,
                label="last two crank turns",
            )
        angle = np.linspace(0.0, 2.0 * math.pi, 361)
        ax.plot(c * np.cos(angle), c * np.sin(angle), "k--", lw=1.0, label=f"c = {c:.3g} mm")
        ax.plot(0.0, 0.0, "k+", ms=10)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("$e_x$ (global x) [mm]")
        ax.set_ylabel("$e_y$ (global y) [mm]")
        ax.set_title(f"{name}\njournal ({joint.bodies[1]}) in bearing ({joint.bodies[0]})")
        ax.grid(alpha=0.3)
    legend_beside(ax)  # the last joint's: the same three entries for each
    fig.suptitle(f"{results.model.name}: journal-centre orbit{_paper(results, '7d')}")
    return fig


def _profiles_over_time(results: Results) -> list[tuple[float, pd.DataFrame]]:
    """(time [s], wear table) of each snapshot, and of the end of the run if not a snapshot."""
    snaps = results.wear_snapshots
    profiles = [(float(t), table) for t, table in snaps.groupby("time_s")] if len(snaps) else []
    t_end = float(results.timeseries["time"].iloc[-1])
    half_row = 0.5 * results.model.solver.output_interval
    if not profiles or profiles[-1][0] < t_end - half_row:
        profiles.append((t_end, results.wear))
    return profiles


def _mark_peak(
    ax: Axes, results: Results, joint: str, surface: str, unit: tuple[str, float]
) -> None:
    """Annotate the summary's deepest sector of ``surface`` (depth in ``unit``: name, per m)."""
    entry = results.summary["clearance_joints"][joint]
    depth = entry[f"max_wear_depth_{surface}_m"] * unit[1]
    angle = entry[f"max_wear_angle_{surface}_deg"]
    if angle is None:  # no wear on this surface
        return
    ax.annotate(
        f"max {depth:.3g} {unit[0]} at {angle:g}°",
        (angle, depth),
        xytext=(8, 4),
        textcoords="offset points",
        fontsize="small",
    )


def plot_wear_sectors(results: Results) -> Figure:
    """Wear depth per sector at each snapshot, journal and bearing: paper Fig. 8.

    One row per clearance joint, journal on the left, bearing on the right. Depths in nm, µm
    or mm, as the deepest reads (``scaling.length_unit``).
    """
    joints = _require_joints(results)
    profiles = _profiles_over_time(results)
    unit, per_m = length_unit(results.wear["depth_m"])
    colors = colormaps["viridis"](np.linspace(0.85, 0.0, len(profiles)))
    fig = Figure(figsize=(11.0 + LEGEND_ROOM, 3.8 * len(joints) + 0.5), layout="constrained")
    axes = fig.subplots(len(joints), 2, squeeze=False)
    for row, joint in zip(axes, joints, strict=True):
        for ax, surface in zip(row, KIND.surfaces, strict=True):
            for (time, table), color in zip(profiles, colors, strict=True):
                angle, depth = _profile(table, joint.name, surface)
                label = _turns_label(results, time)
                ax.plot(angle, depth * per_m, "o-", ms=3, lw=1.0, color=color, label=label)
            _mark_peak(ax, results, joint.name, surface, (unit, per_m))
            body = _surface_body(joint, surface)
            ax.set_title(f"{joint.name}: {surface} ({body})")
            ax.set_xlabel(f"angle in the {body} frame [deg]")
            ax.set_ylabel(f"wear depth [{unit}]")
            ax.set_xlim(0.0, 360.0)
            ax.set_xticks(np.arange(0, 361, 45))
            ax.set_ylim(0.0, PEAK_ROOM * ax.get_ylim()[1])  # room for the peak's note
            ax.grid(alpha=0.3)
        legend_beside(row[-1])
    fig.suptitle(f"{results.model.name}: wear depth per sector{_paper(results, '8')}")
    return fig


def plot_wear_polar(results: Results) -> Figure:
    """Final wear depth per sector in polar form, journal and bearing: paper Fig. 9.

    Depths in nm, µm or mm, as the deepest reads (``scaling.length_unit``).
    """
    joints = _require_joints(results)
    unit, per_m = length_unit(results.wear["depth_m"])
    fig = Figure(figsize=(10.0, 5.0 * len(joints) + 0.5), layout="constrained")
    t_end = float(results.timeseries["time"].iloc[-1])
    for k, joint in enumerate(joints):
        for s, surface in enumerate(KIND.surfaces):
            ax = fig.add_subplot(len(joints), 2, 2 * k + s + 1, projection="polar")
            angle, depth = _profile(results.wear, joint.name, surface)
            theta = np.radians(np.append(angle, angle[0]))
            radius = np.append(depth, depth[0]) * per_m
            ax.plot(theta, radius, color="tab:red", lw=1.2)
            peak = int(np.argmax(depth))
            ax.plot(theta[peak], radius[peak], "o", color="tab:red", ms=4)
            ax.fill(theta, radius, color="tab:red", alpha=0.25)
            ax.set_rlabel_position(67.5)
            ax.set_title(
                f"{joint.name}: {surface} ({_surface_body(joint, surface)})\n"
                f"wear depth [{unit}] {_turns_label(results, t_end)}",
                fontsize="medium",
            )
    fig.suptitle(f"{results.model.name}: total wear per sector{_paper(results, '9')}")
    return fig


def wear_exaggeration(results: Results, joint: str) -> float:
    """Factor by which Fig. 10 magnifies ``joint``'s wear depths [-].

    The deepest sector of either surface is drawn as ``PROFILE_SHARE`` of the journal
    radius; the factor is rounded to two significant digits (1 without wear).
    """
    depth = results.wear.loc[results.wear["joint"] == joint, "depth_m"].max()
    if not depth > 0.0:
        return 1.0
    radius = results.model.joint(joint).clearance.journal_radius
    exact = PROFILE_SHARE * radius / depth
    return float(f"{exact:.2g}")


def _factor_text(factor: float) -> str:
    """'500', '1.2e5': the exaggeration factor as the figures print it."""
    if factor < 1e4:
        return f"{factor:g}"
    mantissa, exponent = f"{factor:.1e}".split("e")
    return f"{mantissa.removesuffix('.0')}e{int(exponent)}"


def plot_wear_profile(results: Results) -> Figure:
    """Nominal and worn journal and bearing profiles [mm], wear exaggerated: paper Fig. 10.

    Worn radius ``R_J - s h`` (journal) and ``R_B + s h`` (bearing), with ``h`` the sector
    depths interpolated linearly and periodically between sector centres, as the contact
    model does, and ``s`` from ``wear_exaggeration``. Drawn in each surface's body frame.
    """
    joints = _require_joints(results)
    fig = Figure(figsize=(10.0 + LEGEND_ROOM, 5.2 * len(joints) + 0.5), layout="constrained")
    axes = fig.subplots(len(joints), 2, squeeze=False)
    for row, joint in zip(axes, joints, strict=True):
        scale = wear_exaggeration(results, joint.name)
        factor = _factor_text(scale)
        for ax, surface in zip(row, KIND.surfaces, strict=True):
            centres, depth = _profile(results.wear, joint.name, surface)
            angle = np.unique(np.concatenate([np.linspace(0.0, 360.0, 721), centres]))
            worn_depth = np.interp(angle, centres, depth, period=360.0)
            nominal = _radius(joint, surface)
            sign = 1.0 if surface == "bearing" else -1.0
            worn = (nominal + sign * scale * worn_depth) * MM
            cos, sin = np.cos(np.radians(angle)), np.sin(np.radians(angle))
            ax.fill(
                np.concatenate([worn * cos, nominal * MM * cos[::-1]]),
                np.concatenate([worn * sin, nominal * MM * sin[::-1]]),
                color="tab:red",
                alpha=0.3,
                lw=0.0,
            )
            ax.plot(nominal * MM * cos, nominal * MM * sin, "k--", lw=1.0, label="initial")
            ax.plot(worn * cos, worn * sin, color="tab:red", lw=1.4, label=f"worn, wear × {factor}")
            body = _surface_body(joint, surface)
            ax.annotate(
                "",
                xy=(0.85 * nominal * MM, 0.0),
                xytext=(0.0, 0.0),
                arrowprops={"arrowstyle": "->", "color": "0.4"},
            )
            ax.text(0.05 * nominal * MM, 0.04 * nominal * MM, f"{body} x axis", color="0.4")
            ax.set_aspect("equal")
            ax.set_xlabel(f"{body} x [mm]")
            ax.set_ylabel(f"{body} y [mm]")
            ax.set_title(f"{joint.name}: {surface} ({body}), R = {nominal * MM:.4g} mm")
            ax.grid(alpha=0.3)
        legend_beside(ax)
    fig.suptitle(
        f"{results.model.name}: initial and worn profiles, wear exaggerated{_paper(results, '10')}"
    )
    return fig


def draw_life_profiles(
    fig: Figure, place: SubplotSpec, joint: RevoluteJoint, profiles: pd.DataFrame, updates: dict
) -> None:
    """Wear depth per sector of the journal and the bearing, polar, at a few updates.

    ``profiles``: the joint's rows of a life run's profiles.csv; ``updates``: the updates
    drawn, each with its colour.
    """
    unit, per_m = length_unit(profiles["depth_m"])
    cells = place.subgridspec(1, len(KIND.surfaces))
    for s, surface in enumerate(KIND.surfaces):
        ax = fig.add_subplot(cells[0, s], projection="polar")
        for update, colour in updates.items():
            rows = profiles[profiles["update"] == update]
            angle, depth = _profile(rows, joint.name, surface)
            theta = np.radians(np.append(angle, angle[0]))
            label = f"{int(rows['cycles'].iloc[0]):,} cycles"
            ax.plot(theta, np.append(depth, depth[0]) * per_m, color=colour, lw=1.2, label=label)
        ax.set_rlabel_position(67.5)
        title = f"{joint.name}: {surface} ({_surface_body(joint, surface)})\nwear depth [{unit}]"
        ax.set_title(title, fontsize="medium")
        if s == 0:
            ax.legend(loc="lower left", bbox_to_anchor=(-0.25, -0.12), fontsize="small")


def save_figures(results: Results, folder: str | Path, ideal: Results | None = None) -> list[Path]:
    """Write the clearance figures into ``folder`` as PNG; return the paths."""
    return save_pngs(kind_drawings(KIND, results, ideal), Path(folder))
