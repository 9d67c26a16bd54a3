"""One update of a long-life wear run: simulate, measure, extrapolate, record.

``study.life`` describes the method; ``LifeRun.update`` carries out one step of it and
writes its row, profiles and checkpoint (``files``), and stops the run at a run-away
(``runaway``).
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from ...engine.simulate import simulate
from ...engine.status import CLEARANCE_LIMIT, FAILED, INTERRUPTED, RUNAWAY, SUCCESS, WORN_THROUGH
from ...joints import joints_by_kind
from ...model import Model
from ...results import Results
from ...results.clearance import UM
from ...results.run_state import RunState
from . import files
from .records import Profiles, cells, clearance_growths, profile_rows, table_columns, update_row
from .runaway import Runaway, Watch
from .settings import LifeSettings

RESUME = "; --resume (resume=True) goes on from there"


class LifeRun:
    """The updates of one session of a life run, and how it ended (``status``, ``message``).

    Parameters
    ----------
    model, settings
        The model as run and the life settings.
    driver, period
        The driver whose torque is followed, and the cycle [s] (``cycle_driver``).
    folder, record
        The run's folder, and the settings and model its checkpoints carry.
    wall_before
        Wall time of the earlier sessions of the run [s].
    stop_requested
        The flag of ``interrupts.stop_requests``: once set, no further cycle is simulated.
    rows
        life.csv's rows of the earlier sessions, as dictionaries (``runaway.Watch``).

    Attributes
    ----------
    runaway
        The run-away that stopped the run, if one did.
    """

    def __init__(
        self,
        model: Model,
        settings: LifeSettings,
        driver: str,
        period: float,
        folder: Path,
        record: dict,
        wall_before: float,
        stop_requested: list[bool],
        rows: list[dict],
    ) -> None:
        self.model, self.settings, self.driver, self.period = model, settings, driver, period
        self.folder, self.record, self.stop_requested = folder, record, stop_requested
        self.wall_before, self.start = wall_before, time.perf_counter()
        self.status, self.message = SUCCESS, f"reached {settings.cycles} cycles"
        self.columns = table_columns(model, driver)
        self.watch = Watch(model, settings.runaway_factor, rows)
        self.runaway: Runaway | None = None

    def wall(self) -> float:
        """Wall time of the run, over every session [s]."""
        return self.wall_before + time.perf_counter() - self.start

    def stop(self, status: str, message: str) -> None:
        """End the run with ``status``."""
        self.status, self.message = status, message

    def update(self, point: files.Checkpoint) -> files.Checkpoint:
        """Simulate, extrapolate and record one update; return the new checkpoint.

        ``point`` comes back unchanged if the run stops instead (``status``).
        """
        settings, model = self.settings, self.model
        left = settings.cycles - point.cycles
        settling = point.state is None and settings.settle_cycles > 0
        if settling:
            simulated = min(settings.settle_cycles, left)
            settled = self._simulate(point, None, 0, simulated)
            if settled is None:
                return point
            runs = measured = [settled]
            rate = {kind: wear / simulated for kind, wear in settled.final.wear.items()}
            steady = True
        else:
            outcome = self._measure(point, left)
            if outcome is None:
                return point
            runs, measured, rate, steady = outcome
            simulated = len(runs)
        final = runs[-1].final
        motion = [r.timeseries for r in measured]
        extra = 0
        if settings.extrapolate and not settling:
            growth = clearance_growths(model, final.wear, motion)
            done = _wear_since(final, point.state)
            extra = self._extrapolated_cycles(rate, done, growth, left - simulated)
        wear = {kind: final.wear[kind] + extra * rate[kind] for kind in final.wear}
        growth = clearance_growths(model, wear, motion)
        cycles = point.cycles + simulated + extra
        if self._past_limit(wear, growth, point.cycles, cycles):
            return point
        update = 0 if settling else point.update + 1
        counts = (update, cycles, point.simulated_cycles + simulated, extra, int(steady))
        row = update_row(
            model, self.driver, counts, self.period, wear, rate, growth, measured, self.wall()
        )
        files.append_update(self.folder, row, profile_rows(model, update, cycles, wear))
        self.watch.record(dict(zip(self.columns, row, strict=True)))
        new = files.Checkpoint(update, cycles, counts[2], row[-1], final.with_wear(wear))
        files.save_checkpoint(self.folder, new, self.record)
        return new

    def _measure(
        self, point: files.Checkpoint, left: int
    ) -> tuple[list[Results], list[Results], Profiles, bool] | None:
        """Simulate cycle by cycle until the wear per cycle is steady.

        Without extrapolation ``measure_cycles`` cycles. With it, until the mean wear of the
        last ``measure_cycles`` agrees with that of the ``measure_cycles`` before them to
        ``steady_tolerance``, and at most ``max_update_cycles``.

        Returns
        -------
        tuple or None
            The runs (one per cycle), those measured, the wear per cycle [m] (their mean,
            per joint type), and whether it was steady (False after ``max_update_cycles``:
            then the second half of the runs is measured); None if a run failed, was
            interrupted or ran away.
        """
        settings = self.settings
        most = settings.max_update_cycles if settings.extrapolate else settings.measure_cycles
        state, runs, rates = point.state, [], []
        while len(runs) < min(most, left):
            results = self._simulate(point, state, len(runs), 1)
            if results is None:
                return None
            rates.append(_wear_since(results.final, state))
            runs.append(results)
            state = results.final
            if self._ran_away(point.cycles, len(runs), results, rates[-1]):
                return None
            if not settings.extrapolate:
                continue
            m = settings.measure_cycles
            if len(runs) >= 2 * m:
                last = _mean(rates[-m:])
                if self._steady(_mean(rates[-2 * m : -m]), last):
                    return runs, runs[-m:], last, True
        if not settings.extrapolate:
            return runs, runs, _mean(rates), True
        unsettled = len(runs) == most  # not for want of cycles left
        # A motion that does not settle (a chaotic one) wears at its long-run mean: that of
        # the update's second half, past the transient the jump in the profiles started.
        first = len(runs) // 2 if unsettled else min(1, len(runs) - 1)
        return runs, runs[first:], _mean(rates[first:]), not unsettled

    def _steady(self, before: Profiles, last: Profiles) -> bool:
        """Whether two wears per cycle agree, cell by cell, to ``steady_tolerance``."""
        for kind, k, joint in joints_by_kind(self.model):
            then = cells(kind, joint, before[kind.name][k])
            now = cells(kind, joint, last[kind.name][k])
            if np.abs(now - then).max() > self.settings.steady_tolerance * now.max():
                return False
        return True

    def _simulate(
        self, point: files.Checkpoint, begin: RunState | None, after: int, count: int
    ) -> Results | None:
        """Simulate ``count`` cycles from ``begin``, ``after`` cycles past ``point``.

        None if the run failed or was interrupted (``status`` then says so).
        """
        first = point.cycles + after
        span = f"cycles {first} to {first + count}"
        if self.stop_requested[0]:
            self.stop(INTERRUPTED, f"interrupted before {span}{RESUME}")
            return None
        try:
            outcome = simulate(self._cycles_model(count), initial=begin)
        except KeyboardInterrupt:  # during its set-up: nothing of this span computed
            self.stop(INTERRUPTED, f"interrupted before {span}{RESUME}")
            return None
        if outcome.status == INTERRUPTED:
            self.stop(INTERRUPTED, f"interrupted during {span}{RESUME}")
            return None
        if outcome.status != SUCCESS:
            self.stop(FAILED, f"the run of {span} ended '{outcome.status}': {outcome.message}")
            return None
        return outcome

    def _ran_away(self, before: int, count: int, results: Results, wear: Profiles) -> bool:
        """Stop if the ``count``-th cycle after ``before`` ran away (``runaway``); True if so.

        ``results``: its run; ``wear``: the depths it wore [m].
        """
        found = self.watch.check(before + count, results, wear)
        if found is None:
            return False
        self.runaway = found
        settings = self.settings
        self.stop(RUNAWAY, found.message(before, settings.runaway_factor, settings.extrapolate))
        return True

    def _cycles_model(self, count: int) -> Model:
        """The model run for ``count`` cycles (one wear snapshot, at the end)."""
        duration = count * self.period
        solver = self.model.solver.model_copy(
            update={"t_end": duration, "wear_snapshot_interval": duration}
        )
        return self.model.model_copy(update={"solver": solver})

    def _extrapolated_cycles(
        self, rate: Profiles, done: Profiles, growth: dict[str, float], left: int
    ) -> int:
        """Cycles over which ``rate`` may be extrapolated, ``left`` at most.

        No cell may change by more than ``max_change`` in the whole update: the depth
        ``done`` [m] its simulated cycles wore, plus the extrapolated cycles times ``rate``
        [m/cycle].
        """
        extra = left
        for kind, k, joint in joints_by_kind(self.model):
            bound = self.settings.change_bound(kind.gap(joint) + growth[joint.name])
            per_cycle = cells(kind, joint, rate[kind.name][k])
            wearing = per_cycle > 0.0
            if wearing.any():
                worn = cells(kind, joint, done[kind.name][k])
                room = (bound - worn[wearing]) / per_cycle[wearing]
                extra = min(extra, max(0, math.floor(room.min())))
        return extra

    def _past_limit(
        self, wear: Profiles, growth: dict[str, float], before: int, after: int
    ) -> bool:
        """Stop if profiles ``wear`` pass a limit (``study.life``); True if so."""
        for kind, k, joint in joints_by_kind(self.model):
            span = f"between cycles {before} and {after}"
            problem = kind.worn_through(joint, wear[kind.name][k], span)
            if problem is not None:
                self.stop(WORN_THROUGH, f"{joint.name}: {problem}")
                return True
            c, grown = kind.gap(joint), growth[joint.name]
            if grown > self.settings.max_growth * c:
                self.stop(
                    CLEARANCE_LIMIT,
                    f"{joint.name}: the effective clearance would grow by {grown * UM:.4g} "
                    f"µm, {grown / c:.0%} of the nominal {c * UM:.4g} µm, {span}: past "
                    f"max_growth {self.settings.max_growth:g}. {kind.growth_limit}, so the "
                    "model would no longer describe the joint (resume with a larger max_growth "
                    "to go on regardless)",
                )
                return True
        return False


def _wear_since(final: RunState, start: RunState | None) -> Profiles:
    """The depths [m] worn from ``start`` (None: unworn) to ``final``, per joint type."""
    if start is None:
        return {kind: wear.copy() for kind, wear in final.wear.items()}
    return {kind: wear - start.wear[kind] for kind, wear in final.wear.items()}


def _mean(rates: list[Profiles]) -> Profiles:
    """The mean of wears per cycle [m], per joint type."""
    return {kind: np.mean([r[kind] for r in rates], axis=0) for kind in rates[0]}
