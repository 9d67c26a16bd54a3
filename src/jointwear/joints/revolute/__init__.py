"""The revolute joint with clearance: a journal in its bearing (``kernels.elements.journal``).

Wear table rows: ``surface`` is ``bearing`` or ``journal``, ``angle_deg`` the sector's centre
in the surface's body frame. Impact rows: the contact's angle in the bearing's and the
journal's frames. Summary: the common figures, the radial clearance, the deepest wear of each
surface and where, and the law-range checks (``outside_law_ranges``). Life runs: the
clearance growth is the largest over directions and relative angles (``growth``); a journal
worn through its radius stops them.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from types import MappingProxyType

import numpy as np
from numpy.typing import NDArray
from typing_extensions import override

from ...model.laws.lubrication import reads_film_table
from ..kind import (
    PENETRATION_SHARES,
    STATE_FIELDS,
    ClearanceKind,
    common_figures,
    deepest,
    range_report,
    stiffness_rows,
)
from .schema import RevoluteJoint

HERTZ_REFERENCE_FORCES = (100.0, 1000.0)  # loads at which `check` shows the Hertz patch [N]
SURFACES = ("bearing", "journal")  # the first index of the kernel's wear array
UNITS = {
    "fx": "N",  # contact force on the journal
    "fy": "N",
    "ex": "m",  # eccentricity of the journal in its bearing
    "ey": "m",
    "delta": "m",  # penetration
    "fn": "N",  # normal contact force
    "ft": "N",  # friction force
    "vt": "m/s",  # sliding speed at the contact point
    "theta_bearing": "rad",  # direction of the contact normal in the bearing's frame
    "theta_journal": "rad",  # and in the journal's frame
    "delta_dot": "m/s",  # penetration rate
    "fn_elastic": "N",  # the normal force's elastic (undamped) part
    "eps": "1",  # eccentricity ratio (lubricated)
    "film_min": "m",  # minimum film thickness
    "film_fx": "N",
    "film_fy": "N",
    "film_torque": "N m",
    "film_power": "W",
    "asperity_fn": "N",  # load the asperities carry (mixed film), part of fn
    "squeeze_vx": "m/s",  # the film's squeeze velocity V = de/dt - (w / 2) z x e
    "squeeze_vy": "m/s",
    "asperity_share": "1",  # fn / (fn + |film force|)
    "friction_coefficient": "1",  # (boundary + viscous friction power) / (load x sliding speed)
    "lambda": "1",  # film thickness / roughness
    "p_max": "Pa",  # Hertz line contact's peak and mean pressure (tribology.py)
    "p_mean": "Pa",
    "pv": "Pa m/s",
    "friction_power": "W",
    "damping_power": "W",
}


class RevoluteKind(ClearanceKind):
    """A journal in its bearing."""

    name = "revolute"
    schema = RevoluteJoint
    kernel = "journal"
    wear_position = "angle_deg"
    impact_columns = ("bearing_angle_deg", "journal_angle_deg")
    derived_after = "fn_elastic"  # before a lubricated joint's film columns
    figures_module = f"{__name__}.figures"
    animation_module = f"{__name__}.animation"
    surfaces = ("journal", "bearing")  # the journal first, as the paper's Figs. 8-10
    range_words = MappingProxyType({
        "penetration_over_clearance": "penetration / clearance",
        "hertz_half_width_over_journal_radius": "Hertz half-width / journal radius",
        "eccentricity_ratio": "eccentricity ratio (film model)",
    })  # fmt: skip
    ideal_rows = ("x", "y")
    gap_key = "radial_clearance_m"
    life_runs = True
    growth_limit = (
        "The contact stiffness and Hertz patch are those of the nominal radii and the worn "
        "profile enters only radially"
    )
    older_state_names = MappingProxyType({field: field for field in STATE_FIELDS})
    pins_points = True
    figures = (  # the paper's Figs. 7-10, and a finite bearing's film (``draws``)
        ("fig7_dynamics", "plot_dynamics"),
        ("fig7d_orbit", "plot_orbit"),
        ("fig8_wear_sectors", "plot_wear_sectors"),
        ("fig9_wear_polar", "plot_wear_polar"),
        ("fig10_profile", "plot_wear_profile"),
        ("film_pressure", "plot_film_pressure"),
    )
    figures_with_ideal = frozenset({"fig7_dynamics"})

    @property
    @override
    def peaks(self) -> tuple[int, ...]:
        js = self.module
        return (
            *(js.T_MAX_FN, js.T_MAX_DELTA, js.T_PATCH_MAX, js.T_DEPTH_MAX, js.T_FILM_MAX),
            js.T_FILM_CLOSURE,
        )

    @property
    @override
    def energies(self) -> tuple[int, ...]:
        return (*super().energies, self.module.T_FILM_ENERGY)

    @override
    def gap(self, joint: object) -> float:
        return joint.clearance.radial_clearance

    @override
    def row(
        self, joint: object, model: object, bodies: tuple[int, int], angle0: float
    ) -> tuple[list[int], NDArray[np.float64]]:
        from ...model.clearance import WEAR_DISTRIBUTIONS, law_parameters
        from ...model.laws.record import HERTZ_PATCH, PENETRATION

        jc = self.module
        clearance = joint.clearance
        centres = [model.point(b, p) for b, p in zip(joint.bodies, joint.points, strict=True)]
        laws = law_parameters(clearance)
        ints = [0] * jc.N_INTS
        ints[jc.I_BEARING], ints[jc.I_JOURNAL] = bodies
        ints[jc.I_NORMAL] = laws["normal"].code
        ints[jc.I_DAMPING] = laws["damping"].code
        ints[jc.I_LUBRICATION] = laws["lubrication"].code
        ints[jc.I_FRICTION] = laws["friction"].code
        ints[jc.I_WEAR] = laws["wear"].code
        ints[jc.I_SPREAD] = WEAR_DISTRIBUTIONS[clearance.wear_distribution]
        ints[jc.I_FEEDBACK] = int(clearance.wear_feedback)
        ints[jc.I_SECTORS] = clearance.sectors
        param = np.zeros(jc.N_PARAMS)
        param[[jc.P_SB_X, jc.P_SB_Y]] = centres[0]
        param[[jc.P_SJ_X, jc.P_SJ_Y]] = centres[1]
        param[jc.P_RB] = clearance.bearing_radius
        param[jc.P_RJ] = clearance.journal_radius
        param[jc.P_C] = clearance.radial_clearance
        param[jc.P_K] = clearance.stiffness
        param[jc.P_EXP] = clearance.exponent
        (param[jc.P_CE],) = laws["damping"].parameters
        param[jc.P_CF] = clearance.friction_coefficient
        param[[jc.P_F0, jc.P_F1, jc.P_F2]] = laws["friction"].parameters
        param[jc.P_WEAR] = laws["wear"].parameters[0]
        param[jc.P_SHARE] = clearance.journal_wear_share
        param[jc.P_WIDTH] = clearance.width
        param[jc.P_RSTAR] = clearance.relative_radius
        param[jc.P_ESTAR] = clearance.contact_modulus
        param[jc.P_MIN_SPEED] = clearance.min_impact_speed
        param[jc.P_TOL] = clearance.contact_tolerance
        film = [jc.P_VISCOSITY, jc.P_BREAKDOWN, jc.P_ROUGHNESS, jc.P_ASPERITY]
        param[film] = laws["lubrication"].parameters
        param[jc.P_ASPERITY] *= clearance.contact_modulus  # Greenwood-Tripp's E' is E*
        ranges = clearance.law_ranges()
        param[jc.P_DEPTH_LIMIT] = ranges[PENETRATION]
        param[jc.P_PATCH_LIMIT] = ranges.get(HERTZ_PATCH, 0.0)  # 0: the patch is not checked
        return ints, param

    @override
    def draws(self, figure: str, model: object) -> bool:
        """The film pressure only with a finite bearing (the other figures always)."""
        if figure != "film_pressure":
            return True
        return any(reads_film_table(j.clearance.lubrication) for j in self.joints(model))

    @override
    def lookup(self, joint: object) -> NDArray[np.float64]:
        """The finite bearing's impedance table for the joint's L/D, flat; else none."""
        clearance = joint.clearance
        if not reads_film_table(clearance.lubrication):
            return np.zeros(0)
        from ...film.impedance import impedance_table

        width_over_diameter = clearance.width / (2.0 * clearance.journal_radius)
        return impedance_table(width_over_diameter)

    @override
    def columns(self, joint: object) -> tuple[str, ...]:
        jc = self.module
        film = jc.FILM_OUTPUT_NAMES if joint.clearance.lubricated else ()
        return (*jc.OUTPUT_NAMES, *film)

    @override
    def derived_columns(self, joint: object, timeseries: object) -> dict[str, NDArray[np.float64]]:
        from .tribology import tribology_columns  # pandas

        return tribology_columns(joint, timeseries)

    @override
    def unit(self, quantity: str) -> str | None:
        return UNITS.get(quantity)

    @override
    def check_title(self, joint: object) -> str:
        return f"clearance joint '{joint.name}'"

    @override
    def check_rows(self, joint: object, model: object, y0: NDArray[np.float64]) -> list[tuple]:
        clearance = joint.clearance
        rows = [
            ("radial clearance c = R_B - R_J", clearance.radial_clearance * 1e3, "mm"),
            *stiffness_rows(clearance),
        ]
        rows += [
            ("contact modulus E*", clearance.contact_modulus / 1e9, "GPa"),
            ("relative radius R* = R_B R_J / c", clearance.relative_radius, "m"),
        ]
        for share in PENETRATION_SHARES:
            force, stiffness = clearance.elastic_force(share * clearance.radial_clearance)
            rows.append((f"force F at delta = {share:.0%} of c", force / 1e3, "kN"))
            rows.append(("stiffness dF/d(delta) there", stiffness, "N/m"))
        for force in HERTZ_REFERENCE_FORCES:
            b, p_max = clearance.hertz_patch(force)
            rows.append((f"Hertz half-width b at {force:g} N", b * 1e3, "mm"))
            rows.append((f"Hertz peak pressure at {force:g} N", p_max / 1e6, "MPa"))
        cells = f"sectors per surface ({clearance.wear_distribution})"
        return [*rows, *_film_rows(clearance), (cells, clearance.sectors, "")]

    @override
    def wear_rows(self, joint: object, wear: NDArray[np.float64]) -> list[tuple]:
        n = joint.clearance.sectors
        centres = (np.arange(n) + 0.5) * 360.0 / n
        return [
            (surface, i, centres[i], wear[s, i])
            for s, surface in enumerate(SURFACES)
            for i in range(n)
        ]

    @override
    def impact_row(self, info: NDArray[np.float64]) -> dict[str, object]:
        jc = self.module
        return {
            "penetration_velocity_m_s": float(info[jc.IMPACT_SPEED]),
            "bearing_angle_deg": math.degrees(info[jc.IMPACT_THETA_B]),
            "journal_angle_deg": math.degrees(info[jc.IMPACT_THETA_J]),
            "penetration_m": float(info[jc.IMPACT_DELTA]),
        }

    @override
    def summary(
        self, joint: object, totals: NDArray[np.float64], wear: NDArray[np.float64], duration: float
    ) -> dict[str, object]:
        jc = self.module
        c = joint.clearance
        entry = common_figures(self, totals, duration)
        entry = {
            "type": entry.pop("type"),
            self.gap_key: c.radial_clearance,
            **entry,
            "outside_law_ranges": _outside_ranges(jc, c, totals, duration),
        }
        if c.lubricated:
            entry["energy_dissipated_film_j"] = float(totals[jc.T_FILM_ENERGY])
            entry["film"] = _film_summary(jc, c, totals, duration)
        for s, surface in enumerate(SURFACES):
            depth, peak = deepest(wear[s, : c.sectors])
            entry[f"max_wear_depth_{surface}_m"] = depth
            entry[f"max_wear_angle_{surface}_deg"] = (
                None if peak is None else (peak + 0.5) * 360.0 / c.sectors
            )
        return entry

    @override
    def mapped_surfaces(self, joint: object) -> tuple[str, ...]:
        return SURFACES

    @override
    def clearance_growth(
        self, joint: object, wear: NDArray[np.float64], timeseries: Sequence[object]
    ) -> float:
        from .growth import clearance_growth, relative_angle_range

        n = joint.clearance.sectors
        psi = relative_angle_range(joint.bodies, timeseries)
        return clearance_growth(wear[0, :n], wear[1, :n], psi)

    @override
    def worn_volume(self, joint: object, wear: NDArray[np.float64]) -> float:
        """Depth x R x 2 pi / N x L, summed over both surfaces' sectors."""
        c = joint.clearance
        arc = 2.0 * math.pi / c.sectors * c.width
        bearing, journal = wear[0, : c.sectors].sum(), wear[1, : c.sectors].sum()
        return float((bearing * c.bearing_radius + journal * c.journal_radius) * arc)

    @override
    def worn_through(self, joint: object, wear: NDArray[np.float64], when: str) -> str | None:
        c = joint.clearance
        journal = wear[SURFACES.index("journal"), : c.sectors].max()
        if journal < c.journal_radius:
            return None
        return (
            f"the journal would be worn {journal * 1e3:.4g} mm deep {when}, through its radius "
            f"{c.journal_radius * 1e3:.4g} mm"
        )


