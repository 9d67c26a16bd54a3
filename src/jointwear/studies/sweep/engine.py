"""The engine of the studies: run named cases of one model and tabulate them.

``run_study`` is what a sweep (``study``) and a sampled study (``studies.sample``) share: it
validates every case's model first (a bad path or value stops the study before anything
runs), skips the cases a previous run of the same study finished, runs the others in local
processes or on a Dask cluster, and writes into the study folder:

- ``cases/<case>/``: each case's results folder (``jointwear run`` without figures, or a
  long-life wear run), with ``case.json``: its overrides, resolved model and outcome;
- ``<kind>.csv`` and ``<kind>.parquet``: one row per case: its name, the varied values (SI),
  status, error, wall time and the headline figures of its summary;
- ``<kind>.json``: the study itself (model, what varies, settings, case names).

A failed case is recorded with its error and the others go on. After Ctrl-C or SIGTERM the
finished cases are kept and the table is written with what is done.
"""

from __future__ import annotations

import json
import math
import os
import re
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from ...engine.interrupts import stop_requests
from ...engine.status import COMPLETE, NOT_RUN, SETTLED
from ...io import check_folder, claim, make_folder, write_atomic, write_text
from ...model import Model, ModelError, load_model
from ...model.files import SAVED_MODEL
from ...model.laws.user import used_laws
from ..life.settings import MAX_CYCLES, whole
from .cases import Case, si_value
from .runners import CaseTask, Outcome, read_record, run_dask, run_local, run_serial

CASES_FOLDER = "cases"
FIXED_COLUMNS = ("case", "status", "error", "wall_s")  # the varied paths follow "case"


@dataclass(frozen=True)
class CaseReport:
    """What the progress callback hears about each case."""

    case: str
    status: str
    error: str
    wall_s: float  # [s]
    skipped: bool  # finished by an earlier run of the study


# (report, cases done, cases in all); the report is None once, when the runs start
StudyProgress = Callable[[CaseReport | None, int, int], None]


def incomplete(table: pd.DataFrame) -> list[str]:
    """The cases of a study's table not complete (``COMPLETE``), or not run."""
    return table.loc[~table["status"].isin(COMPLETE), "case"].tolist()


@dataclass(frozen=True)
class StudyResults:
    """Outcome of a study: its table, and where it and the figures are."""

    folder: Path
    table: pd.DataFrame
    skipped: list[str] = field(default_factory=list)
    figures: list[Path] = field(default_factory=list)
    interrupted: bool = False

    @property
    def failed(self) -> list[str]:
        """The cases not complete (a life run at a joint's limit is), or not run."""
        return incomplete(self.table)


@dataclass(frozen=True)
class StudyRun:
    """What ``run_study`` did: the table, the cases' models and what happened."""

    folder: Path
    table: pd.DataFrame
    models: dict[str, Model]
    skipped: list[str]
    interrupted: bool


def check_run_options(cycles: int | None, scheduler: str | None, workers: int | None) -> list[str]:
    """The problems of a study's ``cycles``, ``scheduler`` and ``workers``, one line each."""
    problems = []
    for option, value in (("--cycles", cycles), ("--workers", workers)):
        if value is not None and not (whole(value) and value <= MAX_CYCLES):
            problems.append(
                f"{option}: got {value!r}; expected a whole number from 1 to {MAX_CYCLES:.0e}"
            )
    if workers is not None and scheduler is not None:
        problems.append(
            "--workers: only for local processes; with --scheduler the cluster's workers run "
            "the cases"
        )
    return problems


