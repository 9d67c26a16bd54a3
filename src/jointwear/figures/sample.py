"""Figures of a sampled study: how the results spread, what drives them, whether n was enough.

Drawn for the key outputs (the life, the forces, the deeper wear of each joint and the drive
torque a design is judged by, ``KEY_OUTPUTS``) that vary between cases:

- ``distributions.png``: a histogram of each output, its empirical distribution function
  over it, and P5, P50 and P95 marked with their confidence intervals shaded;
- ``scatter.png``: each key output against each input, Spearman's rho in the corner;
- ``sensitivity.png``: per output, each input's Sobol' indices (first order and total) or
  rank correlations (Spearman's and the partial one), with their intervals;
- ``convergence.png``: the mean and P95 of the first k cases against k, with the final
  interval: a curve still drifting at the right end says more cases are needed.

Values are shown in the units a designer reads (kN, µm, N m; ``figures.sweep.quantity``), the
inputs in the unit their distribution was given in. Figures without pyplot.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from ..units import unit_of
from .files import save_png
from .sweep import quantity

WEAR_DEPTH = r"max_wear_depth_[a-z_]+_m"
KEY_OUTPUTS = (  # column keys (regular expressions) of the outputs drawn, in this order
    r"hours_to_clearance_growth_50pct",  # a life run's: the mechanism's, then each joint's
    r"max_contact_force_n",
    WEAR_DEPTH,
    r"torque_range_n_m",
    r"force_range_n",
    r"clearance_growth_m",
)
MAX_OUTPUTS = 12  # key outputs drawn at most (the statistics cover all)
MAX_INPUTS = 8  # inputs in the scatter figure at most (the most influential)
PANEL = (3.6, 2.7)  # [in] one panel
MARKS = {"p5": ("P5", "tab:blue"), "p50": ("P50", "black"), "p95": ("P95", "tab:red")}


def owner(column: str) -> str:
    """The joint or driver an output is of, ``mechanism`` for a life run's own figures."""
    return column.partition(".")[0] if "." in column else "mechanism"


def key_outputs(stats: pd.DataFrame) -> list[str]:
    """The outputs drawn: those of ``KEY_OUTPUTS`` with a spread, in its order.

    Of a joint's wear depths (bearing and journal), the deeper on average only.
    """
    spread = stats[(stats["std"] > 0) & (stats["n"] > 1)].set_index("output")["mean"]
    chosen = []
    for key in KEY_OUTPUTS:
        found = [c for c in spread.index if re.fullmatch(key, c.rpartition(".")[2])]
        found.sort(key=lambda column: "." in column)  # the mechanism's before its joints'
        if key == WEAR_DEPTH:
            deepest = {}
            for column in found:
                joint = column.partition(".")[0]
                if joint not in deepest or spread[column] > spread[deepest[joint]]:
                    deepest[joint] = column
            found = list(deepest.values())
        chosen += found
    return chosen[:MAX_OUTPUTS]


def save_sample_figures(
    table: pd.DataFrame,
    labels: Mapping[str, str],
    units: Mapping[str, str | None],
    stats: pd.DataFrame,
    sensitivity: pd.DataFrame,
    folder: Path,
) -> list[Path]:
    """Write the study's figures into ``folder``; return their paths.

    ``table`` holds the cases to draw (a study's independent, complete ones); ``labels``
    names each input (its dotted path: a short name), ``units`` the unit each input's
    distribution was given in (None: a plain number); ``sensitivity`` has an ``effect``
    column that ranks the inputs.
    """
    drawn = key_outputs(stats)
    if not drawn:
        return []
    rows = stats.set_index("output")
    written = [
        save_png(plot_distributions(table, drawn, rows), folder / "distributions.png"),
        save_png(plot_convergence(table, drawn, rows), folder / "convergence.png"),
    ]
    shown = _influential(sensitivity, list(labels), drawn)
    if shown:
        figure = plot_scatter(table, {p: labels[p] for p in shown}, units, drawn, sensitivity)
        written.append(save_png(figure, folder / "scatter.png"))
    if len(sensitivity):
        figure = plot_sensitivity(sensitivity, labels, drawn)
        written.append(save_png(figure, folder / "sensitivity.png"))
    return written


def _grid(count: int, columns: int = 3) -> tuple[Figure, list[Axes]]:
    across = min(count, columns)
    down = math.ceil(count / across)
    figure = Figure(figsize=(PANEL[0] * across, PANEL[1] * down), layout="constrained")
    axes = figure.subplots(down, across, squeeze=False).ravel()
    for ax in axes[count:]:
        ax.set_visible(False)
    return figure, list(axes[:count])


