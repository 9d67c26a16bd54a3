"""Figures of a long-life wear run, from its tables (life.csv, profiles.csv).

``life_wear.png``: maximum wear depth per surface and effective clearance growth, peak contact
force and the driver's torque range, against cycles (and hours of operation, on the top axis),
the clearance growth shaded over its uncertainty band where the run has one (life_band.csv),
and the cycle of a run-away marked where the run stopped at one; ``life_profiles.png``: the
wear profiles of every clearance joint at a few cycle counts, each drawn by its kind
(``draw_life_profiles`` of its ``figures_module``: a revolute joint's in polar form, a
translational joint's along its surfaces).
"""

from __future__ import annotations

from importlib import import_module
from itertools import cycle
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib import colormaps
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch

from ..joints import joints_by_kind
from ..model import Model
from ..results.cycles import cycles_at
from .files import save_png
from .legends import LEGEND_ROOM, legend_beside
from .names import LIFE_FIGURES
from .scaling import length_unit

PROFILE_COUNTS = 5  # profiles drawn: at about 1/5, 2/5, ... of the cycles reached
STYLES = ("-", "--", "-.", (0, (1, 1)))  # of each surface's deepest wear, in report order


def plot_life_wear(
    model: Model,
    table: pd.DataFrame,
    driver: str,
    band: pd.DataFrame | None = None,
    marks: dict | None = None,
    *,
    growth_mark: float,
    range_column: str,
    period_s: float,
    runaway: dict | None = None,
) -> Figure:
    """Wear depth and clearance growth, peak contact force [kN], torque range, vs cycles.

    ``band`` (life_band.csv) shades the clearance growth's band; ``marks`` (the summary's
    ``clearance_joints``) gives the band of the cycles to the growth of ``growth_mark`` of
    the gap for the annotation; ``range_column``: the table's column of the driver's range;
    ``period_s``: the cycle [s], for the axis of hours; ``runaway``: the summary's entry of
    a run-away, marked at its cycle.
    """
    fig = Figure(figsize=(8.0 + LEGEND_ROOM, 9.0), layout="constrained")
    depth, force, torque = fig.subplots(3, 1, sharex=True)
    cycles = table["cycles"].to_numpy()
    lengths = [c for c in table if ".max_wear_depth_" in c or c.endswith(".clearance_growth_m")]
    joints = [(kind, joint) for kind, _, joint in joints_by_kind(model)]
    marks_m = [growth_mark * kind.gap(joint) for kind, joint in joints]
    unit, per_m = length_unit([*table[lengths].to_numpy().ravel(), *marks_m])
    per_hour = 3600.0 / period_s  # cycles
    for (kind, joint), mark_m in zip(joints, marks_m, strict=True):
        name = joint.name
        mapped = kind.mapped_surfaces(joint)
        shown = [surface for surface in kind.surfaces if surface in mapped]
        for surface, style in zip(shown, cycle(STYLES)):
            values = table[f"{name}.max_wear_depth_{surface}_m"] * per_m
            depth.plot(cycles, values, ls=style, label=f"{name}: {surface}, deepest")
        growth = table[f"{name}.clearance_growth_m"] * per_m
        line = depth.plot(cycles, growth, "-", lw=2.0, label=f"{name}: clearance growth")[0]
        if band is not None:
            low, high = (band[f"{name}.clearance_growth_{e}_m"] * per_m for e in ("low", "high"))
            depth.fill_between(
                band["cycles"], low, high, color=line.get_color(), alpha=0.25, lw=0,
                label=f"{name}: clearance growth, band of {band['runs'].max()} runs",
            )  # fmt: skip
        mark = mark_m * per_m
        depth.axhline(mark, color=line.get_color(), ls=":", lw=1.0)
        reached = cycles_at(table["cycles"], growth, mark)
        text = f"{growth_mark:.0%} of c"
        if reached:
            text += f" at {reached:,.0f} cycles ({reached / per_hour:.3g} h)"
        text += _band_text((marks or {}).get(name, {}).get("band"))
        depth.annotate(
            text, (cycles[0], mark), xytext=(2, 2), textcoords="offset points",
            color=line.get_color(), fontsize="small",
        )  # fmt: skip
        if reached:
            depth.plot(reached, mark, "o", color=line.get_color(), ms=4)
        force.plot(cycles, table[f"{name}.max_contact_force_n"] / 1e3, ".-", label=name)
    torque.plot(cycles, table[range_column], ".-", color="k")
    depth.set_ylabel(f"wear depth [{unit}]")
    legend_beside(depth)
    force.set_ylabel("peak contact force\nof the measured cycles [kN]")
    legend_beside(force)
    what, unit = ("torque", "N m") if range_column.startswith("torque") else ("force", "N")
    torque.set_ylabel(f"{what} range of driver\n'{driver}', max - min [{unit}]")
    torque.set_xlabel("cycles")
    top = depth.secondary_xaxis("top", functions=(lambda c: c / per_hour, lambda h: h * per_hour))
    top.set_xlabel("hours of operation")
    for ax in (depth, force, torque):
        ax.grid(alpha=0.3)
        if runaway is not None:
            ax.axvline(runaway["cycle"], color="tab:red", ls="--", lw=1.0)
    if runaway is not None:
        depth.annotate(
            f"run-away of {runaway['joint']} in cycle {runaway['cycle']:,}",
            (runaway["cycle"], 0.5), xycoords=("data", "axes fraction"), xytext=(-3, 0),
            textcoords="offset points", ha="right", va="center", rotation=90, color="tab:red",
            fontsize="small",
        )  # fmt: skip
    fig.suptitle(f"{model.name}: wear over {int(cycles[-1]):,} cycles")
    return fig


