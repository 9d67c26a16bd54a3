"""The commands about one model: ``run``, ``check`` and ``plot``."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape
from rich.table import Table

from .common import (
    PLAIN,
    T_END,
    Animation,
    EndTime,
    ModelPath,
    Overrides,
    end_time,
    err,
    fail,
    joint_kind,
    keep_whole,
    number,
    one_line,
    out,
    print_table,
)
from .progress import CompileNotice, ProgressBar

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from ..joints import ClearanceKind
    from ..model import Model
    from ..model.clearance import ClearanceTable
    from ..results import Results

PROGRESS_AFTER_S = 1.0  # show a progress bar only for runs longer than this


def run(
    model: ModelPath,
    out_dir: Annotated[Path, typer.Option("--out", help="Results folder.")] = Path("results"),
    t_end: EndTime = None,
    overrides: Overrides = None,
    figures: Annotated[bool, typer.Option("--figures/--no-figures", help="Draw figures.")] = True,
    animation: Animation = False,
    ideal: Annotated[
        bool,
        typer.Option(
            "--ideal/--no-ideal",
            help="With clearance joints, also run the all-ideal mechanism into OUT/ideal.",
        ),
    ] = True,
) -> None:
    """Simulate MODEL and write the results folder (summary, time series, wear, figures)."""
    from ..figures.render import drawing_helper

    settings = end_time(overrides, t_end)
    with drawing_helper(figures):  # first: its processes start up while this one imports
        results = _run(model, out_dir, settings, t_end, figures, animation, ideal)
    _report(results, out_dir)


def _run(
    model: Path,
    out_dir: Path,
    settings: list[str],
    t_end: str | None,
    figures: bool,
    animation: bool,
    ideal: bool,
) -> Results:
    """The run of ``run``, with its compile notice and progress bar."""
    from ..engine.run_file import run as run_model
    from ..model import ModelError
    from .compiling import compile_notice

    bar = ProgressBar(
        "simulating", "t = {task.completed:.4g} / {task.total:.4g} s", PROGRESS_AFTER_S
    )
    compiling = CompileNotice()
    try:
        with compile_notice(compiling.started, compiling):
            return run_model(
                model, out_dir, overrides=settings, figures=figures, animation=animation,
                ideal=ideal,
                progress=compiling.then(bar),
            )  # fmt: skip
    except ModelError as error:
        raise fail(error, {T_END: "--t-end"} if t_end is not None else None) from None
    except KeyboardInterrupt:
        if compiling.active:
            raise compiling.interrupted() from None
        err.print("interrupted before the run started; nothing was written", **PLAIN)
        raise typer.Exit(code=130) from None
    finally:
        compiling.bar.close()
        bar.close()


def _report(results: Results, out_dir: Path) -> None:
    """The console lines of ``run``; the exit code of a run that stopped early."""
    from ..engine.status import SUCCESS

    stats = results.summary["stats"]
    out.print(
        f"{results.status}: {results.message}; t = {stats['t_reached']:.6g} s, "
        f"{stats['accepted_steps']} steps, {stats['simulation_wall_s']:.3g} s wall",
        soft_wrap=True,
    )
    span = results.summary.get("steady_state", {})
    steady = span.get("from_s") is not None and span["settle_s"] > 0.0
    if steady:
        out.print(
            f"steady state from t = {span['from_s']:.4g} s (settling: {span['settling']}); "
            "the whole run's figures are under whole_run in summary.json",
            soft_wrap=True,
            highlight=False,
        )
    for name, joint in results.summary.get("clearance_joints", {}).items():
        out.print(_joint_line(name, joint, steady), soft_wrap=True, highlight=False)
        for line in _range_warnings(name, joint):
            err.print(line, soft_wrap=True, highlight=False, markup=False)
    moved = results.summary.get("not_written")
    if moved is not None:
        saved = moved["saved_in"] or f"{out_dir} (without its figures)"
        err.print(
            f"could not write {moved['folder']}: {moved['error']}; the results are in {saved}",
            **PLAIN,
        )
        raise typer.Exit(code=3)
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


def _range_warnings(name: str, joint: dict) -> list[str]:
    """One warning per law assumption the joint's run went beyond (summary.json has them)."""
    words = joint_kind(joint).range_words
    return [
        f"warning: joint '{name}': {words.get(check, check)} reached {entry['largest']:.3g}, "
        f"beyond the law's range {entry['limit']:.3g} for "
        f"{100 * entry['time_fraction_beyond']:.3g} % of the time "
        "(summary.json: outside_law_ranges)"
        for check, entry in joint.get("outside_law_ranges", {}).items()
        if entry["time_beyond_s"] > 0.0
    ]


