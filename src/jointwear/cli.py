"""Command-line interface: thin wrappers over ``run``, ``load_model`` and the plots.

Exit codes: 0 success, 1 the run ended without reaching its end time (interrupted or a
solver failure; the results folder holds what was computed), 2 invalid input (one line per
problem on stderr, no traceback).
"""

from __future__ import annotations

import math
import time
from pathlib import Path
from typing import Annotated

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn, TimeRemainingColumn
from rich.table import Table

from .assembly import assemble
from .model import ModelError, load_model
from .model.clearance import Clearance
from .results import load_results
from .run import IDEAL_FOLDER
from .run import run as run_model
from .status import SUCCESS
from .studies.life.study import life as run_life
from .studies.sweep.cases import make_plan
from .studies.sweep.study import CaseReport
from .studies.sweep.study import sweep as run_sweep
from .system import build_system

app = typer.Typer(add_completion=False, no_args_is_help=True, help=__doc__.splitlines()[0])
err = Console(stderr=True)
out = Console()
PLAIN = {"soft_wrap": True, "markup": False, "highlight": False}  # text as written
PROGRESS_AFTER_S = 1.0  # show a progress bar only for runs longer than this
HERTZ_REFERENCE_FORCES = (100.0, 1000.0)  # loads at which `check` shows the Hertz patch [N]

ModelPath = Annotated[Path, typer.Argument(help="TOML model file.", show_default=False)]
Overrides = Annotated[
    list[str] | None,
    typer.Option("--set", help="Override a model value: dotted.path=value (repeatable)."),
]


def _fail(error: ModelError) -> typer.Exit:
    for line in error.problems:
        err.print(line, **PLAIN)
    return typer.Exit(code=2)


def _progress(label: str, count: str) -> Progress:
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


class _ProgressBar:
    """A progress bar on a terminal, shown once the work has lasted ``after_s`` [s].

    Called as ``bar(done, total)``; ``count`` formats them (rich task fields).
    """

    def __init__(self, label: str, count: str, after_s: float = 0.0) -> None:
        self.label, self.count, self.after_s = label, count, after_s
        self.start = time.perf_counter()
        self.bar: Progress | None = None
        self.task = 0

    def __call__(self, done: float, total: float) -> None:
        if self.bar is None:
            if not err.is_terminal or time.perf_counter() - self.start < self.after_s:
                return  # no bar in logs and pipes, nor for short work
            self.bar = _progress(self.label, self.count)
            self.bar.start()
            self.task = self.bar.add_task(self.label, total=total)
        self.bar.update(self.task, completed=done)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


@app.command()
def run(
    model: ModelPath,
    out_dir: Annotated[Path, typer.Option("--out", help="Results folder.")] = Path("results"),
    t_end: Annotated[float | None, typer.Option("--t-end", help="End time [s].")] = None,
    overrides: Overrides = None,
    figures: Annotated[bool, typer.Option("--figures/--no-figures", help="Draw figures.")] = True,
    ideal: Annotated[
        bool,
        typer.Option(
            "--ideal/--no-ideal",
            help="With clearance joints, also run the all-ideal mechanism into OUT/ideal.",
        ),
    ] = True,
) -> None:
    """Simulate MODEL and write the results folder (summary, time series, wear, figures)."""
    settings = list(overrides or [])
    if t_end is not None:
        settings.append(f"solver.t_end={t_end!r}")
    bar = _ProgressBar(
        "simulating", "t = {task.completed:.4g} / {task.total:.4g} s", PROGRESS_AFTER_S
    )
    try:
        results = run_model(
            model, out_dir, overrides=settings, figures=figures, ideal=ideal, progress=bar
        )
    except ModelError as error:
        raise _fail(error) from None
    finally:
        bar.close()
    stats = results.summary["stats"]
    out.print(
        f"{results.status}: {results.message}; t = {stats['t_reached']:.6g} s, "
        f"{stats['accepted_steps']} steps, {stats['simulation_wall_s']:.3g} s wall",
        soft_wrap=True,
    )
    for name, joint in results.summary.get("clearance_joints", {}).items():
        out.print(_joint_line(name, joint), soft_wrap=True, highlight=False)
    out.print(f"results in {out_dir}", soft_wrap=True)
    comparison = results.summary.get("ideal_comparison", {"status": SUCCESS})
    if comparison["status"] != SUCCESS:
        err.print(
            f"the run with ideal joints ended '{comparison['status']}'; it is not saved and "
            "Fig. 7 shows the clearance run alone",
            soft_wrap=True,
        )
        raise typer.Exit(code=1)
    if results.status != SUCCESS:
        raise typer.Exit(code=1)


