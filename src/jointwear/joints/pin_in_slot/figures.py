"""Figures of the pin-in-slot clearance joints: a pin in a round-ended slot with a gap.

Functions ``Results -> matplotlib Figure`` and ``save_figures`` that writes them all. As in
the time series: ``along`` is the pin centre's position along the slot's axis from the
slot's point, ``across`` its offset towards the +v side (the axis turned +90 degrees); the
surfaces and wear positions are those of the wear table (``joints.pin_in_slot``).
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
from . import ENDS, KIND, SIDES, SURFACES
from .schema import PinInSlotJoint

MM = 1e3  # [mm/m]
SURFACE_COLORS = dict(zip(SURFACES, ("tab:blue", "tab:orange", "tab:green", "tab:red",
                                     "tab:purple"), strict=True))  # fmt: skip
OUTLINE = {"color": "k", "ls": "--", "lw": 0.8}


def _joints(results: Results) -> tuple[PinInSlotJoint, ...]:
    joints = results.model.joints_of("pin_in_slot")
    if not joints:
        raise ValueError(f"model '{results.model.name}' has no pin-in-slot clearance joints")
    return joints


def touched(joint: PinInSlotJoint, along: np.ndarray, across: np.ndarray) -> np.ndarray:
    """The index in ``SURFACES`` of the slot surface nearest the pin, per row (the kernel's)."""
    half = 0.5 * joint.clearance.slot_length
    side = np.where(across >= 0.0, 0, 1)
    end = np.where(along >= 0.0, 2, 3)
    return np.where(np.abs(along) < half, side, end)


def reach(joint: PinInSlotJoint, points: int = 60) -> np.ndarray:
    """(n, 2) outline [m] where the pin centre touches the unworn slot, closed, in (along, across).

    A stadium: ``gap`` c off the segment between the end centres, half circles round them.
    """
    c = joint.clearance
    half, gap = 0.5 * c.slot_length, c.gap
    turn = np.linspace(-0.5 * math.pi, 0.5 * math.pi, points)
    front = np.column_stack([half + gap * np.cos(turn), gap * np.sin(turn)])
    rear = np.column_stack([-half - gap * np.cos(turn), -gap * np.sin(turn)])
    return np.concatenate([front, rear, front[:1]])


def plot_pin_path(results: Results) -> Figure:
    """Each pin's path in its slot over the run, and its offset across the slot.

    Left: the pin centre, across [µm or as fits] against along [mm], with the outline where
    it touches the unworn slot (dashed); the run's start and end marked. Right: the offset
    across against the crank angle [deg] (or time [s]), with the gap ±c.
    """
    joints = _joints(results)
    df = results.timeseries
    x = crank_abscissa(results)
    fig = Figure(figsize=(11.0 + LEGEND_ROOM, 4.2 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(len(joints), 2, squeeze=False)
    for (path, offset), joint in zip(axes, joints, strict=True):
        along = df[f"{joint.name}_along"].to_numpy()
        across = df[f"{joint.name}_across"].to_numpy()
        unit, per_m = length_unit([joint.clearance.gap, *across])
        outline = reach(joint)
        path.plot(outline[:, 0] * MM, outline[:, 1] * per_m, **OUTLINE, label="touches the slot")
        path.plot(along * MM, across * per_m, lw=0.8, color="tab:blue", label="pin centre")
        path.plot(along[0] * MM, across[0] * per_m, "o", color="tab:green", label="start")
        path.plot(along[-1] * MM, across[-1] * per_m, "s", color="tab:red", label="end")
        path.set_xlabel(f"along the slot from its point ({joint.bodies[0]} frame) [mm]")
        path.set_ylabel(f"across the slot [{unit}]")
        path.set_title(f"{joint.name}: pin centre in the slot", loc="left", fontsize="medium")
        path.grid(alpha=0.3)
        legend_beside(path)
        offset.plot(x.values, across * per_m, lw=0.9, color="tab:blue")
        for sign in (1.0, -1.0):
            label = f"gap ±c = ±{joint.clearance.gap * per_m:.3g} {unit}" if sign > 0 else None
            offset.axhline(sign * joint.clearance.gap * per_m, **OUTLINE, label=label)
        offset.set_ylabel(f"across the slot [{unit}]")
        offset.set_title(f"{joint.name}: offset across the slot", loc="left", fontsize="medium")
        offset.grid(alpha=0.3)
        legend_beside(offset)
        set_abscissa(offset, x)
    fig.suptitle(f"{results.model.name}: pin path in the slot")
    return fig


def plot_contact_force(results: Results) -> Figure:
    """Each joint's normal contact force [N] against the crank angle [deg] (or time [s]).

    Coloured by the slot surface the pin touches; the title gives the largest force among the
    time-series rows (the summary's maximum is over every step, so it can be larger).
    """
    joints = _joints(results)
    df = results.timeseries
    x = crank_abscissa(results)
    fig = Figure(figsize=(9.0 + LEGEND_ROOM, 3.6 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(len(joints), 1, sharex=True, squeeze=False)[:, 0]
    for ax, joint in zip(axes, joints, strict=True):
        force = df[f"{joint.name}_fn"].to_numpy()
        where = touched(joint, df[f"{joint.name}_along"].to_numpy(),
                        df[f"{joint.name}_across"].to_numpy())  # fmt: skip
        ax.plot(x.values, force, lw=0.6, color="0.7", zorder=1)
        for s, surface in enumerate(SURFACES[:4]):
            mine = (where == s) & (force > 0.0)
            if mine.any():
                ax.plot(x.values[mine], force[mine], ".", ms=2.5, color=SURFACE_COLORS[surface],
                        label=surface)  # fmt: skip
        peak = np.max(force, initial=0.0)
        ax.set_title(f"{joint.name}: normal force on the pin (largest row {peak:.4g} N)",
                     loc="left", fontsize="medium")  # fmt: skip
        ax.set_ylabel("normal force [N]")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            legend_beside(ax)
    set_abscissa(axes[-1], x)
    fig.suptitle(f"{results.model.name}: contact force in the slot")
    return fig


def _wear_panel(ax: Axes, results: Results, joint: PinInSlotJoint, surfaces: tuple) -> None:
    """Wear depth along ``surfaces`` at the end of the run (positions as the wear table's)."""
    unit, per_m = length_unit(results.wear["depth_m"])
    table = results.wear[results.wear["joint"] == joint.name]
    for surface in surfaces:
        rows = table[table["surface"] == surface].sort_values("sector")
        if len(rows):
            ax.plot(rows["position_m"] * MM, rows["depth_m"] * per_m, "o-", ms=3, lw=1.2,
                    color=SURFACE_COLORS[surface], label=surface)  # fmt: skip
    ax.set_ylabel(f"wear depth [{unit}]")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        legend_beside(ax)


def plot_wear(results: Results) -> Figure:
    """Wear depth of each surface at the end of the run: the sides, the ends, the pin.

    Sides along the slot's axis from its point; ends along their arcs from the axis; the pin
    along its circle from its body's x axis (the wear table's ``position_m``). A slot of
    length 0 has no sides: its panel says so.
    """
    joints = _joints(results)
    t_end = float(results.timeseries["time"].iloc[-1])
    fig = Figure(figsize=(15.0 + LEGEND_ROOM, 3.8 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(len(joints), 3, squeeze=False)
    for (sides, ends, pin), joint in zip(axes, joints, strict=True):
        slot, body = joint.bodies
        _wear_panel(sides, results, joint, SIDES)
        sides.set_xlabel(f"along the slot from its point ({slot} frame) [mm]")
        sides.set_title(f"{joint.name}: slot sides", loc="left", fontsize="medium")
        if joint.clearance.slot_length == 0.0:
            sides.text(0.5, 0.5, "slot length 0: no sides", ha="center", va="center",
                       transform=sides.transAxes)  # fmt: skip
        _wear_panel(ends, results, joint, ENDS)
        ends.set_xlabel("along the end's arc from the slot's axis [mm]")
        ends.set_title(f"{joint.name}: slot ends", loc="left", fontsize="medium")
        _wear_panel(pin, results, joint, ("pin",))
        pin.set_xlabel(f"along the pin's circle from {body}'s x axis [mm]")
        pin.set_title(f"{joint.name}: pin", loc="left", fontsize="medium")
    fig.suptitle(f"{results.model.name}: wear depth at t = {t_end:.4g} s")
    return fig


def draw_life_profiles(
    fig: Figure, place: SubplotSpec, joint: PinInSlotJoint, profiles: pd.DataFrame,
    updates: dict,
) -> None:  # fmt: skip
    """Wear depth along the slot's sides, its ends and the pin at a few updates of a life run.

    The first surface of each pair solid, the second dashed. ``profiles``: the joint's rows
    of a life run's profiles.csv; ``updates``: the updates drawn, each with its colour.
    """
    unit, per_m = length_unit(profiles["depth_m"])
    cells = place.subgridspec(1, 3)
    groups = (("slot sides", SIDES, "along the slot from its point"),
              ("slot ends", ENDS, "along the end's arc from the slot's axis"),
              ("pin", ("pin",), "along the pin's circle"))  # fmt: skip
    for n, (title, surfaces, where) in enumerate(groups):
        ax = fig.add_subplot(cells[0, n])
        for update, colour in updates.items():
            rows = profiles[profiles["update"] == update]
            for surface, style in zip(surfaces, ("-", "--"), strict=False):
                line = rows[rows["surface"] == surface].sort_values("sector")
                label = f"{int(rows['cycles'].iloc[0]):,} cycles" if style == "-" else None
                ax.plot(line["position_m"] * MM, line["depth_m"] * per_m, ls=style,
                        color=colour, lw=1.2, label=label)  # fmt: skip
        ax.set_title(f"{joint.name}: {title}", loc="left", fontsize="medium")
        ax.set_xlabel(f"{where} [mm]")
        ax.set_ylabel(f"wear depth [{unit}]")
        ax.set_ylim(bottom=0.0)
        ax.grid(alpha=0.3)
    ax.legend(fontsize="small")


def save_figures(results: Results, folder: str | Path) -> list[Path]:
    """Write the pin-in-slot figures into ``folder`` as PNG; return the paths (none without)."""
    return save_pngs(kind_drawings(KIND, results), Path(folder))
