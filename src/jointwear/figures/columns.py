"""Any time-series columns against another: the figure ``Results.plot`` draws."""

from __future__ import annotations

from typing import TYPE_CHECKING

from matplotlib.figure import Figure  # figures without pyplot: no global backend switch

from .legends import LEGEND_ROOM, legend_beside

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ..results import Results


def plot_columns(
    results: Results, columns: tuple[str, ...], x: str = "time", ax: Axes | None = None
) -> Figure:
    """Plot time-series ``columns`` of ``results`` against column ``x``, labelled with units.

    Parameters
    ----------
    results
        The run.
    columns
        Names of time-series columns, checked by the caller (``Results.plot``).
    x
        The column along the horizontal axis.
    ax
        Axes to draw on; a new figure with one axes if None.

    Returns
    -------
    Figure
        The figure drawn on (``ax``'s if given).
    """
    units = results.units("timeseries")
    table = results.timeseries
    own = ax is None  # a figure of its own has room for the legend beside the axes
    if own:
        fig = Figure(figsize=(7.0 + LEGEND_ROOM * (len(columns) > 1), 4.0), layout="constrained")
        ax = fig.subplots()
        ax.set_title(results.model.name)
    else:
        fig = ax.figure
    for column in columns:
        ax.plot(table[x].to_numpy(), table[column].to_numpy(), label=_label(column, units))
    ax.set_xlabel(_label(x, units))
    shown = {units[c] for c in columns}
    if len(shown) == 1:  # one unit: it labels the axis
        ax.set_ylabel(_label(columns[0] if len(columns) == 1 else "", units, shown.pop()))
    if len(columns) > 1 and own:
        legend_beside(ax)
    elif len(columns) > 1:  # in the caller's axes, whose figure's layout is theirs
        ax.legend(loc="best")
    ax.grid(alpha=0.3)
    return fig


def _label(column: str, units: dict[str, str], unit: str | None = None) -> str:
    """``"omega_crank [rad/s]"``; the bare name for a dimensionless column."""
    unit = units.get(column, "?") if unit is None else unit
    text = f"{column} [{unit}]" if unit not in ("", "1") else column
    return text.strip()