def _values(table: pd.DataFrame, column: str) -> tuple[np.ndarray, str, float]:
    """Finite values of a column in display units, the axis label and the factor."""
    values = pd.to_numeric(table[column], errors="coerce").to_numpy(dtype=float)
    values = values[np.isfinite(values)]
    label, factor = quantity(column, float(np.abs(values).max(initial=0.0)))
    return values * factor, label, factor


def _title(ax: Axes, column: str) -> None:
    ax.set_title(owner(column), fontsize=9, loc="left")


def plot_distributions(table: pd.DataFrame, outputs: Sequence[str], stats: pd.DataFrame) -> Figure:
    """A histogram and ECDF of each output, P5/P50/P95 marked with their intervals."""
    figure, axes = _grid(len(outputs))
    for ax, column in zip(axes, outputs, strict=True):
        values, label, factor = _values(table, column)
        ax.hist(values, bins=min(30, max(5, len(values) // 4)), color="0.8", density=True)
        ecdf = ax.twinx()
        ecdf.ecdf(values, color="0.3", linewidth=1.0)
        ecdf.set_ylim(0, 1)
        ecdf.set_ylabel("share of cases ≤ x", fontsize=8)
        for key, (name, colour) in MARKS.items():
            row = stats.loc[column]
            ax.axvline(row[key] * factor, color=colour, linestyle="--", linewidth=1.0,
                       label=f"{name} {row[key] * factor:.4g}")  # fmt: skip
            if np.isfinite(row[f"{key}_low"]):
                ax.axvspan(row[f"{key}_low"] * factor, row[f"{key}_high"] * factor,
                           color=colour, alpha=0.12, linewidth=0)  # fmt: skip
        ax.set_xlabel(label)
        ax.set_yticks([])
        ax.legend(fontsize=7, loc="upper left", framealpha=0.8)
        _title(ax, column)
    figure.suptitle("distribution of each output (shaded: 95 % intervals)", fontsize=10)
    return figure


def plot_convergence(table: pd.DataFrame, outputs: Sequence[str], stats: pd.DataFrame) -> Figure:
    """The mean and P95 of the first k cases against k, each with its final interval."""
    figure, axes = _grid(len(outputs))
    for ax, column in zip(axes, outputs, strict=True):
        values, label, factor = _values(table, column)
        path = running(values)
        row = stats.loc[column]
        for key, name, colour in (("mean", "mean", "black"), ("p95", "P95", "tab:red")):
            ax.plot(path["cases"], path[key], color=colour, linewidth=1.2, label=name)
            if np.isfinite(row[f"{key}_low"]):
                ax.axhspan(row[f"{key}_low"] * factor, row[f"{key}_high"] * factor,
                           color=colour, alpha=0.12, linewidth=0)  # fmt: skip
        ax.set_xlabel("cases")
        ax.set_ylabel(label)
        ax.legend(fontsize=7)
        _title(ax, column)
    figure.suptitle("estimate against the number of cases (shaded: final 95 % interval)",
                    fontsize=10)  # fmt: skip
    return figure


def running(values: Sequence[float]) -> pd.DataFrame:
    """The mean and P95 of the first k cases, for k = 1 to n (finite values in case order)."""
    x = np.asarray(values, dtype=float)
    x = x[np.isfinite(x)]
    count = np.arange(1, len(x) + 1)
    p95 = [np.quantile(x[:k], 0.95) for k in count]
    return pd.DataFrame({"cases": count, "mean": np.cumsum(x) / count, "p95": p95})


def _influential(sensitivity: pd.DataFrame, inputs: Sequence[str], outputs: Sequence[str]):
    """The inputs by their largest effect on the drawn outputs, at most ``MAX_INPUTS``."""
    rows = sensitivity[sensitivity["output"].isin(outputs)]
    largest = rows["effect"].groupby(rows["input"]).max()
    ranked = sorted(inputs, key=lambda name: -largest.get(name, 0.0))
    return ranked[:MAX_INPUTS]


def _input_axis(table: pd.DataFrame, path: str, label: str, unit: str | None) -> tuple:
    """An input's values in the unit of its distribution, and its axis label."""
    values = pd.to_numeric(table[path], errors="coerce").to_numpy(dtype=float)
    size = unit_of(f"1 {unit}") if unit else None
    if size is None:
        return values, label
    return values / size[1], f"{label} [{unit}]"


def plot_scatter(
    table: pd.DataFrame,
    labels: Mapping[str, str],
    units: Mapping[str, str | None],
    outputs: Sequence[str],
    sensitivity: pd.DataFrame,
) -> Figure:
    """Each output (rows) against each input (columns, ``labels``), with its rank correlation."""
    inputs = list(labels)
    figure = Figure(figsize=(2.6 * len(inputs), 2.2 * len(outputs)), layout="constrained")
    axes = figure.subplots(len(outputs), len(inputs), squeeze=False)
    rho = sensitivity.set_index(["output", "input"])["rho"] if "rho" in sensitivity else None
    for i, column in enumerate(outputs):
        y = pd.to_numeric(table[column], errors="coerce").to_numpy(dtype=float)
        label, factor = quantity(column, float(np.nanmax(np.abs(y), initial=0.0)))
        for j, path in enumerate(inputs):
            ax = axes[i, j]
            x, xlabel = _input_axis(table, path, labels[path], units.get(path))
            ax.scatter(x, y * factor, s=6, alpha=0.6, color="tab:blue", linewidths=0)
            if rho is not None and (column, path) in rho.index:
                ax.text(0.03, 0.93, f"ρ = {rho[(column, path)]:.2f}", transform=ax.transAxes,
                        fontsize=7, va="top")  # fmt: skip
            if i == len(outputs) - 1:
                ax.set_xlabel(xlabel, fontsize=8)
            if j == 0:
                ax.set_ylabel(f"{owner(column)}\n{label}", fontsize=8)
            ax.tick_params(labelsize=7)
    return figure


def plot_sensitivity(
    sensitivity: pd.DataFrame, labels: Mapping[str, str], outputs: Sequence[str]
) -> Figure:
    """Per output, a bar per input: Sobol' S1 and ST, or Spearman's rho, with intervals.

    The ``MAX_INPUTS`` strongest inputs of each output, the strongest on top.
    """
    shown = [o for o in outputs if o in set(sensitivity["output"])]
    sobol = "ST" in sensitivity
    height = 0.3 * min(MAX_INPUTS, sensitivity["input"].nunique()) + 1.0
    down = math.ceil(len(shown) / 2)
    across = min(len(shown), 2)
    figure = Figure(figsize=(5.2 * across, height * down + 0.5), layout="constrained")
    axes = list(figure.subplots(down, across, squeeze=False).ravel())
    for ax in axes[len(shown) :]:
        ax.set_visible(False)
    if sobol:
        keys = (("S1", "first order S1", -0.2), ("ST", "total ST", 0.2))
    elif sensitivity["prcc"].notna().any():
        keys = (("rho", "Spearman's ρ", -0.2), ("prcc", "partial (PRCC)", 0.2))
    else:
        keys = (("rho", "Spearman's ρ", 0.0),)
    for number, (ax, column) in enumerate(zip(axes, shown, strict=False)):
        rows = sensitivity[sensitivity["output"] == column]
        rows = rows.sort_values("effect")[-MAX_INPUTS:]
        place = np.arange(len(rows))
        for key, name, shift in keys:
            low = (rows[key] - rows[f"{key}_low"]).clip(lower=0)
            high = (rows[f"{key}_high"] - rows[key]).clip(lower=0)
            ax.barh(place + shift, rows[key], height=0.6 / len(keys), label=name,
                    xerr=[low, high], capsize=2, error_kw={"linewidth": 0.8})  # fmt: skip
        ax.set_yticks(place, [labels[path] for path in rows["input"]], fontsize=7)
        ax.axvline(0, color="0.5", linewidth=0.8)
        ax.set_xlim(-0.05 if sobol else -1.0, 1.05 if sobol else 1.0)
        ax.set_xlabel("Sobol' index" if sobol else "rank correlation", fontsize=8)
        ax.set_title(f"{owner(column)}: {quantity(column)[0]}", fontsize=9, loc="left")
        if len(keys) > 1 and number == 0:
            ax.legend(fontsize=7, loc="lower right")
    more = sensitivity["input"].nunique() > MAX_INPUTS
    shown_inputs = f" (the {MAX_INPUTS} strongest inputs of each)" if more else ""
    figure.suptitle(f"sensitivity of each output{shown_inputs}; bars: 95 % intervals",
                    fontsize=10)  # fmt: skip
    return figure
