"""Comparison figures of a sweep: each headline figure of merit against the varied values.

One PNG per figure of merit, with a panel per clearance joint (and per surface for the wear
depth), drawn when the table has its columns and they change between cases:

- ``max_contact_force.png``: the largest contact force, the load the clearance adds;
- ``max_wear_depth.png``: the deepest wear of each surface, what the clearance grows by;
- ``worn_volume.png``: the material worn away in all;
- ``contact_time.png``: the share of the time in contact (free flight and impacts against
  continuous contact);
- ``clearance_growth.png`` and ``wear_life.png`` (long-life runs, ``--cycles``): the growth
  of the clearance, and the cycles until it has grown by half;
- ``friction_coefficient.png`` and ``asperity_load_share.png`` (lubricated joints): the
  friction the joint's load meets, and the share of the load its surfaces carry where the
  film is too thin;
- ``stribeck.png`` (lubricated joints, 3 cases or more): the Stribeck curve, friction
  coefficient against the Hersey number (``figures.stribeck``).

These are what Flores (2009) judges a clearance joint by: the forces it causes and the wear
they cause. The rest of the summary stays in the table: the penetration follows the force,
the friction energy the friction coefficient, and the diagnostics (law ranges, wear angles,
the whole run with its start-up) are not comparisons of designs.

The x axis is the first varied path, in the unit its values were given in (mm for
"0.1 mm"). Cases on a grid (every combination of the varied values) are drawn as lines, one
per combination of the other varied values. Other designs (linked paths, a random design)
are drawn as points, coloured by the second varied path: each case appears once per panel
and the colour shows how the two act together, which a panel per path, each blind to the
other, would not. Further varied paths are in the table. Figures without pyplot.
"""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Mapping, Sequence
from contextlib import suppress
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.axes import Axes
from matplotlib.axis import Axis
from matplotlib.collections import PathCollection
from matplotlib.colors import LogNorm, Normalize
from matplotlib.figure import Figure
from matplotlib.ticker import (
    AutoLocator,
    FuncFormatter,
    LogLocator,
    NullFormatter,
    NullLocator,
    ScalarFormatter,
)

from ..io import ForeignFileError, remove
from ..model.overrides import toml_value
from ..units import unit_of
from .files import save_png
from .legends import LEGEND_ROOM
from .stribeck import plot_stribeck, stribeck_joints

LOG_AXIS_RATIO = 10.0  # positive values spanning more than a decade get a logarithmic axis
LONG_LENGTH = (1e-3, "m", 1.0)  # lengths in a column reaching this [m] are drawn in metres
SAME = 1e-9  # values differing by less than this share of the largest are the same
MAX_VALUE_TICKS = 8  # numeric values up to this many get a tick each, if their labels fit
COLOUR_BAR_ROOM = 1.2  # [in] figures with a colour bar are this much wider
MAX_LEGEND = 12  # more lines or colours than this: no legend (the table tells them apart)
MAX_THINNING = 20  # tick labels are thinned to every n-th at most, n up to this
PLAIN = FuncFormatter(lambda value, _: f"{value:.6g}")  # numbers as numbers, on any scale
FIGURES_OF_MERIT = (  # file name, title, a joint's column key (a regular expression)
    ("max_contact_force", "max contact force", r"max_contact_force_n"),
    ("max_wear_depth", "max wear depth", r"max_wear_depth_[a-z_]+_m"),
    ("worn_volume", "worn volume", r"worn_volume_m3"),
    ("contact_time", "time in contact", r"contact_time_fraction"),
    ("clearance_growth", "clearance growth", r"clearance_growth_m"),
    ("wear_life", "cycles to 50 % clearance growth", r"cycles_to_clearance_growth_50pct"),
    ("friction_coefficient", "friction coefficient", r"film\.friction_coefficient"),
    ("asperity_load_share", "asperity load share", r"film\.asperity_load_share"),
)
LIFE_KEYS = {  # a life run's milestones: their labels
    "hours_to_clearance_growth_50pct": "hours to 50 % clearance growth [h]",
    "cycles_to_clearance_growth_50pct": "cycles to 50 % clearance growth",
    "hours_reached": "hours reached [h]",
    "cycles_reached": "cycles reached",
}
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