def _joint_line(name: str, joint: dict) -> str:
    """One line of a clearance joint's headline figures."""
    wear = []
    for surface in ("journal", "bearing"):
        angle = joint[f"max_wear_angle_{surface}_deg"]
        where = f" at {angle:.4g}°" if angle is not None else ""
        wear.append(f"{surface} {joint[f'max_wear_depth_{surface}_m'] * 1e6:.4g} µm{where}")
    return (
        f"{name}: max contact force {joint['max_contact_force_n'] / 1e3:.4g} kN, in contact "
        f"{100 * joint['contact_time_fraction']:.4g} % of the time, {joint['impacts']} impacts; "
        f"max wear depth {', '.join(wear)}"
    )


@app.command()
def check(model: ModelPath, overrides: Overrides = None) -> None:
    """Validate MODEL, assemble it and print its degrees of freedom, initial pose and joints.

    The pose is assembled with every journal centred in its bearing; for each clearance
    joint the radial clearance, the contact stiffness K and the Hertz parameters follow.
    """
    try:
        parsed = load_model(model, overrides or [])
        assembly = assemble(parsed, build_system(parsed, ideal=True))
    except ModelError as error:
        raise _fail(error) from None
    out.print(f"model '{parsed.name}': valid")
    freed = 2 * len(parsed.clearance_joints)
    out.print(
        f"degrees of freedom: {assembly.dof_without_drivers + freed} (joints only), "
        f"{assembly.dof + freed} with drivers"
        + (f", of which {freed} from clearance joints" if freed else "")
    )
    out.print(
        f"assembled in {assembly.iterations} Newton iterations, residual {assembly.residual:.2e}"
    )
    table = Table(title="initial pose")
    for column in ("body", "x [m]", "y [m]", "phi [deg]", "vx [m/s]", "vy [m/s]", "omega [rad/s]"):
        table.add_column(escape(column), justify="right")
    n = assembly.y0.shape[0] // 2
    for i, body in enumerate(parsed.bodies):
        x, y, phi = assembly.y0[3 * i : 3 * i + 3]
        vx, vy, w = assembly.y0[n + 3 * i : n + 3 * i + 3]
        table.add_row(body.name, *(f"{v:.6g}" for v in (x, y, math.degrees(phi), vx, vy, w)))
    out.print(table)
    for joint in parsed.clearance_joints:
        out.print(_clearance_table(joint.name, joint.clearance))


def _clearance_table(name: str, clearance: Clearance) -> Table:
    """The derived contact and wear parameters of a clearance joint."""
    table = Table(title=f"clearance joint '{name}'")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    rows = [
        ("radial clearance c = R_B - R_J", clearance.radial_clearance * 1e3, "mm"),
        (f"contact stiffness K (n = {clearance.exponent:g})", clearance.stiffness, "N/m^n"),
        ("contact modulus E*", clearance.contact_modulus / 1e9, "GPa"),
        ("relative radius R* = R_B R_J / c", clearance.relative_radius, "m"),
    ]
    for force in HERTZ_REFERENCE_FORCES:
        b, p_max = clearance.hertz_patch(force)
        rows.append((f"Hertz half-width b at {force:g} N", b * 1e3, "mm"))
        rows.append((f"Hertz peak pressure at {force:g} N", p_max / 1e6, "MPa"))
    rows.append((f"normal law: {clearance.normal_law}", clearance.restitution_coefficient, "c_e"))
    rows.append((f"friction law: {clearance.friction_law}", clearance.friction_coefficient, "c_f"))
    if clearance.wear_law == "archard":
        rows.append(("wear law: archard, k", clearance.archard_coefficient, "1/Pa"))
    else:
        rows.append(("wear law: reye, shear strength", clearance.shear_strength / 1e6, "MPa"))
    rows.append((f"sectors per surface ({clearance.wear_distribution})", clearance.sectors, ""))
    for quantity, value, unit in rows:
        shown = "-" if value is None else f"{value:.6g}"
        table.add_row(escape(quantity), shown, escape(unit))
    return table


