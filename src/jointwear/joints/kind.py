"""The contract of a joint type with clearance: what the rest of jointwear asks of a kind.

A kind is one subpackage of ``jointwear.joints`` holding everything about a joint type with
clearance, and one compiled module in ``kernels/elements/`` (the contact element). It is a
``ClearanceKind`` instance registered in ``joints.KINDS``, in the order of the kernels' kinds
(``kernels.elements.Elements``). The rest of the code iterates over ``KINDS`` and never names
a kind. A kind gives:

1. ``name``: the joint ``type`` of the model file (``"revolute"``), also the key of its
   arrays in a ``RunState`` and in the run's tables; ``kernel``: its compiled module's name.
2. ``row(joint, model, bodies, angle0)``: its row of the kernel tables (integers and SI
   parameters); ``start_problems``: why a joint cannot start from the assembled pose.
3. ``columns(joint)``: its time-series columns (without the joint's name).
4. ``wear_rows``, ``wear_position``: its rows of the wear table and the column naming where
   along a surface a row is; ``impact_row``, ``impact_columns``: its rows of the impact table.
5. ``summary(joint, totals, wear, duration)``: its figures in ``summary.json``.
6. ``peaks`` and ``energies``: which of its totals are running peaks and dissipated energies
   (totals 0-7 mean the same in every kind: ``TOTALS``).

The kernel module gives ``make_tables(ints, params, snapshots)`` -> (table, state, log,
scratch), ``N_INTS``, ``N_PARAMS``, ``N_IMPACT_INFO``, ``SLOTS`` (contact slots per joint) and
``DEGREES_OF_FREEDOM`` (what the clearance frees beyond the ideal joint).
"""

from __future__ import annotations

from collections.abc import Callable
from importlib import import_module
from types import ModuleType
from typing import Any

import numpy as np
from numpy.typing import NDArray

# The totals every kind keeps in its first columns, by index (kernels/elements/*.py T_*).
TOTALS = {
    "contact_time": 0,  # time with a positive normal force [s]
    "max_fn": 1,  # largest normal force [N]
    "max_delta": 2,  # largest penetration [m]
    "impacts": 3,  # contact periods begun
    "damping_energy": 4,  # dissipated by damping [J]
    "friction_energy": 5,  # dissipated by friction [J]
    "worn_volume": 6,  # removed from all surfaces [m^3]
    "sliding": 7,  # sliding distance while sliding [m]
}
STATE_FIELDS = ("contact_on", "impact_speed", "wear")  # a kind's restart arrays, kernel names


class ClearanceKind:
    """A joint type with clearance (the module docstring lists what it gives)."""

    name: str = ""
    kernel: str = ""  # the compiled module, ``jointwear.kernels.elements.<kernel>``
    wear_position: str = ""  # wear table column of a row's place on its surface
    impact_columns: tuple[str, ...] = ()  # impact table columns of its own
    energies: tuple[int, ...] = (TOTALS["damping_energy"], TOTALS["friction_energy"])

    @property
    def module(self) -> ModuleType:
        """The compiled contact element (imports numba on first use)."""
        return import_module(f"jointwear.kernels.elements.{self.kernel}")

    @property
    def peaks(self) -> tuple[int, ...]:
        """Columns of the totals that are running peaks (the rest are sums)."""
        return (TOTALS["max_fn"], TOTALS["max_delta"])

    def joints(self, model: Any) -> tuple:
        """``model``'s joints of this kind with clearance, in file order (the kernels' order)."""
        return tuple(j for j in model.joints if j.type == self.name and j.clearance is not None)

    def row(
        self, joint: Any, model: Any, bodies: tuple[int, int], angle0: float
    ) -> tuple[list[int], NDArray[np.float64]]:
        """The integer and parameter row of ``joint`` in the kernel's table.

        ``bodies``: the kernel indices of its two bodies (-1: ground); ``angle0``: the second
        body's initial angle minus the first's [rad].
        """
        raise NotImplementedError

    def start_problems(
        self, joint: Any, model: Any, place: Callable[[str, tuple[float, float]], NDArray]
    ) -> list[str]:
        """Why ``joint`` cannot start from the assembled pose; none by default.

        ``place(body, point)``: a body's point [m] in global axes at that pose.
        """
        return []

    def columns(self, joint: Any) -> tuple[str, ...]:
        """The joint's time-series columns, without its name."""
        raise NotImplementedError

    def wear_rows(self, joint: Any, wear: NDArray[np.float64]) -> list[tuple]:
        """(surface, cell, position, depth [m]) per mapped cell of ``wear`` (this joint's)."""
        raise NotImplementedError

    def impact_row(self, info: NDArray[np.float64]) -> dict[str, object]:
        """An onset's figures from its ``info`` (the kernel's IMPACT_* columns)."""
        raise NotImplementedError

    def summary(
        self, joint: Any, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
    ) -> dict[str, object]:
        """The joint's figures for ``summary.json`` (SI units in the keys)."""
        raise NotImplementedError


def common_figures(kind: ClearanceKind, totals: NDArray[np.float64], duration: float) -> dict:
    """The figures every kind reports, from its totals (``TOTALS``) over ``duration`` [s]."""
    fraction = min(1.0, float(totals[TOTALS["contact_time"]] / duration)) if duration else 0.0
    return {
        "type": kind.name,
        "max_contact_force_n": float(totals[TOTALS["max_fn"]]),
        "contact_time_fraction": fraction,
        "impacts": int(totals[TOTALS["impacts"]]),
        "max_penetration_m": float(totals[TOTALS["max_delta"]]),
        "worn_volume_m3": float(totals[TOTALS["worn_volume"]]),
        "sliding_distance_m": float(totals[TOTALS["sliding"]]),
        "energy_dissipated_damping_j": float(totals[TOTALS["damping_energy"]]),
        "energy_dissipated_friction_j": float(totals[TOTALS["friction_energy"]]),
    }


def deepest(depths: NDArray[np.float64]) -> tuple[float, int | None]:
    """The largest depth of a profile [m] and its cell (None if unworn)."""
    peak = int(np.argmax(depths))
    return float(depths[peak]), (peak if depths[peak] > 0.0 else None)
