"""Wear of a flat surface (a guide's or a slider's face) kept in segments along its length.

| symbol | meaning | unit |
|---|---|---|
| x | position along the surface from its middle, -length / 2 to length / 2 | m |
| length | the surface's length | m |
| depths | wear depth of each of the N equal segments, first at -length / 2 | m |
| width | the surface's width (out of the plane) | m |

Segment i covers [-length / 2 + i length / N, -length / 2 + (i + 1) length / N). A step's
worn volume goes into the segment where the contact acts (a corner or an edge touches along a
line across the width), so the depths add up to the volume exactly, whatever N. The depth
read back is piecewise linear between the segment centres and constant beyond the outer
centres, so that the worn gap, and the contact force with it, stay continuous.
"""

import math

import numpy as np
from numba import njit
from numpy.typing import NDArray


@njit(cache=True, no_cfunc_wrapper=True)
def segment_of(x: float, length: float, n: int) -> int:
    """Index of the segment (of n) containing position x [m], clamped to the surface."""
    i = math.floor((x / length + 0.5) * n)
    return min(max(i, 0), n - 1)


@njit(cache=True, no_cfunc_wrapper=True)
def add_wear(depths: NDArray[np.float64], x: float, length: float, width: float, volume: float):
    """Add a worn volume [m^3] to the segment at x [m] as a uniform depth, in place."""
    n = depths.shape[0]
    depths[segment_of(x, length, n)] += volume * n / (length * width)


@njit(cache=True, no_cfunc_wrapper=True)
def depth_along(x: float, depths: NDArray[np.float64], length: float) -> float:
    """Wear depth [m] at position x [m]: linear between segment centres; 0 without segments."""
    n = depths.shape[0]
    if n == 0:
        return 0.0
    if n == 1:
        return depths[0]
    s = min(max((x / length + 0.5) * n - 0.5, 0.0), n - 1.0)
    below = min(math.floor(s), n - 2)
    w = s - below
    return (1.0 - w) * depths[below] + w * depths[below + 1]