def _joint_line(name: str, joint: dict, steady: bool) -> str:
    """One line of a clearance joint's headline figures (``steady``: in the steady state)."""
    depth = "{0} {1:.4g} µm{2}"
    wear = [
        depth.format(
            surface, joint[f"max_wear_depth_{surface}_m"] * 1e6, _wear_place(joint, surface)
        )
        for surface in joint_kind(joint).surfaces
        if f"max_wear_depth_{surface}_m" in joint  # an unbounded guide keeps no wear map
    ]
    whole = joint.get("whole_run", {})
    start_up = (
        f" (whole run {whole['max_contact_force_n'] / 1e3:.4g} kN, {whole['impacts']} impacts)"
        if steady and whole
        else ""
    )
    return (
        f"{name}: max contact force {joint['max_contact_force_n'] / 1e3:.4g} kN, in contact "
        f"{100 * joint['contact_time_fraction']:.4g} % of the time, {joint['impacts']} impacts"
        f"{start_up}; max wear depth {', '.join(wear)}"
    )


def _wear_place(joint: dict, surface: str) -> str:
    """Where a surface's deepest wear is: " at <angle>°" or " at <position> mm"; "" if unworn."""
    angle = joint.get(f"max_wear_angle_{surface}_deg")
    position = joint.get(f"max_wear_position_{surface}_m")
    if angle is not None:
        return f" at {angle:.4g}°"
    return "" if position is None else f" at {position * 1e3:.4g} mm"


def check(model: ModelPath, overrides: Overrides = None) -> None:
    """Validate MODEL, assemble it and print its degrees of freedom, initial pose and joints.

    A driven mechanism is also moved through one driver cycle (or to the end time), and
    refused if it locks up. The pose is assembled with every journal centred in its bearing;
    for each clearance joint the radial clearance, the contact stiffness K and the Hertz
    parameters follow.
    """
    from ..engine.prepare import prepare  # the model schema and the kernels, no pandas
    from ..joints import KINDS
    from ..mechanism.system import freed_degrees_of_freedom
    from ..model import ModelError, load_model

    try:
        parsed = load_model(model, overrides or [])
        ready = prepare(parsed)  # ModelError if a contact cannot be computed (build_system)
        assembly = ready.assembly
        if ready.lock is not None:
            raise ModelError([f"drivers: {ready.lock.message()}"])
    except ModelError as error:
        raise fail(error) from None
    out.print(f"model '{one_line(parsed.name)}': valid", **PLAIN)
    freed = freed_degrees_of_freedom(parsed)
    out.print(
        f"degrees of freedom: {assembly.dof_without_drivers + freed} (joints only), "
        f"{assembly.dof + freed} with drivers"
        + (f", of which {freed} from clearance joints" if freed else "")
    )
    out.print(
        f"assembled in {assembly.iterations} Newton iterations, residual {assembly.residual:.2e}"
    )
    if assembly.redundant:
        out.print(
            f"redundant constraints: {assembly.redundant} equation(s) depend on others; the "
            "reactions reported are the least-norm set (docs/model-format.md, Formulations)"
        )
    print_table(_pose_table(parsed, assembly.y0))
    for kind in KINDS:
        for joint in kind.joints(parsed):
            print_table(_clearance_table(kind, joint, parsed, assembly.y0))


def _pose_table(model: Model, y0: NDArray) -> Table:
    """Each body's pose and velocities at y0, a line each.

    As one row of cells of a line per body: rich lays a table out cell by cell, 0.6 ms a row,
    and with every column kept whole (``keep_whole``) the lines line up as rows would.
    """
    table = Table(title="initial pose")
    for column in ("body", "x [m]", "y [m]", "phi [deg]", "vx [m/s]", "vy [m/s]", "omega [rad/s]"):
        table.add_column(escape(column), justify="right")
    n = y0.shape[0] // 2
    q, qd = y0[:n].reshape(-1, 3).T.tolist(), y0[n:].reshape(-1, 3).T.tolist()
    values = (q[0], q[1], [math.degrees(phi) for phi in q[2]], *qd)
    names = "\n".join(body.name for body in model.bodies)
    table.add_row(names, *("\n".join(map(number, column)) for column in values))
    return keep_whole(table, *range(7))


def _clearance_table(kind: ClearanceKind, joint: object, model: Model, y0: NDArray) -> Table:
    """A clearance joint's layout and derived contact parameters, its laws with their keys."""
    table = Table(title=kind.check_title(joint), caption_justify="left")
    for column in ("quantity", "value", "unit"):
        table.add_column(column, justify="right" if column == "value" else "left")
    rows = kind.check_rows(joint, model, y0)
    return _filled(table, [*rows, *_law_rows(joint.clearance, table)])


