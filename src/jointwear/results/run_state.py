"""The state a run ends in, from which another run can go on (restarts, long-life wear).

A ``RunState`` holds what the dynamics need to continue exactly where a run stopped: the time,
the coordinates and velocities, the worn profiles of every clearance joint's surfaces, and
each contact's period (whether one is under way, and the impact speed its damping uses).
``simulate(model, initial=state)`` starts from it; every ``Results`` carries the state its run
ended in as ``results.final``. ``save`` and ``load`` keep it in one ``.npz`` file, written
atomically.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..io import write_atomic


@dataclass(frozen=True)
class RunState:
    """Where a run stands: enough to continue it.

    Attributes
    ----------
    time
        Time reached [s].
    y
        Coordinates then velocities, (q, q') of every moving body [m, rad, m/s, rad/s].
    wear
        (clearance joints, 2, sectors) wear depth of the bearing (0) and journal (1) [m].
    contact_on
        (clearance joints,) 1 while a contact period is under way.
    impact_speed
        (clearance joints,) penetration rate at the onset of that period [m/s].
    slider_wear, slider_contact_on, slider_impact_speed
        The same of the translational clearance joints: (sliders, 4, segments) wear depth of
        each surface (``kernels.elements.slider.SURFACES``) [m], and per contact slot
        (sliders * 8,) its period and impact speed [m/s].
    """

    time: float
    y: NDArray[np.float64]
    wear: NDArray[np.float64]
    contact_on: NDArray[np.int64]
    impact_speed: NDArray[np.float64]
    slider_wear: NDArray[np.float64] = field(default_factory=lambda: np.zeros((0, 4, 1)))
    slider_contact_on: NDArray[np.int64] = field(
        default_factory=lambda: np.zeros(0, dtype=np.int64)
    )
    slider_impact_speed: NDArray[np.float64] = field(default_factory=lambda: np.zeros(0))

    def with_wear(self, wear: NDArray[np.float64]) -> RunState:
        """The same state with the worn profiles ``wear`` [m] instead."""
        if wear.shape != self.wear.shape:
            raise ValueError(f"wear has shape {wear.shape}; this state's is {self.wear.shape}")
        return replace(self, wear=wear.copy())

    def save(self, path: str | os.PathLike) -> None:
        """Write the state to ``path`` (``.npz``) atomically: never half a file."""
        write_atomic(path, self._write)

    def _write(self, path: Path) -> None:
        with open(path, "wb") as f:  # a file, not a name: np.savez would append ".npz"
            np.savez(
                f,
                time=self.time,
                y=self.y,
                wear=self.wear,
                contact_on=self.contact_on,
                impact_speed=self.impact_speed,
                slider_wear=self.slider_wear,
                slider_contact_on=self.slider_contact_on,
                slider_impact_speed=self.slider_impact_speed,
            )


def load_run_state(path: str | os.PathLike) -> RunState:
    """Read a state written by ``RunState.save``."""
    with np.load(path) as data:
        return RunState(
            time=float(data["time"]),
            y=data["y"].copy(),
            wear=data["wear"].copy(),
            contact_on=data["contact_on"].astype(np.int64),
            impact_speed=data["impact_speed"].copy(),
            **{
                name: data[name].copy()
                for name in ("slider_wear", "slider_contact_on", "slider_impact_speed")
                if name in data  # states saved before translational clearance joints lack them
            },
        )