@app.command()
def plot(
    folder: Annotated[Path, typer.Argument(help="Results folder.")],
    animation: Annotated[
        bool, typer.Option("--animation/--no-animation", help="Also write the GIF.")
    ] = True,
) -> None:
    """Draw (again) the figures of a results folder into FOLDER/figures."""
    if not (folder / "summary.json").is_file():
        err.print(f"{folder}: not a results folder (no summary.json)", markup=False, soft_wrap=True)
        raise typer.Exit(code=2)
    from .figures.folder import save_figures  # matplotlib only for this command

    companion = folder / IDEAL_FOLDER
    ideal = load_results(companion) if (companion / "summary.json").is_file() else None
    figures = save_figures(load_results(folder), folder / "figures", ideal, animation=animation)
    for path in figures:
        out.print(str(path), soft_wrap=True)


class _SweepProgress:
    """Cases done: a progress bar on a terminal, else a line per case on stderr."""

    def __init__(self) -> None:
        self.bar: Progress | None = None
        self.task = 0

    def __call__(self, report: CaseReport | None, done: int, total: int) -> None:
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
            self.bar = _progress("sweep", "{task.completed}/{task.total} cases")
            self.bar.start()
            self.task = self.bar.add_task("sweep", total=total)
        console = err if self.bar is None else self.bar.console
        if line is not None:
            console.print(line, **PLAIN)
        if self.bar is not None:
            self.bar.update(self.task, completed=done)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


@app.command()
def sweep(
    model: ModelPath,
    out_dir: Annotated[Path, typer.Option("--out", help="Sweep folder.", show_default=False)],
    vary: Annotated[
        list[str] | None,
        typer.Option(
            "--vary", help="Vary a model value: dotted.path=V1,V2,... (repeatable; all combined)."
        ),
    ] = None,
    sweep_file: Annotated[
        Path | None,
        typer.Option("--file", help="Sweep file: TOML with [vary] (path = [values]) and [set]."),
    ] = None,
    overrides: Overrides = None,
    t_end: Annotated[float | None, typer.Option("--t-end", help="End time [s].")] = None,
    cycles: Annotated[
        int | None, typer.Option("--cycles", help="Long-life wear runs of N cycles per case.")
    ] = None,
    scheduler: Annotated[
        str | None, typer.Option("--scheduler", help="Dask scheduler address (tcp://host:8786).")
    ] = None,
    workers: Annotated[
        int | None, typer.Option("--workers", help="Local processes [default: one per core].")
    ] = None,
    figures: Annotated[
        bool, typer.Option("--figures/--no-figures", help="Draw comparison figures.")
    ] = True,
) -> None:
    """Run MODEL for every combination of the varied values; tabulate and compare the cases.

    OUT gets cases/<case>/ (a results folder per case), sweep.csv and sweep.parquet (one row
    per case) and figures/. Running the same sweep again skips the cases already finished.
    """
    settings = list(overrides or [])
    if t_end is not None:
        settings.append(f"solver.t_end={t_end!r}")
    bar = _SweepProgress()
    try:
        plan = make_plan(vary or [], sweep_file, settings)
        results = run_sweep(
            model,
            out_dir,
            vary=plan.vary,
            overrides=plan.overrides,
            cycles=cycles,
            scheduler=scheduler,
            workers=workers,
            figures=figures,
            progress=bar,
        )
    except ModelError as error:
        raise _fail(error) from None
    finally:
        bar.close()
    table = results.table
    counts = table["status"].value_counts(sort=False)  # in the order the cases come
    order = sorted(counts.index, key=lambda status: status != SUCCESS)
    tally = ", ".join(f"{counts[status]} {status}" for status in order)
    skipped = f" ({len(results.skipped)} finished before)" if results.skipped else ""
    out.print(f"{len(table)} cases{skipped}: {tally}", soft_wrap=True, highlight=False)
    for _, row in table[table["status"] != SUCCESS].iterrows():
        out.print(f"{row['case']}: {row['status']}: {row['error']}", **PLAIN)
    out.print(f"table in {out_dir / 'sweep.csv'} and sweep.parquet", **PLAIN)
    if results.interrupted:
        err.print("interrupted: the table holds the cases finished so far", soft_wrap=True)
    if results.failed:
        raise typer.Exit(code=1)


