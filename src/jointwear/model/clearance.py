"""What every ``[joints.clearance]`` table has: materials, laws and wear (docs/model-format.md).

Laws are chosen by name from their records (``model.laws``); each law's parameters are
separate keys, and a key that the chosen law does not use is refused, so a model never carries
a setting that silently does nothing. Validation reads only the records: nothing here imports
the compiled kernels, except the derived numbers asked for at the point of use
(``elastic_force``, ``hertz_patch``, ``computation_problems``). ``ClearanceTable`` holds
what every joint type's clearance table shares (materials, laws, wear); each joint type
subclasses it (``joints.<type>.schema``).
"""

import math
from collections.abc import Callable
from functools import cache, partial
from typing import TYPE_CHECKING, Annotated, ClassVar, NamedTuple

from annotated_types import Ge, Gt, Le
from pydantic import AfterValidator, BeforeValidator, ConfigDict, create_model, model_validator

from ..units import Length, Pressure, Speed, Viscosity, WearCoefficient, registry, to_si
from .errors import unknown
from .laws import DAMPING, EVERY, FRICTION, LUBRICATION, NORMAL, SHARED, WEAR, WEAR_DISTRIBUTION
from .laws import user as user_laws
from .laws.normal import effective_modulus
from .laws.record import SHAPE_NAMES, Contact, Family, Key, Law, family_keys
from .tables import Number, Table

if TYPE_CHECKING:
    from .schema import Model

# The shared families by title, and the distributions' codes.
FAMILIES = {family.title: family for family in SHARED}
WEAR_DISTRIBUTIONS = {law.name: law.code for law in WEAR_DISTRIBUTION.laws}

PositiveLength = Annotated[Length, Gt(0)]
Modulus = Annotated[Pressure, Gt(0)]
Poisson = Annotated[Number, Ge(0), Le(0.5)]
PositiveSpeed = Annotated[Speed, Gt(0)]


def _plain_stiffness(value: object) -> object:
    if isinstance(value, str):
        raise ValueError(
            f"{value!r}: give K as a plain number in SI units, N/m^exponent (units are not "
            "read here: they depend on exponent)"
        )
    return value


# The value type of a law key by its registry unit (a pint unit string; "" a plain number).
_KEY_TYPES = {"": Number, "m": Length, "m/s": Speed, "Pa": Pressure, "1/Pa": WearCoefficient,
              "Pa*s": Viscosity,
              "N/m^n": Annotated[Number, BeforeValidator(_plain_stiffness)]}  # fmt: skip


def _value_type(unit: str) -> object:
    """The value type of a key in ``unit``: a built-in key's, or any SI unit pint reads."""
    if unit in _KEY_TYPES:
        return _KEY_TYPES[unit]
    dimension = str(registry().get_dimensionality(unit))
    return Annotated[float, BeforeValidator(partial(to_si, dimension=dimension))]


def _key_field(key: Key) -> tuple[object, object]:
    """(annotation, default) of a law's key in the schema, from its record."""
    bounds = [] if key.low is None else [Gt(key.low) if key.positive else Ge(key.low)]
    bounds += [] if key.high is None else [Le(key.high)]
    value = _value_type(key.unit)
    value = Annotated[(value, *bounds)] if bounds else value
    if key.default is None:
        return value | None, None
    return value, key.default


_LawKeys = create_model(
    "_LawKeys",
    __base__=Table,
    **{name: _key_field(key) for family in EVERY for name, key in family_keys(family).items()},
)


class PackedLaw(NamedTuple):
    """A chosen law's code and its parameters as the kernels read them (SI)."""

    code: int
    parameters: tuple[float, ...]


def law_parameters(clearance: "ClearanceTable") -> dict[str, PackedLaw]:
    """Per family title ("normal", "friction", ...): the chosen law's code and packed parameters."""
    return {
        family.title: PackedLaw(law.code, law.pack(clearance.law_values(law)))
        for family, law in clearance.chosen_laws()
    }


def _unused(key: str, family: Family, readers: list[str], chosen: Law) -> str:
    """The line refusing ``key``, which only the laws ``readers`` of ``family`` read."""
    names = " or ".join(f"'{name}'" for name in readers)
    return (
        f"{key} is used by {family.key} {names} only, and this joint's {family.key} is "
        f"'{chosen.name}'; remove it or choose another {family.key}"
    )


