"""Parameter studies: many runs of one model with some values varied, and their table.

``sweep`` validates every case's model first (a bad path or value stops the sweep before
anything runs), skips the cases a previous run of the same sweep finished, runs the others
in local processes or on a Dask cluster, and writes into the sweep folder:

- ``cases/<case>/``: each case's results folder (``jointwear run`` without figures, or a
  long-life wear run), with ``case.json``: its overrides, resolved model and outcome;
- ``sweep.csv`` and ``sweep.parquet``: one row per case: its name, the varied values (SI),
  status, error, wall time and the headline figures of its summary;
- ``figures/``: a figure per headline figure of merit (contact force, wear depth, ...)
  against the varied values (``jointwear.figures.sweep``);
- ``sweep.json``: the sweep itself (model, varied values, settings, case names).

A failed case is recorded with its error and the others go on. After Ctrl-C or SIGTERM the
finished cases are kept and the table is written with what is done.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from ...engine.interrupts import stop_requests
from ...engine.status import NOT_RUN, SUCCESS
from ...io import check_folder, claim, make_folder, write_atomic, write_text
from ...model import Model, ModelError, load_model
from ...model.files import SAVED_MODEL
from ...model.laws.user import used_laws
from ..life.settings import MAX_CYCLES
from .cases import Case, check_link, check_vary, make_cases, si_value, value_text
from .runners import CaseTask, Outcome, read_record, run_dask, run_local, run_serial

CASES_FOLDER = "cases"
FIGURES = "figures"
FIXED_COLUMNS = ("case", "status", "error", "wall_s")  # the varied paths follow "case"


@dataclass(frozen=True)
class CaseReport:
    """What the progress callback hears about each case."""

    case: str
    status: str
    error: str
    wall_s: float  # [s]
    skipped: bool  # finished by an earlier run of the sweep


# (report, cases done, cases in all); the report is None once, when the runs start
SweepProgress = Callable[[CaseReport | None, int, int], None]


@dataclass(frozen=True)
class SweepResults:
    """Outcome of ``sweep``: the table, and where it and the figures are."""

    folder: Path
    table: pd.DataFrame
    skipped: list[str] = field(default_factory=list)
    figures: list[Path] = field(default_factory=list)
    interrupted: bool = False

    @property
    def failed(self) -> list[str]:
        """The cases that did not end with status success (including those not run)."""
        return self.table.loc[self.table["status"] != SUCCESS, "case"].tolist()


def sweep(
    model_path: str | os.PathLike | Model,
    out: str | os.PathLike,
    *,
    vary: Mapping[str, Sequence[object]],
    link: Mapping[str, Sequence[object]] | None = None,
    overrides: Sequence[str] = (),
    cycles: int | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    figures: bool = True,
    progress: SweepProgress | None = None,
) -> SweepResults:
    """Run the Cartesian product of the varied values of a model, and tabulate the cases.

    Parameters
    ----------
    model_path
        TOML model file, a results folder (its ``model.json``), or a ``Model`` (saved as
        ``out/model.json`` for the cases to read).
    out
        Sweep folder (created); a case finished there by an earlier run of the same sweep
        (same resolved model and cycles) is not run again.
    vary
        Dotted path (as for ``--set``) -> list of values. Strings are read as ``--set`` reads
        them (``"0.1 mm"``, ``"abm"``); numbers and lists are taken as they are.
    link
        Dotted paths -> lists of values of one length, stepped through together (a crank's
        speed and the frequency of the load it drives), combined with ``vary``'s.
    overrides
        ``dotted.path=value`` settings common to every case.
    cycles
        None: each case is a normal run (no figures, no ideal companion). A number: each case
        is a long-life wear run of that many cycles (``jointwear.life``).
    scheduler
        Address of a Dask distributed scheduler to run the cases on (workers must see
        ``model_path`` and ``out`` at the same paths); None: local processes.
    workers
        Local processes (default: one per core); 1 runs the cases in this process. Local
        processes import the calling script again: call ``sweep`` from a script under
        ``if __name__ == "__main__":``.
    figures
        Draw the comparison figures into ``out/figures``.
    progress
        Called as each case is done or found done, as ``progress(report, cases done, cases in
        all)``, and once with report None when the runs start.

    Returns
    -------
    SweepResults
        The table (also in ``out/sweep.csv`` and ``out/sweep.parquet``) and what happened.

    Raises
    ------
    ModelError
        Before anything runs, if an option or any case's model is invalid (one line per
        problem, naming the case), or if the scheduler cannot be reached.
    """
    texts = {path: _texts(values) for path, values in _mapping(vary).items()}
    linked = {path: _texts(values) for path, values in _mapping(link or {}).items()}
    _check_options(texts, linked, overrides, cycles, scheduler, workers)
    cases = make_cases(texts, linked)
    models = _load_cases(model_path, overrides, cases)
    folder = Path(out).resolve()
    check_folder(folder)
    claim(folder, ("sweep.json", "sweep.csv", "sweep.parquet", f"{CASES_FOLDER}/", f"{FIGURES}/"))
    if isinstance(model_path, Model):  # the cases, maybe in other processes, read it there
        claim(folder, (SAVED_MODEL,))
        make_folder(folder)
        write_text(folder / SAVED_MODEL, model_path.model_dump_json(indent=2))
        model_path = folder
    tasks = [_task(model_path, folder, overrides, cycles, c, models[c.id]) for c in cases]
    record = _plan_record(model_path, texts, linked, overrides, cycles, cases)
    _write_json(folder / "sweep.json", record)

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

    table = _table(cases, models, outcomes)
    with stop_requests():  # a second Ctrl-C must not leave half a table
        _write_table(table, folder)
        drawn = []
        if figures:
            joints = {j.name for m in models.values() for j in m.clearance_joints}
            drawn = _draw(folder, table, cases, joints)
    return SweepResults(folder, table, skipped, drawn, interrupted)


def redraw_sweep_figures(folder: str | os.PathLike) -> list[Path]:
    """Draw the comparison figures of the sweep folder ``folder`` again; return their paths.

    Raises
    ------
    ModelError
        If the folder is not a complete sweep folder (``sweep.json``, ``sweep.parquet``).
    """
    path = Path(folder)
    try:
        plan = json.loads((path / "sweep.json").read_text())
        table = pd.read_parquet(path / "sweep.parquet")
        cases = make_cases(plan["vary"], plan.get("link"))
        saved = [path / CASES_FOLDER / case / SAVED_MODEL for case in plan["cases"]]
        model = json.loads(next(p for p in saved if p.is_file()).read_text())
    except (OSError, ValueError, LookupError, TypeError, StopIteration) as error:
        raise ModelError(
            [f"{path}: not a complete sweep folder ({type(error).__name__})"]
        ) from None
    joints = {j["name"] for j in model.get("joints", []) if j.get("clearance")}
    return _draw(path, table, cases, joints)


def _draw(folder: Path, table: pd.DataFrame, cases: Sequence[Case], joints: set[str]) -> list[Path]:
    """The comparison figures of a sweep's table, into ``folder/figures``."""
    from ...figures.sweep import save_sweep_figures  # matplotlib only when drawing

    given = {  # per varied path, its table values as the sweep was given them
        path: dict(zip(table[path], [c.values[path] for c in cases], strict=True))
        for path in cases[0].values
    }
    return save_sweep_figures(table, sorted(joints), given, folder / FIGURES)


