"""Parameter sweeps: many runs of one model with some values varied, and their table.

``sweep`` makes the cases (every combination of the varied values, ``cases``) and runs them
with the study engine (``engine``): into the sweep folder go ``cases/<case>/``,
``sweep.csv``, ``sweep.parquet`` and ``sweep.json`` (``engine.run_study``), and
``figures/``: a figure per headline figure of merit (contact force, wear depth, ...)
against the varied values (``jointwear.figures.sweep``).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path

import pandas as pd

from ...engine.interrupts import stop_requests
from ...model import Model, ModelError
from ...model.files import SAVED_MODEL
from .cases import Case, check_link, check_vary, make_cases, value_text
from .engine import CASES_FOLDER, StudyProgress, StudyResults, check_run_options, run_study

FIGURES = "figures"


class SweepResults(StudyResults):
    """Outcome of ``sweep``: the table, and where it and the figures are."""


def sweep(
    model_path: str | os.PathLike | Model,
    out: str | os.PathLike,
    *,
    vary: Mapping[str, Sequence[object]] | None = None,
    link: Mapping[str, Sequence[object]] | None = None,
    overrides: Sequence[str] = (),
    cycles: int | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    figures: bool = True,
    progress: StudyProgress | None = None,
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
        them (``"0.1 mm"``, ``"abm"``); numbers and lists are taken as they are. May be left
        out when ``link`` gives the cases.
    link
        Dotted paths -> lists of values of one length, stepped through together (a crank's
        speed and the frequency of the load it drives, or a design's rows drawn elsewhere),
        combined with ``vary``'s.
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
    texts = {path: _texts(values) for path, values in _mapping(vary or {}).items()}
    linked = {path: _texts(values) for path, values in _mapping(link or {}).items()}
    _check_options(texts, linked, overrides, cycles, scheduler, workers)
    cases = make_cases(texts, linked)
    done = run_study(
        model_path, out, cases, kind="sweep", record={"vary": texts, "link": linked},
        overrides=overrides, cycles=cycles, scheduler=scheduler, workers=workers,
        progress=progress, also_writes=(f"{FIGURES}/",),
    )  # fmt: skip
    drawn = []
    if figures:
        with stop_requests():
            joints = {j.name for m in done.models.values() for j in m.clearance_joints}
            drawn = _draw(done.folder, done.table, cases, joints)
    return SweepResults(done.folder, done.table, done.skipped, drawn, done.interrupted)


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
    problems += check_run_options(cycles, scheduler, workers)
    if problems:
        raise ModelError(problems)
