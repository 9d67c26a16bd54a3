"""The argument of a table or a Fourier series: what it names, and the units of its values.

An argument is ``time``, a driver's name (the value it prescribes: the crank angle of an
angle driver, the slide of a distance driver), or a state quantity: ``<body>.angle`` and
``<body>.angular_speed`` (absolute), ``<joint>.slide`` and ``<joint>.slide_speed`` of a joint
along an axis (its second point from its first, along the axis in the first body's frame).
"""

from collections.abc import Iterator, Sequence
from typing import NamedTuple

from ..joints import BY_NAME
from ..kernels.codes import ArgumentKind
from ..units import to_si
from .errors import did_you_mean
from .functions import TIME, FunctionOfArgument, TableFunction

_STATE = {  # suffix: kind, what it is of, dimension
    "angle": (ArgumentKind.ANGLE, "body", "[]"),
    "angular_speed": (ArgumentKind.ANGULAR_SPEED, "body", "1/[time]"),
    "slide": (ArgumentKind.SLIDE, "joint", "[length]"),
    "slide_speed": (ArgumentKind.SLIDE_SPEED, "joint", "[length] / [time]"),
}
_DRIVER_DIMENSION = {"angle": "[]", "distance": "[length]"}


class Argument(NamedTuple):
    """A resolved argument: its kind, the driver, body or joint it names, its dimension."""

    kind: ArgumentKind
    name: str
    dimension: str


def resolve(argument: str, drivers: Sequence, bodies: Sequence, joints: Sequence) -> Argument:
    """The argument a name stands for; ValueError saying what is allowed if none."""
    if argument == TIME:
        return Argument(ArgumentKind.TIME, "", "[time]")
    for driver in drivers:
        if driver.name == argument:
            return Argument(ArgumentKind.DRIVER, argument, _DRIVER_DIMENSION[driver.type])
    owner, _, quantity = argument.rpartition(".")
    if quantity in _STATE:
        kind, of, dimension = _STATE[quantity]
        names = [b.name for b in bodies] if of == "body" else _axial(joints)
        if owner in names:
            return Argument(kind, owner, dimension)
        raise ValueError(
            f"{argument!r}: no {of} {owner!r} with {quantity.replace('_', ' ')}; "
            f"{'bodies' if of == 'body' else 'joints along an axis'} are "
            f"{', '.join(names) or 'none'}{did_you_mean(owner, names)}"
        )
    choices = [TIME, *(d.name for d in drivers)]
    raise ValueError(
        f"unknown argument {argument!r}; an argument is {', '.join(choices)} (time or a "
        "driver), <body>.angle, <body>.angular_speed, <joint>.slide or <joint>.slide_speed"
        f"{did_you_mean(argument, choices)}"
    )


def _axial(joints: Sequence) -> list[str]:
    return [j.name for j in joints if BY_NAME[j.type].slides]


def argument_problems(
    drivers: Sequence, bodies: Sequence, joints: Sequence, forces: Sequence
) -> list[str]:
    """One line per function whose argument is unknown, not allowed there, or of other units."""
    functions = list(_functions(drivers, forces))
    of_time = [path for path, function, _ in functions if function.argument == TIME]
    problems = [
        f"drivers[{i}].name: 'time' is the argument of functions of time ({of_time[0]}'s), so "
        "this driver could not be one; rename it"
        for i, driver in enumerate(drivers)
        if driver.name == TIME and of_time
    ]
    for path, function, is_driver in functions:
        try:
            argument = resolve(function.argument, drivers, bodies, joints)
        except ValueError as error:
            problems.append(f"{path}.argument: {error}")
            continue
        problems += [
            f"{path}.{line}" for line in _use_problems(function, argument, is_driver, drivers)
        ]
        for key, values in function.given_with_units().items():
            for value in values:
                try:
                    to_si(value, argument.dimension)
                except ValueError as error:
                    problems.append(
                        f"{path}.{key}: {error} (its argument is {function.argument!r})"
                    )
                    break
    return problems


def _use_problems(
    function: FunctionOfArgument, argument: Argument, is_driver: bool, drivers: Sequence
) -> list[str]:
    problems = []
    if argument.kind == ArgumentKind.DRIVER:
        named = next(d for d in drivers if d.name == argument.name)
        inner = getattr(named.function, "argument", TIME)
        if inner != TIME:
            problems.append(
                f"argument: driver {named.name!r} is itself a function of {inner!r}; an "
                "argument driver must be a function of time"
            )
    elif argument.kind != ArgumentKind.TIME and is_driver:
        problems.append(
            f"argument: {function.argument!r} is of the mechanism's state; a driver prescribes "
            "a function of time or of another driver"
        )
    if is_driver and isinstance(function, TableFunction) and function.interpolation == "linear":
        problems.append(
            "interpolation: 'linear' gives a driver a speed that jumps at every point (an "
            "infinite acceleration); use 'pchip' or 'cubic'"
        )
    return problems


def _functions(
    drivers: Sequence, forces: Sequence
) -> Iterator[tuple[str, FunctionOfArgument, bool]]:
    for i, driver in enumerate(drivers):
        if isinstance(driver.function, FunctionOfArgument):
            yield f"drivers[{i}].function", driver.function, True
    for i, force in enumerate(forces):
        for key, function in force.functions.items():
            if isinstance(function, FunctionOfArgument):
                yield f"forces[{i}].{key}", function, False
