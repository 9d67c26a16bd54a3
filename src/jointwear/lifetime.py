"""Long-life wear: simulate a few steady cycles, extrapolate their wear, update, repeat.

Simulating a million cycles directly is out of reach, and not needed: one cycle's wear is
tiny against the clearance, so the dynamics change only slowly as the surfaces wear. After
S. Mukras, N.H. Kim, N.A. Mauntler, T.L. Schmitz and W.G. Sawyer, "Analysis of planar
multibody systems with revolute joint wear", Wear 268 (2010) 643-652, a life run

1. simulates ``settle_cycles`` cycles from the assembled start (the start-up transient);
2. simulates cycles one after another from where the last run ended, on the current worn
   profiles, until the mean wear of the last ``measure_cycles`` agrees with that of the
   ``measure_cycles`` before them (to ``steady_tolerance``), and takes it as the wear of one
   cycle. So it simulates two cycles at least: a jump in the profiles starts a transient,
   and a transient extrapolated as if it lasted the whole update distorts the result (the
   paper's four-bar passes through short bursts of chaotic impacts, which one measured
   cycle per update stretches over much of its life). If ``max_update_cycles`` cycles do
   not settle, the update extrapolates nothing and the next tries again;
3. extrapolates it over as many further cycles as keep the largest depth it adds to any
   sector of any surface within ``max_change`` (a depth, or a share of the joint's current
   clearance, nominal plus growth), never past ``cycles`` in all; both surfaces' profiles
   are updated, and the next run starts from the last state with them (``RunState.with_wear``);
4. repeats 2-3 until ``cycles`` cycles are done.

A cycle is the period of the model's drivers (an angle driver at constant speed: 2 pi /
speed; a harmonic function: 2 pi / angular frequency). The run stops early, with its status
and a message, if a simulated run fails or is interrupted (Ctrl-C, SIGTERM: the update in
progress is lost, nothing else), if a journal would be worn through, or if a joint's
effective clearance (``lifetime_records``) would grow by more than ``max_growth`` times its
nominal clearance: the contact stiffness and the Hertz patch are computed from the nominal
radii, and the worn profile enters the contact only as a radial depth (its slope neglected),
so past a few times the nominal clearance the model no longer describes the joint.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from os import PathLike
from pathlib import Path

import numpy as np
import pandas as pd
from numpy.typing import NDArray

from . import lifetime_files as files
from .interrupts import stop_requests
from .lifetime_records import (
    clearance_growths,
    life_summary,
    profile_rows,
    relative_angle_range,
    table_columns,
    update_row,
)
from .lifetime_settings import LifeSettings, cycle_driver, with_feedback
from .model import Model, ModelError, load_model
from .results import Results
from .run_state import RunState
from .simulate import simulate

LifeProgress = Callable[[int, int], None]  # (cycles done, cycles asked for)
UM = 1e6  # [µm/m]
RESUME = "; --resume (resume=True) goes on from there"


@dataclass(frozen=True)
class LifeResults:
    """Outcome of ``life``: the tables of its folder, its summary and where it ended.

    Attributes
    ----------
    table
        life.csv: one row per update (``lifetime_records.table_columns``).
    profiles
        profiles.csv: the wear profiles after every update.
    summary
        summary.json: status, message, cycles reached, updates, per joint the final figures.
    final
        The state the run ended in (profiles updated), None if it made no update.
    """

    table: pd.DataFrame
    profiles: pd.DataFrame
    summary: dict
    final: RunState | None

    @property
    def status(self) -> str:
        """``success``, ``interrupted``, ``failed``, ``clearance_limit`` or ``worn_through``."""
        return self.summary["status"]

    @property
    def message(self) -> str:
        """What the status means."""
        return self.summary["message"]


def life(
    model_path: str | PathLike,
    out: str | PathLike,
    *,
    cycles: int,
    overrides: Sequence[str] = (),
    settle_cycles: int = 2,
    measure_cycles: int = 1,
    steady_tolerance: float = 0.05,
    max_update_cycles: int = 20,
    max_change: str | float = "2%",
    extrapolate: bool = True,
    feedback: bool | None = None,
    max_growth: float = 1.0,
    resume: bool = False,
    figures: bool = True,
    progress: LifeProgress | None = None,
) -> LifeResults:
    """Predict the wear of ``model_path``'s clearance joints over ``cycles`` driver cycles.

    Parameters
    ----------
    model_path
        TOML model file, with clearance joints and periodic drivers.
    out
        Folder for life.csv, profiles.csv, summary.json, model.json, figures/ and checkpoint/.
    cycles
        Driver cycles to reach, simulated and extrapolated.
    overrides
        ``dotted.path=value`` settings applied before validation (as ``--set``).
    settle_cycles
        Cycles simulated first, from the assembled start, before any extrapolation.
    measure_cycles
        Cycles whose mean wear is the wear of one cycle (without extrapolation: the cycles
        of an update).
    steady_tolerance
        With extrapolation, an update simulates cycle after cycle until the mean wear of the
        last ``measure_cycles`` and of the ``measure_cycles`` before them agree: no sector's
        differs by more than this share of the deepest [-].
    max_update_cycles
        At most this many cycles per update. If they never agree (a burst of chaotic impacts,
        a drifting regime) nothing is extrapolated: the update is a stretch of direct
        simulation, its row says ``steady`` 0, and the next update tries again. (A lasting
        chaotic regime is extrapolated by averaging: raise ``measure_cycles``.)
    max_change
        Largest depth an update's extrapolation may add to a sector: a length (``"1 um"``,
        or a number [m]) or a share of the joint's current clearance (``"2%"``).
    extrapolate
        False: no extrapolation, every cycle is simulated (a direct run, update by update).
    feedback
        Whether the worn profiles feed back into the contact; None keeps each joint's
        ``wear_feedback``.
    max_growth
        Stop when a joint's effective clearance would grow by more than this share of its
        nominal clearance [-] (module docstring).
    resume
        Continue the run interrupted in ``out``, with the same settings and model.
    figures
        Draw the figures into ``out/figures``.
    progress
        Called after every update with the cycles done and ``cycles``.

    Returns
    -------
    LifeResults
        Also when the run stopped early (its status says why).

    Raises
    ------
    ModelError
        For invalid settings or models, one line per problem.
    """
    settings = LifeSettings(
        cycles, settle_cycles, measure_cycles, steady_tolerance, max_update_cycles, max_change,
        extrapolate, feedback, max_growth,
    )  # fmt: skip
    problems = settings.problems()
    try:
        model = with_feedback(load_model(model_path, overrides), feedback)
    except ModelError as error:
        raise ModelError(problems + error.problems) from None
    try:
        driver, period = cycle_driver(model)
    except ModelError as error:
        problems += error.problems
    if not model.has_clearance:
        problems.append("joints: a life run needs a clearance joint ([joints.clearance])")
    if problems:
        raise ModelError(problems)
    folder = Path(out)
    record = {"settings": asdict(settings), "model": model.model_dump(mode="json")}
    if resume:
        point = files.load_checkpoint(folder, record)
    else:
        files.start_folder(folder, table_columns(model, driver), record)
        point = files.Checkpoint(0, 0, 0, 0.0, None)
    run = _Run(model, settings, driver, period, folder, record, point.wall_s)
    with stop_requests() as stop:
        while point.cycles < cycles and run.status == "success":
            point = run.update(point)
            if progress is not None and run.status == "success":
                progress(point.cycles, cycles)
            if stop[0] and run.status == "success":
                run.stop("interrupted", f"interrupted at {point.cycles} cycles{RESUME}")
    with stop_requests():  # the folder is completed whatever comes now
        table, profiles = files.read_tables(folder)
        wear = None if point.state is None else point.state.wear
        outcome = {
            "status": run.status,
            "message": run.message,
            "cycles": cycles,
            "period_s": period,
            "driver": driver,
            "wall_s": run.wall(),
            "settings": {**record["settings"], "overrides": list(overrides)},
        }
        summary = life_summary(model, table, wear, outcome)
        files.write_summary(folder, summary)
        if figures and len(table):
            from .lifetime_plots import save_life_figures  # matplotlib only when asked for

            save_life_figures(model, driver, table, profiles, folder / files.FIGURES)
    return LifeResults(table, profiles, summary, point.state)


class _Run:
    """The updates of one session of a life run, and how it ended."""

    def __init__(
        self,
        model: Model,
        settings: LifeSettings,
        driver: str,
        period: float,
        folder: Path,
        record: dict,
        wall_before: float,
    ) -> None:
        self.model, self.settings, self.driver, self.period = model, settings, driver, period
        self.folder, self.record = folder, record
        self.wall_before, self.start = wall_before, time.perf_counter()
        self.status, self.message = "success", f"reached {settings.cycles} cycles"

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
            rate, steady = settled.final.wear / simulated, True
        else:
            outcome = self._measure(point, left)
            if outcome is None:
                return point
            runs, measured, rate, steady = outcome
            simulated = len(runs)
        final = runs[-1].final
        psi = [relative_angle_range(joint, measured) for joint in model.clearance_joints]
        extra = 0
        if settings.extrapolate and steady and not settling:
            growth = clearance_growths(model, final.wear, psi)
            extra = self._extrapolated_cycles(rate, growth, left - simulated)
        wear = final.wear + extra * rate
        growth = clearance_growths(model, wear, psi)
        cycles = point.cycles + simulated + extra
        if self._past_limit(wear, growth, point.cycles, cycles):
            return point
        update = 0 if settling else point.update + 1
        counts = (update, cycles, point.simulated_cycles + simulated, extra, int(steady))
        row = update_row(model, self.driver, counts, wear, rate, growth, measured, self.wall())
        files.append_update(self.folder, row, profile_rows(model, update, cycles, wear))
        new = files.Checkpoint(update, cycles, counts[2], self.wall(), final.with_wear(wear))
        files.save_checkpoint(self.folder, new, self.record)
        return new

    def _measure(
        self, point: files.Checkpoint, left: int
    ) -> tuple[list[Results], list[Results], NDArray[np.float64], bool] | None:
        """Simulate cycle by cycle until the wear per cycle is steady.

        Without extrapolation ``measure_cycles`` cycles. With it, until the mean wear of the
        last ``measure_cycles`` agrees with that of the ``measure_cycles`` before them to
        ``steady_tolerance``, and at most ``max_update_cycles``.

        Returns
        -------
        tuple or None
            The runs (one per cycle), those measured, the wear per cycle [m] (their mean;
            of all but the first run if never steady), and whether it was steady (False only
            after ``max_update_cycles``); None if a run failed or was interrupted.
        """
        settings = self.settings
        most = settings.max_update_cycles if settings.extrapolate else settings.measure_cycles
        state, runs, rates = point.state, [], []
        while len(runs) < min(most, left):
            results = self._simulate(point, state, len(runs), 1)
            if results is None:
                return None
            start = np.zeros_like(results.final.wear) if state is None else state.wear
            rates.append(results.final.wear - start)
            runs.append(results)
            state = results.final
            if not settings.extrapolate:
                continue
            m = settings.measure_cycles
            if len(runs) >= 2 * m:
                last = np.mean(rates[-m:], axis=0)
                if self._steady(np.mean(rates[-2 * m : -m], axis=0), last):
                    return runs, runs[-m:], last, True
        first = 1 if settings.extrapolate and len(runs) > 1 else 0
        unsettled = settings.extrapolate and len(runs) == most  # not for want of cycles left
        return runs, runs[first:], np.mean(rates[first:], axis=0), not unsettled

    def _steady(self, before: NDArray[np.float64], last: NDArray[np.float64]) -> bool:
        """Whether two wears per cycle agree, sector by sector, to ``steady_tolerance``."""
        for k, joint in enumerate(self.model.clearance_joints):
            n = joint.clearance.sectors
            change = np.abs(last[k, :, :n] - before[k, :, :n]).max()
            if change > self.settings.steady_tolerance * last[k, :, :n].max():
                return False
        return True

    def _simulate(
        self, point: files.Checkpoint, begin: RunState | None, after: int, count: int
    ) -> Results | None:
        """Simulate ``count`` cycles from ``begin``, ``after`` cycles past ``point``.

        None if the run failed or was interrupted (``status`` then says so).
        """
        outcome = simulate(self._cycles_model(count), initial=begin)
        first = point.cycles + after
        span = f"cycles {first} to {first + count}"
        if outcome.status == "interrupted":
            self.stop("interrupted", f"interrupted during {span}{RESUME}")
            return None
        if outcome.status != "success":
            self.stop("failed", f"the run of {span} ended '{outcome.status}': {outcome.message}")
            return None
        return outcome

    def _cycles_model(self, count: int) -> Model:
        """The model run for ``count`` cycles (one wear snapshot, at the end)."""
        duration = count * self.period
        solver = self.model.solver.model_copy(
            update={"t_end": duration, "wear_snapshot_interval": duration}
        )
        return self.model.model_copy(update={"solver": solver})

    def _extrapolated_cycles(
        self, rate: NDArray[np.float64], growth: NDArray[np.float64], left: int
    ) -> int:
        """Cycles over which ``rate`` may be extrapolated: max_change, and ``left`` at most."""
        extra = left
        for k, joint in enumerate(self.model.clearance_joints):
            peak = rate[k, :, : joint.clearance.sectors].max()
            if peak > 0.0:
                bound = self.settings.change_bound(joint.clearance.radial_clearance + growth[k])
                extra = min(extra, math.floor(bound / peak))
        return extra

    def _past_limit(
        self, wear: NDArray[np.float64], growth: NDArray[np.float64], before: int, after: int
    ) -> bool:
        """Stop if profiles ``wear`` pass a limit (module docstring); True if so."""
        for k, joint in enumerate(self.model.clearance_joints):
            c = joint.clearance
            journal = wear[k, 1, : c.sectors].max()
            if journal >= c.journal_radius:
                self.stop(
                    "worn_through",
                    f"{joint.name}: the journal would be worn {journal * 1e3:.4g} mm deep "
                    f"between cycles {before} and {after}, through its radius "
                    f"{c.journal_radius * 1e3:.4g} mm",
                )
                return True
            limit = self.settings.max_growth * c.radial_clearance
            if growth[k] > limit:
                self.stop(
                    "clearance_limit",
                    f"{joint.name}: the effective clearance would grow by {growth[k] * UM:.4g} "
                    f"µm, {growth[k] / c.radial_clearance:.0%} of the nominal "
                    f"{c.radial_clearance * UM:.4g} µm, between cycles {before} and {after}: "
                    f"past max_growth {self.settings.max_growth:g}. The contact stiffness and "
                    "Hertz patch are those of the nominal radii and the worn profile enters "
                    "only radially, so the model would no longer describe the joint (raise "
                    "max_growth to go on regardless)",
                )
                return True
        return False
