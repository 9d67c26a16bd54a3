"""The Stribeck curve of a sweep: a lubricated joint's friction coefficient against Hersey's.

From the sweep table's film columns of each case (``<joint>.film.friction_coefficient``,
``<joint>.film.hersey_number`` mu N / P, ``<joint>.film.min_lambda``,
``<joint>.film.asperity_load_share``; ``joints.revolute`` ``_film_summary``). The points are
coloured by the lubrication regime their thinnest film puts them in, lambda = h_min / sigma:
boundary below 1, mixed from 1 to 3, hydrodynamic (full film) above 3, the customary bounds
of the film parameter (Hamrock, Schmid and Jacobson 2004, ch. 1), and the Hersey axis is
shaded by regime between the cases. Without lambda (no roughness) they are coloured by the
asperities' share of the load. Figures without pyplot.

References
----------
B.J. Hamrock, S.R. Schmid, B.O. Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed.,
Marcel Dekker (2004).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

MIN_CASES = 3  # a curve needs this many cases with a finite coefficient and Hersey number
MAX_NOTES = 12  # more cases than this: the points are not labelled with their values
REGIMES = (  # upper bound of lambda_min, name, colour
    (1.0, "boundary, λ < 1", "tab:red"),
    (3.0, "mixed, 1 ≤ λ < 3", "tab:orange"),
    (math.inf, "hydrodynamic, λ ≥ 3", "tab:blue"),
)
FILM = "film"  # the summary's table of a lubricated joint, a prefix of the columns


def _column(joint: str, key: str) -> str:
    return f"{joint}.{FILM}.{key}"


def _cases(table: pd.DataFrame, joint: str) -> pd.DataFrame:
    """The rows of ``joint`` with a finite friction coefficient and a positive Hersey number."""
    needed = [_column(joint, "friction_coefficient"), _column(joint, "hersey_number")]
    if not set(needed) <= set(table.columns):
        return table.iloc[:0]
    values = table[needed].apply(pd.to_numeric, errors="coerce")
    rows = np.isfinite(values).all(axis=1) & (values[needed[1]] > 0.0)
    return table[rows]


def stribeck_joints(table: pd.DataFrame, joints: Sequence[str]) -> list[str]:
    """The ``joints`` whose film columns in ``table`` give a curve (``MIN_CASES`` cases)."""
    return [joint for joint in joints if len(_cases(table, joint)) >= MIN_CASES]


def regime(lam: float) -> int:
    """The index in ``REGIMES`` of a film parameter lambda_min [-]."""
    return next(i for i, (upper, _, _) in enumerate(REGIMES) if lam < upper)


def plot_stribeck(
    table: pd.DataFrame,
    joints: Sequence[str],
    notes: Mapping[object, str] | None = None,
    varied: str | None = None,
) -> Figure:
    """Friction coefficient against the Hersey number mu N / P (log), a panel per joint.

    Parameters
    ----------
    table
        The sweep table, a row per case (``studies.sweep``).
    joints
        Lubricated joints with a curve (``stribeck_joints``).
    notes, varied
        The table's column ``varied`` (a varied path) and the text of each of its values
        (0.01 -> "0.01 Pa*s"): each point is labelled with its case's and its lambda_min,
        for up to ``MAX_NOTES`` cases; none: no labels.
    """
    fig = Figure(figsize=(8.5, 4.6 * len(joints) + 0.6), layout="constrained")
    axes = fig.subplots(len(joints), 1, squeeze=False)[:, 0]
    for ax, joint in zip(axes, joints, strict=True):
        cases = _cases(table, joint)
        cases = cases.iloc[np.argsort(cases[_column(joint, "hersey_number")].to_numpy(float))]
        x = cases[_column(joint, "hersey_number")].to_numpy(float)
        y = cases[_column(joint, "friction_coefficient")].to_numpy(float)
        ax.plot(x, y, color="0.5", lw=0.9, zorder=1)
        lam = _values(cases, _column(joint, "min_lambda"))
        if np.isfinite(lam).all():
            _by_regime(ax, x, y, lam)
        else:
            _by_share(fig, ax, x, y, _values(cases, _column(joint, "asperity_load_share")))
        if notes is not None and varied is not None and len(cases) <= MAX_NOTES:
            for xi, yi, value, film in zip(x, y, cases[varied], lam, strict=True):
                text = notes.get(value, f"{value}")
                text += f", λ {film:.2g}" if np.isfinite(film) else ""
                ax.annotate(text, (xi, yi), xytext=(5, 5), textcoords="offset points",
                            fontsize="x-small")  # fmt: skip
        ax.set_xscale("log")
        if y.min() > 0.0 and y.max() > 10.0 * y.min():
            ax.set_yscale("log")
        ax.set_ylabel("friction coefficient f [-]")
        ax.set_title(joint, fontsize="medium")
        ax.grid(alpha=0.3, which="both")
    axes[-1].set_xlabel("Hersey number μN/P [-] (N relative speed [rev/s], P load / (L 2 R_J))")
    fig.suptitle("Stribeck curve: friction coefficient against the Hersey number")
    return fig


def _by_regime(ax: Axes, x: np.ndarray, y: np.ndarray, lam: np.ndarray) -> None:
    """Points coloured by their regime, the Hersey axis shaded by it between the cases."""
    kinds = [regime(value) for value in lam]
    colours = [REGIMES[k][2] for k in kinds]
    ax.scatter(x, y, c=colours, s=45, edgecolors="k", linewidths=0.6, zorder=3)
    # each case's span reaches half-way (geometrically) to its neighbours
    edges = np.concatenate([[x[0] / 3.0], np.sqrt(x[:-1] * x[1:]), [x[-1] * 3.0]])
    for k, left, right in zip(kinds, edges[:-1], edges[1:], strict=True):
        ax.axvspan(left, right, color=REGIMES[k][2], alpha=0.12, lw=0.0, zorder=0)
    ax.set_xlim(edges[0], edges[-1])
    shown = sorted(set(kinds))
    handles = [
        Line2D([], [], ls="", marker="o", mfc=REGIMES[k][2], mec="k", label=REGIMES[k][1])
        for k in shown
    ]
    ax.legend(handles=handles, title="thinnest film λ = h_min/σ", fontsize="small",
              title_fontsize="small", loc="best")  # fmt: skip


def _values(table: pd.DataFrame, column: str) -> np.ndarray:
    """A column's numbers, NaN where there is none (or no such column)."""
    if column not in table.columns:
        return np.full(len(table), np.nan)
    return pd.to_numeric(table[column], errors="coerce").to_numpy(float)


def _by_share(fig: Figure, ax: Axes, x: np.ndarray, y: np.ndarray, share: np.ndarray) -> None:
    """Points coloured by the asperities' share of the load [%] (grey where unknown)."""
    values = share * 100.0
    top = max(np.nanmax(values, initial=0.0), 1.0)
    points = ax.scatter(x, y, c=values, cmap="viridis", vmin=0.0, vmax=top, s=45,
                        edgecolors="k", linewidths=0.6, zorder=3)  # fmt: skip
    fig.colorbar(points, ax=ax, label="asperity load share [%]")
