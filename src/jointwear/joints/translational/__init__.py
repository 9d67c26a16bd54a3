"""The translational joint with clearance: a slider in its guide (``kernels.elements.slider``).

Wear table rows: ``surface`` is one of the mapped surfaces (``guide_top``, ``guide_bottom``,
``slider_top``, ``slider_bottom``; an unbounded guide keeps no map of its wear, so its surfaces
have no rows), ``position_m`` the segment's centre along its surface from the surface's middle,
in its body's frame (the guide's from the joint's first point, the slider's from its centre,
positive along the axis). Impact rows: the contact (a corner or a guide edge,
``kernels.elements.slider.CONTACT_NAMES``) and where along the guide it is.

Life runs: the clearance growth is that of the worse side, top or bottom, each side's taken
as its guide surface's deepest segment plus its slider surface's deepest, as if the two met
wherever they are (at most what the slider can move across its guide, tilted or not, beyond
the nominal gap; conservative). An unbounded guide keeps no wear map, so there the growth
is the slider's alone. A slider worn through its height (top and bottom at one segment)
stops them.
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
    STATE_FIELDS,
    ClearanceKind,
    common_figures,
    deepest,
    range_report,
    segment_centres,
    stiffness_rows,
)
from .schema import TranslationalJoint

SURFACES = ("guide_top", "guide_bottom", "slider_top", "slider_bottom")  # the kernel's order
UNITS = {
    "lateral": "m",  # the slider's offset across its guide
    "tilt": "rad",  # and its tilt in it
    "fx": "N",  # contact force on the slider
    "fy": "N",
    "friction_power": "W",
    "damping_power": "W",
}  # and per contact: fn_<contact> [N], vt_<contact> [m/s]


def surfaces(joint: object) -> dict[str, float]:
    """{mapped surface: its length [m]}, in the order of the kernel's wear array."""
    c = joint.clearance
    guide = c.guide_length
    lengths = (guide, guide, c.slider_length, c.slider_length)
    return {name: length for name, length in zip(SURFACES, lengths, strict=True) if length}


