"""Functions of time in the model file: constant speed, polynomial and harmonic tables.

Drivers prescribe an angle or a distance with one of them; a force component or a torque
is a constant quantity or a polynomial or harmonic table of it.
"""

import math
from collections.abc import Sequence
from typing import Annotated, ClassVar, Generic, Literal, TypeVar

from pydantic import BaseModel, Discriminator, Field, Tag

from ..kernels.codes import FunctionKind
from ..units import Angle, AngularSpeed, Force, Length, Speed, Torque
from .errors import SCALAR_TAG
from .tables import Number, Table

_T = TypeVar("_T")
_RateT = TypeVar("_RateT")


class ConstantSpeed(Table, Generic[_RateT, _T]):
    """f(t) = initial + speed t, a driver's function.

    Built in Python, its values take the units of the driver it is given to (checked there).

    Attributes
    ----------
    speed
        [rad/s] for an angle driver, [m/s] for a distance driver.
    initial
        f(0) [rad or m]; None: the driven coordinate at the initial pose guess.
    """

    type: Literal["constant_speed"] = "constant_speed"
    speed: _RateT
    initial: _T | None = None


class Polynomial(Table):
    """f(t) = sum_k coefficients[k] t^k, t in [s].

    Attributes
    ----------
    coefficients
        c_0 ... c_7, plain SI numbers: [unit of f / s^k] (rad, m, N or N m over s^k).
    """

    kind: ClassVar = FunctionKind.POLYNOMIAL
    type: Literal["polynomial"] = "polynomial"
    coefficients: Annotated[tuple[Number, ...], Field(min_length=1, max_length=8)]


class Harmonic(Table, Generic[_T]):
    """f(t) = offset + amplitude sin(angular_frequency t + phase), t in [s].

    Built in Python, its offset and amplitude take the units of where it is given (an angle
    driver [rad], a distance driver [m], a force component [N], a torque [N m]; checked there).

    Attributes
    ----------
    offset, amplitude
        In the units of f.
    angular_frequency
        [rad/s] (``"Hz"`` is refused: cycles or radians per second?).
    phase
        [rad].
    """

    kind: ClassVar = FunctionKind.HARMONIC
    type: Literal["harmonic"] = "harmonic"
    offset: _T = 0.0
    amplitude: _T
    angular_frequency: AngularSpeed
    phase: Angle = 0.0


# One named class per quantity, defined here at module level: pickle finds a class by its
# module and name, and pydantic names every parametrisation of a generic alike by the types'
# reprs (Harmonic[Force] and Harmonic[Torque] are both "Harmonic[Annotated[float, ...]]").
class ForceHarmonic(Harmonic[Force]):
    """A harmonic force [N]."""


class TorqueHarmonic(Harmonic[Torque]):
    """A harmonic torque [N m]."""


class AngleHarmonic(Harmonic[Angle]):
    """A harmonic angle [rad]."""


class DistanceHarmonic(Harmonic[Length]):
    """A harmonic distance [m]."""


class AngleAtConstantSpeed(ConstantSpeed[AngularSpeed, Angle]):
    """An angle [rad] turning at a constant speed [rad/s]."""


class DistanceAtConstantSpeed(ConstantSpeed[Speed, Length]):
    """A distance [m] travelled at a constant speed [m/s]."""


def _tag(value: object) -> object:
    if isinstance(value, dict):
        return value.get("type")
    return value.type if isinstance(value, BaseModel) else SCALAR_TAG


def _quantity_or_function(quantity: object, harmonic: type[Harmonic]) -> object:
    """Build the type: a constant `quantity`, or a polynomial or ``harmonic`` table of it."""
    return Annotated[
        Annotated[quantity, Tag(SCALAR_TAG)]
        | Annotated[Polynomial, Tag("polynomial")]
        | Annotated[harmonic, Tag("harmonic")],
        Discriminator(_tag),
    ]


ForceValue = _quantity_or_function(Force, ForceHarmonic)
TorqueValue = _quantity_or_function(Torque, TorqueHarmonic)
AngleFunction = Annotated[
    AngleAtConstantSpeed | Polynomial | AngleHarmonic, Field(discriminator="type")
]
DistanceFunction = Annotated[
    DistanceAtConstantSpeed | Polynomial | DistanceHarmonic, Field(discriminator="type")
]


def period(function: object, kind: str) -> float | None:
    """Period [s] of a time function; 0 for a constant, None if it never repeats."""
    if isinstance(function, ConstantSpeed):
        if function.speed == 0.0:
            return 0.0
        return 2.0 * math.pi / abs(function.speed) if kind == "angle" else None
    if isinstance(function, Polynomial):
        return 0.0 if not any(function.coefficients[1:]) else None
    if isinstance(function, Harmonic):
        if function.angular_frequency == 0.0 or function.amplitude == 0.0:
            return 0.0
        return 2.0 * math.pi / abs(function.angular_frequency)
    return 0.0  # a constant value


def longest_period(drivers: Sequence, forces: Sequence) -> float | None:
    """The longest period [s] of the drivers' and loads' functions; None if none repeats.

    The mechanism's cycle for per-cycle figures: functions that never repeat are passed
    over (a life run, which needs one cycle for everything, checks more strictly).
    """
    functions = [(d.function, d.type) for d in drivers]
    for load in forces:
        values = load.force if load.type == "point_force" else (getattr(load, "torque", 0.0),)
        functions += [(value, "load") for value in values]
    periods = [period(function, kind) for function, kind in functions]
    return max((p for p in periods if p), default=None)
