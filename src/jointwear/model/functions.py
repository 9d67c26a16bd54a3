"""Functions in the model file: constant speed, polynomials, harmonics, tables, Fourier series.

Drivers prescribe an angle or a distance with one of them; a force component, a torque or a
pressure is a constant quantity or one of these functions of it. Polynomials and harmonics
are of time; a table or a Fourier series is of its ``argument``: the time, a driver's value
(the crank angle of an angle driver), or a state quantity (``<body>.angle``,
``<body>.angular_speed``, ``<joint>.slide``, ``<joint>.slide_speed``); the model checks the
name and the units (``arguments``).
"""

import math
from collections.abc import Sequence
from typing import Annotated, Any, ClassVar, Generic, Literal, TypeVar, Union

from annotated_types import Gt
from pydantic import (
    BaseModel,
    Discriminator,
    Field,
    PrivateAttr,
    Tag,
    ValidatorFunctionWrapHandler,
    model_validator,
)

from ..kernels.codes import FunctionKind
from ..units import (
    Angle,
    AngularSpeed,
    Force,
    Length,
    Pressure,
    Speed,
    Torque,
    dimension_of,
    to_si,
)
from .errors import SCALAR_TAG
from .table_files import MAX_ROWS, read_columns
from .tables import Number, Table

_T = TypeVar("_T")
_RateT = TypeVar("_RateT")
TIME = "time"
INTERPOLATIONS = ("linear", "cubic", "pchip")
MAX_HARMONICS = 1000


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


class FunctionOfArgument(Table):
    """A function of its ``argument``: the time, a driver's name or a state quantity.

    Values of the argument (``ARGUMENT_KEYS``) may carry any units when validated; the model
    checks them against what the argument is (``arguments.argument_problems``), from the
    values as given, kept aside.
    """

    ARGUMENT_KEYS: ClassVar[tuple[str, ...]] = ("period",)
    argument: str = TIME
    _given: dict[str, list] = PrivateAttr(default_factory=dict)

    @model_validator(mode="wrap")
    @classmethod
    def _argument_values_in_si(cls, data: Any, handler: ValidatorFunctionWrapHandler) -> Any:
        if isinstance(data, FunctionOfArgument):  # built in Python, given where it is used
            table = handler(data)
            table._given = table._given or data._given
            return table
        if not isinstance(data, dict):
            return handler(data)
        data = cls._inline(dict(data))
        given, kinds = {}, {}
        for key in cls.ARGUMENT_KEYS:
            value = data.get(key)
            if getattr(value, "ndim", 0) > 0:  # an array, or an array Quantity: its items
                value = list(value)
            items = value if isinstance(value, list | tuple) else [value]
            dimensions = [_dimension(key, i, item, value) for i, item in enumerate(items)]
            with_units = {d for d in dimensions if d is not None}
            kinds |= dict.fromkeys(with_units, key)
            if len(kinds) > 1:
                raise ValueError(
                    f"{', '.join(dict.fromkeys(kinds.values()))}: values with units of "
                    "different kinds; give them all in units of the argument"
                )
            if with_units:
                given[key] = [item for item, d in zip(items, dimensions, strict=True) if d]
                si = [to_si(v, d) if d else v for v, d in zip(items, dimensions, strict=True)]
                data[key] = si if isinstance(value, list | tuple) else si[0]
        table = handler(data)
        table._given = given
        return table

    @classmethod
    def _inline(cls, data: dict) -> dict:
        """Read whatever the table names (a file, units of its columns) into its values."""
        return data

    @property
    def own_period(self) -> float | None:
        """The period in the argument [SI], or None if the function does not repeat."""
        return self.period

    def given_with_units(self) -> dict[str, list]:
        """Each argument key's values as given with units (checked against the argument)."""
        return self._given

    def __eq__(self, other: object) -> bool:
        """Equal values, however they were written (a saved model holds them in SI)."""
        return type(other) is type(self) and other.__dict__ == self.__dict__

    __hash__ = Table.__hash__


def _dimension(key: str, index: int, item: object, value: object) -> str | None:
    try:
        return dimension_of(item)
    except ValueError as error:
        where = f"{key}[{index}]" if isinstance(value, list | tuple) else key
        raise ValueError(f"{where}: {error}") from None


