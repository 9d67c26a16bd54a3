"""The state a run ends in, from which another run can go on (restarts, long-life wear).

A ``RunState`` holds what the dynamics need to continue exactly where a run stopped: the time,
the coordinates and velocities, both surfaces' worn profiles of every clearance joint, and
each joint's contact period (whether one is under way, and the impact speed its damping uses).
``simulate(model, initial=state)`` starts from it; every ``Results`` carries the state its run
ended in as ``results.final``. ``save`` and ``load`` keep it in one ``.npz`` file, written
atomically.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
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
    """

    time: float
    y: NDArray[np.float64]
    wear: NDArray[np.float64]
    contact_on: NDArray[np.int64]
    impact_speed: NDArray[np.float64]

    def with_wear(self, wear: NDArray[np.float64]) -> RunState:
        """The same state with the worn profiles ``wear`` [m] instead."""
        if wear.shape != self.wear.shape:
            raise ValueError(f"wear has shape {wear.shape}; this state's is {self.wear.shape}")
        return RunState(self.time, self.y, wear.copy(), self.contact_on, self.impact_speed)

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
        )
