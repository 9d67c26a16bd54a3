"""Schema of a revolute joint's ``[joints.clearance]`` table (docs/model-format.md).

The joint's first body carries the bearing (the hole, centred on the joint's first point),
the second the journal (the pin, centred on its second point). Laws are chosen by name from
the kernels' codes; each law's parameters are separate keys, and a key that the chosen law
does not use is refused, so a model never carries a setting that silently does nothing.
``ContactKeys`` holds what every clearance joint shares (materials, laws, wear); the
translational joint's table is ``model.slide_clearance``.
"""

import math
from collections.abc import Callable
from functools import partial
from typing import Annotated, NamedTuple

from annotated_types import Ge, Gt, Le
from pydantic import BeforeValidator, create_model, model_validator

from ..kernels.laws.friction import FRICTION_LAWS as FRICTION_FAMILY
from ..kernels.laws.lubrication import LUBRICATION_LAWS as LUBRICATION_FAMILY
from ..kernels.laws.normal import DAMPING_LAWS as DAMPING_FAMILY
from ..kernels.laws.normal import NORMAL_LAWS as NORMAL_FAMILY
from ..kernels.laws.normal import (
    ElasticLaw,
    effective_modulus,
    effective_radius,
    elastic_force,
    elastic_stiffness,
    foundation_modulus,
    internal_cylinder_stiffness,
)
from ..kernels.laws.registry import Key, Law, by_name, family_keys
from ..kernels.laws.wear import WEAR_LAWS as WEAR_FAMILY
from ..kernels.laws.wear import hertz_line_contact
from ..units import Length, Pressure, Speed, Viscosity, WearCoefficient, to_si
from .tables import Number, Table, one_of

NORMAL_LAWS = by_name(NORMAL_FAMILY)
DAMPING_LAWS = by_name(DAMPING_FAMILY)
FRICTION_LAWS = by_name(FRICTION_FAMILY)
WEAR_LAWS = by_name(WEAR_FAMILY)
LUBRICATION_LAWS = by_name(LUBRICATION_FAMILY)
FAMILIES = {"normal": ("normal_law", NORMAL_LAWS), "damping": ("damping", DAMPING_LAWS),
            "friction": ("friction_law", FRICTION_LAWS), "wear": ("wear_law", WEAR_LAWS),
            "lubrication": ("lubrication", LUBRICATION_LAWS)}  # fmt: skip
# How a step's wear goes into the sectors; the value is the kernel's code (journal.I_SPREAD).
WEAR_DISTRIBUTIONS = {"hertz": 0, "peak": 1, "elastic_foundation": 2}
# Before damping was its own key, normal_law named a damped Hertz law: still read that way.
_DAMPED_HERTZ = ("lankarani_nikravesh", "hunt_crossley", "flores2011")

PositiveLength = Annotated[Length, Gt(0)]
Modulus = Annotated[Pressure, Gt(0)]
Poisson = Annotated[Number, Ge(0), Le(0.5)]
PositiveSpeed = Annotated[Speed, Gt(0)]


def _users(laws: dict[str, Law]) -> dict[str, tuple[str, ...]]:
    """{key: the laws of a family that read it}, from the family's registry."""
    users: dict[str, tuple[str, ...]] = {}
    for law in laws.values():
        for key in law.keys:
            users[key.name] = (*users.get(key.name, ()), law.name)
    return users


# Keys that only some laws use: {law key: {key: the laws that use it}}.
_LAW_KEYS = {law_key: _users(laws) for law_key, laws in FAMILIES.values()}
# The value type of a law key by its registry unit (a pint unit string; "" a plain number).
_KEY_TYPES = {"": Number, "m": Length, "m/s": Speed, "Pa": Pressure, "1/Pa": WearCoefficient,
              "Pa*s": Viscosity}  # fmt: skip


def _key_field(key: Key) -> tuple[object, object]:
    """(annotation, default) of a law's key in the schema, from its registry record."""
    bounds = [] if key.low is None else [Gt(key.low) if key.positive else Ge(key.low)]
    bounds += [] if key.high is None else [Le(key.high)]
    value = Annotated[(_KEY_TYPES[key.unit], *bounds)] if bounds else _KEY_TYPES[key.unit]
    if key.default is None:
        return value | None, None
    return value, key.default


