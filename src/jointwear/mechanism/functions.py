"""The function table the kernels read (``kernels.functions``).

Each driver's and load's function is a kind, parameters, an argument and, for tables and
series, flat data. Tables become scipy's piecewise cubics (``PPoly`` coefficients): linear from
``make_interp_spline``, cubic from ``CubicSpline`` (periodic conditions for a periodic table),
pchip from ``PchipInterpolator`` (on a periodic table, built over a wrapped neighbourhood so
that its slope is continuous across the period's end).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ..kernels.codes import ArgumentKind, FunctionKind
from ..model import Model
from ..model.arguments import resolve
from ..model.functions import ConstantSpeed, TableFunction, period

MAX_COEFFICIENTS = 8
RANGE_SAMPLES = 4001  # samples of a driver over the run, for the range its tables must cover
_NO_GEOMETRY = (0.0, 0.0, 0.0, 0.0, 1.0, 0.0)


class FunctionRows:
    """Collects functions into rows: kind, parameters, argument, geometry; and their data."""

    def __init__(self, model: Model, body_index: dict[str, int], local: Callable) -> None:
        self.model = model
        self.body_index = body_index
        self.local = local
        self.kind: list[int] = []
        self.param: list[NDArray[np.float64]] = []
        self.argument: list[tuple[int, int, int]] = []
        self.geometry: list[tuple[float, ...]] = []
        self.data: list[float] = []
        self._tables: list[tuple[int, str, TableFunction]] = []  # to check against the run
        self._overflows: list[str] = []  # functions floating point cannot hold

    def add(self, spec: object, path: str, initial: float = 0.0) -> int:
        """Add a constant or a function table of the model (at ``path`` in the file)."""
        first = len(self.data)
        kind, values = self._parameters(spec, initial)
        if not np.isfinite(values).all() or not np.isfinite(self.data[first:]).all():
            self._overflows.append(
                f"{path}: its coefficients are not finite numbers (its points or period are too "
                "close together or too far apart for floating point); rescale its x values"
            )
        row = np.zeros(MAX_COEFFICIENTS)
        row[: len(values)] = values
        self.kind.append(int(kind))
        self.param.append(row)
        argument, geometry = self._argument(getattr(spec, "argument", "time"))
        self.argument.append(argument)
        self.geometry.append(geometry)
        if isinstance(spec, TableFunction) and spec.period is None:
            self._tables.append((len(self.kind) - 1, path, spec))
        return len(self.kind) - 1

    def _parameters(self, spec: object, initial: float) -> tuple[FunctionKind, list[float]]:
        if isinstance(spec, int | float):
            return FunctionKind.POLYNOMIAL, [float(spec)]
        if spec.type == "constant_speed":
            return FunctionKind.POLYNOMIAL, [
                initial if spec.initial is None else spec.initial,
                spec.speed,
            ]
        if spec.type == "polynomial":
            return FunctionKind.POLYNOMIAL, list(spec.coefficients)
        if spec.type == "harmonic":
            return FunctionKind.HARMONIC, [
                spec.offset,
                spec.amplitude,
                spec.angular_frequency,
                spec.phase,
            ]
        first = len(self.data)
        if spec.type == "table":
            breaks, coefficients = piecewise_cubic(spec)
            self.data += [*breaks, *coefficients.T.ravel()]
            return FunctionKind.SPLINE, [first, len(breaks) - 1, spec.period or 0.0]
        harmonics = max(len(spec.cosine), len(spec.sine))
        pairs = np.zeros((harmonics, 2))
        pairs[: len(spec.cosine), 0] = spec.cosine
        pairs[: len(spec.sine), 1] = spec.sine
        self.data += [spec.mean, *pairs.ravel()]
        return FunctionKind.FOURIER, [first, harmonics, 2.0 * math.pi / spec.period]

    def _argument(self, name: str) -> tuple[tuple[int, int, int], tuple[float, ...]]:
        model = self.model
        argument = resolve(name, model.drivers, model.bodies, model.joints)
        if argument.kind == ArgumentKind.TIME:
            return (int(argument.kind), -1, -1), _NO_GEOMETRY
        if argument.kind == ArgumentKind.DRIVER:
            index = [d.name for d in model.drivers].index(argument.name)
            return (int(argument.kind), index, -1), _NO_GEOMETRY
        if argument.kind in (ArgumentKind.ANGLE, ArgumentKind.ANGULAR_SPEED):
            return (int(argument.kind), self.body_index[argument.name], -1), _NO_GEOMETRY
        joint = model.joint(argument.name)
        b1, b2 = joint.bodies
        points = (*self.local(b1, joint.points[0]), *self.local(b2, joint.points[1]))
        bodies = (int(argument.kind), self.body_index[b1], self.body_index[b2])
        return bodies, (*points, *joint.axis)

    def range_problems(self, mechanism: object) -> list[str]:
        """One line per function that overflows, or per table that the run leaves.

        A table without a period is left when its argument leaves its points in the run.

        Only arguments known before the run are judged: the time, and a driver's value
        (sampled over the run, and over a whole period of a driver whose values repeat). A
        table of the state that is left during a run stops it as non-finite.
        """
        from ..kernels.functions import evaluate  # compiled: only when there is a table

        if self._overflows:  # their values cannot be sampled
            return self._overflows
        problems = []
        t_end = self.model.solver.t_end
        for row, path, table in self._tables:
            kind, index, _ = self.argument[row]
            if kind == ArgumentKind.TIME:
                low, high = 0.0, t_end
            elif kind == ArgumentKind.DRIVER:
                driver = self.model.drivers[index]
                repeat = t_end  # a constant speed's value runs on: the run's span
                if not isinstance(driver.function, ConstantSpeed):  # its values repeat
                    repeat = period(driver.function, driver.type, self.model.drivers) or t_end
                g = mechanism.driver_function[index]
                values = [
                    evaluate(
                        mechanism.function_kind[g],
                        mechanism.function_param[g],
                        mechanism.function_data,
                        t,
                    )[0]
                    for t in np.linspace(0.0, max(repeat, t_end), RANGE_SAMPLES)
                ]
                low, high = min(values), max(values)
            else:
                continue
            if low < table.x[0] or high > table.x[-1]:
                problems.append(
                    f"{path}: its points cover {table.argument} from {table.x[0]:.6g} to "
                    f"{table.x[-1]:.6g} (SI), but the run takes it from {low:.6g} to {high:.6g} "
                    "(t_end included); give points that cover the run, or a period for a "
                    "table that repeats"
                )
        return problems


def piecewise_cubic(table: TableFunction) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Breakpoints (n + 1) and cubic coefficients (4, n) of a table's interpolant [SI].

    Coefficients NaN where floating point cannot hold them (``FunctionRows`` refuses them).
    """
    x, y = (np.asarray(v, dtype=float) for v in table.points())
    with np.errstate(all="ignore"):  # an overflow shows as non-finite coefficients
        try:
            pieces = _interpolant(x, y, table.interpolation, table.period is not None)
        except ValueError:  # scipy refuses the non-finite slopes of an overflow
            return x, np.full((4, x.size - 1), np.nan)
        columns = np.searchsorted(pieces.x, x[:-1], side="right") - 1  # the intervals of x
        return x, _cubic(pieces.c[:, columns])


def _interpolant(
    x: NDArray[np.float64], y: NDArray[np.float64], interpolation: str, periodic: bool
) -> object:
    """The piecewise cubic (a scipy ``PPoly``) through the points (x, y) [SI]."""
    from scipy.interpolate import CubicSpline, PchipInterpolator, PPoly, make_interp_spline

    if interpolation == "linear":
        return PPoly.from_spline(make_interp_spline(x, y, k=1))
    if interpolation == "cubic":
        return CubicSpline(x, y, bc_type="periodic" if periodic else "not-a-knot")
    if not periodic:
        return PchipInterpolator(x, y)
    n, span = x.size - 1, x[-1] - x[0]  # two points of the neighbouring periods on each side
    wrapped_x = np.concatenate([x[n - 2 : n] - span, x, x[1:3] + span])  # set the end slopes
    return PchipInterpolator(wrapped_x, np.concatenate([y[n - 2 : n], y, y[1:3]]))


def _cubic(c: NDArray[np.float64]) -> NDArray[np.float64]:
    """Coefficients padded to a cubic's four rows (highest power first)."""
    return np.vstack([np.zeros((4 - c.shape[0], c.shape[1])), c])
