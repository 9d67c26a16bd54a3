"""Energy balance of conservative mechanisms, watched while a run goes.

A mechanism is conservative when nothing does work on it from outside and nothing dissipates:
no drivers, no clearance joints, and loads that are gravity or undamped springs. Its kinetic
plus potential energy then stays constant, whatever the formulation keeps the constraints
with; a change beyond ``solver.max_energy_error`` of the run's energy scale means the motion
is wrong, most often a jump to another assembly branch at a singular position, where the
constraints stay met and no other check sees it.
"""

from __future__ import annotations

import numpy as np

from ..model import Model

ENERGY_FLOOR = 1e-12  # energy scale below which changes are not judged [J]
ROUNDING = 1e3 * np.finfo(float).eps  # of the energies' magnitude: changes by rounding [-]


def not_conservative(model: Model) -> str | None:
    """Why ``model`` is not conservative, or None if it is."""
    if model.drivers:
        return "drivers do work on it"
    if model.has_clearance:
        return "its clearance joints dissipate energy"
    for force in model.forces:
        if force.does_work:
            return f"an applied {force.type.replace('_', ' ')} does work on it"
        if getattr(force, "damping", 0.0) > 0.0:
            return "a damper dissipates energy"
    return None


class EnergyMonitor:
    """The largest change of kinetic plus potential energy, relative to the run's scale.

    The scale is the largest kinetic energy plus the range of the potential energy seen. A
    change within ROUNDING of the energies' magnitude is rounding, whatever the scale (a small
    swing far from the potential's zero).
    """

    def __init__(self, model: Model, columns: list[str]) -> None:
        self.reason = not_conservative(model)
        self.bound = model.solver.max_energy_error
        self._kinetic = columns.index("energy_kinetic")
        self._potential = columns.index("energy_potential")
        self.initial: float | None = None
        self.max_change = 0.0
        self.time_exceeded: float | None = None
        self._kinetic_max = 0.0
        self._potential_range = [np.inf, -np.inf]
        self._magnitude = 0.0

    @property
    def scale(self) -> float:
        """The run's energy scale so far [J]."""
        low, high = self._potential_range
        return self._kinetic_max + (high - low if high >= low else 0.0)

    def update(self, rows: np.ndarray) -> bool:
        """Take a chunk's output rows; True once the change exceeds the bound."""
        if self.reason is not None or rows.shape[0] == 0:
            return False
        kinetic, potential = rows[:, self._kinetic], rows[:, self._potential]
        total = kinetic + potential
        if self.initial is None:
            self.initial = float(total[0])
        self._kinetic_max = max(self._kinetic_max, float(kinetic.max()))
        low, high = self._potential_range
        self._potential_range = [min(low, potential.min()), max(high, potential.max())]
        change = np.abs(total - self.initial)
        self.max_change = max(self.max_change, float(change.max()))
        self._magnitude = max(self._magnitude, float((np.abs(kinetic) + np.abs(potential)).max()))
        limit = self.bound * max(self.scale, ENERGY_FLOOR) + ROUNDING * self._magnitude
        if self.time_exceeded is None and self.max_change > limit:
            self.time_exceeded = float(rows[int(np.argmax(change > limit)), 0])
        return self.time_exceeded is not None

    def summary(self) -> dict:
        """The ``energy`` entry of ``summary.json``."""
        if self.reason is not None:
            return {"conservative": False, "not_monitored_because": self.reason}
        scale = max(self.scale, ENERGY_FLOOR)
        return {
            "conservative": True,
            "initial_j": self.initial,
            "scale_j": scale,
            "max_change_j": self.max_change,
            "relative_change": self.max_change / scale,
            "bound": self.bound,
            "exceeded_at_s": self.time_exceeded,
        }
