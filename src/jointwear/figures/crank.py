"""The crank of a run's mechanism, and the x axis of plots against it (no pyplot)."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from matplotlib.axes import Axes
from matplotlib.ticker import MultipleLocator

from ..joints import BY_NAME
from ..results import Results
from .plan import crank_driver

TURN = 360.0  # [deg]
MAX_TURN_TICKS = 8  # more crank turns than this: a tick every few turns


class Abscissa(NamedTuple):
    """The x axis of the time plots: the crank angle turned [deg], or time [s]."""

    values: np.ndarray  # one per time-series row
    label: str
    crank: str | None  # the crank body, None when against time


def crank_body(results: Results) -> str | None:
    """The crank body, or None.

    The body a constant-speed driver turns, else the first body pinned to the ground (a
    revolute joint, ``ClearanceKind.pins_points``) whose angle spans more than one turn in the run.
    """
    crank = crank_driver(results)
    if crank is not None:
        return crank[1]
    df = results.timeseries
    for joint in results.model.joints:
        if BY_NAME[joint.type].pins_points and "ground" in joint.bodies:
            body = joint.bodies[1] if joint.bodies[0] == "ground" else joint.bodies[0]
            phi = df[f"phi_{body}"]
            if phi.max() - phi.min() > 2.0 * math.pi:
                return body
    return None


def crank_abscissa(results: Results) -> Abscissa:
    """The crank angle turned since the run's start [deg] (positive either way), or time [s]."""
    df = results.timeseries
    body = crank_body(results)
    if body is None:
        return Abscissa(df["time"].to_numpy(), "time [s]", None)
    phi = df[f"phi_{body}"].to_numpy()
    turned = np.degrees(phi - phi[0])
    if turned[-1] < 0.0:
        turned = -turned
    label = f"{body} angle turned since t = {df['time'].iloc[0]:.4g} s [deg]"
    return Abscissa(turned, label, body)


def set_abscissa(ax: Axes, x: Abscissa) -> None:
    """Label the bottom x axis; crank angle ticks every turn (or every few), minor every 90°."""
    ax.set_xlabel(x.label)
    if x.crank is None:
        return
    turns = max(float(np.max(x.values)) / TURN, 1.0)
    step = TURN * math.ceil(turns / MAX_TURN_TICKS)
    ax.xaxis.set_major_locator(MultipleLocator(step))
    if step == TURN:
        ax.xaxis.set_minor_locator(MultipleLocator(TURN / 4.0))