def _law_rows(clearance: ClearanceTable, table: Table) -> list[tuple]:
    """Rows of the friction coefficient and each chosen law with its keys; the caption too."""
    from ..model.clearance import FAMILIES

    rows: list[tuple] = [("friction coefficient c_f", clearance.friction_coefficient, "")]
    summaries = []
    for title, family in FAMILIES.items():
        law = family.by_name[getattr(clearance, family.key)]
        values = clearance.law_values(law)
        rows.append((f"{title} law", law.name, ""))
        rows += [(f"  {key.name}", values[key.name], key.unit) for key in law.keys]
        packed = law.pack(values)
        rows += [
            (f"  {label}", value, unit)
            for (label, unit), value in zip(law.shown, packed[: len(law.shown)], strict=True)
        ]
        summaries.append(f"{law.name}: {law.summary}")
    table.caption = "\n".join(summaries)
    return rows


def _filled(table: Table, rows: list[tuple]) -> Table:
    for quantity, value, unit in rows:
        shown = "-" if value is None else value if isinstance(value, str) else number(value)
        table.add_row(escape(quantity), escape(shown), escape(unit))
    return keep_whole(table, 1)


STUDY_FOLDERS = {"life.csv": "life-run", "sweep.json": "sweep", "sample.json": "sampled study"}


def plot(
    folder: Annotated[
        Path, typer.Argument(help="Results folder of a run, a life run, a sweep or a sample.")
    ],
    animation: Animation = False,
) -> None:
    """Draw (again) the figures of a results folder into FOLDER/figures."""
    kind = next((kind for name, kind in STUDY_FOLDERS.items() if (folder / name).is_file()), None)
    if kind is not None:
        _redraw_study(folder, kind)
        return
    if not (folder / "summary.json").is_file():
        err.print(f"{folder}: not a results folder (no summary.json)", **PLAIN)
        raise typer.Exit(code=2)
    from ..figures.render import drawing_helper

    with drawing_helper():
        _redraw(folder, animation)


def _redraw_study(folder: Path, kind: str) -> None:
    """Draw the figures of a life-run, sweep or sample folder again (``plot``)."""
    from ..model import ModelError
    from ..studies.life.redraw import redraw_life_figures
    from ..studies.sample.study import redraw_sample_figures
    from ..studies.sweep.study import redraw_sweep_figures

    redraw = {"life-run": redraw_life_figures, "sweep": redraw_sweep_figures,
              "sampled study": redraw_sample_figures}[kind]  # fmt: skip
    try:
        figures = redraw(folder)
    except ModelError as error:
        raise fail(error) from None
    except OSError as error:
        err.print(f"{folder}: cannot write its figures: {one_line(str(error))}", **PLAIN)
        raise typer.Exit(code=3) from None
    except (ValueError, LookupError, TypeError) as error:  # tables that do not fit the model
        reason = one_line(" ".join(str(error).split()))[:300]
        err.print(
            f"{folder}: cannot draw its results ({type(error).__name__}: {reason}); the "
            f"folder is damaged or incomplete: run the {kind} again",
            **PLAIN,
        )
        raise typer.Exit(code=2) from None
    for path in figures:
        out.print(str(path), soft_wrap=True)


def _redraw(folder: Path, animation: bool) -> None:
    """Draw the figures of the run folder ``folder`` (``plot``)."""
    from ..figures.folder import save_figures  # matplotlib only for this command
    from ..model import ModelError
    from ..results import IDEAL_FOLDER, load_results

    companion = folder / IDEAL_FOLDER
    try:
        results = load_results(folder)
        ideal = load_results(companion) if (companion / "summary.json").is_file() else None
    except (ModelError, OSError, ValueError, LookupError, TypeError, RecursionError) as error:
        reason = one_line(" ".join(str(error).split()))[:300]
        err.print(f"{folder}: cannot read its results ({type(error).__name__}: {reason}); "
                  "the folder is damaged or incomplete: run the model again", **PLAIN)  # fmt: skip
        raise typer.Exit(code=2) from None
    try:
        figures = save_figures(results, folder / "figures", ideal, animation=animation)
    except OSError as error:
        err.print(f"{folder}: cannot write its figures: {one_line(str(error))}", **PLAIN)
        raise typer.Exit(code=3) from None
    except (ValueError, LookupError, TypeError) as error:  # tables that do not fit the model
        reason = one_line(" ".join(str(error).split()))[:300]
        err.print(f"{folder}: cannot draw its results ({type(error).__name__}: {reason}); "
                  "the folder is damaged or incomplete: run the model again", **PLAIN)  # fmt: skip
        raise typer.Exit(code=2) from None
    for path in figures:
        out.print(str(path), soft_wrap=True)
