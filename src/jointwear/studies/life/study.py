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
   not settle, the motion is taken as chaotic and the mean wear of their second half (past
   the transient) as the wear of one cycle;
3. extrapolates it over as many further cycles as keep the largest depth the update (its
   simulated and extrapolated cycles) adds to any cell of any surface within
   ``max_change`` (a depth, or a share of the joint's current clearance, nominal plus
   growth), never past ``cycles`` in all; every surface's profile is updated, and the next
   run starts from the last state with them (``RunState.with_wear``);
4. repeats 2-3 until ``cycles`` cycles are done.

Then, unless ``band`` is empty, the same life run at each bound of ``band`` (``band``): the
spread of these runs around the one at ``max_change`` is the prediction's uncertainty. They
run beside it, in local processes or on a Dask cluster (``companions``).

A cycle is the period of the model's drivers (an angle driver at constant speed: 2 pi /
speed; a harmonic function: 2 pi / angular frequency). The run stops early, with its status
and a message, if a simulated run fails or is interrupted (Ctrl-C, SIGTERM: the update in
progress is lost, nothing else), if a part would be worn through (a journal through its
radius, a slider through its height: ``ClearanceKind.worn_through``), if a joint's
effective clearance (``ClearanceKind.clearance_growth``) would grow by more than
``max_growth`` times its nominal clearance (default 1: doubled): the contact stiffness is
computed from the nominal geometry, and the worn profile enters the contact only as a depth
(its slope neglected), so well past the nominal clearance the model no longer describes the
joint; or if a joint runs away (its peak force or wear per cycle jumps by more than
``runaway_factor``, or it leaves its contact law's range: ``runaway``).

Every joint type whose kind supports life runs (``ClearanceKind.life_runs``: revolute and
translational) is extrapolated alike, its profiles per joint type in ``RunState.wear``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from os import PathLike
from pathlib import Path

import pandas as pd

from ...engine.interrupts import stop_requests
from ...engine.status import FAILED, INTERRUPTED, SUCCESS
from ...joints import joints_by_kind
from ...model import Model, ModelError, load_model
from ...results.run_state import RunState
from . import files
from .band import BAND, band_summary, band_table, folder_name
from .band import FOLDER as BAND_FOLDER
from .companions import Band, Companion, companion, local_processes
from .records import figure_options, life_summary, profile_columns, table_columns
from .settings import (
    MAX_CYCLES,
    RUNAWAY_FACTOR,
    LifeSettings,
    cycle_driver,
    whole,
    with_feedback,
)
from .update import RESUME, LifeRun

LifeProgress = Callable[[int, int], None]  # (cycles done, cycles asked for)


@dataclass(frozen=True)
class LifeResults:
    """Outcome of ``life``: the tables of its folder, its summary and where it ended.

    Attributes
    ----------
    table
        life.csv: one row per update (``records.table_columns``).
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
        """How the run ended: ``success``, or what stopped it (``engine.status``)."""
        return self.summary["status"]

    @property
    def message(self) -> str:
        """What the status means."""
        return self.summary["message"]


def life(
    model_path: str | PathLike | Model,
    out: str | PathLike,
    *,
    cycles: int,
    overrides: Sequence[str] = (),
    settle_cycles: int = 2,
    measure_cycles: int = 1,
    steady_tolerance: float = 0.05,
    max_update_cycles: int = 20,
    max_change: str | float = "0.25%",
    band: Sequence[str | float] = BAND,
    extrapolate: bool = True,
    feedback: bool | None = None,
    max_growth: float = 1.0,
    runaway_factor: float = RUNAWAY_FACTOR,
    resume: bool = False,
    figures: bool = True,
    progress: LifeProgress | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
) -> LifeResults:
    """Predict the wear of ``model_path``'s clearance joints over ``cycles`` driver cycles.

    Parameters
    ----------
    model_path
        TOML model file, with clearance joints and periodic drivers; or a results folder (its
        ``model.json``), or a ``Model``.
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
        At most this many cycles per update. If they never agree (chaotic impacts, a
        drifting regime) the mean wear of their second half is extrapolated, and the
        update's row says ``steady`` 0.
    max_change
        Largest depth an update (simulated and extrapolated cycles) may add to a sector: a
        length (``"1 um"``, or a number [m]) or a share of the joint's current clearance
        (``"2%"``).
    band
        Further ``max_change`` bounds, each a life run of its own in ``out/band/<bound>/``,
        whose spread around this run is its uncertainty band (``band`` module): in
        life_band.csv, summary.json and the figure. Empty: this run alone. Not without
        extrapolation.
    extrapolate
        False: no extrapolation, every cycle is simulated (a direct run, update by update).
    feedback
        Whether the worn profiles feed back into the contact; None keeps each joint's
        ``wear_feedback``.
    max_growth
        Stop when a joint's effective clearance would grow by more than this share of its
        nominal clearance [-] (module docstring).
    runaway_factor
        Stop (status ``runaway``) when a joint's peak contact force or wear per cycle in a
        simulated cycle is more than this many times the median of the last updates', or
        when it leaves its contact law's range (``runaway``) [-]; 0: no such check.
    resume
        Continue the run interrupted in ``out``, with the same settings and model (but
        ``max_growth`` and ``runaway_factor`` may be larger, ``runaway_factor`` 0).
    figures
        Draw the figures into ``out/figures``.
    progress
        Called as the runs go on with the cycles done and to do, over all the runs of the
        band (``cycles`` each).
    workers
        Processes for the runs of the band, this one included (``companions``); None: one
        per core; 1: one run after the other, here.
    scheduler
        Address of a Dask distributed scheduler (``tcp://host:8786``) to run the band's
        companions on; its workers must see ``out`` at the same path.

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
        extrapolate, feedback, max_growth, runaway_factor,
    )  # fmt: skip
    problems = settings.problems() + _runner_problems(workers, scheduler)
    bounds = list(dict.fromkeys(band)) if extrapolate else []
    for bound in bounds:
        try:
            LifeSettings(cycles, max_change=bound).change_bound(0.0)
        except ValueError as error:
            problems.append(f"band: {error}")
    try:
        model = with_feedback(load_model(model_path, overrides), feedback)
    except ModelError as error:
        raise ModelError(problems + error.problems) from None
    problems += model_problems(model)
    if problems:
        raise ModelError(problems)
    driver, period = cycle_driver(model)
    folder = Path(out)
    record = {"settings": asdict(settings), "model": model.model_dump(mode="json")}
    columns = (table_columns(model, driver), profile_columns(model))
    if resume:
        point = files.load_checkpoint(folder, record, *columns)
        rows = files.read_tables(folder)[0].to_dict("records")
    else:
        files.start_folder(folder, *columns, record)
        point, rows = files.Checkpoint(0, 0, 0, 0.0, None), []
    total = cycles * (1 + len(bounds))
    options = {
        "settle_cycles": settle_cycles, "measure_cycles": measure_cycles,
        "steady_tolerance": steady_tolerance, "max_update_cycles": max_update_cycles,
        "band": (), "max_growth": max_growth, "runaway_factor": runaway_factor,
        "figures": False,
    }  # fmt: skip
    processes = local_processes(workers, len(bounds))
    band = Band(bounds, folder, model, cycles, options, resume, processes, scheduler)
    started = time.perf_counter()
    with stop_requests() as stop:
        run = LifeRun(model, settings, driver, period, folder, record, point.wall_s, stop, rows)
        try:
            band.start(stop, compiled=False)
            while point.cycles < cycles and run.status == SUCCESS:
                point = run.update(point)
                if run.status not in (INTERRUPTED, FAILED):
                    band.start(stop, compiled=True)
                if progress is not None and run.status == SUCCESS:
                    progress(point.cycles + band.cycles_done(), total)
                if stop[0] and run.status == SUCCESS and point.cycles < cycles:
                    run.stop(INTERRUPTED, f"interrupted at {point.cycles} cycles{RESUME}")
            if run.status in (INTERRUPTED, FAILED):
                band.abandon(stop)  # the band of a run that did not end means nothing
            else:
                band.start(stop, compiled=True)  # resumed at its end: it made no update here
            # The folder is completed whatever comes now.
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
            if run.runaway is not None:
                outcome["runaway"] = run.runaway.record()
            summary = life_summary(model, table, wear, outcome)
            files.write_summary(folder, summary)
            done = point.cycles
            report = None if progress is None else lambda c: progress(done + c, total)
            companions = band.collect(report)
        except BaseException:
            band.abandon(stop)  # the runs beside it stop at their next cycle, resumable
            raise
    shaded = None
    if bounds and run.status not in (INTERRUPTED, FAILED):
        if not band.beside:

            def one(bound: str | float, where: Path) -> Companion:
                offset = cycles * (1 + bounds.index(bound))
                res = life(
                    model, where, cycles=cycles, **options, max_change=bound,
                    resume=band.resumed[str(bound)], workers=1,
                    progress=None if progress is None else lambda c, _: progress(offset + c, total),
                )  # fmt: skip
                return companion(res.summary, res.table)

            companions = {bound: one(bound, where) for bound, where in band.places.items()}
        elapsed = time.perf_counter() - started
        with stop_requests():
            summary, shaded = _with_band(
                model, folder, table, summary, max_change, companions, elapsed
            )
            files.write_summary(folder, summary)
    if figures and len(table):
        with stop_requests():
            from ...figures.life import save_life_figures  # matplotlib only when asked for

            save_life_figures(
                model, driver, table, profiles, folder / files.FIGURES, band=shaded,
                marks=summary["clearance_joints"], runaway=summary.get("runaway"),
                **figure_options(model, driver, period),
            )  # fmt: skip
    return LifeResults(table, profiles, summary, point.state)


def model_problems(model: Model) -> list[str]:
    """What keeps ``model`` from a life run: no periodic driver, no clearance joint that can.

    One line each; none if it can run.
    """
    problems = []
    try:
        cycle_driver(model)
    except ModelError as error:
        problems += error.problems
    joints = [(kind, joint) for kind, _, joint in joints_by_kind(model)]
    if not joints:
        problems.append("joints: a life run needs a clearance joint ([joints.clearance])")
    problems += [
        f"joints.{joint.name}: life runs do not support {kind.name} clearance joints yet; "
        "run it with `jointwear run`"
        for kind, joint in joints
        if not kind.life_runs
    ]
    return problems


def _runner_problems(workers: int | None, scheduler: str | None) -> list[str]:
    """What is wrong with where the band's runs are to run (``workers``, ``scheduler``)."""
    problems = []
    if workers is not None and not (whole(workers) and workers <= MAX_CYCLES):
        problems.append(f"workers: got {workers!r}; expected a whole number from 1")
    if workers is not None and scheduler is not None:
        problems.append(
            "workers: only for local processes; with a scheduler the cluster's workers run "
            "the band's companions"
        )
    return problems


def _with_band(
    model: Model,
    folder: Path,
    table: pd.DataFrame,
    summary: dict,
    max_change: str | float,
    companions: dict[str, Companion],
    elapsed: float,
) -> tuple[dict, pd.DataFrame]:
    """The summary with the band's entries, and life_band.csv (written into ``folder``).

    ``elapsed``: the wall time of this session's runs of the band, side by side or not [s].
    """
    mine = companion(summary, table)
    runs = []
    for bound, res, where in [
        (str(max_change), mine, "."),
        *((b, r, f"{BAND_FOLDER}/{folder_name(b)}") for b, r in companions.items()),
    ]:
        runs.append({"max_change": bound, "folder": where, "status": res.status,
                     "cycles_reached": res.cycles_reached, "wall_s": res.wall_s,
                     "runaway_cycle": res.runaway_cycle})  # fmt: skip
    ended = {b: r.table for b, r in companions.items() if r.status not in (INTERRUPTED, FAILED)}
    top, joints = band_summary(model, table, ended, runs, summary["cycles"], summary["period_s"])
    wall = {"wall_s": sum(r["wall_s"] for r in runs), "elapsed_s": elapsed}
    summary = {**summary, "band": {**top, **wall}}
    for name, entry in joints.items():
        summary["clearance_joints"][name]["band"] = entry
    stopped = [b for b, r in companions.items() if r.status == INTERRUPTED]
    if stopped and summary["status"] == SUCCESS:
        summary["status"] = INTERRUPTED
        summary["message"] = (
            f"the band's run at max_change {stopped[0]} was interrupted; the band is that of "
            f"the runs that ended{RESUME}"
        )
    shaded = (
        band_table(model, table, list(ended.values()), summary["period_s"]) if len(table) else None
    )
    if shaded is not None:
        files.write_band(folder, shaded)
    return summary, shaded
