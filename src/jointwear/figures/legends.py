"""Legends beside their axes, where they hide no data and no label."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.legend import Legend

LEGEND_ROOM = 2.0  # [in] figures with legends beside their axes are this much wider


def legend_beside(ax: Axes) -> Legend:
    """The legend of ``ax`` to its right, top-aligned; the figure's layout makes room for it."""
    return ax.legend(
        loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, fontsize="small"
    )