def _band_text(entry: dict | None) -> str:
    """`` (band low-high)`` of the cycles to 50 % growth, or "" without a band."""
    if not entry or entry["cycles_to_clearance_growth_50pct"]["low"] is None:
        return ""
    at = entry["cycles_to_clearance_growth_50pct"]
    high = "not reached" if at["high"] is None else f"{at['high']:,.0f}"
    return f" (band {at['low']:,.0f} to {high})"


def profile_updates(table: pd.DataFrame) -> list[int]:
    """The updates whose profiles are drawn: nearest to 1/5, 2/5, ... of the cycles reached."""
    cycles = table["cycles"].to_numpy()
    targets = cycles[-1] * np.arange(1, PROFILE_COUNTS + 1) / PROFILE_COUNTS
    rows = sorted({int(np.argmin(np.abs(cycles - target))) for target in targets})
    return [int(table["update"].iloc[row]) for row in rows]


def plot_life_profiles(model: Model, table: pd.DataFrame, profiles: pd.DataFrame) -> Figure:
    """Wear profiles of every clearance joint at a few cycle counts, a row each."""
    joints = [(kind, joint) for kind, _, joint in joints_by_kind(model)]
    updates = profile_updates(table)
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, len(updates)))
    fig = Figure(figsize=(10.0, 5.0 * len(joints) + 0.5), layout="constrained")
    rows = fig.add_gridspec(len(joints), 1)
    for row, (kind, joint) in zip(rows, joints, strict=True):
        draw = import_module(kind.figures_module).draw_life_profiles
        mine = profiles[profiles["joint"] == joint.name]
        draw(fig, row, joint, mine, dict(zip(updates, colours, strict=True)))
    fig.suptitle(f"{model.name}: wear profiles as the cycles accumulate")
    return fig


def save_life_figures(
    model: Model,
    driver: str,
    table: pd.DataFrame,
    profiles: pd.DataFrame,
    folder: Path,
    band: pd.DataFrame | None = None,
    marks: dict | None = None,
    *,
    growth_mark: float,
    range_column: str,
    period_s: float,
    runaway: dict | None = None,
) -> list[Path]:
    """Write life_wear.png and life_profiles.png into ``folder``; return their paths.

    The other arguments as for ``plot_life_wear``.
    """
    options = {"growth_mark": growth_mark, "range_column": range_column, "period_s": period_s}
    figures = (
        plot_life_wear(model, table, driver, band, marks, **options, runaway=runaway),
        plot_life_profiles(model, table, profiles),
    )
    return [save_png(fig, folder / name) for name, fig in zip(LIFE_FIGURES, figures, strict=True)]