_LawKeys = create_model(
    "_LawKeys",
    __base__=Table,
    **{
        name: _key_field(key)
        for _, laws in FAMILIES.values()
        for name, key in family_keys(tuple(laws.values())).items()
    },
)


class PackedLaw(NamedTuple):
    """A chosen law's code and its parameters as the kernels read them (SI)."""

    code: int
    parameters: tuple[float, ...]


def law_parameters(clearance: "ContactKeys") -> dict[str, PackedLaw]:
    """Per family ("normal", "friction", "wear"): the chosen law's code and packed parameters."""
    return {family: _packed(clearance, law_key, laws) for family, (law_key, laws) in
            FAMILIES.items()}  # fmt: skip


def _packed(clearance: "ContactKeys", law_key: str, laws: dict[str, Law]) -> PackedLaw:
    """The chosen law of one family, packed; ValueError saying what it needs, if it cannot."""
    law = laws[getattr(clearance, law_key)]
    values = {key.name: getattr(clearance, key.name) for key in law.keys}
    return PackedLaw(law.code, law.pack(values))


DERIVED_CHECK_SHARES = (0.01, 0.1, 0.4)  # of the clearance: penetrations the laws must handle
DERIVED_CHECK_FORCE = 1000.0  # [N] a load the Hertz patch must handle
HERTZ_EXPONENT = 1.5  # the exponent the internal-cylinder stiffness formula is for


def _plain_stiffness(value: object) -> object:
    if isinstance(value, str):
        raise ValueError(
            f"{value!r}: give K as a plain number in SI units, N/m^exponent (units are not "
            "read here: they depend on exponent)"
        )
    return value


