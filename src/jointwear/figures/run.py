"""Figures from a results folder: functions Results -> matplotlib Figure.

Plots see only ``Results`` (time series with the model's own column names, and the model),
never the kernel arrays.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from matplotlib.figure import Figure  # figures without pyplot: no global backend switch

from ..results import Results
from ..results.energy_balance import energy_balance, unaccounted
from .legends import LEGEND_ROOM, legend_beside
from .plan import crank_driver

STILL_SPEED = 1e-9  # [rad/s] a body whose angular velocity stays below this does not turn


def _last_turn(df: pd.DataFrame, speed: float) -> pd.DataFrame:
    period = 2.0 * math.pi / abs(speed)
    t_end = df["time"].iloc[-1]
    return df[df["time"] >= t_end - period * (1.0 + 1e-9)]


def plot_cycle(results: Results) -> Figure:
    """Plot the undriven bodies' angular velocity and acceleration, and the driver torque.

    Against the crank angle over the last crank turn (paper Fig. 7a-c, ideal case).
    """
    crank = crank_driver(results)
    if crank is None:
        raise ValueError("plot_cycle needs a constant-speed angle driver")
    name, driven, speed = crank
    turn = _last_turn(results.timeseries, speed)
    angle = np.degrees(turn[f"phi_{driven}"].to_numpy()) % 360.0
    order = np.argsort(angle)
    bodies = [  # those that turn: a piston's angular velocity is zero throughout
        b.name
        for b in results.model.bodies
        if b.name != driven and np.abs(turn[f"omega_{b.name}"]).max() > STILL_SPEED
    ]
    fig = Figure(figsize=(7.0 + LEGEND_ROOM, 8.0), layout="constrained")
    axes = fig.subplots(3, 1, sharex=True)
    for body in bodies:
        axes[0].plot(angle[order], turn[f"omega_{body}"].to_numpy()[order], label=body)
        axes[1].plot(angle[order], turn[f"alpha_{body}"].to_numpy()[order], label=body)
    axes[2].plot(angle[order], turn[f"torque_{name}"].to_numpy()[order], color="k")
    axes[0].set_ylabel("angular velocity [rad/s]")
    axes[1].set_ylabel("angular acceleration [rad/s²]")
    axes[2].set_ylabel(f"driver '{name}' torque [N m]")
    axes[2].set_xlabel(f"{driven} angle [deg]")
    axes[2].set_xlim(0.0, 360.0)
    axes[2].set_xticks(np.arange(0, 361, 45))
    if bodies:
        legend_beside(axes[0])
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.axhline(0.0, color="0.6", lw=0.6)
    fig.suptitle(f"{results.model.name}: one {driven} turn ({abs(speed):.4g} rad/s)")
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