@dataclass(frozen=True)
class _Scale:
    """How a varied path's table values become positions along an axis."""

    label: str
    factor: float  # display unit per SI unit (numeric values)
    categories: tuple  # the values in the sweep's order if they are not all numbers, else ()
    log: bool

    def positions(self, values: pd.Series) -> np.ndarray:
        if self.categories:
            return values.map(self.categories.index).to_numpy(dtype=float)
        return values.to_numpy(dtype=float) * self.factor


def plot_sweep(
    table: pd.DataFrame,
    columns: Sequence[str],
    texts: Mapping[str, Mapping[object, str]],
    title: str = "",
) -> Figure:
    """Plot ``columns`` of the sweep table, a panel each, against the first varied path.

    Parameters
    ----------
    table
        The sweep table: one row per case, a column per varied path (SI values).
    columns
        Headline columns ``<joint>.<key>``, e.g. ``coupler_follower.max_wear_depth_journal_m``.
    texts
        Per varied path, in order, each of its table values as the sweep was given it (e.g.
        0.0099 -> "9.9 mm"), for units, categories and legend.
    title
        The figure's title, e.g. the figure of merit.
    """
    varied = [path for path in texts if table[path].nunique() > 1] or list(texts)[:1]
    x_path, *others = varied
    x_scale = _scale(table, x_path, texts[x_path])
    grid = len(table[varied].drop_duplicates()) == math.prod(table[p].nunique() for p in varied)
    series = _grid_series(table, others, texts) if grid else []
    colour = None if grid or not others else _scale(table, others[0], texts[others[0]])
    colour_bar = colour is not None and not colour.categories
    legend = 1 < (len(colour.categories) if colour else len(series)) <= MAX_LEGEND
    room = LEGEND_ROOM * legend + COLOUR_BAR_ROOM * colour_bar
    ncols = 1 if len(columns) == 1 else 2
    nrows = math.ceil(len(columns) / ncols)
    size = (1.5 + 4.8 * ncols + room, 1.2 + 3.2 * nrows)
    fig = Figure(figsize=size, layout="constrained")
    axes = fig.subplots(nrows, ncols, sharex=True, squeeze=False).ravel()
    for ax in axes[len(columns) :]:
        fig.delaxes(ax)
    for index, (ax, column) in enumerate(zip(axes, columns, strict=False)):
        x = x_scale.positions(table[x_path])
        label, factor = quantity(column, pd.to_numeric(table[column], errors="coerce").abs().max())
        y = pd.to_numeric(table[column], errors="coerce").to_numpy(dtype=float) * factor
        if grid:
            for rows, line in series:
                order = np.argsort(x[rows], kind="stable")
                ax.plot(x[rows][order], y[rows][order], marker="o", label=line)
        else:
            points = _scatter(ax, x, y, table, others, texts, colour)
        ax.set_title(column.partition(".")[0], fontsize="medium")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        if _wide(y):
            ax.set_yscale("log")
            _own_ticks(ax.yaxis)
        ax.xaxis.set_tick_params(labelbottom=index + ncols >= len(columns))
    _x_axis(axes[0], x_scale, table[x_path], texts[x_path])
    if legend:
        fig.legend(*axes[0].get_legend_handles_labels(), loc="outside right upper",
                   fontsize="small")  # fmt: skip
    if colour_bar:
        bar = fig.colorbar(points, ax=list(axes[: len(columns)]), label=colour.label)
        if colour.log:
            _own_ticks(bar.ax.yaxis)
    fig.supxlabel(f"{x_scale.label}  ({x_path})", fontsize="medium")
    fig.suptitle(title or quantity(columns[0])[0].partition(" [")[0])
    _unclutter(fig, axes[: len(columns)], bool(x_scale.categories))
    return fig


