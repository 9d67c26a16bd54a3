"""Progress on a terminal: a bar for runs and life runs, a bar or a line per case for sweeps."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING

import typer
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn

from .common import PLAIN, err

if TYPE_CHECKING:
    from ..studies.sweep.engine import CaseReport


def progress_bar(label: str, count: str) -> Progress:
    """A transient rich progress bar on stderr: label, bar, count, elapsed time and ETA."""
    return Progress(
        TextColumn(label),
        BarColumn(),
        TextColumn(count),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
        console=err,
        transient=True,
    )


class ProgressBar:
    """A progress bar on a terminal, shown once the work has lasted ``after_s`` [s].

    Called as ``bar(done, total)``; ``count`` formats them (rich task fields).
    """

    def __init__(self, label: str, count: str, after_s: float = 0.0) -> None:
        self.label, self.count, self.after_s = label, count, after_s
        self.start = time.perf_counter()
        self.bar: Progress | None = None
        self.task = 0

    def __call__(self, done: float, total: float) -> None:
        """Show ``done`` of ``total``."""
        if self.bar is None:
            if not err.is_terminal or time.perf_counter() - self.start < self.after_s:
                return  # no bar in logs and pipes, nor for short work
            self.bar = progress_bar(self.label, self.count)
            self.bar.start()
            self.task = self.bar.add_task(self.label, total=total)
        self.bar.update(self.task, completed=done)

    def close(self) -> None:
        """Remove the bar, if one was shown."""
        if self.bar is not None:
            self.bar.stop()
            self.bar = None


COMPILING = (
    "compiling the kernels for this run's integrator and formulation: they are not in numba's "
    "cache yet (a first run, an upgrade, an edited kernel or a new combination); later runs "
    "load them from the cache"
)


class CompileNotice:
    """Says once on stderr that numba is compiling the kernels; a bar of functions on a terminal.

    ``then(progress)`` wraps the work's progress callback so that it removes this bar first.
    """

    def __init__(self) -> None:
        self.bar = ProgressBar("compiling", "{task.completed}/~{task.total} kernels")
        self.active = False  # compiling, before the work's first progress report

    def started(self) -> None:
        """The first compile of the process has begun."""
        self.active = True
        err.print(COMPILING, soft_wrap=True)

    def __call__(self, done: int, total: int) -> None:
        """Show ``done`` of about ``total`` functions compiled (until the work reports)."""
        if self.active:  # one live display at a time: never beside the work's own bar
            self.bar(done, total)

    def interrupted(self) -> typer.Exit:
        """Say that Ctrl-C stopped the compiling (nothing is written then); the exit to raise."""
        self.bar.close()
        err.print(
            "interrupted while compiling the kernels: nothing was written (the next run "
            "compiles again)",
            soft_wrap=True,
        )
        return typer.Exit(code=130)

    def then(self, progress: Callable[[float, float], None]) -> Callable[[float, float], None]:
        """``progress``, removing the compile bar before it shows its own."""

        def report(done: float, total: float) -> None:
            self.active = False
            self.bar.close()
            progress(done, total)

        return report


class SweepProgress:
    """Cases done: a progress bar on a terminal, else a line per case on stderr."""

    def __init__(self, label: str = "sweep") -> None:
        self.bar: Progress | None = None
        self.task = 0
        self.label = label  # the study's kind, the bar's name

    def __call__(self, report: CaseReport | None, done: int, total: int) -> None:
        """Show a case's report (None: the runs start) and ``done`` of ``total`` cases."""
        if report is None:
            line = None  # the runs start
        elif report.skipped:
            line = f"[{done}/{total}] {report.case}: finished before, skipped"
        else:
            outcome = report.status + (f" ({report.error})" if report.error else "")
            line = f"[{done}/{total}] {report.case}: {outcome}, {report.wall_s:.3g} s"
        runs_started = report is None or not report.skipped
        if self.bar is None and runs_started and err.is_terminal:
            # only once the local processes have started: they may be forked, and the bar
            # runs a thread
            self.bar = progress_bar(self.label, "{task.completed}/{task.total} cases")
            self.bar.start()
            self.task = self.bar.add_task(self.label, total=total)
        console = err if self.bar is None else self.bar.console
        if line is not None:
            console.print(line, **PLAIN)
        if self.bar is not None:
            self.bar.update(self.task, completed=done)

    def close(self) -> None:
        """Remove the bar, if one was shown."""
        if self.bar is not None:
            self.bar.stop()
            self.bar = None