def run_study(
    model_path: str | os.PathLike | Model,
    out: str | os.PathLike,
    cases: Sequence[Case],
    *,
    kind: str,
    record: Mapping[str, object],
    overrides: Sequence[str] = (),
    cycles: int | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    progress: StudyProgress | None = None,
    also_writes: Sequence[str] = (),
    life_options: Mapping[str, object] | None = None,
    columns: Mapping[str, Sequence[object]] | None = None,
) -> StudyRun:
    """Run ``cases`` of a model into the study folder ``out`` (module docstring).

    Parameters
    ----------
    model_path
        TOML model file, a results folder (its ``model.json``), or a ``Model`` (saved as
        ``out/model.json`` for the cases to read).
    cases
        The named cases, each with its overrides (after the common ``overrides``).
    kind
        The study's name (``sweep``, ``sample``): its files ``<kind>.json``, ``.csv``, ...
    record
        What ``<kind>.json`` says of the study, besides the model, settings and case names.
    also_writes
        Further files and folders (``figures/``) the study writes into ``out``.
    life_options
        Keyword arguments of ``jointwear.life`` for every case (with ``cycles``).
    columns
        Further columns of the table, a value per case, after the varied values.

    Raises
    ------
    ModelError
        Before anything runs, if any case's model is invalid (one line per problem, naming
        the case), or if the scheduler cannot be reached.
    """
    models = _load_cases(model_path, overrides, cases, life=cycles is not None)
    folder = Path(out).resolve()
    check_folder(folder)
    tables = (f"{kind}.json", f"{kind}.csv", f"{kind}.parquet")
    claim(folder, (*tables, f"{CASES_FOLDER}/", *also_writes))
    if isinstance(model_path, Model):  # the cases, maybe in other processes, read it there
        claim(folder, (SAVED_MODEL,))
        make_folder(folder)
        write_text(folder / SAVED_MODEL, model_path.model_dump_json(indent=2))
        model_path = folder
    options = dict(life_options or {})
    tasks = [_task(model_path, folder, overrides, cycles, options, c, models[c.id]) for c in cases]
    plan = {
        "model": str(Path(model_path).resolve()),
        **record,
        "set": list(overrides),
        "cycles": cycles,
        "cases": [case.id for case in cases],
    }
    make_folder(folder)
    write_text(folder / tables[0], json.dumps(plan, indent=2))

    outcomes: dict[str, Outcome] = {}
    skipped = [task.case for task in tasks if _finished(Path(task.folder), task.record)]
    for name in skipped:
        outcomes[name] = read_record(folder / CASES_FOLDER / name)
        _report(progress, name, outcomes[name], len(outcomes), len(tasks), skipped=True)
    todo = [task for task in tasks if task.case not in outcomes]
    with stop_requests() as stop:
        runs = _runner(todo, scheduler, workers, stop)  # local processes start here
        if progress is not None:
            progress(None, len(outcomes), len(tasks))
        for task, outcome in runs:
            outcomes[task.case] = outcome
            _report(progress, task.case, outcome, len(outcomes), len(tasks), skipped=False)
        interrupted = stop[0]

    table = _table(cases, models, outcomes, columns or {})
    with stop_requests():  # a second Ctrl-C must not leave half a table
        write_table(table, folder / tables[1], folder / tables[2])
    return StudyRun(folder, table, models, skipped, interrupted)


def _load_cases(
    model_path: str | os.PathLike | Model,
    overrides: Sequence[str],
    cases: Sequence[Case],
    life: bool,
) -> dict[str, Model]:
    """Validate every case's model (for a life run too, with ``life``).

    A problem that many cases share but for its numbers (a drawn value out of range) is
    told once, for the first case, with the count of the others.
    """
    from ..life.study import model_problems

    models: dict[str, Model] = {}
    problems: dict[str, list[tuple[str, str]]] = {}  # problem's form -> (case, its line)
    for case in cases:
        try:
            models[case.id] = load_model(model_path, [*overrides, *case.overrides])
            lines = model_problems(models[case.id]) if life else []
        except ModelError as error:
            lines = error.problems
        for line in lines:
            problems.setdefault(_NUMBERS.sub("#", line), []).append((case.id, line))
    if problems:
        raise ModelError([_naming(found, len(cases)) for found in problems.values()])
    return models


_NUMBERS = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")  # a problem's form


def _naming(found: list[tuple[str, str]], total: int) -> str:
    """A problem of the cases ``found`` (case, line): its first line, naming the case."""
    first, line = found[0]
    if len(found) == total > 1 and all(text == line for _, text in found):
        return line  # not about any one case
    others = len(found) - 1
    more = f" (and {others} other case{'s' * (others > 1)})" if others else ""
    return f"case {first}{more}: {line}"


def _task(
    model_path: str | os.PathLike,
    folder: Path,
    overrides: Sequence[str],
    cycles: int | None,
    life_options: dict,
    case: Case,
    model: Model,
) -> CaseTask:
    every = (*overrides, *case.overrides)
    record = {
        "case": case.id,
        "kind": "run" if cycles is None else "life",
        "cycles": cycles,
        "life_options": json.loads(json.dumps(life_options, default=str)),
        "overrides": list(every),
        "model": json.loads(model.model_dump_json()),
    }
    return CaseTask(
        case=case.id,
        model_path=str(Path(model_path).resolve()),
        folder=str(folder / CASES_FOLDER / case.id),
        overrides=every,
        cycles=cycles,
        record=record,
        laws=used_laws(model),
        life_options=life_options if cycles is not None else {},
    )