def _scale(table: pd.DataFrame, path: str, texts: Mapping[object, str]) -> _Scale:
    """The axis of a varied path: numbers in the unit they were given in, else categories."""
    values = table[path]
    name = _name(path)
    if not pd.api.types.is_numeric_dtype(values) or pd.api.types.is_bool_dtype(values):
        return _Scale(name, 1.0, tuple(dict.fromkeys(values)), log=False)
    given = [toml_value(text) for text in texts.values()]
    units = Counter(unit_of(value) for value in given if isinstance(value, str))
    units.pop(None, None)
    unit, size = units.most_common(1)[0][0] if units else ("", 1.0)
    log = _wide(values.to_numpy(dtype=float))
    return _Scale(f"{name} [{unit}]" if unit else name, 1.0 / size, (), log)


def _grid_series(
    table: pd.DataFrame, others: Sequence[str], texts: Mapping[str, Mapping[object, str]]
) -> list[tuple[np.ndarray, str | None]]:
    """(rows, legend text) of each line: one per combination of the other varied paths."""
    if not others:
        return [(np.arange(len(table)), None)]
    lines = []
    for key, rows in table.groupby(list(others), sort=False, dropna=False).indices.items():
        values = key if isinstance(key, tuple) else (key,)
        pairs = zip(others, values, strict=True)
        lines.append((rows, ", ".join(f"{_name(p)} {texts[p].get(v, v)}" for p, v in pairs)))
    return lines


def _scatter(
    ax: Axes,
    x: np.ndarray,
    y: np.ndarray,
    table: pd.DataFrame,
    others: Sequence[str],
    texts: Mapping[str, Mapping[object, str]],
    colour: _Scale | None,
) -> PathCollection:
    """The cases as points, coloured by the second varied path if there is one."""
    if colour is None:
        return ax.scatter(x, y)
    if colour.categories:
        path = others[0]
        for value in colour.categories:
            rows = (table[path] == value).to_numpy()
            points = ax.scatter(x[rows], y[rows], label=texts[path].get(value, str(value)))
        return points
    c = colour.positions(table[others[0]])
    norm = (LogNorm if colour.log else Normalize)(c.min(), c.max())
    return ax.scatter(x, y, c=c, norm=norm, cmap="viridis", edgecolors="0.3", linewidths=0.4)


def _wide(values: np.ndarray) -> bool:
    """Whether values are positive and span more than a decade (a logarithmic axis)."""
    finite = values[np.isfinite(values)]
    return bool(finite.size and finite.min() > 0 and finite.max() > LOG_AXIS_RATIO * finite.min())


def _own_ticks(axis: Axis) -> None:
    """The axis' own ticks for its scale; on a log scale at 1, 2 and 5 of each decade."""
    if axis.get_scale() == "log":
        axis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        axis.set_major_formatter(PLAIN)
        axis.set_minor_locator(LogLocator(subs="auto"))
        axis.set_minor_formatter(NullFormatter())
    else:
        axis.set_major_locator(AutoLocator())
        axis.set_major_formatter(ScalarFormatter())
        axis.set_minor_locator(NullLocator())


def _x_axis(ax: Axes, scale: _Scale, values: pd.Series, texts: Mapping[object, str]) -> None:
    """Ticks of the shared x axis: a category's text, or a few values at their places."""
    if scale.categories:
        labels = [texts.get(c, str(c)) for c in scale.categories]
        ax.set_xticks(range(len(labels)), labels)
        return
    if scale.log:
        ax.set_xscale("log")
    places = np.unique(scale.positions(values))
    if len(places) <= MAX_VALUE_TICKS:
        ax.set_xticks(places, [PLAIN(v) for v in places])
        ax.xaxis.set_minor_locator(NullLocator())
    else:
        _own_ticks(ax.xaxis)


def _unclutter(fig: Figure, axes: Sequence[Axes], categories: bool) -> None:
    """Make the x tick labels of the figure not overlap.

    Labels at the values give way to the axis' own ticks, categories turn upright; then
    every second, third, ... of those labels is kept, until none overlap.
    """
    ax = axes[-1]  # the x axis is shared, and the last panel shows its labels
    fig.draw_without_rendering()
    if not any(_overlap(panel) for panel in axes):
        return
    if categories:
        for panel in axes:
            panel.tick_params(axis="x", labelrotation=90)
    else:
        _own_ticks(ax.xaxis)
    fig.draw_without_rendering()
    ticks = [(label.get_position()[0], label.get_text()) for label in ax.get_xticklabels()]
    for step in range(2, MAX_THINNING + 1):
        if not any(_overlap(panel) for panel in axes):
            return
        ax.set_xticks(*zip(*ticks[::step], strict=True))
        fig.draw_without_rendering()


