"""The state a run ends in, from which another run can go on (restarts, long-life wear).

A ``RunState`` holds what the dynamics need to continue exactly where a run stopped: the time,
the coordinates and velocities, and per joint type with clearance (``jointwear.joints``) the
arrays of its contact elements' restart state: each contact's period (whether one is under
way, and the impact speed its damping uses) and the worn profiles of every surface.
``simulate(model, initial=state)`` starts from it; every ``Results`` carries the state its run
ended in as ``results.final``. ``save`` and ``load`` keep it in one ``.npz`` file, written
atomically.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..io import write_atomic
from ..joints import KINDS

FIELDS = ("contact_on", "impact_speed", "wear")  # each kind's arrays (``kernels.elements``)


@dataclass(frozen=True)
class RunState:
    """Where a run stands: enough to continue it.

    Attributes
    ----------
    time
        Time reached [s].
    y
        Coordinates then velocities, (q, q') of every moving body [m, rad, m/s, rad/s].
    contacts
        Per joint type with clearance, its restart arrays by name (``FIELDS``):
        ``contact_on`` (slots,) 1 while a contact period is under way; ``impact_speed``
        (slots,) penetration rate at the onset of that period [m/s]; ``wear`` (joints,
        surfaces, cells) wear depth of each mapped surface [m] (the kind's docstring in
        ``jointwear.joints`` names the surfaces).
    """

    time: float
    y: NDArray[np.float64]
    contacts: dict[str, dict[str, NDArray]]

    @property
    def wear(self) -> dict[str, NDArray[np.float64]]:
        """Per joint type, the worn profiles [m]."""
        return {kind: arrays["wear"] for kind, arrays in self.contacts.items()}

    def with_wear(self, wear: dict[str, NDArray[np.float64]]) -> RunState:
        """The same state with the worn profiles ``wear`` [m] (per joint type) instead."""
        contacts = {kind: dict(arrays) for kind, arrays in self.contacts.items()}
        for kind, profiles in wear.items():
            mine = self.contacts.get(kind, {}).get("wear")
            if mine is None or profiles.shape != mine.shape:
                have = None if mine is None else mine.shape
                raise ValueError(
                    f"wear['{kind}'] has shape {profiles.shape}; this state's is {have}"
                )
            contacts[kind]["wear"] = profiles.copy()
        return replace(self, contacts=contacts)

    def save(self, path: str | os.PathLike) -> None:
        """Write the state to ``path`` (``.npz``) atomically: never half a file."""
        write_atomic(path, self._write)

    def _write(self, path: Path) -> None:
        arrays = {
            f"{kind}.{name}": value
            for kind, fields in self.contacts.items()
            for name, value in fields.items()
        }
        with open(path, "wb") as f:  # a file, not a name: np.savez would append ".npz"
            np.savez(f, time=self.time, y=self.y, **arrays)


def load_run_state(path: str | os.PathLike) -> RunState:
    """Read a state written by ``RunState.save`` (also by versions before joint-type keys)."""
    with np.load(path) as data:
        contacts: dict[str, dict[str, NDArray]] = {}
        for key in data.files:
            if "." in key:
                kind, name = key.split(".", 1)
                contacts.setdefault(kind, {})[name] = data[key].copy()
        if not contacts:  # saved before the joint types were keyed by name
            for kind in KINDS:
                for name, old in kind.older_state_names.items():
                    if old in data.files:
                        contacts.setdefault(kind.name, {})[name] = data[old].copy()
        for fields in contacts.values():
            if "contact_on" in fields:
                fields["contact_on"] = fields["contact_on"].astype(np.int64)
        return RunState(time=float(data["time"]), y=data["y"].copy(), contacts=contacts)
