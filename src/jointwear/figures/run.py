"""Figures from a results folder: functions Results -> matplotlib Figure.

Plots see only ``Results`` (time series with the model's own column names, and the model),
never the kernel arrays.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch

from ..mechanism.system import load_columns
from ..results import Results
from ..results.energy_balance import energy_balance, unaccounted
from .legends import LEGEND_ROOM, legend_beside
from .plan import crank_driver

STILL_SPEED = 1e-9  # [rad/s] a body whose angular velocity stays below this does not turn


class CycleRows(NamedTuple):
    """The rows of the last cycle, against the crank's angle in it."""

    rows: pd.DataFrame
    angle: np.ndarray  # [deg], 0 to 360 turns, the driver's value modulo the cycle
    turns: int  # crank turns in the cycle
    driver: str
    crank: str
    speed: float  # [rad/s]


def last_cycle(results: Results) -> CycleRows | None:
    """The last cycle's rows against the crank angle, or None without a crank driver.

    The cycle is the model's (its longest period: 720 deg for a four-stroke cylinder
    pressure) when it is a whole number of crank turns, else one turn.
    """
    crank = crank_driver(results)
    if crank is None:
        return None
    name, driven, speed = crank
    turn = 2.0 * math.pi / abs(speed)
    cycle = results.model.cycle or turn
    turns = round(cycle / turn)
    if turns < 1 or abs(cycle / turn - turns) > 1e-6:
        turns = 1
    df = results.timeseries
    rows = df[df["time"] >= df["time"].iloc[-1] - turns * turn * (1.0 + 1e-9)]
    driver = next(d for d in results.model.drivers if d.name == name)
    value = rows[f"phi_{driven}"].to_numpy()
    if driver.relative_to != "ground":
        value = value - rows[f"phi_{driver.relative_to}"].to_numpy()
    angle = np.degrees(value) % (360.0 * turns)
    return CycleRows(rows, angle, turns, name, driven, speed)


def _crank_axis(ax: Axes, cycle: CycleRows) -> None:
    span = 360.0 * cycle.turns
    ax.set_xlabel(f"{cycle.crank} angle [deg] (driver '{cycle.driver}')")
    ax.set_xlim(0.0, span)
    ax.set_xticks(np.arange(0, span + 1, 45 * cycle.turns))


def _in_order(cycle: CycleRows, column: str) -> tuple[np.ndarray, np.ndarray]:
    """A column's values against the cycle's angle, sorted by it."""
    order = np.argsort(cycle.angle)
    return cycle.angle[order], cycle.rows[column].to_numpy()[order]


def plot_cycle(results: Results) -> Figure:
    """Plot the undriven bodies' angular velocity and acceleration, and the driver torque.

    Against the crank angle over the last cycle (paper Fig. 7a-c, ideal case).
    """
    cycle = last_cycle(results)
    if cycle is None:
        raise ValueError("plot_cycle needs a constant-speed angle driver")
    bodies = [  # those that turn: a piston's angular velocity is zero throughout
        b.name
        for b in results.model.bodies
        if b.name != cycle.crank and np.abs(cycle.rows[f"omega_{b.name}"]).max() > STILL_SPEED
    ]
    fig = Figure(figsize=(7.0 + LEGEND_ROOM, 8.0), layout="constrained")
    axes = fig.subplots(3, 1, sharex=True)
    for body in bodies:
        axes[0].plot(*_in_order(cycle, f"omega_{body}"), label=body)
        axes[1].plot(*_in_order(cycle, f"alpha_{body}"), label=body)
    axes[2].plot(*_in_order(cycle, f"torque_{cycle.driver}"), color="k")
    axes[0].set_ylabel("angular velocity [rad/s]")
    axes[1].set_ylabel("angular acceleration [rad/s²]")
    axes[2].set_ylabel(f"driver '{cycle.driver}' torque [N m]")
    _crank_axis(axes[2], cycle)
    if bodies:
        legend_beside(axes[0])
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="0.6", lw=0.6)
    turns = "one turn" if cycle.turns == 1 else f"one cycle of {cycle.turns} turns"
    fig.suptitle(f"{results.model.name}: {turns} of {cycle.crank} ({abs(cycle.speed):.4g} rad/s)")
    return fig


def plot_loads(results: Results) -> Figure:
    """Every applied load but gravity, as the run applied it: one panel per load.

    Against the crank angle over the last cycle with a crank driver, else against time.
    """
    loads: dict[str, list[str]] = {}  # the load's column stem -> its columns
    for column, quantity in load_columns(results.model).items():
        loads.setdefault(column.removesuffix(f"_{quantity}"), []).append(column)
    units = results.units()
    cycle = last_cycle(results)
    fig = Figure(figsize=(7.0 + LEGEND_ROOM, 1.0 + 2.2 * len(loads)), layout="constrained")
    axes = np.atleast_1d(fig.subplots(len(loads), 1, sharex=True, squeeze=False)[:, 0])
    for ax, (stem, columns) in zip(axes, loads.items(), strict=True):
        twin = None
        for k, column in enumerate(columns):
            unit = units[column]
            target = ax if k == 0 or unit == units[columns[0]] else (twin := twin or ax.twinx())
            x, y = (
                _in_order(cycle, column)
                if cycle
                else (results.timeseries["time"], results.timeseries[column])
            )
            target.plot(x, y, lw=1.0, color=f"C{k}", label=column.removeprefix(f"{stem}_"))
            target.set_ylabel(f"{column.removeprefix(f'{stem}_')} [{unit}]", color=f"C{k}")
        ax.set_title(stem.removeprefix("load_"), loc="left", fontsize="medium")
        ax.grid(alpha=0.3)
    if cycle:
        _crank_axis(axes[-1], cycle)
    else:
        axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"{results.model.name}: applied loads")
    return fig


def plot_energy(results: Results) -> Figure:
    """The energy balance and the constraint violation against time.

    Kinetic, potential and contact energy; where the time series holds every flow
    (``results.energy_balance``), also the energy the clearance joints dissipated and the
    drivers' work, both integrated over the rows, and the balance stored + dissipated - work,
    which stays at zero as far as the rows resolve the motion.
    """
    df = results.timeseries
    model = results.model
    fig = Figure(figsize=(7.0 + LEGEND_ROOM, 6.5), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=(2, 1))
    parts = [c for c in ("energy_kinetic", "energy_potential", "energy_contact") if c in df]
    for column in parts:
        top.plot(df["time"], df[column], label=column.removeprefix("energy_"), lw=1.0)
    why = unaccounted(model)
    if why is None and (model.drivers or model.has_clearance):
        flows = energy_balance(model, df)
        top.plot(flows["time"], flows["dissipated"], label="dissipated (contacts)", lw=1.0)
        if model.drivers:
            top.plot(flows["time"], flows["driver_work"], label="driver work", lw=1.0)
        top.plot(flows["time"], flows["balance"], color="k", lw=1.5,
                 label="balance: stored + dissipated - work")  # fmt: skip
        interval = model.solver.output_interval
        title = f"energy balance (rows every {interval:.3g} s; finer rows tighten it)"
    else:
        top.plot(df["time"], df[parts].sum(axis=1), label="total", color="k")
        title = "energy" + (f" (no balance: {why})" if why else "")
    top.set_ylabel("energy [J]")
    legend_beside(top)
    bottom.semilogy(df["time"], np.maximum(df["constraint_violation"], 1e-18))
    bottom.set_ylabel("constraint violation |Φ| [m]")
    bottom.set_xlabel("time [s]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.suptitle(f"{model.name}: {title}", fontsize="medium")
    return fig