class TableFunction(FunctionOfArgument, Generic[_T]):
    """f(x) interpolated in a table of points (x_i, y_i), x increasing; SI once validated.

    ``file``, ``columns``, ``x_unit`` and ``y_unit`` are read into ``x`` and ``y`` when the
    table is validated, and then cleared. Built in Python, y takes the units of where the
    table is given (a torque [N m], a pressure [Pa], ...; checked there).

    Attributes
    ----------
    argument
        ``"time"`` (default), a driver's name, ``"<body>.angle"``, ``"<body>.angular_speed"``,
        ``"<joint>.slide"`` or ``"<joint>.slide_speed"``.
    x, y
        The points: x in the argument's units, increasing; y in the units of f. Numbers are
        SI, or in ``x_unit`` and ``y_unit`` when given; strings carry their own units.
    interpolation
        ``"pchip"`` (default: monotone between points, no overshoot), ``"cubic"`` (a
        not-a-knot spline, periodic when ``period`` is given) or ``"linear"``.
    period
        In the argument's units (``"720 deg"``): the table repeats. Without it the argument
        must stay within the points (checked before a run for time and drivers).
    file, columns
        A CSV file (relative to the model file) whose header names each column with its unit
        (``crank angle [deg]``); ``columns`` names the x and y columns (default: the first
        two).
    source
        The file the points were read from.
    """

    kind: ClassVar = FunctionKind.SPLINE
    ARGUMENT_KEYS: ClassVar[tuple[str, ...]] = ("x", "period")
    type: Literal["table"] = "table"
    x: Annotated[tuple[Number, ...], Field(min_length=2, max_length=MAX_ROWS)]
    y: Annotated[tuple[_T, ...], Field(min_length=2, max_length=MAX_ROWS)]
    interpolation: Literal["linear", "cubic", "pchip"] = "pchip"
    period: Annotated[Number, Gt(0)] | None = None
    file: str | None = None
    columns: tuple[str, str] | None = None
    x_unit: str | None = None
    y_unit: str | None = None
    source: str | None = None  # the file the points were read from

    @classmethod
    def _inline(cls, data: dict) -> dict:
        if data.get("file") is not None:
            # A saved table holds the points of its source: a file given to it replaces them.
            if data.get("source") is None and ("x" in data or "y" in data):
                raise ValueError("give the points as x and y, or in a file, not both")
            path, columns = str(data.pop("file")), data.pop("columns", None)
            if columns is not None and not (
                isinstance(columns, list | tuple) and [type(c) for c in columns] == [str, str]
            ):
                raise ValueError(
                    f"columns: got {columns!r}; give two header names (without units), of "
                    "the x and the y column"
                )
            x, x_unit, y, y_unit = read_columns(path, columns)
            x_unit, y_unit = x_unit or data.get("x_unit"), y_unit or data.get("y_unit")
            data |= {"x": x, "y": y, "x_unit": x_unit, "y_unit": y_unit, "source": path}
        for key in ("x", "y"):
            unit = data.pop(f"{key}_unit", None)
            if unit is not None and isinstance(data.get(key), list | tuple):
                data[key] = [_with_unit(v, unit) for v in data[key]]
        return data

    @model_validator(mode="after")
    def _points(self) -> "TableFunction":
        if len(self.x) != len(self.y):
            raise ValueError(f"x has {len(self.x)} points and y {len(self.y)}; give as many")
        for i in range(1, len(self.x)):
            if not self.x[i] > self.x[i - 1]:
                raise ValueError(
                    f"x[{i}] = {self.x[i]:.6g} does not follow x[{i - 1}] = {self.x[i - 1]:.6g} "
                    "(SI); x must increase strictly"
                )
        if self.period is not None:
            span = self.x[-1] - self.x[0]
            if span > self.period * (1.0 + PERIOD_RTOL):
                raise ValueError(
                    f"the points span {span:.6g} (SI), more than the period {self.period:.6g}; "
                    "give one period of points"
                )
            if len(self.points()[0]) < 3:
                raise ValueError("a periodic table needs at least two points in its period")
            scale = max(abs(v) for v in self.y) or 1.0
            if span >= self.period * (1.0 - PERIOD_RTOL) and abs(self.y[-1] - self.y[0]) > (
                PERIOD_RTOL * scale
            ):
                raise ValueError(
                    f"the points span the whole period, but y ends at {self.y[-1]:.6g} and "
                    f"starts at {self.y[0]:.6g} (SI); a periodic table ends where it starts "
                    "(or leave the last point out)"
                )
        return self

    def points(self) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The points; a periodic table's closed by its first point one period on [SI]."""
        if self.period is None or self.x[-1] - self.x[0] >= self.period * (1.0 - PERIOD_RTOL):
            return self.x, self.y
        return (*self.x, self.x[0] + self.period), (*self.y, self.y[0])


PERIOD_RTOL = 1e-9  # a table spanning its period to this is closed


def _with_unit(value: object, unit: str) -> object:
    return f"{value!r} {unit}" if isinstance(value, int | float) else value


