"""The ``sample`` command: a sampled (tolerance, Monte-Carlo or Sobol') study of a model."""

from __future__ import annotations

from contextlib import closing
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape
from rich.table import Table

from .common import (
    PLAIN,
    T_END,
    EndTime,
    ModelPath,
    Overrides,
    end_time,
    err,
    keep_whole,
    out,
    print_table,
)
from .progress import SweepProgress
from .study_commands import print_tally, study_errors

DEFAULT_METHOD, DEFAULT_SEED = "lhs", 1  # studies.sample.study.sample's, not imported: light


def sample(
    model: ModelPath,
    out_dir: Annotated[Path, typer.Option("--out", help="Study folder.", show_default=False)],
    n: Annotated[
        int | None,
        typer.Option(
            "--n",
            help="Cases (saltelli: base points, n x (inputs + 2) cases) [default: the study "
            "file's n].",
            show_default=False,
        ),
    ] = None,
    dist: Annotated[
        list[str] | None,
        typer.Option(
            "--dist",
            help="An input's distribution: dotted.path=normal(10 mm, 0.01 mm); also uniform, "
            "truncnormal, lognormal, loguniform, triangular, or a list [v1, v2] (repeatable).",
        ),
    ] = None,
    method: Annotated[
        str | None,
        typer.Option(
            "--method",
            help=f"random, lhs, sobol or saltelli (Sobol' indices) [default: {DEFAULT_METHOD}].",
            show_default=False,
        ),
    ] = None,
    seed: Annotated[
        int | None,
        typer.Option(
            "--seed",
            help=f"The same seed draws the same cases [default: {DEFAULT_SEED}].",
            show_default=False,
        ),
    ] = None,
    correlate: Annotated[
        list[str] | None,
        typer.Option(
            "--correlate",
            help="Correlate two inputs: dotted.path,dotted.path=rho (of their normal scores; "
            "repeatable).",
        ),
    ] = None,
    study_file: Annotated[
        Path | None,
        typer.Option(
            "--file",
            help="Study file: TOML with [distributions] (path = distribution), [set], and "
            "optionally n, method, seed and correlations.",
        ),
    ] = None,
    overrides: Overrides = None,
    t_end: EndTime = None,
    cycles: Annotated[
        int | None, typer.Option("--cycles", help="Long-life wear runs of N cycles per case.")
    ] = None,
    max_change: Annotated[
        str | None,
        typer.Option(
            "--max-change",
            help="With --cycles: the life runs' largest change per update ('1%', '1 um') "
            "[default: life's].",
            show_default=False,
        ),
    ] = None,
    scheduler: Annotated[
        str | None, typer.Option("--scheduler", help="Dask scheduler address (tcp://host:8786).")
    ] = None,
    workers: Annotated[
        int | None, typer.Option("--workers", help="Local processes [default: one per core].")
    ] = None,
    figures: Annotated[bool, typer.Option("--figures/--no-figures", help="Draw figures.")] = True,
) -> None:
    """Run MODEL with inputs drawn from distributions; the statistics and sensitivities.

    OUT gets cases/<case>/ (a results folder per case), sample.csv and sample.parquet (inputs
    and outputs per case), statistics.csv (mean, sd, P5, P50, P95 with 95 % intervals),
    sensitivity.csv and figures/. Running the same study again skips the finished cases.
    """
    from ..model import ModelError
    from ..studies.sample.plan import make_sample_plan
    from ..studies.sample.study import sample as run_sample

    bar = SweepProgress("sample")
    named: dict[str, str] = {}
    with study_errors(out_dir, named, "study"), closing(bar):
        plan = make_sample_plan(dist or [], study_file, end_time(overrides, t_end), correlate or [])
        if t_end is not None:
            named[T_END] = "--t-end"
        count = n if n is not None else plan.n
        if count is None:
            raise ModelError(["--n: how many cases? give --n N (or n in the study file)"])
        results = run_sample(
            model, out_dir, distributions=plan.distributions, n=count,
            method=method or plan.method or DEFAULT_METHOD,
            seed=_first(seed, plan.seed, DEFAULT_SEED), correlations=plan.correlations,
            overrides=plan.overrides, cycles=cycles, max_change=max_change, scheduler=scheduler,
            workers=workers,
            figures=figures, progress=bar,
        )  # fmt: skip
    _print_results(results, out_dir)
    if results.interrupted:
        err.print("interrupted: the tables hold the cases finished so far", soft_wrap=True)
    if results.failed:
        raise typer.Exit(code=1)


