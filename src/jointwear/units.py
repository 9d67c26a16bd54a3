"""Physical quantities in model files: plain SI numbers or strings with units.

A value is either a plain number, taken as SI (m, kg, s, rad, N, N m, Pa), or a string made
of a number and a unit that pint knows (``"9.8 mm"``, ``"207 GPa"``, ``"1500 rpm"``,
``"90 deg"``). The unit must match what the field means. Strings are read with a small
grammar (a number, then unit names joined by ``*``, ``/``, spaces and integer powers), so
nothing in them is evaluated as an expression.

The ``Annotated`` types at the end (``Length``, ``Mass``, ...) apply :func:`to_si` when a
pydantic model is validated, so a validated model holds plain SI floats.

pint is imported, and its registry built, at the first string with units: plain numbers (a
saved ``model.json``, for one) never need them.
"""

from __future__ import annotations

import math
import re
import reprlib
from functools import cache
from typing import TYPE_CHECKING, Annotated, NamedTuple

from pydantic import BeforeValidator

if TYPE_CHECKING:
    import pint


@cache
def registry() -> pint.UnitRegistry:
    """The unit registry of pint, built once.

    Its definitions are parsed once per pint version and kept in pint's cache folder
    (``cache_folder=":auto:"``, the user's cache directory), which takes a second process
    about 0.1 s less than parsing them again. Where that folder cannot be used, they are
    parsed as without a cache; the registry is the same either way.
    """
    import pint

    try:
        return pint.UnitRegistry(cache_folder=":auto:")
    except Exception:  # an unwritable or half-written cache: the same registry, uncached
        return pint.UnitRegistry()


class _Kind(NamedTuple):
    noun: str
    example: str


# Keys are pint dimension expressions. Rotational stiffness has the dimension of a torque, so
# its key spells that dimension differently to get its own name and example.
_KINDS: dict[str, _Kind] = {
    "[]": _Kind("angle", "90 deg"),
    "[length]": _Kind("length", "9.8 mm"),
    "[length] ** 2": _Kind("area", "50 cm^2"),
    "[mass]": _Kind("mass", "3.12 kg"),
    "[mass] * [length] ** 2": _Kind("moment of inertia", "0.042 kg*m^2"),
    "[time]": _Kind("time", "0.5 ms"),
    "1/[time]": _Kind("angular speed", "1500 rpm"),
    "[length] / [time]": _Kind("speed", "0.3 m/s"),
    "[length] / [time] ** 2": _Kind("acceleration", "9.81 m/s^2"),
    "[force]": _Kind("force", "100 N"),
    "[force] * [length]": _Kind("torque", "5 N*m"),
    "[length] * [force]": _Kind("rotational stiffness", "10 N*m/rad"),
    "[force] / [length]": _Kind("stiffness", "1000 N/m"),
    "[force] * [time] / [length]": _Kind("damping coefficient", "5 N*s/m"),
    "[force] * [length] * [time]": _Kind("rotational damping coefficient", "0.1 N*m*s/rad"),
    "[pressure]": _Kind("pressure", "207 GPa"),
    "1/[pressure]": _Kind("wear coefficient", "8e-14 1/Pa"),
}

_SHORT = reprlib.Repr()  # values in messages: nesting, lists and long texts cut short
_SHORT.maxlevel, _SHORT.maxlist, _SHORT.maxstring, _SHORT.maxother, _SHORT.maxlong = (
    3,
    4,
    60,
    60,
    20,
)
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_UNIT = r"[^\W\d]\w*(?:\s*(?:\^|\*\*)\s*-?[1-9]\d?)?"  # powers 1 to 99, not 0
_QUANTITY = re.compile(rf"\s*({_NUMBER})\s*((?:1\s*/\s*)?{_UNIT}(?:\s*[*/ ]\s*{_UNIT})*)?\s*")


def _article(noun: str) -> str:
    return f"an {noun}" if noun[0] in "aeiou" else f"a {noun}"


@cache
def _nouns() -> dict[pint.util.UnitsContainer, str]:
    ureg = registry()
    return {ureg.get_dimensionality(key): kind.noun for key, kind in reversed(_KINDS.items())}


def _describe(dimensionality: pint.util.UnitsContainer) -> str:
    return _nouns().get(dimensionality, str(dimensionality))


def to_si(value: object, dimension: str, field_name: str | None = None) -> float:
    """Convert a plain SI number or a string with units to an SI float.

    Parameters
    ----------
    value
        A number (already SI; radians for angles), a string such as ``"9.8 mm"``, or a
        pint Quantity.
    dimension
        The expected pint dimension, e.g. ``"[length]"``, ``"[mass] * [length] ** 2"``,
        ``"1/[time]"`` for angular speeds or ``"[]"`` for angles.
    field_name
        Prefixed to the error message when given.

    Returns
    -------
    float
        The value in SI units [m, kg, s, rad, N, Pa and their products].

    Raises
    ------
    ValueError
        If the value is not a finite number or a readable string with units of `dimension`.
    """
    kind = _KINDS.get(dimension, _Kind(f"quantity of dimension {dimension}", "1 m"))
    expected = f"expected {_article(kind.noun)}, e.g. '{kind.example}'"
    try:
        return _to_si(value, dimension, expected)
    except ValueError as error:
        if field_name is None:
            raise
        raise ValueError(f"{field_name}: {error}") from None


