"""The figure of a finite journal bearing's film: its pressure over the unwrapped film.

``plot_film_pressure`` draws the field ``film_field`` solves at one output row: the film
thickness around the bearing above, the pressure p(a, z) below, cavitated region and
thinnest film marked. Figures without pyplot.
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure, SubFigure
from matplotlib.patches import Patch
from matplotlib.ticker import LogLocator, MaxNLocator, NullLocator

from ...results import Results
from .film_field import FilmField, film_field, finite_bearings

MM, UM, MPA = 1e3, 1e6, 1e-6  # display units per SI unit
LEVELS = 12  # pressure bands, about
UNFILLED = 1e-3  # pressures below this share of the peak are left white (none, or cavitated)
CAVITATED = "0.55"  # hatch colour of the cavitated film
ROUGHNESS_LINES = (1.0, 3.0)  # film thickness / roughness marked in the thickness panel
PEAK_WIDTHS = 2.0  # the angle axis is linear over this many sqrt(1 - eps) [rad] about 0
ANGLE_TICKS = (2, 5, 10, 20, 45, 90, 180)  # [deg] on either side of 0, those the scale spreads


def plot_film_pressure(
    results: Results, joint: str | None = None, time: float | None = None
) -> Figure:
    """Film pressure p(a, z) [MPa] of finite journal bearings at one instant.

    The film unwrapped: the film angle a [deg] counter-clockwise from the line of centres
    (bearing centre to journal centre), so the thinnest film is at 0 and the inlet, where
    the solver holds p = 0, at +-180; across it the axial position z [mm] over the whole
    width; the angle axis is linear over the pressure peak and logarithmic beyond. Above,
    the film thickness h(a) = c (1 - eps cos a) [µm] the Reynolds equation saw (with
    asperities touching, its thinnest is the rough surfaces' mean gap), with the roughness
    sigma and 3 sigma. The cavitated region (p = 0, Reynolds condition) is hatched. The
    pressure is the one the run's film force came from (``film_field``); the title gives
    the instant, the film's eccentricity ratio, thinnest film, the force the pressure
    integrates to and the peak pressure, then the row's lambda (-delta / sigma) and the
    load the asperities carry.

    Parameters
    ----------
    results
        A run with finite journal bearings (``lubrication = "finite_bearing"``).
    joint
        The joint; None: each finite bearing, a row each.
    time
        The instant [s] (the nearest output row); None: each joint's row of largest film
        force, in the steady state if the run has one.

    Raises
    ------
    ValueError
        If the run has no finite bearing (the short and long bearings have no figure: their
        closed forms are limits with the half-Sommerfeld film, not a solved field), or
        ``joint`` is not one, or ``time`` is outside the run.
    """
    names = (joint,) if joint is not None else finite_bearings(results)
    if not names:
        raise ValueError(
            f"model '{results.model.name}' has no finite journal bearing "
            '(lubrication = "finite_bearing"), whose film pressure this figure shows'
        )
    fields = [film_field(results, name, time) for name in names]
    fig = Figure(figsize=(10.0, 6.4 * len(fields) + 0.4), layout="constrained")
    rows = fig.subfigures(len(fields), 1, squeeze=False)[:, 0]
    for sub, field in zip(rows, fields, strict=True):
        _draw(sub, results, field, peak=time is None)
    fig.suptitle(f"{results.model.name}: film pressure of the finite journal bearing")
    return fig


def _draw(sub: SubFigure, results: Results, field: FilmField, peak: bool) -> None:
    """One joint's thickness panel, pressure map and title into ``sub``."""
    joint = results.model.joint(field.joint)
    c = joint.clearance
    top, ax = sub.subplots(2, 1, sharex=True, height_ratios=(1.0, 3.2))
    a = np.degrees(field.angle_faces)
    centres = 0.5 * (field.angle_faces[:-1] + field.angle_faces[1:])
    z = field.axial_faces * MM
    z_centres = 0.5 * (z[:-1] + z[1:])
    # the edges, where p = 0 (the inlet at +-180 deg, the bearing's ends), close the map
    x = np.concatenate([[-180.0], np.degrees(centres), [180.0]])
    y = np.concatenate([[z[0]], z_centres, [z[-1]]])
    p = np.pad(field.pressure * MPA, 1)
    peak_p = float(p.max())
    if peak_p > 0.0:
        ticks = MaxNLocator(LEVELS).tick_values(0.0, peak_p)
        levels = np.concatenate([[UNFILLED * peak_p], ticks[1:]])
        bands = ax.contourf(x, y, p.T, levels=levels, cmap="viridis")
        bar = sub.colorbar(bands, ax=ax, location="bottom", shrink=0.7, aspect=40, pad=0.02)
        bar.set_ticks(ticks[1:])
        bar.set_label("film pressure p [MPa]")
        i, k = np.unravel_index(np.argmax(p), p.shape)
        ax.plot(x[i], y[k], "o", ms=6, mfc="w", mec="k")
        ax.annotate(f"peak {peak_p:.3g} MPa", (x[i], y[k]), xytext=(8, 8),
                    textcoords="offset points", fontsize="small",
                    bbox={"boxstyle": "round", "fc": "w", "ec": "0.6"})  # fmt: skip
    if field.cavitated.any():
        mask = np.pad(field.cavitated.astype(float), 1, mode="edge")
        ax.contourf(x, y, mask.T, levels=(0.5, 1.5), colors="none", hatches=("///",))
        ax.contour(x, y, mask.T, levels=(0.5,), colors=CAVITATED, linewidths=0.8)
    ax.axvline(0.0, color="k", ls="--", lw=0.9)
    _angle_axis(ax, field.eps)
    ax.set_ylim(z[0], z[-1])
    ax.set_ylabel("axial position z [mm]")
    ax.lines[-1].set_label("thinnest film")
    handles = [
        *([Patch(fc="w", ec=CAVITATED, hatch="///", label="cavitated, p = 0")]
          if field.cavitated.any() else []),
        *([Patch(fc="w", ec=CAVITATED, label=f"p < {UNFILLED * peak_p:.2g} MPa")]
          if peak_p > 0.0 else []),
        ax.lines[-1],
    ]  # fmt: skip
    ax.legend(handles=handles, loc="lower left", fontsize="small", framealpha=0.9)
    _thickness(top, field, c.roughness, a)
    sub.suptitle(_title(results, field, peak, joint), fontsize="medium")


def _angle_axis(ax: Axes, eps: float) -> None:
    """The film angle axis [deg]: linear about the thinnest film, logarithmic beyond (asinh).

    The pressure peak is about sqrt(1 - eps) rad wide (``film.reynolds``): at eps = 0.99
    a few degrees of the 360 on a linear axis.
    """
    width = min(180.0, math.degrees(PEAK_WIDTHS * math.sqrt(1.0 - eps)))
    ax.set_xscale("asinh", linear_width=width)
    ax.set_xlim(-180.0, 180.0)
    side = [t for t in ANGLE_TICKS if t >= 0.4 * width or t == ANGLE_TICKS[-1]]
    ticks = [-t for t in side[::-1]] + [0] + side
    ax.set_xticks(ticks, [f"{t:g}".replace("-", "\N{MINUS SIGN}") for t in ticks])
    ax.xaxis.set_minor_locator(NullLocator())
    ax.set_xlabel(
        "film angle a from the line of centres [deg], counter-clockwise "
        f"(linear within ±{width:.2g}°, logarithmic beyond)"
    )


def _thickness(ax: Axes, field: FilmField, roughness: float, a: np.ndarray) -> None:
    """The film thickness h(a) = c (1 - eps cos a) [µm], log scale, with sigma and 3 sigma."""
    angle = np.linspace(-180.0, 180.0, 721)
    h = field.clearance * (1.0 - field.eps * np.cos(np.radians(angle)))
    ax.semilogy(angle, h * UM, color="tab:blue", lw=1.3)
    for share in ROUGHNESS_LINES:
        level = share * roughness * UM
        ax.axhline(level, color="0.5", ls=":", lw=0.9)
        name = "σ" if share == 1.0 else f"{share:g} σ"
        ax.text(178.0, level, f" {name}", va="bottom", ha="right", fontsize="x-small", color="0.4")
    ax.axvline(0.0, color="k", ls="--", lw=0.9)
    ax.set_ylabel("film h [µm]")
    ax.yaxis.set_major_locator(LogLocator(numticks=10))
    ax.grid(alpha=0.3, which="both")
    ax.set_ylim(bottom=min(0.5 * roughness, 0.5 * field.film_min) * UM)
    ax.annotate(f"thinnest {field.film_min * UM:.3g} µm", (0.0, field.film_min * UM),
                xytext=(6, 2), textcoords="offset points", fontsize="small")  # fmt: skip


def _title(results: Results, field: FilmField, peak: bool, joint: object) -> str:
    """Which joint and instant, and the field's figures."""
    ts = results.timeseries
    row = ts.iloc[int(np.argmin(np.abs(ts["time"].to_numpy() - field.time)))]
    theta = math.degrees(row[f"{field.joint}_theta_bearing"]) % 360.0
    which = ", the largest film force" + (
        " of the steady state" if (results.summary.get("steady_state") or {}).get("from_s")
        is not None else " of the run"
    ) if peak else ""  # fmt: skip
    force = math.hypot(*field.force)
    return (
        f"{field.joint}: journal ({joint.bodies[1]}) in bearing ({joint.bodies[0]}) at "
        f"t = {field.time * 1e3:.4g} ms{which}\n"
        f"film: ε = {field.eps:.4f}, thinnest {field.film_min * UM:.3g} µm, force "
        f"{force / 1e3:.3g} kN, peak pressure {field.pressure.max() * MPA:.3g} MPa\n"
        f"surfaces: λ = {row[f'{field.joint}_lambda']:.3g}, asperity load "
        f"{row[f'{field.joint}_asperity_fn']:.3g} N; line of centres at {theta:.0f}° "
        f"in the {joint.bodies[0]} frame"
    )
