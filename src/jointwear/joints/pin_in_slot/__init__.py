"""The pin-in-slot joint with clearance: a pin in a slot (``kernels.elements.pin_slot``).

Wear table rows: ``surface`` is one of ``SURFACES`` (the slot's sides ``side_plus_v`` and
``side_minus_v``, on the side the axis turned +90 degrees points to and the other; its ends
``end_plus_u`` and ``end_minus_u``; the ``pin``); a slot of length 0 has no sides, so no
side rows. ``position_m`` is the cell's centre along its surface: on a side, along the axis
from the slot's point; on an end, along its arc from the slot's axis, positive towards the
side turned +90 degrees from the end's outward direction; on the pin, along its circle from
the pin body's x axis, counter-clockwise, from 0 to 2 pi R_p. Impact rows: the surface
touched (``contact``) and where: ``side_position_m`` on a side, ``end_angle_deg`` on an end.
Summary: the common figures, the gap, the deepest wear of each surface and where, and the
law-range checks (``outside_law_ranges``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray
from typing_extensions import override

from ..kind import (
    PENETRATION_SHARES,
    ClearanceKind,
    common_figures,
    deepest,
    range_report,
    segment_centres,
    stiffness_rows,
)
from .schema import PinInSlotJoint

HERTZ_REFERENCE_FORCES = (100.0, 1000.0)  # loads at which `check` shows the Hertz patch [N]
SIDES = ("side_plus_v", "side_minus_v")
ENDS = ("end_plus_u", "end_minus_u")
SURFACES = (*SIDES, *ENDS, "pin")  # the first index of the kernel's wear array
UNITS = {
    "along": "m",  # the pin centre along the slot's axis from the slot's point
    "across": "m",  # and across it, towards the +v side
    "fx": "N",  # contact force on the pin
    "fy": "N",
    "fn": "N",  # normal contact force
    "vt": "m/s",  # sliding speed at the contact point
    "friction_power": "W",
    "damping_power": "W",
}


def cells(joint: object) -> dict[str, NDArray[np.float64]]:
    """{mapped surface: its cells' centres along it [m]} (``position_m``), kernel order."""
    c = joint.clearance
    side = segment_centres(c.slot_length, c.segments) if c.slot_length > 0.0 else None
    end = segment_centres(math.pi * c.slot_half_width, c.sectors // 2)
    pin = (np.arange(c.sectors) + 0.5) * 2.0 * math.pi * c.pin_radius / c.sectors
    centres = (side, side, end, end, pin)
    return {s: x for s, x in zip(SURFACES, centres, strict=True) if x is not None}


class PinInSlotKind(ClearanceKind):
    """A pin in a straight slot with round ends."""

    name = "pin_in_slot"
    schema = PinInSlotJoint
    kernel = "pin_slot"
    wear_position = "position_m"
    impact_columns = ("contact", "side_position_m", "end_angle_deg")
    figures_module = f"{__name__}.figures"
    animation_module = f"{__name__}.animation"
    surfaces = ("pin", *SIDES, *ENDS)  # the moving part first, as the revolute joint's journal
    references = MappingProxyType({
        "skrinjar2017": (
            'I. Skrinjar, J. Slavič, M. Boltežar, "A validated model for a pin-slot clearance '
            'joint", Nonlinear Dynamics 88 (2017) 131-143'
        ),
    })  # fmt: skip
    citations = ("skrinjar2017",)  # the pin-slot contact's geometry
    life_runs = True
    growth_limit = (
        "The contact stiffness is that of the nominal radii and the worn profiles enter only "
        "as depths along the contact's normal"
    )
    range_words = MappingProxyType({
        "penetration_over_clearance": "penetration / gap",
        "hertz_half_width_over_journal_radius": "Hertz half-width / pin radius",
    })  # fmt: skip
    ideal_rows = ("line",)
    pins_points = False
    slides = True
    figures = (
        ("pin_slot_path", "plot_pin_path"),
        ("pin_slot_forces", "plot_contact_force"),
        ("pin_slot_wear", "plot_wear"),
    )

    @property
    @override
    def peaks(self) -> tuple[int, ...]:
        ps = self.module
        return (ps.T_MAX_FN, ps.T_MAX_DELTA, ps.T_PATCH_MAX, ps.T_DEPTH_MAX)

    @override
    def gap(self, joint: object) -> float:
        return joint.clearance.gap

    @override
    def row(
        self, joint: object, model: object, bodies: tuple[int, int], angle0: float
    ) -> tuple[list[int], NDArray[np.float64]]:
        from ...model.clearance import law_parameters
        from ...model.laws.record import HERTZ_PATCH, PENETRATION

        ps = self.module
        c = joint.clearance
        points = [model.point(b, p) for b, p in zip(joint.bodies, joint.points, strict=True)]
        laws = law_parameters(c)
        ints = [0] * ps.N_INTS
        ints[ps.I_SLOT], ints[ps.I_PIN] = bodies
        ints[ps.I_NORMAL] = laws["normal"].code
        ints[ps.I_DAMPING] = laws["damping"].code
        ints[ps.I_FRICTION] = laws["friction"].code
        ints[ps.I_WEAR] = laws["wear"].code
        ints[ps.I_FEEDBACK] = int(c.wear_feedback)
        ints[ps.I_SEGMENTS] = c.segments
        ints[ps.I_END_SECTORS] = c.sectors // 2
        ints[ps.I_PIN_SECTORS] = c.sectors
        param = np.zeros(ps.N_PARAMS)
        param[[ps.P_C_X, ps.P_C_Y]] = points[0]
        param[[ps.P_U_X, ps.P_U_Y]] = joint.axis  # a unit vector (the schema's)
        param[[ps.P_P_X, ps.P_P_Y]] = points[1]
        param[ps.P_L] = 0.5 * c.slot_length
        param[ps.P_RS] = c.slot_half_width
        param[ps.P_RP] = c.pin_radius
        param[ps.P_C] = c.gap
        param[ps.P_K] = c.stiffness
        param[ps.P_EXP] = c.exponent
        (param[ps.P_CE],) = laws["damping"].parameters
        param[ps.P_CF] = c.friction_coefficient
        param[[ps.P_F0, ps.P_F1, ps.P_F2]] = laws["friction"].parameters
        param[ps.P_WEAR] = laws["wear"].parameters[0]
        param[ps.P_SHARE] = c.pin_wear_share
        param[ps.P_WIDTH] = c.width
        param[ps.P_ESTAR] = c.contact_modulus
        param[ps.P_MIN_SPEED] = c.min_impact_speed
        param[ps.P_TOL] = c.contact_tolerance
        ranges = c.law_ranges()
        param[ps.P_DEPTH_LIMIT] = ranges[PENETRATION]
        param[ps.P_PATCH_LIMIT] = ranges.get(HERTZ_PATCH, 0.0)  # 0: the patch is not checked
        return ints, param

    @override
    def start_problems(self, joint: object, model: object, place: object) -> list[str]:
        """A pin that starts pressed into an end: its centre beyond an end centre by c or more."""
        c = joint.clearance
        slot, pin = joint.bodies
        origin = place(slot, model.point(slot, joint.points[0]))
        axis = place(slot, joint.axis) - place(slot, (0.0, 0.0))
        x = float((place(pin, model.point(pin, joint.points[1])) - origin) @ axis)
        if abs(x) - 0.5 * c.slot_length < c.gap:
            return []
        return [
            f"joints.{joint.name}: the pin starts beyond the slot's end (its centre "
            f"{x * 1e3:.6g} mm along the axis from the slot's point, the end centres at "
            f"±{0.5 * c.slot_length * 1e3:.6g} mm); move the pin or the slot's point, or "
            "lengthen slot_length"
        ]

    @override
    def columns(self, joint: object) -> tuple[str, ...]:
        return self.module.OUTPUT_NAMES

    @override
    def unit(self, quantity: str) -> str | None:
        return UNITS.get(quantity)

    @override
    def check_title(self, joint: object) -> str:
        return f"pin-in-slot clearance joint '{joint.name}'"

    @override
    def check_rows(self, joint: object, model: object, y0: NDArray[np.float64]) -> list[tuple]:
        c = joint.clearance
        slot, pin = joint.bodies
        phi = 0.0 if slot == "ground" else y0[3 * model.body_names.index(slot) + 2]
        axis = math.degrees(math.atan2(joint.axis[1], joint.axis[0]) + phi)
        rows = [
            ("gap c = slot_width / 2 - R_p", c.gap * 1e3, "mm"),
            (f"slot (on '{slot}'): width 2 R_s", c.slot_width * 1e3, "mm"),
            ("  length between end centres", c.slot_length * 1e3, "mm"),
            ("  axis, from global x at the start", axis, "deg"),
            (f"pin (on '{pin}'): radius R_p", c.pin_radius * 1e3, "mm"),
            *stiffness_rows(c),
            ("contact modulus E*", c.contact_modulus / 1e9, "GPa"),
            ("relative radius in an end R* = R_s R_p / c", c.end_radius, "m"),
        ]
        for share in PENETRATION_SHARES:
            force, stiffness = c.elastic_force(share * c.gap)
            rows.append((f"force F at delta = {share:.0%} of c", force / 1e3, "kN"))
            rows.append(("stiffness dF/d(delta) there", stiffness, "N/m"))
        for force in HERTZ_REFERENCE_FORCES:
            for where, on_side in (("on a side", True), ("in an end", False)):
                b, p_max = c.hertz_patch(force, on_side=on_side)
                rows.append((f"Hertz half-width b at {force:g} N {where}", b * 1e3, "mm"))
                rows.append((f"Hertz peak pressure at {force:g} N {where}", p_max / 1e6, "MPa"))
        return [
            *rows,
            ("segments per side", c.segments, ""),
            ("sectors of the pin (each end: half)", c.sectors, ""),
        ]

    @override
    def wear_rows(self, joint: object, wear: NDArray[np.float64]) -> list[tuple]:
        return [
            (surface, i, x, wear[SURFACES.index(surface), i])
            for surface, centres in cells(joint).items()
            for i, x in enumerate(centres)
        ]

    @override
    def impact_row(self, info: NDArray[np.float64]) -> dict[str, object]:
        ps = self.module
        surface = int(info[ps.IMPACT_SURFACE])
        where = float(info[ps.IMPACT_WHERE])
        on_side = surface in (ps.SIDE_PLUS_V, ps.SIDE_MINUS_V)
        return {
            "penetration_velocity_m_s": float(info[ps.IMPACT_SPEED]),
            "contact": SURFACES[surface],
            "side_position_m": where if on_side else None,
            "end_angle_deg": None if on_side else math.degrees(where),
            "penetration_m": float(info[ps.IMPACT_DELTA]),
        }

    @override
    def summary(
        self, joint: object, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
    ) -> dict[str, object]:
        entry = common_figures(self, totals, duration)
        entry = {
            "type": entry.pop("type"),
            "gap_m": joint.clearance.gap,
            **entry,
            "outside_law_ranges": self._outside_ranges(joint.clearance, totals, duration),
        }
        for surface, centres in cells(joint).items():
            depth, peak = deepest(wear[SURFACES.index(surface), : len(centres)])
            entry[f"max_wear_depth_{surface}_m"] = depth
            entry[f"max_wear_position_{surface}_m"] = None if peak is None else centres[peak]
        return entry

    @override
    def mapped_surfaces(self, joint: object) -> tuple[str, ...]:
        return tuple(cells(joint))

    @override
    def clearance_growth(
        self, joint: object, wear: NDArray[np.float64], timeseries: Sequence[object]
    ) -> float:
        """The deepest slot surface plus the deepest pin cell: an upper bound, as if they met."""
        slot = max(
            float(wear[SURFACES.index(s), : len(x)].max())
            for s, x in cells(joint).items()
            if s != "pin"
        )
        return slot + float(wear[SURFACES.index("pin"), : joint.clearance.sectors].max())

    @override
    def worn_volume(self, joint: object, wear: NDArray[np.float64]) -> float:
        """Depth x cell length x width, summed over every mapped surface's cells."""
        c = joint.clearance
        lengths = {"pin": 2.0 * math.pi * c.pin_radius, **dict.fromkeys(SIDES, c.slot_length),
                   **dict.fromkeys(ENDS, math.pi * c.slot_half_width)}  # fmt: skip
        return c.width * sum(
            float(wear[SURFACES.index(s), : len(x)].sum()) * lengths[s] / len(x)
            for s, x in cells(joint).items()
        )

    @override
    def worn_through(self, joint: object, wear: NDArray[np.float64], when: str) -> str | None:
        c = joint.clearance
        depth = float(wear[SURFACES.index("pin"), : c.sectors].max())
        if depth < c.pin_radius:
            return None
        return (
            f"the pin would be worn {depth * 1e3:.4g} mm deep {when}, through its radius "
            f"{c.pin_radius * 1e3:.4g} mm"
        )

    def _outside_ranges(self, c: object, row: NDArray[np.float64], duration: float) -> dict:
        """The penetration and the Hertz patch the kernel tracks (``_track_ranges``)."""
        from ...model.laws.record import HERTZ_PATCH, PENETRATION

        ps = self.module
        totals = {
            PENETRATION: (ps.T_DEPTH_TIME, ps.T_DEPTH_MAX),
            HERTZ_PATCH: (ps.T_PATCH_TIME, ps.T_PATCH_MAX),
        }
        return range_report(c.law_ranges(), totals, row, duration)


KIND = PinInSlotKind()
