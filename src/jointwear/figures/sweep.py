"""Comparison figures of a sweep: one headline figure against the first varied value.

One PNG per headline column of the sweep table (``<joint>.<key>``), with one line per
combination of the other varied values. Figures without pyplot, as in ``plots``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from contextlib import suppress
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from ..io import ForeignFileError, remove
from .files import save_png
from .legends import LEGEND_ROOM, legend_beside

LOG_AXIS_RATIO = 100.0  # positive values spanning more than this get a logarithmic axis
LONG_LENGTH = (1e-3, "m", 1.0)  # lengths in a column reaching this [m] are drawn in metres
MAX_TICKS = 12  # more numeric values than this: ticks of the axis, not one per value
MAX_LEGEND = 12  # more lines than this: no legend (the table tells them apart)
DISPLAY_UNITS = (  # column suffix (SI), axis unit, factor from SI; the first match counts
    ("_m3", "mm³", 1e9),
    ("_m_per_cycle", "nm/cycle", 1e9),
    ("_n_m", "N m", 1.0),
    ("_m", "µm", 1e6),  # wear depths, penetrations, clearances; see LONG_LENGTH
    ("_n", "kN", 1e-3),
    ("_j", "J", 1.0),
    ("_deg", "deg", 1.0),
    ("_fraction", "%", 100.0),
    ("_s", "s", 1.0),
)


def plot_sweep(
    table: pd.DataFrame, column: str, texts: Mapping[str, Mapping[object, str]]
) -> Figure:
    """Plot ``column`` of the sweep table against the first varied path.

    Parameters
    ----------
    table
        The sweep table: one row per case, a column per varied path (SI values).
    column
        The headline figure to plot, e.g. ``coupler_follower.max_wear_depth_journal_m``.
    texts
        Per varied path, in order, each of its table values as the sweep was given it (e.g.
        0.0099 -> "9.9 mm"), for ticks and legend. The first path is the x axis; each
        combination of the others makes a line.
    """
    x_path, *others = texts
    numeric_x = pd.api.types.is_numeric_dtype(table[x_path])
    categories = list(dict.fromkeys(table[x_path]))
    label, factor = quantity(column, pd.to_numeric(table[column], errors="coerce").abs().max())
    groups = table.groupby(others, sort=False, dropna=False) if others else [((), table)]
    legend = bool(others) and len(groups) <= MAX_LEGEND
    fig = Figure(figsize=(7.0 + LEGEND_ROOM * legend, 4.5), layout="constrained")
    ax = fig.subplots()
    for key, rows in groups:
        x = rows[x_path].to_numpy() if numeric_x else rows[x_path].map(categories.index).to_numpy()
        y = pd.to_numeric(rows[column], errors="coerce").to_numpy(dtype=float) * factor
        order = np.argsort(x, kind="stable")
        values = key if isinstance(key, tuple) else (key,)
        pairs = zip(others, values, strict=True)
        line = ", ".join(f"{_name(path)} {texts[path].get(v, v)}" for path, v in pairs)
        ax.plot(x[order], y[order], marker="o", label=line or None)
    if numeric_x:
        values = table[x_path].to_numpy(dtype=float)
        if np.all(values > 0) and values.max() > LOG_AXIS_RATIO * values.min():
            ax.set_xscale("log")
            ax.minorticks_off()
        if len(categories) <= MAX_TICKS:  # else the axis's own ticks, which do not overlap
            ax.set_xticks(categories, [texts[x_path].get(c, str(c)) for c in categories])
    else:
        ax.set_xticks(range(len(categories)), [texts[x_path].get(c, str(c)) for c in categories])
    if legend:
        legend_beside(ax)
    ax.set_xlabel(f"{_name(x_path)}  ({x_path})")
    ax.set_ylabel(label)
    ax.grid(alpha=0.3)
    joint = column.rpartition(".")[0]
    words = label.partition(" [")[0]
    fig.suptitle(f"{joint}: {words}" if joint else words)
    return fig


def quantity(column: str, largest: float = 0.0) -> tuple[str, float]:
    """Axis label and factor from SI for a table column, by its unit suffix.

    ``coupler_follower.max_wear_depth_journal_m`` -> ("max wear depth journal [µm]", 1e6);
    lengths whose ``largest`` value [m] reaches a millimetre (a sliding distance) in metres.
    """
    key = column.rpartition(".")[2]
    for suffix, unit, factor in DISPLAY_UNITS:
        if key.endswith(suffix):
            if suffix == "_m" and largest >= LONG_LENGTH[0]:
                unit, factor = LONG_LENGTH[1:]
            return f"{key.removesuffix(suffix).replace('_', ' ')} [{unit}]", factor
    return key.replace("_", " "), 1.0


def _name(path: str) -> str:
    """The last part of a dotted path in words (``a.b_c``: b c)."""
    return path.rpartition(".")[2].replace("_", " ")


def save_sweep_figures(
    table: pd.DataFrame,
    columns: Sequence[str],
    texts: Mapping[str, Mapping[object, str]],
    folder: str | Path,
) -> list[Path]:
    """Write one figure per headline column whose value changes between cases; return paths.

    ``texts`` as for ``plot_sweep``. PNGs that an earlier sweep wrote in ``folder`` and that
    are not drawn again are removed (only jointwear's own files, ``jointwear.io.remove``).
    """
    path = Path(folder)
    written = []
    for column in columns:
        if pd.to_numeric(table[column], errors="coerce").dropna().nunique() > 1:
            file = path / f"{re.sub(r'[^A-Za-z0-9._-]+', '_', column)}.png"
            with suppress(ForeignFileError):  # a file of the user's of that name is kept
                written.append(save_png(plot_sweep(table, column, texts), file, dpi=120))
    for stale in set(path.glob("*.png")) - set(written):
        remove(stale)
    return written
