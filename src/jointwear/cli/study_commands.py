"""The commands of the studies: ``sweep`` and ``life``."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import closing, contextmanager
from pathlib import Path
from typing import Annotated

import typer

from .common import (
    PLAIN,
    T_END,
    EndTime,
    ModelPath,
    Overrides,
    end_time,
    err,
    fail,
    joint_kind,
    one_line,
    out,
)
from .progress import CompileNotice, ProgressBar, SweepProgress


def sweep(
    model: ModelPath,
    out_dir: Annotated[Path, typer.Option("--out", help="Sweep folder.", show_default=False)],
    vary: Annotated[
        list[str] | None,
        typer.Option(
            "--vary", help="Vary a model value: dotted.path=V1,V2,... (repeatable; all combined)."
        ),
    ] = None,
    link: Annotated[
        list[str] | None,
        typer.Option(
            "--link",
            help="Vary model values together: dotted.path=V1,V2,... (repeatable; the linked "
            "paths step through their values as one, combined with --vary).",
        ),
    ] = None,
    sweep_file: Annotated[
        Path | None,
        typer.Option(
            "--file", help="Sweep file: TOML with [vary] and [link] (path = [values]) and [set]."
        ),
    ] = None,
    overrides: Overrides = None,
    t_end: EndTime = None,
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
    """Run MODEL for every combination of the varied (and linked) values; compare the cases.

    OUT gets cases/<case>/ (a results folder per case), sweep.csv and sweep.parquet (one row
    per case) and figures/. Running the same sweep again skips the cases already finished.
    """
    from ..studies.sweep.cases import make_plan
    from ..studies.sweep.study import sweep as run_sweep

    bar = SweepProgress()
    named: dict[str, str] = {}  # solver.t_end's problems are --t-end's, unless it is varied
    with study_errors(out_dir, named, "sweep"), closing(bar):
        plan = make_plan(vary or [], sweep_file, end_time(overrides, t_end), link or [])
        if t_end is not None and T_END not in plan.vary and T_END not in plan.link:
            named[T_END] = "--t-end"
        results = run_sweep(
            model,
            out_dir,
            vary=plan.vary,
            link=plan.link,
            overrides=plan.overrides,
            cycles=cycles,
            scheduler=scheduler,
            workers=workers,
            figures=figures,
            progress=bar,
        )
    print_tally(results.table, results.skipped, results.failed)
    out.print(f"table in {out_dir / 'sweep.csv'} and sweep.parquet", **PLAIN)
    if results.interrupted:
        err.print("interrupted: the table holds the cases finished so far", soft_wrap=True)
    if results.failed:
        raise typer.Exit(code=1)


@contextmanager
def study_errors(out_dir: Path, named: dict[str, str], kind: str) -> Iterator[None]:
    """A study's invalid input as exit code 2, and a folder it cannot write as exit code 3.

    ``named``: as for ``fail``, filled in while the study is set up.
    """
    from ..model import ModelError

    try:
        yield
    except ModelError as error:
        raise fail(error, named) from None
    except OSError as error:
        err.print(
            f"could not write in {out_dir}: {one_line(str(error))}; the finished cases are "
            f"kept in its cases folder, and running the {kind} again skips them",
            **PLAIN,
        )
        raise typer.Exit(code=3) from None


def print_tally(table: object, skipped: list[str], failed: list[str], shown: int = 20) -> None:
    """A study's cases by status, then the first ``shown`` cases that are not complete."""
    from ..engine.status import SUCCESS

    counts = table["status"].value_counts(sort=False)  # in the order the cases come
    order = sorted(counts.index, key=lambda status: status != SUCCESS)
    tally = ", ".join(f"{counts[status]} {status}" for status in order)
    before = f" ({len(skipped)} finished before)" if skipped else ""
    out.print(f"{len(table)} cases{before}: {tally}", soft_wrap=True, highlight=False)
    for _, row in table[table["case"].isin(failed[:shown])].iterrows():
        out.print(f"{row['case']}: {row['status']}: {row['error']}", **PLAIN)
    if len(failed) > shown:
        out.print(f"... and {len(failed) - shown} more not complete (the table's error)", **PLAIN)


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
    ] = "0.25%",
    band: Annotated[
        str,
        typer.Option(
            "--band",
            help="Further --max-change bounds, comma-separated, each a life run in OUT/band/; "
            "their spread around this run is its uncertainty band ('' or --no-band: none).",
        ),
    ] = "0.5%,1%",  # studies.life.band.BAND, not imported: the command line starts light
    no_band: Annotated[
        bool, typer.Option("--no-band", help="This run alone, without the band's runs.")
    ] = False,
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
    runaway_factor: Annotated[
        float,
        typer.Option(
            "--runaway-factor",
            help="Stop when a joint's peak force or wear per cycle jumps by more than this "
            "factor over the last updates, or it leaves its contact law's range (0: never).",
        ),
    ] = 10.0,  # studies.life.settings.RUNAWAY_FACTOR, not imported: the command line starts light
    workers: Annotated[
        int | None,
        typer.Option(
            "--workers",
            help="Processes for the band's runs, this one included; 1: one after the other "
            "[default: one per core].",
        ),
    ] = None,
    scheduler: Annotated[
        str | None,
        typer.Option(
            "--scheduler", help="Dask scheduler address (tcp://host:8786) for the band's runs."
        ),
    ] = None,
    figures: Annotated[bool, typer.Option("--figures/--no-figures", help="Draw figures.")] = True,
) -> None:
    """Predict the wear of MODEL's clearance joints over many driver cycles.

    Simulates a few cycles, extrapolates their wear over many (each update changing a
    profile by at most --max-change), updates the joint geometry and repeats; the band's
    runs at the coarser --band bounds run beside it. OUT gets life.csv (one row per update),
    profiles.csv, summary.json and figures/.
    """
    from ..engine.status import SUCCESS
    from ..model import ModelError
    from ..studies.life.study import life as run_life
    from .compiling import compile_notice

    bar = ProgressBar("wearing", "{task.completed:,} / {task.total:,} cycles")
    compiling = CompileNotice()
    try:
        with compile_notice(compiling.started, compiling):
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
                band=[] if no_band else [b.strip() for b in band.split(",") if b.strip()],
                extrapolate=extrapolate,
                feedback=feedback,
                max_growth=max_growth,
                runaway_factor=runaway_factor,
                resume=resume,
                figures=figures,
                progress=compiling.then(bar),
                workers=workers,
                scheduler=scheduler,
            )
    except ModelError as error:
        raise fail(error) from None
    except OSError as error:
        err.print(
            f"could not write in {out_dir}: {one_line(str(error))}; its last complete "
            "checkpoint is kept: go on with --resume once the folder can be written",
            **PLAIN,
        )
        raise typer.Exit(code=3) from None
    finally:
        compiling.bar.close()
        bar.close()
    summary = results.summary
    unsteady = summary["unsteady_updates"]
    out.print(
        f"{summary['status']}: {summary['message']}; {summary['cycles_reached']:,} cycles in "
        f"{summary['updates']} updates ({summary['simulated_cycles']:,} simulated"
        f"{f', {unsteady} unsteady' if unsteady else ''}), {summary['hours_reached']:.3g} "
        f"hours of operation; {summary['wall_s']:.3g} s wall",
        **PLAIN,
    )
    band = summary.get("band")
    for name, joint in summary["clearance_joints"].items():
        if "clearance_growth_m" in joint:
            out.print(_life_line(name, joint), **PLAIN)
        if "band" in joint and not band["all_ran_away"]:
            out.print(_band_line(name, joint["band"], band), **PLAIN)
    if band is not None and band["all_ran_away"]:
        out.print(_ran_away_line(band), **PLAIN)
    out.print(f"results in {out_dir}", **PLAIN)
    if summary["status"] != SUCCESS:
        raise typer.Exit(code=1)