class TranslationalKind(ClearanceKind):
    """A slider in its guide."""

    name = "translational"
    schema = TranslationalJoint
    kernel = "slider"
    wear_position = "position_m"
    impact_columns = ("contact", "guide_position_m")
    figures_module = f"{__name__}.figures"
    animation_module = f"{__name__}.animation"
    references = MappingProxyType({
        "flores2008translational": (
            'P. Flores, J. Ambrósio, J.C.P. Claro, H.M. Lankarani, "Translational joints with '
            'clearance in rigid multibody systems", Journal of Computational and Nonlinear '
            "Dynamics 3 (2008) 011007"
        ),
    })  # fmt: skip
    citations = ("flores2008translational",)  # the model of the contacts
    range_words = MappingProxyType({
        "penetration_over_gap": "penetration / gap",
        "hertz_half_width_over_corner_radius": "Hertz half-width / corner radius",
    })  # fmt: skip
    surfaces = SURFACES
    ideal_rows = ("angle", "line")
    older_state_names = MappingProxyType({field: f"slider_{field}" for field in STATE_FIELDS})
    pins_points = False
    slides = True
    life_runs = True
    penetration_range = "penetration_over_gap"
    growth_limit = (
        "The contact stiffness is that of the nominal corners and the worn profiles enter "
        "only as depths across the guide"
    )
    figures = (
        ("slider_motion", "plot_slider_motion"),
        ("slider_corner_forces", "plot_corner_forces"),
        ("slider_wear", "plot_guide_wear"),
    )

    @override
    def gap(self, joint: object) -> float:
        return joint.clearance.clearance_gap

    @override
    def row(
        self, joint: object, model: object, bodies: tuple[int, int], angle0: float
    ) -> tuple[list[int], NDArray[np.float64]]:
        from ...model.clearance import law_parameters
        from ...model.laws.record import HERTZ_PATCH, PENETRATION

        sc = self.module
        clearance = joint.clearance
        points = [model.point(b, p) for b, p in zip(joint.bodies, joint.points, strict=True)]
        axis = np.array(joint.axis, dtype=float)
        axis /= np.linalg.norm(axis)
        laws = law_parameters(clearance)
        ints = [0] * sc.N_INTS
        ints[sc.I_GUIDE], ints[sc.I_SLIDER] = bodies
        ints[sc.I_NORMAL] = laws["normal"].code
        ints[sc.I_DAMPING] = laws["damping"].code
        ints[sc.I_FRICTION] = laws["friction"].code
        ints[sc.I_WEAR] = laws["wear"].code
        ints[sc.I_FEEDBACK] = int(clearance.wear_feedback)
        ints[sc.I_SEGMENTS] = clearance.segments
        ints[sc.I_ENDS] = int(clearance.guide_length is not None)
        c, s = np.cos(angle0), np.sin(angle0)
        param = np.zeros(sc.N_PARAMS)
        param[[sc.P_G_X, sc.P_G_Y]] = points[0]
        param[[sc.P_U_X, sc.P_U_Y]] = axis
        param[[sc.P_S_X, sc.P_S_Y]] = points[1]
        param[[sc.P_US_X, sc.P_US_Y]] = (c * axis[0] + s * axis[1], -s * axis[0] + c * axis[1])
        param[sc.P_A] = 0.5 * clearance.slider_length
        param[sc.P_B] = 0.5 * clearance.slider_height
        param[sc.P_H] = clearance.guide_half_height
        param[sc.P_L] = 0.5 * (clearance.guide_length or 0.0)
        param[sc.P_K] = clearance.stiffness
        param[sc.P_EXP] = clearance.exponent
        (param[sc.P_CE],) = laws["damping"].parameters
        param[sc.P_CF] = clearance.friction_coefficient
        param[[sc.P_F0, sc.P_F1, sc.P_F2]] = laws["friction"].parameters
        param[sc.P_WEAR] = laws["wear"].parameters[0]
        param[sc.P_SHARE] = clearance.slider_wear_share
        param[sc.P_WIDTH] = clearance.width
        param[sc.P_ESTAR] = clearance.contact_modulus
        param[sc.P_MIN_SPEED] = clearance.min_impact_speed
        param[sc.P_TOL] = clearance.contact_tolerance
        param[sc.P_ANGLE0] = angle0
        ranges = clearance.law_ranges()
        param[sc.P_RSTAR] = clearance.corner_radius or 0.0  # not given: the patch unchecked
        param[sc.P_DEPTH_LIMIT] = ranges[PENETRATION]
        param[sc.P_PATCH_LIMIT] = ranges.get(HERTZ_PATCH, 0.0) if clearance.corner_radius else 0.0
        return ints, param

    def start_problems(self, joint: object, model: object, place: object) -> list[str]:
        """A slider that starts wholly outside its finite guide."""
        c = joint.clearance
        if c.guide_length is None:
            return []
        guide, slider = joint.bodies
        origin = place(guide, model.point(guide, joint.points[0]))
        axis = place(guide, joint.axis) - place(guide, (0.0, 0.0))
        centre = place(slider, model.point(slider, joint.points[1]))
        x = float((centre - origin) @ axis / np.linalg.norm(axis))
        if abs(x) < 0.5 * (c.guide_length + c.slider_length):
            return []
        return [
            f"joints.{joint.name}: the slider starts wholly outside its guide (its centre "
            f"{x * 1e3:.6g} mm along the axis from the guide's point, the guide "
            f"{c.guide_length * 1e3:.6g} mm long and centred there); move the slider or "
            "the guide's point, or lengthen guide_length"
        ]

    @override
    def columns(self, joint: object) -> tuple[str, ...]:
        return self.module.output_names(joint.clearance.guide_length is not None)

    @override
    def unit(self, quantity: str) -> str | None:
        if quantity.startswith("fn_"):
            return "N"
        if quantity.startswith("vt_"):
            return "m/s"
        return UNITS.get(quantity)

    @override
    def check_title(self, joint: object) -> str:
        return f"translational clearance joint '{joint.name}'"

    @override
    def check_rows(self, joint: object, model: object, y0: NDArray[np.float64]) -> list[tuple]:
        c = joint.clearance
        guide = joint.bodies[0]
        phi = 0.0 if guide == "ground" else y0[3 * model.body_names.index(guide) + 2]
        axis = math.degrees(math.atan2(*reversed(joint.axis)) + phi)
        rows = [
            ("gap on each side c", c.clearance_gap * 1e3, "mm"),
            (f"guide (on '{guide}'): height", 2 * c.guide_half_height * 1e3, "mm"),
            ("  length", "unbounded" if c.guide_length is None else c.guide_length * 1e3, "mm"),
            ("  axis, from global x at the start", axis, "deg"),
            (f"slider (on '{joint.bodies[1]}'): length", c.slider_length * 1e3, "mm"),
            ("  height", c.slider_height * 1e3, "mm"),
            ("contacts", "4 corners" + (" + 4 guide ends" if c.guide_length else ""), ""),
            *stiffness_rows(c),
            ("contact modulus E*", c.contact_modulus / 1e9, "GPa"),
        ]
        if c.corner_radius is not None:
            rows.append(("corner radius r (K = 4/3 E* sqrt(r))", c.corner_radius * 1e3, "mm"))
        for share in PENETRATION_SHARES:
            force, stiffness = c.elastic_force(share * c.clearance_gap)
            rows.append((f"force F at delta = {share:.0%} of c", force / 1e3, "kN"))
            rows.append(("stiffness dF/d(delta) there", stiffness, "N/m"))
        return [*rows, ("segments per surface", c.segments, "")]

    @property
    @override
    def peaks(self) -> tuple[int, ...]:
        return (*super().peaks, self.module.T_DEPTH_MAX, self.module.T_PATCH_MAX)

    def _outside_ranges(self, c: object, row: NDArray[np.float64], duration: float) -> dict:
        """The penetration against the gap, and the corner's Hertz half-width against its radius.

        The half-width where ``corner_radius`` is given; the entries named for this joint.
        """
        from ...model.laws.record import HERTZ_PATCH, PENETRATION

        ks = self.module
        names = {PENETRATION: self.penetration_range}
        if c.corner_radius is not None:
            names[HERTZ_PATCH] = "hertz_half_width_over_corner_radius"
        totals = {
            self.penetration_range: (ks.T_DEPTH_TIME, ks.T_DEPTH_MAX),
            "hertz_half_width_over_corner_radius": (ks.T_PATCH_TIME, ks.T_PATCH_MAX),
        }
        limits = {names[r]: limit for r, limit in c.law_ranges().items() if r in names}
        return range_report(limits, totals, row, duration)

    @override
    def wear_rows(self, joint: object, wear: NDArray[np.float64]) -> list[tuple]:
        n = joint.clearance.segments
        rows = []
        for surface, length in surfaces(joint).items():
            s = SURFACES.index(surface)
            centres = segment_centres(length, n)
            rows += [(surface, i, centres[i], wear[s, i]) for i in range(n)]
        return rows

    @override
    def impact_row(self, info: NDArray[np.float64]) -> dict[str, object]:
        ks = self.module
        return {
            "penetration_velocity_m_s": float(info[ks.IMPACT_SPEED]),
            "contact": ks.CONTACT_NAMES[int(info[ks.IMPACT_CONTACT])],
            "guide_position_m": float(info[ks.IMPACT_X_GUIDE]),
            "penetration_m": float(info[ks.IMPACT_DELTA]),
        }

    @override
    def summary(
        self, joint: object, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
    ) -> dict[str, object]:
        c = joint.clearance
        entry = common_figures(self, totals, duration)
        entry = {
            "type": entry.pop("type"),
            self.gap_key: c.clearance_gap,
            **entry,
            "outside_law_ranges": self._outside_ranges(c, totals, duration),
        }
        for surface, length in surfaces(joint).items():
            depth, peak = deepest(wear[SURFACES.index(surface), : c.segments])
            entry[f"max_wear_depth_{surface}_m"] = depth
            entry[f"max_wear_position_{surface}_m"] = (
                None if peak is None else float(segment_centres(length, c.segments)[peak])
            )
        return entry

    @override
    def mapped_surfaces(self, joint: object) -> tuple[str, ...]:
        return tuple(surfaces(joint))

    @override
    def clearance_growth(
        self, joint: object, wear: NDArray[np.float64], timeseries: Sequence[object]
    ) -> float:
        n = joint.clearance.segments
        deepest = {s: float(wear[SURFACES.index(s), :n].max()) for s in surfaces(joint)}
        return max(
            deepest.get(f"guide_{side}", 0.0) + deepest[f"slider_{side}"]
            for side in ("top", "bottom")
        )

    @override
    def worn_volume(self, joint: object, wear: NDArray[np.float64]) -> float:
        """Depth x segment length x width, summed over the mapped surfaces' segments."""
        c = joint.clearance
        return float(
            sum(
                wear[SURFACES.index(surface), : c.segments].sum() * length / c.segments
                for surface, length in surfaces(joint).items()
            )
            * c.width
        )

    @override
    def worn_through(self, joint: object, wear: NDArray[np.float64], when: str) -> str | None:
        c = joint.clearance
        top, bottom = (wear[SURFACES.index(f"slider_{s}"), : c.segments] for s in ("top", "bottom"))
        depth = float((top + bottom).max())
        if depth < c.slider_height:
            return None
        return (
            f"the slider would be worn {depth * 1e3:.4g} mm deep, top and bottom together, "
            f"{when}, through its height {c.slider_height * 1e3:.4g} mm"
        )


KIND = TranslationalKind()
