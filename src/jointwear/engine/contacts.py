"""The contact elements' arrays of one run, per joint type with clearance (``joints.KINDS``).

The compiled loop reads them as the four tuples of ``kernels.elements`` (tables, restart
states, logs, scratch), each kind's as a struct (``kernels.structs``); Python reads the same
arrays here, by kind name.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..joints import KINDS
from ..kernels.elements import ElementLog, Elements, ElementScratch, ElementState, no_elements
from ..kernels.structs import to_struct
from ..mechanism.system import System
from ..results.run_state import FIELDS, RunState


def _nested(record: NamedTuple) -> NamedTuple:
    """A table with its law table (``kernels.laws.user.KindLaws``) as a struct too."""
    laws = getattr(record, "laws", None)
    return record if laws is None else record._replace(laws=to_struct(laws))


class KindArrays(NamedTuple):
    """One kind's arrays of a run (``kernels.elements.<kind>.make_tables``)."""

    table: NamedTuple
    state: NamedTuple  # contact_on, impact_speed, wear: what a restart needs
    log: NamedTuple  # totals, snapshots
    scratch: NamedTuple


class Contacts:
    """Every kind's arrays of a run, allocated unworn with no contact under way.

    ``laws``: per kind, its rows' laws registered from Python (``engine.user_laws``).
    """

    def __init__(self, system: System, snapshots: int, laws: dict[str, NamedTuple]) -> None:
        self.kinds: dict[str, KindArrays] = {}
        for kind in KINDS:
            rows = system.elements[kind.name]
            lookups = {"lookups": rows.lookups} if rows.lookups.shape[1] else {}
            self.kinds[kind.name] = KindArrays(
                *kind.module.make_tables(
                    rows.ints, rows.params, snapshots, laws[kind.name], **lookups
                )
            )

    def _tuple(self, cls: type, part: str) -> NamedTuple:
        absent = to_struct(no_elements())
        fields = [
            to_struct(_nested(getattr(arrays, part))) if arrays.table.ints.shape[0] else absent
            for arrays in (self.kinds[kind.name] for kind in KINDS)
        ]
        return cls(*fields)

    def structs(self) -> tuple[Elements, ElementState, ElementScratch, ElementLog]:
        """The loop's tuples of structs (sharing these arrays).

        A kind without joints goes in as ``NoElements``, so the loop compiles nothing of it.
        """
        return (
            self._tuple(Elements, "table"),
            self._tuple(ElementState, "state"),
            self._tuple(ElementScratch, "scratch"),
            self._tuple(ElementLog, "log"),
        )

    def slots(self) -> int:
        """Contact slots of all elements."""
        return sum(k.module.SLOTS * self.kinds[k.name].table.ints.shape[0] for k in KINDS)

    def impact_info_width(self) -> int:
        """Columns an onset's entry in the impact log needs, for every kind."""
        return max(k.module.N_IMPACT_INFO for k in KINDS)

    def totals(self) -> dict[str, NDArray[np.float64]]:
        """Per kind, the live totals the loop adds to (elements, columns ``T_*``)."""
        return {name: arrays.log.totals for name, arrays in self.kinds.items()}

    def wear(self) -> dict[str, NDArray[np.float64]]:
        """Per kind, the live worn profiles [m]."""
        return {name: arrays.state.wear for name, arrays in self.kinds.items()}

    def snapshots(self) -> dict[str, NDArray[np.float64]]:
        """Per kind, the wear snapshots (snapshot, element, surface, cell) [m]."""
        return {name: arrays.log.snapshots for name, arrays in self.kinds.items()}

    def accumulated(self) -> dict[str, NDArray[np.float64]]:
        """What the elements accumulate besides the rows, by name (for ``first_non_finite``)."""
        named = {}
        for name, arrays in self.kinds.items():
            named[f"the {name} clearance joints' wear"] = arrays.state.wear
            named[f"the {name} clearance joints' contact totals"] = arrays.log.totals
        return named

    def restart(self) -> dict[str, dict[str, NDArray]]:
        """Copies of every kind's restart arrays (``RunState.contacts``)."""
        return {
            name: {field: getattr(arrays.state, field).copy() for field in FIELDS}
            for name, arrays in self.kinds.items()
        }

    def start_from(self, initial: RunState) -> None:
        """Take the restart arrays of ``initial``; ValueError if they do not fit this model."""
        for name, arrays in self.kinds.items():
            given = initial.contacts.get(name, {})
            for field in FIELDS:
                mine = getattr(arrays.state, field)
                value = given.get(field, np.zeros((0, *mine.shape[1:]), dtype=mine.dtype))
                if value.shape != mine.shape:
                    raise ValueError(
                        f"initial.contacts['{name}']['{field}'] has shape {value.shape}; this "
                        f"model needs {mine.shape}"
                    )
                mine[...] = value
