"""The clearance joints' figures cycle by cycle, and in the steady state after the start-up.

The elements add up their totals (contact time, impacts, energies, worn volume; running
peaks of force and penetration) over the whole run. ``CycleWindows`` reads them between
chunks of the step loop, each time the loop has passed the end of a driver cycle (and the
end of the settling time): a window's sums are the totals' growth over it, and its peaks the
running peaks, which are then set back to zero for the next window. A window ends at the
first step end at or past its nominal end, so a step that straddles a cycle's end counts in
the cycle it began in. The windows after the settling time make the steady state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from ..joints import KINDS, TOTALS
from ..model import Model

MAX_WINDOWS = 10_000  # beyond this many cycles in a run, a window spans several cycles
CYCLE_COLUMNS = [
    "cycle",
    "t_start_s",
    "t_end_s",
    "steady",
    "joint",
    "max_contact_force_n",
    "max_penetration_m",
    "impacts",
    "contact_time_fraction",
    "worn_volume_m3",
    "energy_dissipated_j",
    "sliding_distance_m",
]  # cycles.csv: one row per window and clearance joint


@dataclass(frozen=True)
class Settling:
    """Where a run's steady state begins, and why there."""

    time: float  # [s] after the run's start
    cycle: float | None  # the mechanism's cycle [s], None if nothing repeats
    reason: str  # how the settling time was chosen, in words

    def summary(self, t0: float, t_reached: float, windows: int) -> dict:
        """The summary's ``steady_state`` entry: the span the joints' figures are over."""
        reached = t_reached - t0 > self.time
        return {
            "settle_s": self.time,
            "from_s": t0 + self.time if reached else None,
            "to_s": t_reached if reached else None,
            "settling": self.reason,
            "cycle_s": self.cycle,
            "windows": windows,
            "note": None if reached else (
                "the run ended before the settling time: the joints' figures are the whole run's"
            ),
        }  # fmt: skip


def settling(model: Model, continuing: bool = False) -> Settling:
    """The settling time of ``model``'s run: as its solver section says, or the default.

    By default, one cycle of a periodic mechanism that runs two or more, else none; a run
    that goes on from another's state (``continuing``) starts settled.
    """
    solver, cycle = model.solver, model.cycle
    if solver.settle_time is not None:
        return Settling(solver.settle_time, cycle, f"settle_time {solver.settle_time:g} s")
    if solver.settle_cycles is not None:  # the model's check: it has a cycle
        cycles = solver.settle_cycles
        return Settling(cycles * cycle, cycle, f"settle_cycles {cycles:g} of {cycle:.6g} s")
    if continuing:
        return Settling(0.0, cycle, "none: the run goes on from another's state")
    if cycle is None or solver.t_end < 2.0 * cycle * (1.0 - 1e-12):
        why = "nothing repeats" if cycle is None else "the run is shorter than two cycles"
        return Settling(0.0, cycle, f"none by default: {why}")
    return Settling(cycle, cycle, f"one cycle of {cycle:.6g} s (the default)")