def _first(*values: int | None) -> int:
    return next(value for value in values if value is not None)


def _print_results(results: object, out_dir: Path) -> None:
    """The cases' outcome, the key outputs' statistics and what drives each."""
    from ..engine.status import NOT_RUN
    from ..figures.sample import key_outputs, owner
    from ..figures.sweep import quantity

    table, stats, sensitivity = results.table, results.statistics, results.sensitivity
    print_tally(table, results.skipped, results.failed)
    shown = key_outputs(stats)
    if shown:
        grid = Table("output", "n", "mean", "95 % interval", "P5", "P95", "95 % interval",
                     "moves it most")  # fmt: skip
        rows = stats.set_index("output")
        for column in shown:
            row = rows.loc[column]
            label, factor = quantity(column, abs(float(row["p95"])))
            value = {key: _number(row[key] * factor) for key in rows.columns[2:]}
            grid.add_row(
                escape(f"{owner(column)}: {label}"), _count(row), value["mean"],
                f"{value['mean_low']} to {value['mean_high']}", value["p5"], value["p95"],
                f"{value['p95_low']} to {value['p95_high']}", _strongest(sensitivity, column),
            )  # fmt: skip
        print_table(keep_whole(grid, 1, 2, 4, 5))
        for column in shown:
            row = rows.loc[column]
            if row["n"] < row["cases"]:
                out.print(
                    f"{owner(column)}: {quantity(column)[0]}: not reached in "
                    f"{int(row['cases'] - row['n'])} of {int(row['cases'])} cases (the run "
                    "ended first); its statistics are of the cases that reached it",
                    **PLAIN,
                )  # fmt: skip
    elif len(table):
        out.print("no outputs to describe: the model has no clearance joint or driver", **PLAIN)
    not_run = int((table["status"] == NOT_RUN).sum())
    failed = len(results.failed) - not_run
    notes = [f"{count} {what}" for count, what in ((failed, "incomplete"), (not_run, "not run"))
             if count]  # fmt: skip
    left_out = f"; {' and '.join(notes)} cases left out of the statistics" if notes else ""
    out.print(f"tables in {out_dir}: sample.csv, statistics.csv, sensitivity.csv{left_out}",
              **PLAIN)  # fmt: skip
    if "ST" in sensitivity and notes:
        out.print("Sobol' indices need every case of the design: outputs of the cases left "
                  "out have none", **PLAIN)  # fmt: skip


def _count(row: object) -> str:
    """``n``, or ``n/cases`` where some cases have no value."""
    n, cases = int(row["n"]), int(row["cases"])
    return str(n) if n == cases else f"{n}/{cases}"


def _number(value: float) -> str:
    return "-" if value != value else f"{value:.4g}"  # NaN: no interval


def _strongest(sensitivity: object, column: str) -> str:
    """The input with the largest effect on ``column``: its name and measure."""
    from ..studies.sample.sensitivity import input_labels

    rows = sensitivity[sensitivity["output"] == column]
    if not len(rows) or not rows["effect"].any():
        return "-"
    names = input_labels(sorted(set(sensitivity["input"])))
    top = rows.loc[rows["effect"].idxmax()]
    measure = next(key for key in ("ST", "prcc", "rho") if key in top and top[key] == top[key])
    return f"{names[top['input']]} ({measure} {top[measure]:+.2f})"