class Fourier(FunctionOfArgument, Generic[_T]):
    """f(x) = mean + sum_k a_k cos(2 pi k x / period) + b_k sin(2 pi k x / period).

    Attributes
    ----------
    argument
        As a ``TableFunction``'s.
    period
        The base period, in the argument's units (``"12 ms"``, ``"720 deg"``).
    mean
        In the units of f.
    cosine, sine
        a_1, a_2, ... and b_1, b_2, ... in the units of f (at most 1000 each).
    """

    kind: ClassVar = FunctionKind.FOURIER
    type: Literal["fourier"] = "fourier"
    period: Annotated[Number, Gt(0)]
    mean: _T = 0.0
    cosine: Annotated[tuple[_T, ...], Field(max_length=MAX_HARMONICS)] = ()
    sine: Annotated[tuple[_T, ...], Field(max_length=MAX_HARMONICS)] = ()


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


class PressureHarmonic(Harmonic[Pressure]):
    """A harmonic pressure [Pa]."""


class ForceTable(TableFunction[Force]):
    """A table of a force [N]."""


class TorqueTable(TableFunction[Torque]):
    """A table of a torque [N m]."""


class AngleTable(TableFunction[Angle]):
    """A table of an angle [rad]."""


class DistanceTable(TableFunction[Length]):
    """A table of a distance [m]."""


class PressureTable(TableFunction[Pressure]):
    """A table of a pressure [Pa]."""


class ForceFourier(Fourier[Force]):
    """A Fourier series of a force [N]."""


class TorqueFourier(Fourier[Torque]):
    """A Fourier series of a torque [N m]."""


class AngleFourier(Fourier[Angle]):
    """A Fourier series of an angle [rad]."""


class DistanceFourier(Fourier[Length]):
    """A Fourier series of a distance [m]."""


class PressureFourier(Fourier[Pressure]):
    """A Fourier series of a pressure [Pa]."""


class AngleAtConstantSpeed(ConstantSpeed[AngularSpeed, Angle]):
    """An angle [rad] turning at a constant speed [rad/s]."""


class DistanceAtConstantSpeed(ConstantSpeed[Speed, Length]):
    """A distance [m] travelled at a constant speed [m/s]."""


def _tag(value: object) -> object:
    if isinstance(value, dict):
        return value.get("type")
    return value.type if isinstance(value, BaseModel) else SCALAR_TAG


def _quantity_or_function(quantity: object, *functions: type[Table]) -> object:
    """Build the type: a constant `quantity`, or a polynomial or one of ``functions`` of it."""
    tagged = [Annotated[f, Tag(f.model_fields["type"].default)] for f in functions]
    members = [Annotated[quantity, Tag(SCALAR_TAG)], Annotated[Polynomial, Tag("polynomial")]]
    return Annotated[Union[tuple(members + tagged)], Discriminator(_tag)]  # noqa: UP007


ForceValue = _quantity_or_function(Force, ForceHarmonic, ForceTable, ForceFourier)
TorqueValue = _quantity_or_function(Torque, TorqueHarmonic, TorqueTable, TorqueFourier)
PressureValue = _quantity_or_function(Pressure, PressureHarmonic, PressureTable, PressureFourier)
AngleFunction = Annotated[
    AngleAtConstantSpeed | Polynomial | AngleHarmonic | AngleTable | AngleFourier,
    Field(discriminator="type"),
]
DistanceFunction = Annotated[
    DistanceAtConstantSpeed | Polynomial | DistanceHarmonic | DistanceTable | DistanceFourier,
    Field(discriminator="type"),
]


def period(function: object, kind: str, drivers: Sequence) -> float | None:
    """Period [s] of a driver's or load's function in time; None if it never repeats.

    0 for a constant, or a function of the state (it repeats when the mechanism does).
    ``kind`` is the driver's type ("angle" turns: its constant speed repeats) or "load";
    ``drivers`` are the model's, for functions of a driver's value.
    """
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
    if isinstance(function, FunctionOfArgument):
        return _period_through(function, drivers)
    return 0.0  # a constant value


def _period_through(function: FunctionOfArgument, drivers: Sequence) -> float | None:
    own = function.own_period
    if function.argument == TIME:
        return own
    driver = next((d for d in drivers if d.name == function.argument), None)
    if driver is None:
        return 0.0  # a function of the state
    if isinstance(driver.function, ConstantSpeed):  # x runs on: repeats with its own period
        speed = driver.function.speed
        return 0.0 if speed == 0.0 else (own / abs(speed) if own else None)
    return period(driver.function, driver.type, drivers)  # x repeats, and with it f(x)


def longest_period(drivers: Sequence, forces: Sequence) -> float | None:
    """The longest period [s] of the drivers' and loads' functions; None if none repeats.

    The mechanism's cycle for per-cycle figures: functions that never repeat are passed
    over (a life run, which needs one cycle for everything, checks more strictly).
    """
    functions = [(d.function, d.type) for d in drivers]
    functions += [(value, "load") for load in forces for value in load.functions.values()]
    periods = [period(function, kind, drivers) for function, kind in functions]
    return max((p for p in periods if p), default=None)