def _to_si(value: object, dimension: str, expected: str) -> float:
    if _is_quantity(value):  # a pint Quantity, of any registry: read as its text
        try:
            value = f"{float(value.magnitude)!r} {value.units}"
        except (TypeError, ValueError):
            raise ValueError(f"{_SHORT.repr(value)} is not one number; {expected}") from None
    shown = _SHORT.repr(value)
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ValueError(f"{shown} is not a number; {expected} (plain numbers are SI)")
    if not isinstance(value, str):
        try:
            number = float(value)  # an int of hundreds of digits overflows here
        except OverflowError:
            number = math.inf
        if not math.isfinite(number):
            raise ValueError(f"{shown} is not a finite number; {expected}")
        return number
    match = _QUANTITY.fullmatch(value)
    if match is None:
        raise ValueError(f"cannot read {shown} as a number and a unit; {expected}")
    number, units = match.groups()
    if units is None:
        raise ValueError(f"{shown} has no unit; {expected} (plain numbers are SI)")
    import pint  # imported by registry() already

    ureg = registry()
    try:
        quantity = ureg.Quantity(float(number), ureg.parse_units(units))
        dimensionality = quantity.dimensionality
        pure = [name for name, _ in quantity.unit_items() if _is_pure_number(name)]
    except (pint.PintError, ArithmeticError, LookupError, ValueError) as error:
        reason = " ".join(str(error).split()).rstrip(".") or type(error).__name__
        raise ValueError(f"cannot read {shown}: {reason}; {expected}") from None
    if pure:
        raise ValueError(f"{shown}: '{pure[0]}' is a pure number, not a unit; {expected}")
    if dimension == "[]" and not any(True for _ in quantity.unit_items()):
        raise ValueError(f"{shown} has no angle unit; {expected} (plain numbers are SI)")
    if dimensionality != ureg.get_dimensionality(dimension):
        actual = _describe(dimensionality)
        raise ValueError(f"{shown} has units of {actual}; {expected}")
    if dimension == "1/[time]" and any(name.endswith("hertz") for name, _ in quantity.unit_items()):
        raise ValueError(
            f"{shown} is ambiguous for an angular speed (cycles or radians per second?); "
            "use rad/s or rpm, e.g. '1500 rpm'"
        )
    result = float(quantity.to_base_units().magnitude)
    if not math.isfinite(result):
        raise ValueError(f"{shown} is not finite in SI units; {expected}")
    return result


def dimension_of(value: object) -> str | None:
    """The dimension key of a string with units or a Quantity (``"720 deg"`` -> "[]").

    None for a plain number (SI of whatever the field means). ValueError if it cannot be read.
    """
    if _is_quantity(value):
        value = f"{float(value.magnitude)!r} {value.units}"
    if not isinstance(value, str):
        return None
    match = _QUANTITY.fullmatch(value)
    if match is None or match.group(2) is None:
        raise ValueError(f"cannot read {_SHORT.repr(value)} as a number and a unit")
    import pint

    ureg = registry()
    try:
        dimensionality = ureg.Quantity(1.0, ureg.parse_units(match.group(2))).dimensionality
    except (pint.PintError, ArithmeticError, LookupError, ValueError) as error:
        reason = " ".join(str(error).split()).rstrip(".") or type(error).__name__
        raise ValueError(f"cannot read {_SHORT.repr(value)}: {reason}") from None
    for key in _KINDS:
        if ureg.get_dimensionality(key) == dimensionality:
            return key
    return str(dimensionality)


def unit_of(text: str) -> tuple[str, float] | None:
    """The unit of a number-and-unit text and its size in SI: ``"9.8 mm"`` -> ("mm", 0.001).

    None for a plain number, or for a text that is not a number and a unit pint reads.
    """
    match = _QUANTITY.fullmatch(text)
    if match is None or match.group(2) is None:
        return None
    import pint

    ureg = registry()
    try:
        size = ureg.Quantity(1.0, ureg.parse_units(match.group(2))).to_base_units().magnitude
    except (pint.PintError, ArithmeticError, LookupError, ValueError):
        return None
    return match.group(2), float(size)


def _is_quantity(value: object) -> bool:
    """Whether ``value`` looks like a pint Quantity (a magnitude with units)."""
    return all(hasattr(value, name) for name in ("magnitude", "units", "dimensionality"))


ANGLE_UNITS = frozenset({"radian", "degree", "arcminute", "arcsecond", "turn", "grade"})


def _is_pure_number(unit: str) -> bool:
    """Whether a pint unit is a dimensionless count (percent, ppm, dozen), not an angle."""
    return unit not in ANGLE_UNITS and registry().get_dimensionality(unit) == {}


def _quantity(dimension: str) -> BeforeValidator:
    def convert(value: object) -> float:
        return to_si(value, dimension)

    return BeforeValidator(convert)


Length = Annotated[float, _quantity("[length]")]
Area = Annotated[float, _quantity("[length] ** 2")]
Mass = Annotated[float, _quantity("[mass]")]
Inertia = Annotated[float, _quantity("[mass] * [length] ** 2")]
Angle = Annotated[float, _quantity("[]")]
Time = Annotated[float, _quantity("[time]")]
AngularSpeed = Annotated[float, _quantity("1/[time]")]
Speed = Annotated[float, _quantity("[length] / [time]")]
Acceleration = Annotated[float, _quantity("[length] / [time] ** 2")]
Force = Annotated[float, _quantity("[force]")]
Torque = Annotated[float, _quantity("[force] * [length]")]
Stiffness = Annotated[float, _quantity("[force] / [length]")]
Damping = Annotated[float, _quantity("[force] * [time] / [length]")]
RotationalStiffness = Annotated[float, _quantity("[length] * [force]")]
RotationalDamping = Annotated[float, _quantity("[force] * [length] * [time]")]
Pressure = Annotated[float, _quantity("[pressure]")]
WearCoefficient = Annotated[float, _quantity("1/[pressure]")]
Viscosity = Annotated[float, _quantity("[pressure] * [time]")]

Vector2 = tuple[Length, Length]
Velocity2 = tuple[Speed, Speed]
Acceleration2 = tuple[Acceleration, Acceleration]