def _overlap(ax: Axes) -> bool:
    """Whether any two shown x tick labels of ``ax`` overlap."""
    shown = [t for t in ax.get_xticklabels(which="both") if t.get_visible() and t.get_text()]
    boxes = sorted((t.get_window_extent() for t in shown), key=lambda box: box.x0)
    return any(b.x0 < a.x1 + 2.0 for a, b in pairwise(boxes))


def quantity(column: str, largest: float = 0.0) -> tuple[str, float]:
    """Axis label and factor from SI for a table column, by its unit suffix.

    ``coupler_follower.max_wear_depth_journal_m`` -> ("max wear depth journal [µm]", 1e6);
    lengths whose ``largest`` value [m] reaches a millimetre (a sliding distance) in metres.
    """
    key = column.rpartition(".")[2]
    if key in LIFE_KEYS:
        return LIFE_KEYS[key], 1.0
    for suffix, unit, factor in DISPLAY_UNITS:
        if key.endswith(suffix):
            if suffix == "_m" and largest >= LONG_LENGTH[0]:
                unit, factor = LONG_LENGTH[1:]
            return f"{key.removesuffix(suffix).replace('_', ' ')} [{unit}]", factor
    return key.replace("_", " "), 1.0


def _name(path: str) -> str:
    """The last part of a dotted path in words (``a.b_c``: b c)."""
    return path.rpartition(".")[2].replace("_", " ")


def _headline_columns(table: pd.DataFrame, joints: Sequence[str]) -> dict[str, list[str]]:
    """Per figure of merit (file name), the table's columns of it, joint by joint.

    Only columns with a number; a figure of merit without them is left out.
    """
    found: dict[str, list[str]] = {}
    for name, _, key in FIGURES_OF_MERIT:
        columns = [
            column
            for column in table.columns
            if column.partition(".")[0] in joints
            and re.fullmatch(key, column.partition(".")[2])
            and pd.to_numeric(table[column], errors="coerce").notna().any()
        ]
        if columns:
            found[name] = columns
    return found


def _changes(values: pd.Series) -> bool:
    """Whether a column's values differ between cases by more than rounding (1 in 1e9)."""
    finite = pd.to_numeric(values, errors="coerce").dropna().to_numpy(dtype=float)
    return bool(finite.size) and np.ptp(finite) > SAME * np.abs(finite).max()


def save_sweep_figures(
    table: pd.DataFrame,
    joints: Sequence[str],
    texts: Mapping[str, Mapping[object, str]],
    folder: str | Path,
) -> list[Path]:
    """Write a figure per figure of merit whose value changes between cases; return paths.

    ``joints`` are the model's clearance joints; ``texts`` as for ``plot_sweep``. PNGs that
    an earlier sweep wrote in ``folder`` and that are not drawn again are removed (only
    jointwear's own files, ``jointwear.io.remove``).
    """
    path = Path(folder)
    titles = {name: title for name, title, _ in FIGURES_OF_MERIT}
    written = []
    for name, columns in _headline_columns(table, joints).items():
        if any(_changes(table[column]) for column in columns):
            figure = plot_sweep(table, columns, texts, titles[name])
            with suppress(ForeignFileError):  # a file of the user's of that name is kept
                written.append(save_png(figure, path / f"{name}.png", dpi=120))
    lubricated = stribeck_joints(table, joints)
    if lubricated:
        varied = next((p for p in texts if table[p].nunique() > 1), None)
        notes = texts[varied] if varied else None
        figure = plot_stribeck(table, lubricated, notes, varied)
        with suppress(ForeignFileError):
            written.append(save_png(figure, path / "stribeck.png", dpi=120))
    for stale in set(path.glob("*.png")) - set(written):
        remove(stale)
    return written