class CycleWindows:
    """Cuts the elements' totals into windows at cycle ends and at the settling time.

    ``totals``: per joint type with clearance, the live arrays the compiled loop adds to
    (``ClearanceKind.peaks`` says which of their columns are running peaks).
    """

    def __init__(
        self, t0: float, t_end: float, settle: Settling, totals: dict[str, NDArray[np.float64]]
    ) -> None:
        ends = [t0 + settle.time] if settle.time > 0.0 else []
        if settle.cycle is not None:
            count = math.floor((t_end - t0) / settle.cycle * (1.0 + 1e-12))
            every = max(1, math.ceil(count / MAX_WINDOWS))
            ends += [t0 + k * settle.cycle for k in range(every, count + 1, every)]
        self._ends = sorted({e for e in ends if t0 < e < t_end * (1.0 - 1e-12)})
        self._next = 0
        self._t0, self._start, self._steady_from = t0, t0, t0 + settle.time
        self._cycle = settle.cycle
        self._kinds = [kind for kind in KINDS if kind.name in totals]
        self._totals = [totals[kind.name] for kind in self._kinds]
        self._peaks = [kind.peaks for kind in self._kinds]
        self._last = [t.copy() for t in self._totals]
        self._run_peaks = [np.zeros_like(t) for t in self._totals]
        self.records: list[tuple[float, float, list[NDArray[np.float64]]]] = []

    @property
    def next_end(self) -> float:
        """The next window's nominal end [s]; infinity after the last."""
        return self._ends[self._next] if self._next < len(self._ends) else math.inf

    def passed(self, t: float) -> None:
        """The loop is at ``t`` [s]: close the window if ``t`` is at or past its end."""
        if t < self.next_end:
            return
        while self._next < len(self._ends) and self._ends[self._next] <= t:
            self._next += 1
        self._close(t)

    def finish(self, t: float) -> None:
        """Close the last window at ``t`` [s] and give the totals back their whole-run peaks."""
        if t > self._start:
            self._close(t)
        for live, peaks, run in zip(self._totals, self._peaks, self._run_peaks, strict=True):
            live[:, peaks] = np.maximum(live[:, peaks], run[:, peaks])

    def steady(self) -> tuple[dict[str, NDArray[np.float64]], float, int] | None:
        """The steady state's totals (per kind), its duration [s] and window count; or None."""
        windows = [r for r in self.records if r[0] >= self._steady_from * (1.0 - 1e-12)]
        if not windows:
            return None
        combined = {}
        for i, (kind, peaks) in enumerate(zip(self._kinds, self._peaks, strict=True)):
            values = np.sum([w[2][i] for w in windows], axis=0)
            values[:, peaks] = np.max([w[2][i][:, peaks] for w in windows], axis=0)
            combined[kind.name] = values
        return combined, windows[-1][1] - windows[0][0], len(windows)

    def table(self, model: Model) -> pd.DataFrame:
        """cycles.csv: per window and clearance joint, its figures (``CYCLE_COLUMNS``)."""
        names = [[j.name for j in kind.joints(model)] for kind in self._kinds]
        energies = [kind.energies for kind in self._kinds]
        rows = []
        for start, end, values in self.records:
            cycle = 1 + math.floor((start - self._t0) / self._cycle + 1e-9) if self._cycle else None
            steady = start >= self._steady_from * (1.0 - 1e-12)
            for kind, joints in enumerate(names):
                for k, joint in enumerate(joints):
                    v = values[kind][k]  # the common totals (TOTALS), then the kind's
                    rows.append((
                        cycle, start, end, steady, joint, v[TOTALS["max_fn"]],
                        v[TOTALS["max_delta"]], int(v[TOTALS["impacts"]]),
                        min(1.0, v[TOTALS["contact_time"]] / (end - start)),
                        v[TOTALS["worn_volume"]], float(sum(v[i] for i in energies[kind])),
                        v[TOTALS["sliding"]],
                    ))  # fmt: skip
        return pd.DataFrame(rows, columns=CYCLE_COLUMNS)

    def _close(self, t: float) -> None:
        window = []
        for kind, (live, peaks) in enumerate(zip(self._totals, self._peaks, strict=True)):
            grown = live - self._last[kind]
            grown[:, peaks] = live[:, peaks]
            window.append(grown)
            run = self._run_peaks[kind]
            run[:, peaks] = np.maximum(run[:, peaks], live[:, peaks])
            live[:, peaks] = 0.0
            self._last[kind] = live.copy()
        self.records.append((self._start, t, window))
        self._start = t


WINDOW_KEYS = (
    "max_contact_force_n",
    "contact_time_fraction",
    "impacts",
    "max_penetration_m",
    "worn_volume_m3",
    "sliding_distance_m",
    "energy_dissipated_damping_j",
    "energy_dissipated_friction_j",
    "energy_dissipated_film_j",
    "film",
)  # the joints' figures that depend on the span they are gathered over


def lead_with_steady_state(
    whole: dict[str, dict], steady: dict[str, dict] | None
) -> dict[str, dict]:
    """Per joint: the steady state's figures first, the whole run's under ``whole_run``.

    Without a steady state (a run shorter than its settling time) the figures are the whole
    run's. Wear depths are the profiles' at the end, and the law-range checks the whole
    run's, either way.
    """
    joints = {}
    for name, entry in whole.items():
        first = entry if steady is None else steady[name]
        window = {key: first[key] for key in WINDOW_KEYS if key in first}
        rest = {key: value for key, value in entry.items() if key not in WINDOW_KEYS}
        spans = {key: entry[key] for key in WINDOW_KEYS if key in entry}
        joints[name] = {"type": entry["type"], **window, **rest, "whole_run": spans}
    return joints


def cycles_at(cycles: pd.Series, values: pd.Series, level: float) -> float | None:
    """Cycles at which ``values`` first reach ``level`` (linear between rows); None if never."""
    reached = np.flatnonzero(values.to_numpy() >= level)
    if reached.size == 0:
        return None
    i = int(reached[0])
    if i == 0:
        return float(cycles.iloc[0])
    x0, x1 = cycles.iloc[i - 1], cycles.iloc[i]
    y0, y1 = values.iloc[i - 1], values.iloc[i]
    return float(x0 + (level - y0) / (y1 - y0) * (x1 - x0))
