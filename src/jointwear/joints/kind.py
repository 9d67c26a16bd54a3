"""The contract of a joint type with clearance: what the rest of jointwear asks of a kind.

A kind is one subpackage of ``jointwear.joints`` holding everything about a joint type with
clearance, and one compiled module in ``kernels/elements/`` (the contact element). It is a
``ClearanceKind`` instance registered in ``joints.KINDS``, in the order of the kernels' kinds
(``kernels.elements.Elements``). The rest of the code iterates over ``KINDS`` and never names
a kind. A kind gives:

1. ``name``: the joint ``type`` of the model file (``"revolute"``), also the key of its
   arrays in a ``RunState`` and in the run's tables; ``schema``: its joint's table (a
   ``model.tables.JointTable`` with ``type``, ``kind``, the ideal joint's ``JointKind``, and
   ``clearance``, a ``model.clearance.ClearanceTable``); ``kernel``: its compiled module.
2. ``row(joint, model, bodies, angle0)``: its row of the kernel tables (integers and SI
   parameters); ``lookup(joint)``: a flat table its kernel also reads (the finite journal
   bearing's film), passed to ``make_tables`` as ``lookups`` when some joint has one;
   ``start_problems``: why a joint cannot start from the assembled pose.
3. ``columns(joint)``: its time-series columns (without the joint's name);
   ``derived_columns``: those computed from them after the run (they follow them);
   ``unit(quantity)``: the unit of each.
4. ``wear_rows``, ``wear_position``: its rows of the wear table and the column naming where
   along a surface a row is; ``impact_row``, ``impact_columns``: its rows of the impact table.
5. ``summary(joint, totals, wear, duration)``: its figures in ``summary.json``.
6. ``peaks`` and ``energies``: which of its totals are running peaks and dissipated energies
   (totals 0-7 mean the same in every kind: ``TOTALS``).
7. ``check_rows``: its rows in ``jointwear check``.
8. ``figures``: its figures, each a file name and a function ``Results -> Figure`` of
   ``figures_module`` (its ``figures.py``), which also has ``save_figures(results, folder)``;
   ``draws(figure, model)``: whether a model gets one of them (all, by default);
   ``animation_module``: how the animation draws its joints (an ``Actor`` each), with
   ``gap(joint)`` magnified. Both modules import matplotlib, and only they in the kind.
9. Life runs (``studies.life``): ``life_runs``, whether they support the kind; the profiles
   they extrapolate are the cells of ``wear_rows``, on ``mapped_surfaces(joint)``, and an
   update's depth bound is a share of ``gap(joint)`` plus the growth.
   ``clearance_growth(joint, wear, timeseries)``: the milestone measure, how far the gap has
   grown [m] with profiles ``wear`` at the motion of the measured cycles (``timeseries``),
   conservatively where the kind cannot tell exactly; ``worn_volume(joint, wear)`` [m^3];
   ``worn_through(joint, wear, when)``: why profiles would leave the model (None if not);
   ``growth_limit``: why the model stops describing a joint whose gap has grown much;
   ``gap_key``: the gap's key in summaries; ``penetration_range``: the entry of its
   ``outside_law_ranges`` that holds the penetration against the gap (a life run stops when
   an update leaves it, ``studies.life.runaway``). ``figures_module`` has
   ``draw_life_profiles(fig, place, joint, profiles, updates)``: the joint's profiles at a few
   updates, drawn into the subplot spec ``place``.

The kernel module gives ``make_tables(ints, params, snapshots)`` -> (table, state, log,
scratch), ``N_INTS``, ``N_PARAMS``, ``N_IMPACT_INFO``, ``SLOTS`` (contact slots per joint) and
``DEGREES_OF_FREEDOM`` (what the clearance frees beyond the ideal joint).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from importlib import import_module
from types import MappingProxyType, ModuleType
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

# The totals every kind keeps in its first columns, by index (kernels/elements/*.py T_*).
PENETRATION_SHARES = (0.01, 0.1, 0.4)  # of the gap, where ``check`` shows the contact law
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


class Actor(NamedTuple):
    """A joint in the animation (``figures.animation``)."""

    moved: dict  # {(body, point): (frames, 2) positions [m]} the joint's drawing moves
    extent: np.ndarray  # (k, 2) points it draws [m], for the axes' limits
    setup: Callable  # (Axes) -> draw(frame): adds its artists, returns what moves them


class ClearanceKind:
    """A joint type with clearance (the module docstring lists what it gives)."""

    name: str = ""
    schema: type = object  # the joint's table in the model file
    kernel: str = ""  # the compiled module, ``jointwear.kernels.elements.<kernel>``
    wear_position: str = ""  # wear table column of a row's place on its surface
    impact_columns: tuple[str, ...] = ()  # impact table columns of its own
    energies: tuple[int, ...] = (TOTALS["damping_energy"], TOTALS["friction_energy"])
    derived_after: str = ""  # the own column its derived columns follow (default: the last)
    figures_module: str = ""  # the module of its figures (matplotlib; imported to draw)
    figures: tuple[tuple[str, str], ...] = ()  # (file name without .png, plotting function)
    figures_with_ideal: frozenset[str] = frozenset()  # figures given the ideal run too
    animation_module: str = ""  # its drawing in the animation: ``actor``, ``title``, and
    # ``ideal_actor`` if its ideal joints have a drawing of their own
    pins_points: bool = False  # whether its ideal joint holds its two points together
    older_state_names: dict[str, str] = MappingProxyType({})  # restart arrays' names in
    # states saved before the kinds were keyed by name (``results.run_state``)
    slides: bool = False  # whether a distance driver can prescribe its ideal joint's slide
    references: dict[str, str] = MappingProxyType({})  # its own papers: key -> citation text
    citations: tuple[str, ...] = ()  # keys of ``citations.REFERENCES`` behind the kind's model
    surfaces: tuple[str, ...] = ()  # its worn surfaces, in the order reports list them
    range_words: dict[str, str] = MappingProxyType({})  # outside_law_ranges' checks in words
    ideal_rows: tuple[str, ...] = ()  # what each constraint equation of its ideal joint holds
    gap_key: str = "gap_m"  # the gap's key in its summaries (``gap``)
    life_runs: bool = False  # whether life runs (``studies.life``) support the kind
    growth_limit: str = ""  # why a gap grown much leaves the model, a sentence for life runs
    penetration_range: str = "penetration_over_clearance"  # outside_law_ranges' entry of it

    @property
    def module(self) -> ModuleType:
        """The compiled contact element (imports numba on first use)."""
        return import_module(f"jointwear.kernels.elements.{self.kernel}")

    @property
    def peaks(self) -> tuple[int, ...]:
        """Columns of the totals that are running peaks (the rest are sums)."""
        return (TOTALS["max_fn"], TOTALS["max_delta"])

    def gap(self, joint: Any) -> float:
        """The joint's clearance [m]: what the animation magnifies, wear grows."""
        raise NotImplementedError

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

    def draws(self, figure: str, model: Any) -> bool:
        """Whether ``model`` (with joints of this kind) gets ``figure``, one of ``figures``."""
        return True

    def lookup(self, joint: Any) -> NDArray[np.float64]:
        """Data the kernel reads for ``joint`` beyond its row (a flat table); none by default."""
        return np.zeros(0)

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

    def derived_columns(self, joint: Any, timeseries: Any) -> dict[str, NDArray[np.float64]]:
        """Columns computed from the joint's rows after the run, by full name; none by default."""
        return {}

    def unit(self, quantity: str) -> str | None:
        """The unit (UDUNITS) of one of its columns, without the joint's name; None if unknown."""
        return None

    def check_title(self, joint: Any) -> str:
        """The title of the joint's table in ``jointwear check``."""
        return f"{self.name} clearance joint '{joint.name}'"

    def check_rows(self, joint: Any, model: Any, y0: NDArray[np.float64]) -> list[tuple]:
        """(quantity, value, unit) rows of ``jointwear check``: layout, contact law.

        The laws and their keys follow them; ``y0``: the assembled start.
        """
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

    def mapped_surfaces(self, joint: Any) -> tuple[str, ...]:
        """The joint's surfaces with a wear map, in the order of ``wear_rows``."""
        raise NotImplementedError

    def clearance_growth(
        self, joint: Any, wear: NDArray[np.float64], timeseries: Sequence[Any]
    ) -> float:
        """How far the joint's gap has grown [m] with profiles ``wear`` (this joint's).

        ``timeseries``: the tables of the cycles whose motion the growth is judged at.
        """
        raise NotImplementedError

    def worn_volume(self, joint: Any, wear: NDArray[np.float64]) -> float:
        """The volume [m^3] the profiles ``wear`` (this joint's) hold."""
        raise NotImplementedError

    def worn_through(self, joint: Any, wear: NDArray[np.float64], when: str) -> str | None:
        """Why profiles ``wear`` would leave the model, a clause naming ``when``; None if not."""
        return None


