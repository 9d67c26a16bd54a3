"""Run-away: a joint whose dynamics jump while its profiles change little, and the stop it asks for.

A life run extrapolates the wear of a few simulated cycles on the assumption that the
dynamics change slowly as the profiles deepen. Where they do not, the extrapolation (and
often the contact model itself) has left its ground: a worn profile that enters the contact
only as a depth, a journal that starts to fly across a grown clearance, can turn a 45 kN
contact into a 2.6 MN one within a few cycles, and a wear rate a thousand times the last
one extrapolated over the next update carries the run through every milestone in one
step. So every simulated cycle of an update (the settling cycles aside: there is nothing
before them to compare with) is compared with the updates before it, joint by joint. It is
a run-away if

1. its peak contact force, or its wear per cycle (the fastest-wearing cell's), is more than
   ``runaway_factor`` times the median of the same figure over the last
   ``REFERENCE_UPDATES`` updates (``life.csv``'s ``max_contact_force_n`` and
   ``wear_rate_m_per_cycle``: their typical level, which one odd update does not set); or
2. its penetration goes beyond the normal-contact law's range (``outside_law_ranges``, the
   kind's ``penetration_range``) while the run's first update kept within it. A joint
   already beyond it there (the paper's four-bar is, for half of every cycle) is outside
   the law from the start, which ``jointwear run`` warns of; only a change is a run-away.

The run then stops with status ``runaway`` before the update that holds the cycle: its
tables end at the last update before it, and no milestone is reported through the jump.
The settling update is no reference (it holds the start-up transient), so the first update
after it is checked against nothing.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np

from ...joints import joints_by_kind
from ...model import Model
from ...model.laws.record import PENETRATION
from ...results import Results
from ...results.clearance import UM
from .records import PENETRATION_KEY, Profiles, cells

REFERENCE_UPDATES = 3  # the updates whose median a cycle is compared with
WHAT = {
    "max_contact_force_n": "peak contact force",
    "wear_rate_m_per_cycle": "wear per cycle",
    PENETRATION_KEY: "penetration",
}


class Runaway(NamedTuple):
    """A run-away found: where, in which figure, and by how much.

    ``cycle``: the cycle in which it showed (counted from 1); ``key``: the figure's life.csv
    key (``WHAT``); ``value``: its value in that cycle; ``reference``: the median of the last
    updates, or for the penetration the law's range.
    """

    cycle: int
    joint: str
    key: str
    value: float
    reference: float

    def record(self) -> dict:
        """The entry of summary.json: these fields, ``what`` in words and the ``ratio``."""
        return {**self._asdict(), "what": WHAT[self.key], "ratio": self.value / self.reference}

    def message(self, before: int, factor: float, extrapolated: bool) -> str:
        """The run's message: what ran away, where the results end, and what to try.

        ``before``: the cycles of the last update kept; ``factor``: ``runaway_factor``;
        ``extrapolated``: whether the run extrapolates (else every cycle is simulated).
        """
        ends = f"The results end at the update before it, at {before:,} cycles"
        if self.key == PENETRATION_KEY:
            return (
                f"{self.joint}: run-away in cycle {self.cycle:,}: its penetration reached "
                f"{self.value:.3g} of the gap, beyond the contact law's range "
                f"{self.reference:.3g}, within which its first update kept. {ends}: beyond, the "
                "law no longer describes the contact. A stiffer contact law, or one whose range "
                "reaches further, keeps it within (outside_law_ranges in a run's summary.json "
                "tells how far); resume with runaway_factor 0 to go on regardless"
            )
        shown = _kilonewtons if self.key == "max_contact_force_n" else _per_cycle
        check = (
            "A tighter max_change tells whether the extrapolation stepped past a change of "
            "regime; if the jump stays, the joint has left what its model describes"
            if extrapolated
            else "The joint has left what its model describes"
        )
        return (
            f"{self.joint}: run-away in cycle {self.cycle:,}: its {WHAT[self.key]} jumped to "
            f"{shown(self.value)}, {self.value / self.reference:.3g} times the "
            f"{shown(self.reference)} of the last updates (their median), more than "
            f"runaway_factor {factor:g}. {ends}: no milestone is reported through the jump. "
            f"{check} (the contact law's range, outside_law_ranges in a run's summary.json, or "
            "a stiffer contact law); resume with a larger runaway_factor, or 0, to go on "
            "regardless"
        )


def _kilonewtons(force: float) -> str:
    return f"{force / 1e3:,.4g} kN"


def _per_cycle(depth: float) -> str:
    return f"{depth * UM:.3g} µm per cycle"


def jump(reference: Sequence[float], values: Sequence[float], factor: float) -> int | None:
    """The first of ``values`` above ``factor`` times the median of ``reference``; None if none.

    No verdict (None) without a reference, or where its median is not positive (a joint out
    of contact has no level to jump from).
    """
    if not len(reference):
        return None
    level = float(np.median(reference))
    if not level > 0.0:
        return None
    above = np.flatnonzero(np.asarray(values, dtype=float) > factor * level)
    return int(above[0]) if above.size else None


class Watch:
    """Compares each simulated cycle of a life run with the updates recorded before it.

    Parameters
    ----------
    model
        The model as run.
    factor
        ``runaway_factor``: the jump over the last updates' median that is a run-away; 0: no
        check at all.
    rows
        life.csv's rows so far (a resumed run's), as dictionaries; ``record`` adds each new one.
    """

    def __init__(self, model: Model, factor: float, rows: Sequence[dict]) -> None:
        self.model, self.factor = model, factor
        self.start: dict | None = None  # the first update's row: the penetration's reference
        self.updates: list[dict] = []  # the rows of the updates after the settling
        for row in rows:
            self.record(row)

    def record(self, row: dict) -> None:
        """Add a row of life.csv (``records.table_columns``' keys)."""
        if row["update"] > 0:  # the settling's start-up transient is no reference
            self.start = self.start or row
            self.updates = [*self.updates[1 - REFERENCE_UPDATES :], row]

    def check(self, cycle: int, results: Results, wear: Profiles) -> Runaway | None:
        """The run-away in ``cycle`` (counted from 1), simulated as ``results``; None if none.

        ``wear``: the depths the cycle wore [m], per joint type.
        """
        if not self.factor:
            return None
        for kind, k, joint in joints_by_kind(self.model):
            name = joint.name
            summary = results.summary["clearance_joints"][name]
            now = {
                "max_contact_force_n": summary["max_contact_force_n"],
                "wear_rate_m_per_cycle": float(cells(kind, joint, wear[kind.name][k]).max()),
            }
            for key, value in now.items():
                before = [row[f"{name}.{key}"] for row in self.updates]
                if jump(before, [value], self.factor) is not None:
                    return Runaway(cycle, name, key, value, float(np.median(before)))
            limit = joint.clearance.law_ranges().get(PENETRATION)
            entry = summary.get("outside_law_ranges", {}).get(kind.penetration_range)
            first = math.nan if self.start is None else self.start[f"{name}.{PENETRATION_KEY}"]
            if limit is not None and entry is not None and first <= limit < entry["largest"]:
                return Runaway(cycle, name, PENETRATION_KEY, entry["largest"], limit)
        return None