def _finished(folder: Path, record: dict) -> bool:
    """Whether the case folder holds a run with these settings that would end alike again."""
    done = read_record(folder)
    if done is None or done.get("status") not in SETTLED:
        return False
    if any(done.get(key, {}) != record[key] for key in ("kind", "cycles", "model", "life_options")):
        return False
    try:
        return json.loads((folder / "summary.json").read_text()).get("status") in SETTLED
    except (OSError, ValueError, AttributeError):
        return False


def _runner(tasks: list[CaseTask], scheduler: str | None, workers: int | None, stop: list[bool]):
    if scheduler is not None:
        return run_dask(tasks, scheduler, stop)
    count = min(workers or os.cpu_count() or 1, len(tasks))
    return run_serial(tasks, stop) if count <= 1 else run_local(tasks, count, stop)


def _report(
    progress: StudyProgress | None,
    case: str,
    outcome: Outcome,
    done: int,
    total: int,
    skipped: bool,
) -> None:
    if progress is not None:
        report = CaseReport(case, outcome["status"], outcome["error"], outcome["wall_s"], skipped)
        progress(report, done, total)


# The table ---------------------------------------------------------------------------------


def _table(
    cases: Sequence[Case],
    models: Mapping[str, Model],
    outcomes: Mapping[str, Outcome],
    columns: Mapping[str, Sequence[object]],
) -> pd.DataFrame:
    rows = []
    for index, case in enumerate(cases):
        row: dict[str, object] = {"case": case.id}
        for path, text in case.values.items():
            row[path] = si_value(models[case.id], path, text)
        row |= {name: values[index] for name, values in columns.items()}
        outcome = outcomes.get(case.id) or {
            "status": NOT_RUN,
            "error": "the study stopped before this case ran",
            "wall_s": math.nan,
            "summary": {},
        }
        row |= {key: outcome[key] for key in FIXED_COLUMNS[1:]}
        row |= headline(outcome["summary"])
        rows.append(row)
    return pd.DataFrame(rows)


def headline(summary: Mapping) -> dict[str, float]:
    """The numbers of a run's summary as flat columns.

    Per clearance joint ``<joint>.<key>`` (``coupler_follower.max_wear_depth_journal_m``;
    nested tables by dotted keys), per driver ``<driver>.<key>`` (``motor.torque_range_n_m``),
    the run statistics by their own names (``accepted_steps``), and any other number at the
    top of the summary (e.g. of a long-life run). A missing value (None) becomes NaN.
    """
    columns: dict[str, float] = {}
    for joint, values in summary.get("clearance_joints", {}).items():
        columns.update(_flat(values, joint))
    for driver, values in summary.get("drivers", {}).items():
        columns.update(_flat(values, driver))
    for key, value in [*summary.get("stats", {}).items(), *summary.items()]:
        if _is_number(value):
            columns[key] = value
    return columns


def _flat(values: Mapping, prefix: str) -> dict[str, float]:
    """The numbers of a nested table as ``prefix.key[.key...]`` columns; None becomes NaN."""
    columns: dict[str, float] = {}
    for key, value in values.items():
        if isinstance(value, Mapping):
            columns.update(_flat(value, f"{prefix}.{key}"))
        elif value is None or _is_number(value):
            columns[f"{prefix}.{key}"] = math.nan if value is None else value
    return columns


def _is_number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def write_table(table: pd.DataFrame, csv: Path, parquet: Path) -> None:
    """A study's table as CSV and Parquet, each replaced at once (never half written)."""
    make_folder(csv.parent)
    typed = table.copy()
    for column in typed.columns:
        if not pd.api.types.is_object_dtype(typed[column]):
            continue
        kinds = {type(v) for v in typed[column] if v is not None}
        if len(kinds) > 1:  # parquet wants one type per column
            typed[column] = typed[column].map(lambda v: None if v is None else str(v))
    write_atomic(csv, lambda p: table.to_csv(p, index=False, float_format="%.12g"))
    write_atomic(parquet, lambda p: typed.to_parquet(p, index=False))
