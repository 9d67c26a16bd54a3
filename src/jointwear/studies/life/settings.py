"""What a long-life wear run is asked to do: its settings, and the cycle it counts.

A cycle is the period of the model's time functions: an angle driver at constant speed
turns once in 2 pi / speed, a harmonic function repeats after 2 pi / angular frequency;
constant values fit any period. The cycle is the longest of these periods, and every other
must divide it; a function that never repeats (a polynomial in time, a slide at constant
speed) has no cycle, and is refused.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...model import Model, ModelError
from ...model.functions import period
from ...units import to_si

MAX_CYCLES = 10**15  # more cycles than any machine runs, and within a table's 64-bit integers
PERIOD_RTOL = 1e-9  # periods whose ratio is this close to a whole number divide each other
RUNAWAY_FACTOR = 10.0  # a jump by more than this over the last updates is a run-away (runaway)


@dataclass(frozen=True)
class LifeSettings:
    """How a life run extrapolates (``life`` documents each setting)."""

    cycles: int
    settle_cycles: int = 2
    measure_cycles: int = 1
    steady_tolerance: float = 0.05
    max_update_cycles: int = 20
    max_change: str | float = "0.25%"
    extrapolate: bool = True
    feedback: bool | None = None
    max_growth: float = 1.0
    runaway_factor: float = RUNAWAY_FACTOR

    def problems(self) -> list[str]:
        """One line per invalid setting (empty if all are fine)."""
        lines = []
        for name, least in (("cycles", 1), ("settle_cycles", 0), ("measure_cycles", 1)):
            value = getattr(self, name)
            if not whole(value, least) or value > MAX_CYCLES:
                lines.append(
                    f"{name}: {value!r} is not a whole number from {least} to {MAX_CYCLES:.0e}"
                )
        least = 2 * self.measure_cycles if whole(self.measure_cycles, 1) else 2
        if not whole(self.max_update_cycles, least):
            lines.append(
                f"max_update_cycles: {self.max_update_cycles!r} is not a whole number >= {least}"
                " (twice measure_cycles: two groups of them are compared)"
            )
        tolerance = self.steady_tolerance
        if not _number(tolerance) or not 0.0 < tolerance < 1.0:
            lines.append(
                f"steady_tolerance: {tolerance!r} is not a number between 0 and 1; give the "
                "share of the deepest sector's wear by which two steady cycles may differ"
            )
        try:
            self.change_bound(0.0)
        except ValueError as error:
            lines.append(f"max_change: {error}")
        growth = self.max_growth
        if not _number(growth) or not 0 < growth < math.inf:
            lines.append(
                f"max_growth: {growth!r} is not a finite positive number; give the clearance "
                "growth at which to stop as a share of the nominal clearance (1.0: doubled)"
            )
        factor = self.runaway_factor
        if not _number(factor) or not (factor == 0 or 1 < factor < math.inf):
            lines.append(
                f"runaway_factor: {factor!r} is not a finite number above 1, nor 0; give the "
                f"jump of a joint's peak force or wear per cycle over the last updates that "
                f"stops the run (default {RUNAWAY_FACTOR:g}), or 0 for no run-away check"
            )
        return lines

    def change_bound(self, clearance: float) -> float:
        """Largest depth [m] an update may add, for a joint of current clearance [m]."""
        text = self.max_change
        if isinstance(text, str) and text.strip().endswith("%"):
            try:
                share = float(text.strip().removesuffix("%")) / 100.0
            except ValueError:
                share = math.nan
            if not 0.0 < share <= 1.0:
                raise ValueError(f"{text!r} is not a percentage in (0, 100]; e.g. '2%'")
            return share * clearance
        try:
            depth = to_si(text, "[length]")
        except ValueError as error:
            raise ValueError(f"{error}, or a share of the clearance, e.g. '2%'") from None
        if not depth > 0.0:
            raise ValueError(f"{text!r} is not a positive depth; e.g. '1 um', or '2%'")
        return depth


def _number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def whole(value: object, least: int = 1) -> bool:
    """Whether ``value`` is a whole number (a Python or numpy integer, not a bool) >= least."""
    return isinstance(value, int | np.integer) and not isinstance(value, bool) and value >= least


def cycle_driver(model: Model) -> tuple[str, float]:
    """The driver whose torque (or force) a life run follows, and the cycle period [s].

    Raises
    ------
    ModelError
        If a driver or load never repeats, the periods do not fit one cycle, or no driver
        has a period.
    """
    periods: dict[str, float] = {}
    rates: dict[str, float] = {}  # label -> the speed or angular frequency behind its period
    drivers: list[str] = []  # those with a period, in file order
    problems = []
    functions = [(f"drivers[{i}]", d.function, d.type, d.name) for i, d in enumerate(model.drivers)]
    named = {label: f"{label} '{name}'" for label, _, _, name in functions}  # for messages
    for i, load in enumerate(model.forces):
        label = f"forces[{i}]"
        named[label] = label if load.name is None else f"{label} '{load.name}'"
        functions += [(label, value, "load", None) for value in load.functions.values()]
    for label, function, kind, driver in functions:
        repeat = period(function, kind, model.drivers)
        if repeat is None:
            problems.append(
                f"{label}: a {function.type} function of {getattr(function, 'argument', 'time')} "
                "never repeats; a life run needs "
                "periodic drivers and loads: angle drivers at constant_speed, harmonic "
                "functions, tables or series with a period, or constants"
            )
        elif repeat > 0.0:
            periods[label] = repeat
            rates[label] = 2.0 * math.pi / repeat
            drivers += [driver] if driver else []
    if not problems and not drivers:
        problems.append(
            "drivers: a life run counts the cycles of a periodic driver (an angle driver at "
            "constant_speed, or a harmonic function); this model has none"
        )
    if problems:
        raise ModelError(problems)
    longest = max(periods, key=periods.__getitem__)
    cycle = periods[longest]
    for label, own in periods.items():
        if not divides(own, cycle):
            shown, whole = _apart(own, cycle)
            hints = [
                _rpm_hint(named[name], rates[name]) for name in dict.fromkeys((label, longest))
            ]
            problems.append(
                f"{label}: its period {shown} s does not divide the cycle {whole} s of "
                f"{named[longest]} (the longest period); a life run needs one cycle for the "
                "whole model" + "".join(f"; {hint}" for hint in hints if hint)
            )
    if problems:
        raise ModelError(problems)
    return drivers[0], cycle


def divides(period: float, cycle: float) -> bool:
    """Whether ``cycle`` is a whole number of ``period``s, to ``PERIOD_RTOL`` of the ratio.

    Two speeds meant alike but written differently ("5000 rpm", 523.5987755982989 rad/s)
    give periods a rounding apart: they divide each other.
    """
    ratio = cycle / period
    return round(ratio) >= 1 and abs(ratio - round(ratio)) <= PERIOD_RTOL * ratio


def _apart(first: float, second: float) -> tuple[str, str]:
    """Two numbers shown with the fewest digits (at least 6) that tell them apart."""
    for digits in range(6, 18):
        shown = f"{first:.{digits}g}", f"{second:.{digits}g}"
        if shown[0] != shown[1]:
            break
    return shown


ROUND_RPM_RTOL = 1e-6  # a speed this close to a round rpm value was likely meant as that


def _rpm_hint(label: str, rate: float) -> str:
    """A hint for a speed [rad/s] that is a round rpm value but for its last digits, or ""."""
    rpm = rate * 60.0 / (2.0 * math.pi)
    meant = float(f"{rpm:.4g}")  # four significant digits: "5000", "1500", "0.5"
    off = abs(rpm - meant)
    if not PERIOD_RTOL * meant < off <= ROUND_RPM_RTOL * meant:  # exact, or not round
        return ""
    return (
        f"{label} runs at {rpm:.12g} rpm: if {meant:g} rpm is meant, give it as "
        f"'{meant:g} rpm', exact where a number in rad/s is rounded"
    )


def with_feedback(model: Model, feedback: bool | None) -> Model:
    """``model`` with every clearance joint's ``wear_feedback`` set (None: unchanged)."""
    if feedback is None:
        return model
    joints = tuple(
        joint.model_copy(
            update={"clearance": joint.clearance.model_copy(update={"wear_feedback": feedback})}
        )
        if getattr(joint, "clearance", None) is not None
        else joint
        for joint in model.joints
    )
    return model.model_copy(update={"joints": joints})