DERIVED_CHECK_SHARES = (0.01, 0.1, 0.4)  # of the clearance: penetrations the laws must handle
DERIVED_CHECK_FORCE = 1000.0  # [N] a load the Hertz patch must handle


def law_name(family: Family) -> object:
    """The type of a key naming one of ``family``'s laws, built-in or registered from Python."""
    what = family.title + " law"

    def check(value: str) -> str:
        laws = family.by_name
        if value not in laws:
            registering = (
                "; a law of your own must be registered before the model is loaded "
                "(jointwear.register_law)"
                if family.key in user_laws.ROLES
                else ""
            )
            raise ValueError(unknown(what, value, list(laws), f"known {what}s") + registering)
        return value

    return Annotated[str, AfterValidator(check)]


@cache
def _law_names_table(keys: tuple[str, ...]) -> type[Table]:
    """A table of the law-naming keys ``keys`` (``normal_law``, ...), to validate them first."""
    families = {family.key: family for family in EVERY}
    return create_model(
        "LawNames", __base__=Table, **{key: (law_name(families[key]), ...) for key in keys}
    )


@cache
def _own_keys_table(keys: tuple[Key, ...]) -> type[Table]:
    """A table of the own keys ``keys`` of laws registered from Python, to validate them."""
    return create_model("OwnKeys", __base__=Table, **{key.name: _key_field(key) for key in keys})