def _mapping(vary: Mapping[str, Sequence[object]]) -> dict[str, Sequence[object]]:
    if not isinstance(vary, Mapping):
        raise ModelError(["vary: expected a mapping of dotted path -> list of values"])
    return {str(path): values for path, values in vary.items()}


def _texts(values: object) -> object:
    """Value texts of a list of values; anything else is left for ``check_vary`` to refuse."""
    if isinstance(values, str) or not isinstance(values, Sequence):
        return values
    return [value_text(v) for v in values]


def _check_options(
    vary: Mapping[str, Sequence[str]],
    link: Mapping[str, Sequence[str]],
    overrides: Sequence[str],
    cycles: int | None,
    scheduler: str | None,
    workers: int | None,
) -> None:
    if vary or not link:
        check_vary(vary)
    if link:
        check_link(link, vary)
    problems = [
        f"{path}: both set (--set, --t-end or [set]) and varied (--vary or --link); give it in "
        "one place"
        for path in dict.fromkeys(o.partition("=")[0].strip() for o in overrides)
        if path in vary or path in link
    ]
    for option, value in (("--cycles", cycles), ("--workers", workers)):
        if value is not None and not (_whole(value) and value <= MAX_CYCLES):
            problems.append(
                f"{option}: got {value!r}; expected a whole number from 1 to {MAX_CYCLES:.0e}"
            )
    if workers is not None and scheduler is not None:
        problems.append(
            "--workers: only for local processes; with --scheduler the cluster's workers run "
            "the cases"
        )
    if problems:
        raise ModelError(problems)


