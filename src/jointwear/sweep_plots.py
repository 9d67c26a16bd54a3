"""Comparison figures of a sweep: one headline figure against the first varied value.

One PNG per headline column of the sweep table (``<joint>.<key>``), with one line per
combination of the other varied values. Figures without pyplot, as in ``plots``.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

LOG_AXIS_RATIO = 100.0  # positive values spanning more than this get a logarithmic axis
MAX_LEGEND = 12  # more lines than this: no legend (the table tells them apart)


def plot_sweep(table: pd.DataFrame, column: str, varied: Sequence[str]) -> Figure:
    """Plot ``column`` of the sweep table against the first varied path.

    Parameters
    ----------
    table
        The sweep table: one row per case, a column per varied path (SI values).
    column
        The headline figure to plot, e.g. ``coupler_follower.max_wear_depth_journal_m``.
    varied
        The varied paths; the first is the x axis, the others make one line each.
    """
    x_path, others = varied[0], list(varied[1:])
    numeric_x = pd.api.types.is_numeric_dtype(table[x_path])
    categories = list(dict.fromkeys(table[x_path]))
    fig = Figure(figsize=(7.0, 4.5), layout="constrained")
    ax = fig.subplots()
    groups = table.groupby(others, sort=False, dropna=False) if others else [((), table)]
    lines = 0
    for key, rows in groups:
        x = rows[x_path].to_numpy() if numeric_x else rows[x_path].map(categories.index).to_numpy()
        y = pd.to_numeric(rows[column], errors="coerce").to_numpy(dtype=float)
        order = np.argsort(x, kind="stable")
        values = key if isinstance(key, tuple) else (key,)
        pairs = zip(others, values, strict=True)
        label = ", ".join(f"{path.rsplit('.', 1)[-1]} = {v}" for path, v in pairs)
        ax.plot(x[order], y[order], marker="o", label=label or None)
        lines += 1
    if numeric_x:
        values = table[x_path].to_numpy(dtype=float)
        if np.all(values > 0) and values.max() > LOG_AXIS_RATIO * values.min():
            ax.set_xscale("log")
    else:
        ax.set_xticks(range(len(categories)), [str(c) for c in categories])
    if others and lines <= MAX_LEGEND:
        ax.legend(loc="best", fontsize="small")
    ax.set_xlabel(x_path)
    ax.set_ylabel(column.rsplit(".", 1)[-1])
    ax.grid(alpha=0.3)
    fig.suptitle(column)
    return fig


def save_sweep_figures(
    table: pd.DataFrame, columns: Sequence[str], varied: Sequence[str], folder: str | Path
) -> list[Path]:
    """Write one figure per headline column that has a value; return the paths.

    PNGs in ``folder`` from an earlier sweep that are not drawn again are removed.
    """
    path = Path(folder)
    path.mkdir(parents=True, exist_ok=True)
    written = []
    for column in columns:
        if pd.to_numeric(table[column], errors="coerce").notna().any():
            file = path / f"{re.sub(r'[^A-Za-z0-9._-]+', '_', column)}.png"
            plot_sweep(table, column, varied).savefig(file, dpi=120)
            written.append(file)
    for stale in set(path.glob("*.png")) - set(written):
        stale.unlink()
    return written