def _ran_away_line(band: dict) -> str:
    """The line that replaces the band's when every run of it ran away."""
    runs = ", ".join(f"{r['max_change']} in cycle {r['runaway_cycle']:,}" for r in band["runs"])
    return (
        f"no band: every run of it ran away ({runs}); their spread says nothing of the "
        f"prediction's uncertainty; {_walls(band)}"
    )


def _walls(band: dict) -> str:
    """The band's wall times: its runs' sum, and how long they took side by side."""
    return f"{band['wall_s']:.3g} s wall in all, {band['elapsed_s']:.3g} s elapsed"


def _band_line(name: str, entry: dict, band: dict) -> str:
    """One line of a clearance joint's uncertainty band after a life run."""
    runs = ", ".join(str(b) for b in band["max_change"])
    at, growth = entry["cycles_to_clearance_growth_50pct"], entry["clearance_growth_m"]
    hours = entry["hours_to_clearance_growth_50pct"]
    half = "not reached"
    if at["value"] is not None:
        half = f"at {at['value']:,.0f} cycles, {hours['value']:.3g} h"
    if at["low"] is not None:
        high = "not reached" if at["high"] is None else f"{at['high']:,.0f}"
        high_h = "" if hours["high"] is None else f" to {hours['high']:.3g}"
        half += f" (band {at['low']:,.0f} to {high} cycles, {hours['low']:.3g}{high_h} h)"
    grown = "-"
    if growth["value"] is not None:
        grown = f"{growth['value'] * 1e6:.4g} µm ({growth['low'] * 1e6:.4g} to "
        grown += f"{growth['high'] * 1e6:.4g})"
    return (
        f"{name}: band of the runs at max_change {runs}: 50% growth {half}; "
        f"clearance grown by {grown} at {band['at_cycles']:,} cycles; {_walls(band)}"
    )


def _life_line(name: str, joint: dict) -> str:
    """One line of a clearance joint's wear after a life run."""
    at = joint["cycles_to_clearance_growth_50pct"]
    half = "not reached"
    if at is not None:
        half = f"at {at:,.0f} cycles, {joint['hours_to_clearance_growth_50pct']:.3g} h"
    depths = [
        f"{surface} {joint[f'max_wear_depth_{surface}_m'] * 1e6:.4g} µm"
        for surface in joint_kind(joint).surfaces
        if f"max_wear_depth_{surface}_m" in joint  # an unbounded guide keeps no wear map
    ]
    return (
        f"{name}: max wear depth {', '.join(depths)}; clearance grown by "
        f"{joint['clearance_growth_m'] * 1e6:.4g} µm ({joint['clearance_growth_fraction']:.0%});"
        f" 50% growth {half}"
    )
