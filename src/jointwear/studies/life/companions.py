"""The band's companion runs: one after another in this process, or beside the value's run.

The runs of a band are independent (the same model, another ``max_change``), so they can all
run at once: the value's run in the calling process, its companions in local processes
(``workers``: the processes of the whole band, the calling one included) or on a Dask
cluster (``scheduler``), through the sweep's runners (``sweep.runners``: the same start
method, Ctrl-C and SIGTERM handling, and record of each run's outcome, ``case.json``). On
two cores the value's run (the finest bound, the slowest) takes one and its companions the
other, one after the other: the band then takes about as long as its value's run alone.

Local processes start after the value's first update, whose kernels are then compiled (or
loaded) in the calling process: forked workers start with them, and never compile beside
it. On Dask they start at once (a scheduler that cannot be reached is refused before any
work). A stop request (Ctrl-C, SIGTERM) stops every run at its next cycle, as it stops the
value's; each keeps its checkpoint, and ``--resume`` goes on with them all. Progress counts
the cycles of every run, the companions' read from their checkpoints.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import NamedTuple

import pandas as pd

from ...engine.status import ERROR, INTERRUPTED
from ...model import Model, ModelError
from ...model.laws.user import used_laws
from ..sweep.runners import CaseTask, Outcome, run_dask, run_local
from . import files
from .band import FOLDER, folder_name


class Companion(NamedTuple):
    """What the band takes of a companion run: how it ended, its table, counts and wall time."""

    status: str
    table: pd.DataFrame
    cycles_reached: int
    wall_s: float
    runaway_cycle: int | None


def companion(summary: dict, table: pd.DataFrame) -> Companion:
    """A companion run from its summary.json and life.csv."""
    runaway = summary.get("runaway")  # there when it ran away
    return Companion(
        summary["status"], table, summary["cycles_reached"], summary["wall_s"],
        None if runaway is None else runaway["cycle"],
    )  # fmt: skip


def local_processes(workers: int | None, companions: int) -> int:
    """The local processes for ``companions`` runs beside the calling one (0: in series)."""
    return min(companions, (workers or os.cpu_count() or 1) - 1)


class Band:
    """The companion runs of a life run's band, and where they run.

    Parameters
    ----------
    bounds
        Their ``max_change`` bounds; each runs in ``folder/band/<bound>/``.
    folder
        The value's life folder (its model.json is the model the companions load).
    model
        The model as run.
    cycles
        The cycles each run is to reach.
    options
        Further keywords of ``life`` for every companion (its settings but ``max_change``).
    resume
        Whether the value's run is resumed: so is every companion that has a checkpoint.
    processes
        Local processes beside this one (``local_processes``); 0: in series, here.
    scheduler
        Address of a Dask scheduler to run the companions on, or None.
    """

    def __init__(
        self,
        bounds: Sequence[str | float],
        folder: Path,
        model: Model,
        cycles: int,
        options: dict,
        resume: bool,
        processes: int,
        scheduler: str | None,
    ) -> None:
        self.folder, self.model, self.cycles, self.options = folder, model, cycles, options
        self.places = {str(b): folder / FOLDER / folder_name(b) for b in bounds}
        self.resumed = {
            bound: resume and (where / files.CHECKPOINTS / files.CHECKPOINT).is_file()
            for bound, where in self.places.items()
        }
        self.processes, self.scheduler = processes, scheduler
        self.beside = bool(self.places) and (processes > 0 or scheduler is not None)
        self.runs: Iterator[tuple[CaseTask, Outcome]] | None = None
        self.started = False
        self.on_tick: Callable[[], None] | None = None  # while collecting: progress

    def start(self, stop: list[bool], compiled: bool) -> None:
        """Start the companions beside this process, once (not in series).

        ``compiled``: whether this process has run a cycle (its kernels are ready); local
        processes wait for it, Dask does not.
        """
        if not self.beside or self.started or not (compiled or self.scheduler):
            return
        self.started = True
        tasks = []
        for bound, where in self.places.items():
            if not self.resumed[bound]:
                files.forget_checkpoint(where)  # an earlier run's: not this one's progress
            options = {**self.options, "max_change": bound, "resume": self.resumed[bound]}
            tasks.append(
                CaseTask(
                    case=f"band-{folder_name(bound)}", model_path=str(self.folder.resolve()),
                    folder=str(where.resolve()), overrides=(), cycles=self.cycles,
                    record={"band": bound}, laws=used_laws(self.model), life_options=options,
                )
            )  # fmt: skip
        if self.scheduler is not None:
            self.runs = run_dask(tasks, self.scheduler, stop, self._tick)
        else:
            self.runs = run_local(tasks, self.processes, stop, self._tick)

    def _tick(self) -> None:
        if self.on_tick is not None:
            self.on_tick()

    def cycles_done(self) -> int:
        """The cycles the companions running beside this process have reached (0 in series)."""
        if self.runs is None:
            return 0
        return sum(files.cycles_done(where) for where in self.places.values())

    def collect(self, progress: Callable[[int], None] | None) -> dict[str, Companion]:
        """Wait for the companions started beside this process; by bound, in bounds' order.

        ``progress(done)``, with the cycles the companions have reached, as they run. A
        companion the stop request kept from starting counts as interrupted.

        Raises
        ------
        ModelError
            If a companion could not run (it raised: a file it could not write, ...).
        """
        if self.runs is None:
            return {}
        shown = [-1]

        def tick() -> None:
            done = self.cycles_done()
            if done != shown[0]:
                shown[0] = done
                progress(done)

        self.on_tick = None if progress is None else tick
        outcomes = {task.record["band"]: outcome for task, outcome in self.runs}
        self.runs = None
        problems = [
            f"band: the run at max_change {bound} ({self.places[bound]}): {outcome['error']}"
            for bound, outcome in outcomes.items()
            if outcome["status"] == ERROR
        ]
        if problems:
            raise ModelError(problems)
        found = {}
        for bound, where in self.places.items():
            outcome = outcomes.get(bound, {"status": INTERRUPTED, "summary": {}})
            if outcome["summary"]:
                found[bound] = companion(outcome["summary"], files.read_tables(where)[0])
            else:  # stopped before its run started
                found[bound] = Companion(outcome["status"], pd.DataFrame(), 0, 0.0, None)
        return found

    def abandon(self, stop: list[bool]) -> None:
        """Stop the companions beside this process (now or later) and wait for them to stop."""
        self.started = True  # none start after this
        if self.runs is not None:
            stop[0] = True
            for _ in self.runs:  # the runner stops them at its next poll
                pass
            self.runs = None