class ClearanceTable(_LawKeys):
    """The keys every clearance joint shares: materials, contact, friction and wear laws (SI).

    The keys of the laws (restitution, friction speeds, wear coefficients, ...) come from the
    law records (``_LawKeys``). Pairs of material values are [first body, second body]. An
    element kind's table gives its ``contact`` and the law families it chooses from.
    docs/model-format.md lists every key with its default and bounds.

    Attributes
    ----------
    width
        Length of the contact along the joint's axis [m].
    youngs_modulus
        E [Pa]: one value, or (first body, second body).
    poisson_ratio
        nu [-]: one value, or (first body, second body).
    normal_law, damping, friction_law, wear_law, lubrication
        The laws chosen, by name.
    min_impact_speed
        Floor of the impact speed that scales the damping [m/s].
    contact_tolerance
        Penetration at which a contact period begins [m].
    friction_coefficient
        c_f, the sliding friction coefficient [-].
    wear_feedback
        Whether the worn profiles enlarge the clearance in the penetration.
    restitution_coefficient
        c_e [-] (the damping laws).
    exponent, contact_stiffness, foundation_thickness
        n [-], K [N/m^n] and the elastic layer's thickness [m] (the elastic laws).
    no_friction_speed, full_friction_speed
        v0, v1 [m/s] (``ambrosio``).
    regularisation_speed
        [m/s] (``coulomb``).
    stiction_speed, transition_speed
        [m/s] (``stick_slip``).
    static_friction_coefficient
        mu_s [-] (``stick_slip``).
    wear_coefficient
        Archard's k [1/Pa]; or ``dimensionless_wear_coefficient`` K [-] with ``hardness`` H
        [Pa] of the softer surface, k = K / H.
    shear_strength
        tau [Pa] (``reye``).
    viscosity, film_breakdown
        The lubricant's dynamic viscosity [Pa s] and, for the short and long bearings, the
        eccentricity ratio [-] where the film hands over to solid contact (numerical).
    roughness, roughness_parameter, asperity_slope
        The finite bearing's mixed film: the surfaces' combined RMS roughness sigma [m], eta
        sigma beta [-] and sigma / beta [-] of their asperities (Greenwood and Tripp).
    """

    FAMILIES: ClassVar[tuple[Family, ...]] = SHARED
    model_config = ConfigDict(extra="allow", frozen=True)  # the own keys of registered laws

    width: PositiveLength
    youngs_modulus: Modulus | tuple[Modulus, Modulus]  # both, or [first body, second body]
    poisson_ratio: Poisson | tuple[Poisson, Poisson]
    normal_law: law_name(NORMAL) = NORMAL.default
    damping: law_name(DAMPING) = DAMPING.default
    min_impact_speed: PositiveSpeed = 1e-3
    contact_tolerance: PositiveLength = 1e-10
    friction_law: law_name(FRICTION) = FRICTION.default
    friction_coefficient: Annotated[Number, Ge(0)]
    wear_law: law_name(WEAR) = WEAR.default
    lubrication: law_name(LUBRICATION) = LUBRICATION.default
    wear_feedback: bool = True

    # pydantic runs a class's before-validators from the last defined: this one runs after
    # _damped_default_law, and before every table's check of unknown keys (model.tables).
    @model_validator(mode="before")
    @classmethod
    def _laws_known_first(cls, data: object) -> object:
        """An unknown law name before the keys: a law not registered makes its keys unknown."""
        if isinstance(data, dict):
            keys = tuple(f.key for f in cls.FAMILIES if f.key in data)
            _law_names_table(keys).model_validate({key: data[key] for key in keys})
        return data

    @model_validator(mode="before")
    @classmethod
    def _damped_default_law(cls, data: object) -> object:
        """Read normal_law = "<damping law>" as the default elastic law with that damping."""
        if not isinstance(data, dict):
            return data
        law = data.get("normal_law")
        if law not in DAMPING.by_name or law == DAMPING.laws[0].name:
            return data
        if data.get("damping", law) != law:
            raise ValueError(
                f"normal_law '{law}' is a {NORMAL.default} law with damping '{law}', and "
                f"damping is '{data['damping']}'; give normal_law = \"{NORMAL.default}\" and "
                "one damping"
            )
        return {**data, "normal_law": NORMAL.default, "damping": law}

    @classmethod
    def known_keys(cls) -> list[str]:
        """Its fields, and the own keys of the laws registered from Python."""
        return [*cls.model_fields, *user_laws.own_keys()]

    @model_validator(mode="before")
    @classmethod
    def _own_keys_in_si(cls, data: object) -> object:
        """The own keys of registered laws, validated and in SI, as the fields are."""
        if not isinstance(data, dict):
            return data
        own = user_laws.own_keys()
        given = {name: value for name, value in data.items() if name in own}
        if not given:
            return data
        table = _own_keys_table(tuple(own[name] for name in given))
        values = table.model_validate(given)  # its ValidationError names each key
        return {**data, **values.model_dump()}

    @property
    def contact(self) -> Contact:
        """The contact as the laws see it (the element kind's table defines it)."""
        raise NotImplementedError

    def chosen_laws(self) -> list[tuple[Family, Law]]:
        """(family, the chosen law's record) for each family of this table."""
        return [(family, family.by_name[getattr(self, family.key)]) for family in self.FAMILIES]

    def law_values(self, law: Law) -> dict[str, float | None]:
        """The values of the keys ``law`` reads (SI; None: not given)."""
        own = self.model_extra or {}
        return {
            key.name: getattr(self, key.name) if key.name in type(self).model_fields
            else own.get(key.name, key.default)
            for key in law.keys
        }  # fmt: skip

    def unused_law_keys(self) -> set[str]:
        """The keys of this table's law families that its chosen laws do not read."""
        read = {key.name for _, law in self.chosen_laws() for key in law.keys}
        return {key for family in self.FAMILIES for key in family_keys(family)} - read

    def _unused_keys(self) -> list[str]:
        lines = []  # a default value is not a setting (and model.json writes them all)
        chosen = self.chosen_laws()
        for family, law in chosen:
            for key in family_keys(family):
                given = getattr(self, key) != type(self).model_fields[key].default
                if given and key not in {k.name for k in law.keys}:
                    users = [other.name for other in family.laws
                             if key in {k.name for k in other.keys}]  # fmt: skip
                    lines.append(_unused(key, family, users, law))
        by_family = {family.key: law for family, law in chosen}
        for key in self.model_extra or {}:  # own keys of laws registered from Python
            users = user_laws.readers(key)
            if not any(by_family[user.family].name == user.name for user in users):
                family = user_laws.FAMILIES[users[0].family]
                readers = [user.name for user in users if user.family == family.key]
                lines.append(_unused(key, family, readers, by_family[family.key]))
        return lines

    def _law_problems(self, shape: str) -> list[str]:
        """Laws that do not apply to this joint's contact ``shape``, or lack their keys."""
        lines = []
        for family, law in self.chosen_laws():
            if shape not in law.shapes:
                where = " or ".join(SHAPE_NAMES[s] for s in law.shapes)
                lines.append(
                    f"{family.key} '{law.name}' applies to {where} only, and this joint's "
                    f"contact is {SHAPE_NAMES[shape]}: choose another {family.key}"
                )
                continue
            try:
                law.pack(self.law_values(law))
            except ValueError as error:
                lines.append(f"{family.key} '{law.name}': {error}")
        return lines

    def _stiffness_problems(self) -> list[str]:
        """The elastic law's stiffness, if it cannot be computed from these values."""
        try:
            self.stiffness  # noqa: B018 - computed for the ValueError it may raise
        except ValueError as error:
            return [f"normal_law '{self.normal_law}': {error}"]
        return []

    def computation_problems(self) -> list[str]:
        """A problem if the contact law gives no finite positive value where ``check`` looks.

        At 1, 10 and 40 % of the clearance, and for the Hertz patch at 1 kN where the table
        has one: values at the edges of floating point (a width of 1e300 m) overflow or
        vanish there. Evaluates the kernels (imports them): call it where a run or ``check``
        is prepared, not at validation.
        """
        gap = self.contact.clearance
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
    def stiffness(self) -> float:
        """The elastic law's constant K, as the kernels read it (its record's ``stiffness``).

        A key that replaces the formula (``contact_stiffness``) if given, else the formula
        for this contact; 0 for a law that needs none. ValueError if it cannot be computed.
        """
        law = NORMAL.by_name[self.normal_law]
        if law.stiffness is None:
            return 0.0
        values = self.law_values(law)
        given = law.stiffness.given_by
        if given is not None and values[given] is not None:
            return values[given]
        return law.stiffness.formula(values, self.contact)

    def law_ranges(self) -> dict[str, float]:
        """{range name: limit} of the chosen laws (``outside_law_ranges``); the first law's wins."""
        ranges: dict[str, float] = {}
        for _, law in self.chosen_laws():
            for name, limit in law.ranges:
                ranges.setdefault(name, getattr(self, limit) if isinstance(limit, str) else limit)
        return ranges

    def law_citations(self) -> list[str]:
        """Keys of ``citations.REFERENCES`` of the chosen laws, in family order.

        After the elastic law's own, its stiffness formula's (where no key replaces it).
        """
        keys: list[str] = []
        for _, law in self.chosen_laws():
            keys += law.citations
            stiffness = law.stiffness
            if stiffness is not None:
                replaced = stiffness.given_by is not None and (
                    getattr(self, stiffness.given_by) is not None
                )
                keys += () if replaced else stiffness.citations.get(self.contact.shape, ())
        return keys

    @property
    def lubricated(self) -> bool:
        """Whether a film carries the joint (a lubrication law with a kernel)."""
        return bool(LUBRICATION.by_name[self.lubrication].kernels)

    def elastic_force(self, delta: float) -> tuple[float, float]:
        """(force [N], stiffness dF/d(delta) [N/m]) of the elastic law at delta [m], unworn.

        Evaluates the kernels (imports them).
        """
        contact = self.contact
        args = (delta, self.stiffness, self.exponent, contact.contact_modulus,
                contact.clearance, self.width)  # fmt: skip
        law = user_laws.registered(self.normal_law)
        if law is not None:
            return user_laws.elastic_force(law, args, self.law_values(NORMAL.by_name[law.name]))
        from ..kernels.laws.normal import elastic_force, elastic_stiffness

        code = NORMAL.by_name[self.normal_law].code
        return elastic_force(code, *args), elastic_stiffness(code, *args)


def contact_problems(model: "Model") -> list[str]:
    """``computation_problems`` of every clearance joint, one line each naming its table.

    Evaluates the kernels (imports them): for the preparation of a run or of ``check``.
    """
    return [
        f"joints[{i}].clearance: {problem}"
        for i, joint in enumerate(model.joints)
        if joint.clearance is not None
        for problem in joint.clearance.computation_problems()
    ]