class ContactKeys(_LawKeys):
    """The keys every clearance joint shares: materials, contact, friction and wear laws (SI).

    The keys of the laws (restitution, friction speeds, wear coefficients, ...) come from the
    law registries (``_LawKeys``). Pairs of material values are [first body, second body].
    """

    width: PositiveLength
    youngs_modulus: Modulus | tuple[Modulus, Modulus]  # both, or [first body, second body]
    poisson_ratio: Poisson | tuple[Poisson, Poisson]
    normal_law: Annotated[str, one_of(NORMAL_LAWS, "normal law")] = "hertz"
    damping: Annotated[str, one_of(DAMPING_LAWS, "damping law")] = "lankarani_nikravesh"
    exponent: Annotated[Number, Gt(0)] = 1.5
    contact_stiffness: Annotated[Number, Gt(0), BeforeValidator(_plain_stiffness)] | None = None
    min_impact_speed: PositiveSpeed = 1e-3
    contact_tolerance: PositiveLength = 1e-10
    friction_law: Annotated[str, one_of(FRICTION_LAWS, "friction law")] = "ambrosio"
    friction_coefficient: Annotated[Number, Ge(0)]
    wear_law: Annotated[str, one_of(WEAR_LAWS, "wear law")] = "archard"
    lubrication: Annotated[str, one_of(LUBRICATION_LAWS, "lubrication")] = "none"
    wear_feedback: bool = True

    @model_validator(mode="before")
    @classmethod
    def _damped_hertz(cls, data: object) -> object:
        """Read normal_law = "<damping law>" as a Hertz law with that damping."""
        if not isinstance(data, dict) or data.get("normal_law") not in _DAMPED_HERTZ:
            return data
        law = data["normal_law"]
        if data.get("damping", law) != law:
            raise ValueError(
                f"normal_law '{law}' is a Hertz law with damping '{law}', and damping is "
                f"'{data['damping']}'; give normal_law = \"hertz\" and one damping"
            )
        return {**data, "normal_law": "hertz", "damping": law}

    def _unused_keys(self) -> list[str]:
        lines = []  # a default value is not a setting (and model.json writes them all)
        for law_key, users in _LAW_KEYS.items():
            chosen = getattr(self, law_key)
            for key, laws in users.items():
                given = getattr(self, key) != type(self).model_fields[key].default
                if given and chosen not in laws:
                    names = " or ".join(f"'{law}'" for law in laws)
                    lines.append(
                        f"{key} is used by {law_key} {names} only, and this joint's "
                        f"{law_key} is '{chosen}'; remove it or choose another {law_key}"
                    )
        return lines

    def _law_problems(self) -> list[str]:
        lines = []
        for law_key, laws in FAMILIES.values():
            try:
                _packed(self, law_key, laws)
            except ValueError as error:
                lines.append(f"{law_key} '{getattr(self, law_key)}': {error}")
        power_law = {"exponent": self.exponent != HERTZ_EXPONENT,
                     "contact_stiffness": self.contact_stiffness is not None}  # fmt: skip
        for key in (key for key, given in power_law.items() if given):
            if self.normal_law != "hertz":
                lines.append(
                    f"{key} is used by normal_law 'hertz' only, and this joint's normal_law is "
                    f"'{self.normal_law}' (its stiffness follows from the materials and "
                    'geometry); remove it or choose normal_law = "hertz"'
                )
        if (
            self.normal_law == "hertz"
            and self.exponent != HERTZ_EXPONENT
            and self.contact_stiffness is None
        ):
            lines.append(
                f"exponent {self.exponent:g} needs contact_stiffness [N/m^{self.exponent:g}]: "
                f"the stiffness formula is for exponent {HERTZ_EXPONENT:g}"
            )
        return lines

    def _derived_problems(self, gap: float) -> list[str]:
        """A problem if the contact law gives no finite positive value where ``check`` looks.

        At 1, 10 and 40 % of the clearance ``gap`` [m], and for the Hertz patch at 1 kN: values
        at the edges of floating point (a width of 1e300 m) overflow or vanish there.
        """
        values: dict[str, Callable[[], tuple[float, float]]] = {
            f"force at {share:.0%} of the clearance": partial(self.elastic_force, share * gap)
            for share in DERIVED_CHECK_SHARES
        }
        patch = getattr(self, "hertz_patch", None)
        if patch is not None:
            values[f"Hertz patch at {DERIVED_CHECK_FORCE:g} N"] = partial(
                patch, DERIVED_CHECK_FORCE
            )
        for name, compute in values.items():
            try:
                usable = all(math.isfinite(v) and v > 0.0 for v in compute())
            except (ArithmeticError, ValueError):
                usable = False
            if not usable:
                return [
                    f"the contact cannot be computed with these values (its {name} is not a "
                    "finite positive number); check the sizes, moduli and stiffness against "
                    "their units"
                ]
        return []

    def _pair(self, value: float | tuple[float, float]) -> tuple[float, float]:
        return (value, value) if isinstance(value, float | int) else value

    @property
    def moduli(self) -> tuple[float, float]:
        """Young's moduli of (first body, second body) [Pa]."""
        return self._pair(self.youngs_modulus)

    @property
    def poisson_ratios(self) -> tuple[float, float]:
        """Poisson's ratios of (first body, second body) [-]."""
        return self._pair(self.poisson_ratio)

    @property
    def contact_modulus(self) -> float:
        """E* [Pa] of the two materials."""
        (e_b, e_j), (nu_b, nu_j) = self.moduli, self.poisson_ratios
        return effective_modulus(e_b, nu_b, e_j, nu_j)

    @property
    def archard_coefficient(self) -> float:
        """Archard's dimensional k [1/Pa] (wear_coefficient, or K / H); 0 for Reye."""
        if self.wear_law != "archard":
            return 0.0
        if self.wear_coefficient is not None:
            return self.wear_coefficient
        return self.dimensionless_wear_coefficient / self.hardness


