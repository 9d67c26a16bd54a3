"""The unit of a figure's small lengths (wear depths), chosen from the data it shows."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

LENGTH_UNITS = (("nm", 1e9), ("µm", 1e6), ("mm", 1e3), ("m", 1.0))  # finest first, per metre
NO_DATA_UNIT = ("µm", 1e6)  # for values all zero (no wear yet): the wear scale of the paper


def length_unit(values_m: ArrayLike) -> tuple[str, float]:
    """(unit, its count per metre) in which the largest of ``values_m`` [m] reads below 1000.

    The finest of nm, µm, mm and m that does, so 2.9e-6 m reads 2.9 µm and 6.5e-11 m
    0.065 nm; values all zero or not finite give µm.
    """
    magnitudes = np.abs(np.asarray(values_m, dtype=float)).ravel()
    largest = magnitudes[np.isfinite(magnitudes)].max(initial=0.0)
    if largest == 0.0:
        return NO_DATA_UNIT
    return next((unit for unit in LENGTH_UNITS if largest * unit[1] < 1000.0), LENGTH_UNITS[-1])