def segment_centres(length: float, segments: int) -> NDArray[np.float64]:
    """Centres of a surface's segments from its middle [m]."""
    return (np.arange(segments) + 0.5) * length / segments - 0.5 * length


def range_report(
    limits: dict[str, float], totals: dict[str, tuple[int, int]], row: NDArray, duration: float
) -> dict:
    """``outside_law_ranges``: per range, its limit, the largest value and the time beyond.

    ``limits``: the laws' ranges by name (``ClearanceTable.law_ranges``) that the kind
    checks; ``totals``: their (time beyond, largest value) columns in the kernel's ``row``;
    ``duration`` [s]: the time the totals were gathered over.
    """
    return {
        name: {
            "limit": float(limit),
            "largest": float(row[totals[name][1]]),
            "time_beyond_s": float(row[totals[name][0]]),
            "time_fraction_beyond": float(row[totals[name][0]] / duration) if duration else 0.0,
        }
        for name, limit in limits.items()
    }


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


def stiffness_rows(clearance: Any) -> list[tuple]:
    """``check``'s row of the elastic law's constant K, where its record has one."""
    from ..model.laws import NORMAL

    law = NORMAL.by_name[clearance.normal_law]
    if law.stiffness is None:
        return []
    symbol = law.stiffness.symbol.format(**clearance.law_values(law))
    return [(f"contact stiffness {symbol}", clearance.stiffness, law.stiffness.unit)]