@app.command()
def life(
    model: ModelPath,
    cycles: Annotated[
        int, typer.Option("--cycles", help="Driver cycles to reach.", show_default=False)
    ],
    out_dir: Annotated[Path, typer.Option("--out", help="Life-run folder.", show_default=False)],
    overrides: Overrides = None,
    resume: Annotated[
        bool, typer.Option("--resume", help="Continue the interrupted run in OUT.")
    ] = False,
    settle_cycles: Annotated[
        int, typer.Option("--settle-cycles", help="Cycles simulated before extrapolating.")
    ] = 2,
    measure_cycles: Annotated[
        int, typer.Option("--measure-cycles", help="Cycles averaged for the wear per cycle.")
    ] = 1,
    steady_tolerance: Annotated[
        float,
        typer.Option(
            "--steady-tolerance",
            help="Steady: two groups of --measure-cycles wear alike, per sector, to this share "
            "of the deepest.",
        ),
    ] = 0.05,
    max_update_cycles: Annotated[
        int, typer.Option("--max-update-cycles", help="Most cycles simulated per update.")
    ] = 20,
    max_change: Annotated[
        str,
        typer.Option(
            "--max-change",
            help="Largest depth an update adds to a sector: a length ('1 um') or a share of "
            "the current clearance ('1%').",
        ),
    ] = "1%",
    extrapolate: Annotated[
        bool,
        typer.Option("--extrapolate/--no-extrapolate", help="Off: simulate every cycle."),
    ] = True,
    feedback: Annotated[
        bool | None,
        typer.Option(
            "--feedback/--no-feedback",
            help="Worn profiles feed back into the contact (default: as the model says).",
            show_default=False,
        ),
    ] = None,
    max_growth: Annotated[
        float,
        typer.Option(
            "--max-growth",
            help="Stop when the clearance would grow by this share of the nominal (1: doubled).",
        ),
    ] = 1.0,
    figures: Annotated[bool, typer.Option("--figures/--no-figures", help="Draw figures.")] = True,
) -> None:
    """Predict the wear of MODEL's clearance joints over many driver cycles.

    Simulates a few cycles, extrapolates their wear over many (each update changing a
    profile by at most --max-change), updates the joint geometry and repeats. OUT gets
    life.csv (one row per update), profiles.csv, summary.json and figures/.
    """
    bar = _ProgressBar("wearing", "{task.completed:,} / {task.total:,} cycles")
    try:
        results = run_life(
            model,
            out_dir,
            cycles=cycles,
            overrides=overrides or [],
            settle_cycles=settle_cycles,
            measure_cycles=measure_cycles,
            steady_tolerance=steady_tolerance,
            max_update_cycles=max_update_cycles,
            max_change=max_change,
            extrapolate=extrapolate,
            feedback=feedback,
            max_growth=max_growth,
            resume=resume,
            figures=figures,
            progress=bar,
        )
    except ModelError as error:
        raise _fail(error) from None
    finally:
        bar.close()
    summary = results.summary
    unsteady = summary["unsteady_updates"]
    out.print(
        f"{summary['status']}: {summary['message']}; {summary['cycles_reached']:,} cycles in "
        f"{summary['updates']} updates ({summary['simulated_cycles']:,} simulated"
        f"{f', {unsteady} unsteady' if unsteady else ''}), {summary['wall_s']:.3g} s wall",
        **PLAIN,
    )
    for name, joint in summary["clearance_joints"].items():
        if "clearance_growth_m" in joint:
            out.print(_life_line(name, joint), **PLAIN)
    out.print(f"results in {out_dir}", **PLAIN)
    if summary["status"] != SUCCESS:
        raise typer.Exit(code=1)


def _life_line(name: str, joint: dict) -> str:
    """One line of a clearance joint's wear after a life run."""
    at = joint["cycles_to_clearance_growth_50pct"]
    half = f"at {at:,.0f} cycles" if at is not None else "not reached"
    return (
        f"{name}: max wear depth journal {joint['max_wear_depth_journal_m'] * 1e6:.4g} µm, "
        f"bearing {joint['max_wear_depth_bearing_m'] * 1e6:.4g} µm; clearance grown by "
        f"{joint['clearance_growth_m'] * 1e6:.4g} µm ({joint['clearance_growth_fraction']:.0%});"
        f" 50% growth {half}"
    )