def _load_cases(
    model_path: str | os.PathLike, overrides: Sequence[str], cases: Sequence[Case]
) -> dict[str, Model]:
    """Validate every case's model; report each problem once, naming its case."""
    models: dict[str, Model] = {}
    problems: dict[str, list[str]] = {}  # problem -> the cases that have it
    for case in cases:
        try:
            models[case.id] = load_model(model_path, [*overrides, *case.overrides])
        except ModelError as error:
            for line in error.problems:
                problems.setdefault(line, []).append(case.id)
    if problems:
        raise ModelError([_naming(line, names, len(cases)) for line, names in problems.items()])
    return models


def _naming(line: str, names: list[str], total: int) -> str:
    if len(names) == total > 1:
        return line  # not about any one case
    more = f" (and {len(names) - 1} other case{'s' * (len(names) > 2)})" if len(names) > 1 else ""
    return f"case {names[0]}{more}: {line}"


def _task(
    model_path: str | os.PathLike,
    folder: Path,
    overrides: Sequence[str],
    cycles: int | None,
    case: Case,
    model: Model,
) -> CaseTask:
    every = (*overrides, *case.overrides)
    record = {
        "case": case.id,
        "kind": "run" if cycles is None else "life",
        "cycles": cycles,
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
    )


def _finished(folder: Path, record: dict) -> bool:
    """Whether the case folder holds a successful run with the same settings."""
    done = read_record(folder)
    if done is None or done.get("status") != SUCCESS:
        return False
    if any(done.get(key) != record[key] for key in ("kind", "cycles", "model")):
        return False
    try:
        return json.loads((folder / "summary.json").read_text()).get("status") == SUCCESS
    except (OSError, ValueError, AttributeError):
        return False


def _runner(tasks: list[CaseTask], scheduler: str | None, workers: int | None, stop: list[bool]):
    if scheduler is not None:
        return run_dask(tasks, scheduler, stop)
    count = min(workers or os.cpu_count() or 1, len(tasks))
    return run_serial(tasks, stop) if count <= 1 else run_local(tasks, count, stop)


def _report(
    progress: SweepProgress | None,
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
    cases: Sequence[Case], models: Mapping[str, Model], outcomes: Mapping[str, Outcome]
) -> pd.DataFrame:
    rows = []
    for case in cases:
        row: dict[str, object] = {"case": case.id}
        for path, text in case.values.items():
            row[path] = si_value(models[case.id], path, text)
        outcome = outcomes.get(case.id) or {
            "status": NOT_RUN,
            "error": "the sweep stopped before this case ran",
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
    nested tables by dotted keys), the run statistics by their own names
    (``accepted_steps``), and any other number at the top of the summary (e.g. of a
    long-life run). A missing value (None) becomes NaN.
    """
    columns: dict[str, float] = {}
    for joint, values in summary.get("clearance_joints", {}).items():
        columns.update(_flat(values, joint))
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


def _whole(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and value >= 1


def _is_number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _write_table(table: pd.DataFrame, folder: Path) -> None:
    """``sweep.csv`` and ``sweep.parquet``, each replaced at once (never half written)."""
    make_folder(folder)
    parquet = table.copy()
    for column in parquet.columns:
        if not pd.api.types.is_object_dtype(parquet[column]):
            continue
        kinds = {type(v) for v in parquet[column] if v is not None}
        if len(kinds) > 1:  # parquet wants one type per column
            parquet[column] = parquet[column].map(lambda v: None if v is None else str(v))
    write_atomic(folder / "sweep.csv", lambda p: table.to_csv(p, index=False, float_format="%.12g"))
    write_atomic(folder / "sweep.parquet", lambda p: parquet.to_parquet(p, index=False))


def _write_json(path: Path, data: dict) -> None:
    make_folder(path.parent)
    write_text(path, json.dumps(data, indent=2))


def _plan_record(
    model_path: str | os.PathLike,
    vary: Mapping[str, Sequence[str]],
    link: Mapping[str, Sequence[str]],
    overrides: Sequence[str],
    cycles: int | None,
    cases: Sequence[Case],
) -> dict:
    return {
        "model": str(Path(model_path).resolve()),
        "vary": dict(vary),
        "link": dict(link),
        "set": list(overrides),
        "cycles": cycles,
        "cases": [case.id for case in cases],
    }
