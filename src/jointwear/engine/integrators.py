"""The integrators a run can use, by method: how to make one's state and read where it is.

Every method's state (``kernels.integrate``) holds the time reached in ``scal[0]`` and the
state vector there in ``y``; the run reads them through ``time`` and ``state`` only.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..kernels.codes import Method
from ..kernels.integrate import abm, rk

TIME = 0  # every method's ``scal[TIME]`` is the time reached (rk.S_T, abm.S_T)
INTEGRATORS: dict[Method, Callable[[int], object]] = {  # the state for n equations
    Method.DOPRI5: lambda n: rk.make_rk_state(n, rk.DOPRI5),
    Method.ABM: abm.make_abm_state,
}


def make_integrator(method: Method, n: int) -> object:
    """The state of ``method`` for n equations; ValueError for a method none is registered for."""
    make = INTEGRATORS.get(method)
    if make is None:
        known = ", ".join(m.name.lower() for m in INTEGRATORS)
        raise ValueError(f"no integrator for method {method!r}; known: {known}")
    return make(n)


def time(state: object) -> float:
    """Time the integrator has reached [s]."""
    return float(state.scal[TIME])


def state(state: object) -> NDArray[np.float64]:
    """A copy of the state vector (q, q') where the integrator is."""
    return np.array(state.y, copy=True)
