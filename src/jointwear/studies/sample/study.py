"""Sampled studies: tolerances and material data drawn from distributions, and what follows.

``sample`` draws ``n`` cases of a model's uncertain inputs (``distributions``, ``design``),
runs them with the study engine of sweeps (local processes or Dask, resumable, failures
recorded; ``cycles`` makes each a life run), and writes into the study folder, besides the
engine's ``cases/``, ``sample.csv``, ``sample.parquet`` and ``sample.json``:

- ``statistics.csv``: per output, the mean, standard deviation and P5/P50/P95 with their
  bootstrap intervals (``statistics``);
- ``sensitivity.csv``: per output and input, Sobol' indices (a ``saltelli`` design) or
  Spearman's rank correlation (``sensitivity``);
- ``figures/``: the outputs' distributions, the outputs against the inputs, the sensitivity
  chart and the running mean and P95 against the number of cases (``figures.sample``).

The outputs are the run's per-joint and per-driver figures (``coupler_follower.
max_contact_force_n``, ``motor.torque_range_n_m``); for life runs also the mechanism's life,
the cycles and hours until its first joint's clearance has grown by half, and those the run
reached. A case that fails has no outputs: it is left out of the statistics,
which the table's ``status`` column and the summary's count of failures then qualify; so is
one that stopped early (its figures up to the failure are no outcome). A life run that stopped
at a joint's limit (``clearance_limit``, ``worn_through``) is complete: its milestones are
reached.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ...engine.interrupts import stop_requests
from ...engine.status import COMPLETE
from ...io import write_atomic
from ...model import Model, ModelError
from ..life.settings import LifeSettings, whole
from ..sweep.cases import MAX_CASES, indexed_cases
from ..sweep.engine import (
    FIXED_COLUMNS,
    StudyProgress,
    StudyResults,
    check_run_options,
    run_study,
)
from .design import BASE, METHODS, correlation_matrix, unit_points
from .distributions import Distribution, read_distribution
from .plan import DIST_EXAMPLE
from .sensitivity import input_labels, rank_correlations, sobol_indices
from .statistics import CONFIDENCE, MIN_CASES, statistics

FIGURES = "figures"
NOT_OUTPUTS = re.compile(  # diagnostics, and where on a surface (not how much): not outputs
    r".*\.(whole_run|outside_law_ranges|band)\..*|.*_wear_(angle|position)_[a-z_]+_(deg|m)"
)
LIFE_OUTPUTS = (  # a life run's figures of the whole mechanism
    "hours_to_clearance_growth_50pct", "cycles_to_clearance_growth_50pct", "hours_reached",
    "cycles_reached",
)  # fmt: skip
G12 = "%.12g"  # numbers in the CSV tables


@dataclass(frozen=True)
class SampleResults(StudyResults):
    """Outcome of ``sample``: the tables, and where they and the figures are."""

    statistics: pd.DataFrame = field(default_factory=pd.DataFrame)
    sensitivity: pd.DataFrame = field(default_factory=pd.DataFrame)


def sample(
    model_path: str | os.PathLike | Model,
    out: str | os.PathLike,
    *,
    distributions: Mapping[str, object],
    n: int,
    method: str = "lhs",
    seed: int = 1,
    correlations: Mapping[tuple[str, str], float] | None = None,
    overrides: Sequence[str] = (),
    cycles: int | None = None,
    max_change: str | float | None = None,
    confidence: float = CONFIDENCE,
    scheduler: str | None = None,
    workers: int | None = None,
    figures: bool = True,
    progress: StudyProgress | None = None,
) -> SampleResults:
    """Run ``n`` cases of a model with inputs drawn from ``distributions``; their statistics.

    Parameters
    ----------
    model_path
        TOML model file, a results folder (its ``model.json``), or a ``Model``.
    out
        Study folder (created); running the same study again (same draws: same
        distributions, ``n``, ``method`` and ``seed``) skips the cases already finished.
    distributions
        Dotted path (as for ``--set``) -> distribution: ``"normal(10 mm, 0.01 mm)"``,
        ``uniform``, ``truncnormal``, ``lognormal``, ``loguniform``, ``triangular``, or a list
        of values (``distributions`` module).
    n
        Cases; with ``method="saltelli"`` the base points, giving ``n (inputs + 2)`` cases.
    method
        ``random``, ``lhs`` (Latin hypercube), ``sobol`` (Sobol' sequence) or ``saltelli``
        (the design for Sobol' indices).
    seed
        The same seed draws the same cases.
    correlations
        (path, path) -> correlation of the two inputs' normal scores (not with Saltelli).
    overrides
        ``dotted.path=value`` settings common to every case.
    cycles
        None: each case is a run; a number: a long-life wear run of that many cycles,
        without its own band (the study's spread is the uncertainty) or figures.
    max_change
        The life runs' ``max_change`` (None: ``jointwear.life``'s default).
    confidence
        Of the statistics' and indices' intervals [-].
    scheduler, workers, figures, progress
        As for ``jointwear.sweep``.

    Returns
    -------
    SampleResults
        The tables (also in the folder) and what happened.

    Raises
    ------
    ModelError
        Before anything runs, if an option, a distribution or any case's model is invalid.
    """
    inputs = _distributions(distributions)
    paths = [d.path for d in inputs]
    _check(inputs, n, method, seed, correlations, overrides, confidence)
    n, seed = int(n), int(seed)  # also numpy's integers, which JSON does not write
    problems = check_run_options(cycles, scheduler, workers) + _max_change_problems(
        max_change, cycles
    )
    if problems:
        raise ModelError(problems)
    matrix = correlation_matrix(paths, dict(correlations or {}))
    points, base = unit_points(len(inputs), n, method, seed, matrix)
    columns = [d.values(points[:, i]) for i, d in enumerate(inputs)]
    rows = zip(*columns, strict=True)
    cases = indexed_cases([dict(zip(paths, row, strict=True)) for row in rows])
    record = {
        "distributions": {d.path: d.describe() for d in inputs},
        "correlations": [[a, b, rho] for (a, b), rho in (correlations or {}).items()],
        "method": method,
        "n": n,
        "seed": seed,
        "confidence": confidence,
    }
    done = run_study(
        model_path, out, cases, kind="sample", record=record, overrides=overrides,
        cycles=cycles, scheduler=scheduler, workers=workers, progress=progress,
        also_writes=("statistics.csv", "sensitivity.csv", f"{FIGURES}/"),
        life_options=_life_options(max_change), columns={BASE: base.tolist()},
    )  # fmt: skip
    table = done.table
    with stop_requests():
        stats, sensitivity = analyse(table, paths, method, confidence, done.folder)
        drawn = draw(done.folder, table, paths, stats, sensitivity) if figures else []
    return SampleResults(done.folder, table, done.skipped, drawn, done.interrupted, stats,
                         sensitivity)  # fmt: skip


def _max_change_problems(max_change: str | float | None, cycles: int | None) -> list[str]:
    if max_change is None:
        return []
    if cycles is None:
        return ["--max-change: only for life runs; give --cycles too"]
    try:
        LifeSettings(cycles, max_change=max_change).change_bound(0.0)
    except ValueError as error:
        return [f"--max-change: {error}"]
    return []


def _life_options(max_change: str | float | None) -> dict[str, object]:
    """The life runs of a study's cases: no band of their own, no figures."""
    options: dict[str, object] = {"band": (), "figures": False}
    if max_change is not None:
        options["max_change"] = max_change
    return options


def _distributions(given: Mapping[str, object]) -> list[Distribution]:
    if not isinstance(given, Mapping) or not given:
        raise ModelError([f"distributions: nothing is drawn; give e.g. --dist '{DIST_EXAMPLE}'"])
    found, problems = [], []
    for path, text in given.items():
        try:
            found.append(read_distribution(str(path), text))
        except ModelError as error:
            problems += error.problems
    if problems:
        raise ModelError(problems)
    return found


def _check(
    inputs: Sequence[Distribution],
    n: object,
    method: object,
    seed: object,
    correlations: Mapping | None,
    overrides: Sequence[str],
    confidence: object,
) -> None:
    problems = []
    if method not in METHODS:
        problems.append(f"--method: got {method!r}; expected one of {', '.join(METHODS)}")
    per_point = len(inputs) + 2 if method == "saltelli" else 1
    if not (whole(n) and MIN_CASES <= n * per_point <= MAX_CASES):
        low = -(-MIN_CASES // per_point)
        problems.append(
            f"--n: got {n!r}; expected a whole number from {low} to {MAX_CASES // per_point:,}"
            + (f" (saltelli runs n x {per_point} cases)" if per_point > 1 else "")
        )
    if not whole(seed, 0):
        problems.append(f"--seed: got {seed!r}; expected a whole number from 0")
    if correlations and method == "saltelli":
        problems.append(
            "--correlate: Sobol' indices (saltelli) assume independent inputs; use lhs, "
            "sobol or random with correlations (rank correlations then measure sensitivity)"
        )
    if not (isinstance(confidence, float) and 0.5 <= confidence < 1):
        problems.append(f"confidence: got {confidence!r}; expected a number in [0.5, 1)")
    paths = {d.path for d in inputs}
    problems += [
        f"{path}: both set (--set or [set]) and drawn (--dist); give it in one place"
        for path in dict.fromkeys(o.partition("=")[0].strip() for o in overrides)
        if path in paths
    ]
    if problems:
        raise ModelError(problems)


def outputs(table: pd.DataFrame, inputs: Sequence[str]) -> list[str]:
    """The table's result columns: per joint and driver, numeric, not diagnostics, given."""
    return [
        column
        for column in table.columns
        if ("." in column or column in LIFE_OUTPUTS)
        and column not in inputs
        and column not in FIXED_COLUMNS
        and not NOT_OUTPUTS.fullmatch(column)
        and pd.api.types.is_numeric_dtype(table[column])
        and np.isfinite(table[column].to_numpy(dtype=float)).any()  # None in every summary
    ]


def outcomes(table: pd.DataFrame, inputs: Sequence[str]) -> pd.DataFrame:
    """The table with the outputs of incomplete cases blanked (NaN).

    A case that failed or stopped early (a run-away) has figures only up to there: no
    outcome of its inputs, for the statistics, the sensitivities or the figures.
    """
    whole = table.copy()
    whole.loc[~whole["status"].isin(COMPLETE), outputs(table, inputs)] = np.nan
    return whole


def analyse(
    table: pd.DataFrame, inputs: Sequence[str], method: str, confidence: float, folder: Path
) -> tuple[pd.DataFrame, pd.DataFrame]:
    """``statistics.csv`` and ``sensitivity.csv`` of a sampled study's table (written)."""
    results = outputs(table, inputs)
    whole = outcomes(table, inputs)
    complete = whole[whole[BASE] & whole["status"].isin(COMPLETE)]
    stats = statistics(complete, results, confidence=confidence)
    if method == "saltelli":
        sensitivity = sobol_indices(whole, inputs, results, confidence=confidence)
    else:
        sensitivity = rank_correlations(whole, inputs, results, confidence=confidence)
    for name, frame in (("statistics.csv", stats), ("sensitivity.csv", sensitivity)):
        write_atomic(folder / name, lambda p, f=frame: f.to_csv(p, index=False, float_format=G12))
    return stats, sensitivity


def draw(
    folder: Path,
    table: pd.DataFrame,
    inputs: Sequence[str],
    stats: pd.DataFrame,
    sensitivity: pd.DataFrame,
) -> list[Path]:
    """The study's figures into ``folder/figures``, of its complete cases."""
    from ...figures.sample import save_sample_figures  # matplotlib only when drawing

    plan = json.loads((folder / "sample.json").read_text())
    units = {path: entry["unit"] for path, entry in plan["distributions"].items()}
    whole = outcomes(table, inputs)
    drawn = whole[whole[BASE]] if BASE in whole else whole
    labels = input_labels(inputs)
    return save_sample_figures(drawn, labels, units, stats, sensitivity, folder / FIGURES)


def redraw_sample_figures(folder: str | os.PathLike) -> list[Path]:
    """Draw the figures of the sampled study in ``folder`` again; return their paths.

    Raises
    ------
    ModelError
        If the folder is not a complete study folder (its tables).
    """
    path = Path(folder)
    try:
        plan = json.loads((path / "sample.json").read_text())
        table = pd.read_parquet(path / "sample.parquet")
        stats = pd.read_csv(path / "statistics.csv")
        sensitivity = pd.read_csv(path / "sensitivity.csv")
        inputs = list(plan["distributions"])
    except (OSError, ValueError, LookupError, TypeError) as error:
        raise ModelError(
            [f"{path}: not a complete sampled-study folder ({type(error).__name__})"]
        ) from None
    return draw(path, table, inputs, stats, sensitivity)