def _film_rows(c: object) -> list[tuple]:
    """``check`` rows of a mixed film: its L/D, and where and how the asperities take over."""
    if not getattr(c, "roughness", None):
        return []
    from ...kernels.laws.asperity import asperity_load
    from ...model.laws.lubrication import ASPERITY_START, asperity_constant

    scale = asperity_constant(c.roughness_parameter, c.asperity_slope) * c.contact_modulus
    touching = asperity_load(0.0, c.roughness, scale, c.relative_radius, c.width)
    return [
        ("film width / diameter L/D", c.width / (2.0 * c.journal_radius), ""),
        ("roughness sigma", c.roughness * 1e6, "µm"),
        ("asperities touch below film thickness", ASPERITY_START * c.roughness * 1e6, "µm"),
        (
            "  i.e. above eccentricity ratio",
            1.0 - ASPERITY_START * c.roughness / c.radial_clearance,
            "",
        ),
        ("asperity load at film thickness 0", touching / 1e3, "kN"),
    ]


def _film_summary(jc: object, c: object, totals: NDArray[np.float64], duration: float) -> dict:
    """What a tribologist reads of a lubricated joint over ``duration`` [s] (its totals).

    The thinnest film (negative: the mean planes overlapped); lambda is it over the
    roughness; the asperities' share of the load carried (time integrals of
    the solid contact's normal force and of the film force's magnitude); the friction
    coefficient, the work of boundary friction and of the film's friction (what it
    dissipates less the radial squeeze, -f_r d(delta)/dt) over the integral of load x sliding
    speed (for a steadily loaded bearing T_J / (R W)); the Hersey number mu N / P with the
    mean relative speed N [rev/s] and the mean load carried over the projected area L 2 R_J
    [Pa]; the mean friction power of each kind (viscous: all the film dissipates, squeeze
    included).
    """
    thinnest = c.radial_clearance - float(totals[jc.T_FILM_CLOSURE])
    solid, film = float(totals[jc.T_SOLID_IMPULSE]), float(totals[jc.T_FILM_IMPULSE])
    boundary, viscous = float(totals[jc.T_FRICTION_ENERGY]), float(totals[jc.T_FILM_ENERGY])
    moved = float(totals[jc.T_LOAD_SLIDING])
    sheared = float(totals[jc.T_FILM_FRICTION])
    speed = float(totals[jc.T_SPIN]) / (2.0 * math.pi * duration) if duration else 0.0
    pressure = (solid + film) / duration / (c.width * 2.0 * c.journal_radius) if duration else 0.0
    roughness = getattr(c, "roughness", None)
    return {
        "min_film_thickness_m": thinnest,
        "min_lambda": thinnest / roughness if roughness else None,
        "asperity_load_share": solid / (solid + film) if solid + film > 0.0 else 0.0,
        "friction_coefficient": (boundary + sheared) / moved if moved > 0.0 else None,
        "hersey_number": c.viscosity * speed / pressure if pressure > 0.0 else None,
        "friction_power_boundary_w": boundary / duration if duration else 0.0,
        "friction_power_viscous_w": viscous / duration if duration else 0.0,
    }


def _outside_ranges(jc: object, c: object, row: NDArray[np.float64], duration: float) -> dict:
    """``outside_law_ranges`` of the laws this joint uses (their records' ranges)."""
    from ...model.laws.record import ECCENTRICITY, HERTZ_PATCH, PENETRATION

    totals = {  # the kernel's totals (time beyond, largest value) of each range a law may have
        PENETRATION: (jc.T_DEPTH_TIME, jc.T_DEPTH_MAX),
        HERTZ_PATCH: (jc.T_PATCH_TIME, jc.T_PATCH_MAX),
        ECCENTRICITY: (jc.T_FILM_TIME, jc.T_FILM_MAX),
    }
    return range_report(c.law_ranges(), totals, row, duration)


KIND = RevoluteKind()