class Clearance(ContactKeys):
    """A revolute joint with clearance: journal in bearing, contact, friction and wear (SI).

    Material pairs are [bearing, journal].
    """

    bearing_radius: PositiveLength
    journal_radius: PositiveLength
    journal_wear_share: Annotated[Number, Ge(0), Le(1)] = 0.5
    wear_distribution: Annotated[str, one_of(WEAR_DISTRIBUTIONS, "wear distribution")] = "hertz"
    sectors: Annotated[int, Ge(4), Le(100_000)] = 36

    @model_validator(mode="before")
    @classmethod
    def _radial_clearance(cls, data: object) -> object:
        """Read ``radial_clearance`` c as the bearing radius journal_radius + c [m]."""
        if not isinstance(data, dict) or "radial_clearance" not in data:
            return data
        rest = {key: value for key, value in data.items() if key != "radial_clearance"}
        if "journal_radius" not in data:
            raise ValueError(
                "radial_clearance needs journal_radius: the bearing radius is the journal's "
                "plus the clearance"
            )
        clearance = to_si(data["radial_clearance"], "[length]", "radial_clearance")
        journal = to_si(data["journal_radius"], "[length]", "journal_radius")
        if not clearance > 0.0:
            raise ValueError(f"radial_clearance: got {clearance:g} m; must be > 0")
        return {**rest, "bearing_radius": journal + clearance}

    @model_validator(mode="after")
    def _consistent(self) -> "Clearance":
        problems = [*self._unused_keys(), *self._law_problems()]
        if self.normal_law == "elastic_foundation" and self.poisson_ratios[0] >= 0.5:
            problems.append(
                "normal_law 'elastic_foundation' needs the bearing's poisson_ratio below 0.5 "
                "(its layer modulus (1 - nu) E / ((1 + nu)(1 - 2 nu)) is infinite at 0.5)"
            )
        if self.journal_radius >= self.bearing_radius:
            problems.append(
                f"journal_radius {self.journal_radius * 1e3:.12g} mm must be smaller than "
                f"bearing_radius {self.bearing_radius * 1e3:.12g} mm (the radial clearance is "
                "their difference)"
            )
        elif self.contact_tolerance >= self.radial_clearance:
            problems.append(
                f"contact_tolerance {self.contact_tolerance:g} m must be much smaller than the "
                f"radial clearance {self.radial_clearance:g} m (default 1e-10 m)"
            )
        if not problems:
            problems = self._derived_problems(self.radial_clearance)
        if problems:
            raise ValueError("; ".join(problems))
        return self

    @property
    def radial_clearance(self) -> float:
        """Radial clearance c = R_B - R_J [m]."""
        return self.bearing_radius - self.journal_radius

    @property
    def relative_radius(self) -> float:
        """R* = R_B R_J / (R_B - R_J) [m]."""
        return effective_radius(self.bearing_radius, self.journal_radius)

    @property
    def stiffness(self) -> float:
        """The elastic law's constant K, as the kernels read it.

        hertz: ``contact_stiffness`` if given, else the internal-cylinder formula
        [N/m^exponent]; elastic_foundation: (K_f / h) R_B [Pa], the layer on the bearing;
        0 for the laws that need none.
        """
        (e_b, e_j), (nu_b, nu_j) = self.moduli, self.poisson_ratios
        if self.normal_law == "elastic_foundation":
            return foundation_modulus(e_b, nu_b) / self.foundation_thickness * self.bearing_radius
        if self.normal_law != "hertz":
            return 0.0
        if self.contact_stiffness is not None:
            return self.contact_stiffness
        return internal_cylinder_stiffness(
            self.bearing_radius, self.journal_radius, e_b, nu_b, e_j, nu_j
        )

    def elastic_force(self, delta: float) -> tuple[float, float]:
        """(force [N], stiffness dF/d(delta) [N/m]) of the elastic law at delta [m], unworn."""
        code = ElasticLaw[self.normal_law.upper()]
        args = (delta, self.stiffness, self.exponent, self.contact_modulus,
                self.radial_clearance, self.width)  # fmt: skip
        return elastic_force(code, *args), elastic_stiffness(code, *args)

    def hertz_patch(self, force: float) -> tuple[float, float]:
        """Half-width b [m] and peak pressure p_max [Pa] of the line contact under force [N]."""
        return hertz_line_contact(force, self.relative_radius, self.contact_modulus, self.width)
