"""How far a revolute clearance joint's gap has grown with its worn profiles (life runs).

The effective clearance growth of a joint is the largest increase of the gap between journal
and bearing over every direction, at every relative orientation the two bodies pass through
in the measured cycles: with psi the journal body's angle relative to the bearing body's,
the gap in the direction at angle theta of the bearing's frame grows by
``w_B(theta) + w_J(theta - psi)`` (the worn profiles interpolated as the contact model does,
``kernels.laws.wear.depth_at``), maximised over theta and over psi between its smallest and
largest value in the measured cycles (psi is continuous, so it takes every value in between).
When the bodies turn fully relative to each other it is the sum of the two deepest sectors.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    import pandas as pd

GRID_CELLS = 2**20  # evaluations per block of the clearance-growth search


def relative_angle_range(
    bodies: Sequence[str], timeseries: Sequence[pd.DataFrame]
) -> tuple[float, float]:
    """Smallest and largest angle psi [rad] of the journal's body relative to the bearing's.

    ``bodies``: the bearing's and the journal's; over the rows of every table in ``timeseries``.
    """
    psi = np.concatenate([_angle(t, bodies[1]) - _angle(t, bodies[0]) for t in timeseries])
    return float(psi.min()), float(psi.max())


def _angle(timeseries: pd.DataFrame, body: str) -> NDArray[np.float64]:
    if body == "ground":
        return np.zeros(len(timeseries))
    return timeseries[f"phi_{body}"].to_numpy()


def clearance_growth(
    bearing: NDArray[np.float64], journal: NDArray[np.float64], psi: tuple[float, float]
) -> float:
    """Largest gap increase [m] over directions and relative angles ``psi`` (module docstring).

    Parameters
    ----------
    bearing, journal
        Sector depths of the two surfaces [m], the same number of sectors.
    psi
        Smallest and largest relative angle of the journal's body [rad].
    """
    lo, hi = psi
    if hi - lo >= 2.0 * math.pi:
        return float(bearing.max() + journal.max())
    n = bearing.shape[0]
    sector = 2.0 * math.pi / n
    centres = (np.arange(n) + 0.5) * sector
    # In (theta, phi = theta - psi) the sum is linear on every cell between sector centres,
    # so its largest value on the strip lo <= psi <= hi lies on a vertex of a cell cut by
    # the strip: a pair of centres (psi a whole number of sectors) or a cell edge on the
    # strip's border (psi = lo or hi). For each such psi, it lies on a centre of either
    # surface.
    psis = np.concatenate([[lo, hi], np.arange(math.ceil(lo / sector), hi / sector) * sector])
    largest = 0.0
    for block in np.array_split(psis, math.ceil(psis.size * 2 * n / GRID_CELLS)):
        theta = np.concatenate(
            [np.broadcast_to(centres, (block.size, n)), centres + block[:, None]], 1
        )
        gap = np.interp(theta, centres, bearing, period=2.0 * math.pi)
        gap += np.interp(theta - block[:, None], centres, journal, period=2.0 * math.pi)
        largest = max(largest, float(gap.max()))
    return largest
