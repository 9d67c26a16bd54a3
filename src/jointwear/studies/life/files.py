"""The folder of a long-life wear run, and its checkpoint.

``life.csv`` and ``profiles.csv`` grow by the rows of every update; after them the checkpoint
is written: ``checkpoint/state_<update>.npz`` (the ``RunState`` to go on from) and then
``checkpoint/checkpoint.json`` (update, cycles, wall time, that state's file name, and the
settings and resolved model the run was started with), each replaced at once. A run stopped
at any point is continued from the last complete checkpoint: the rows written after it are
dropped and the same sequence of runs follows, from the same states.
"""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from ...figures.names import LIFE_FIGURES
from ...io import append, check_folder, claim, make_folder, remove, write_atomic, write_text
from ...model import ModelError
from ...results.run_state import RunState, load_run_state

TABLE = "life.csv"
PROFILES = "profiles.csv"
SUMMARY = "summary.json"
BAND_TABLE = "life_band.csv"  # the uncertainty band against cycles (``band``)
MODEL = "model.json"
FIGURES = "figures"
CHECKPOINTS = "checkpoint"
CHECKPOINT = "checkpoint.json"
FILES = (  # the fixed names a life run writes, for ``jointwear.io.claim``
    TABLE, PROFILES, SUMMARY, BAND_TABLE, MODEL, f"{CHECKPOINTS}/{CHECKPOINT}",
    *(f"{FIGURES}/{name}" for name in LIFE_FIGURES),
)  # fmt: skip


@dataclass(frozen=True)
class Checkpoint:
    """Where a life run stands after an update.

    Attributes
    ----------
    update
        Number of the last update (0: the settling cycles, or nothing yet without a state).
    cycles
        Cycles so far, simulated and extrapolated.
    simulated_cycles
        Cycles simulated so far.
    wall_s
        Wall time spent so far, over every session of the run [s].
    state
        The state to go on from (profiles updated); None before the first run.
    """

    update: int
    cycles: int
    simulated_cycles: int
    wall_s: float
    state: RunState | None


def start_folder(
    folder: Path, columns: list[str], profile_columns: list[str], record: dict
) -> None:
    """Make ``folder`` a fresh life-run folder: earlier outputs removed, empty tables, model.

    ``columns`` and ``profile_columns``: those of life.csv and profiles.csv; ``record``
    (settings and resolved model) is kept in the checkpoint, for ``--resume``.
    """
    check_folder(folder)
    claim(folder, FILES)
    make_folder(folder / CHECKPOINTS)
    remove(folder / CHECKPOINTS / CHECKPOINT)  # first: it names the states
    remove(folder / SUMMARY)
    remove(folder / BAND_TABLE)
    for name in LIFE_FIGURES:  # an earlier run's: never mix two runs
        remove(folder / FIGURES / name)
    for old in (folder / CHECKPOINTS).glob("state_*.npz"):
        remove(old)
    _write_rows(folder / TABLE, columns, [])
    _write_rows(folder / PROFILES, profile_columns, [])
    write_text(folder / MODEL, json.dumps(record["model"], indent=2))
    save_checkpoint(folder, Checkpoint(0, 0, 0, 0.0, None), record)


def append_update(folder: Path, row: list, profiles: list[list]) -> None:
    """Add an update's row to life.csv and its profiles to profiles.csv."""
    for name, rows in ((TABLE, [row]), (PROFILES, profiles)):
        append(folder / name, lambda file, rows=rows: csv.writer(file).writerows(rows))


def save_checkpoint(folder: Path, point: Checkpoint, record: dict) -> None:
    """Write the checkpoint: the state's file first, then the JSON naming it."""
    state = None
    if point.state is not None:
        state = f"state_{point.update:06d}.npz"
        point.state.save(folder / CHECKPOINTS / state)
    data = {
        "update": point.update,
        "cycles": point.cycles,
        "simulated_cycles": point.simulated_cycles,
        "wall_s": point.wall_s,
        "state": state,
        **record,
    }
    write_text(folder / CHECKPOINTS / CHECKPOINT, json.dumps(data, indent=2))
    for old in (folder / CHECKPOINTS).glob("state_*.npz"):
        if old.name != state:
            remove(old)


def load_checkpoint(
    folder: Path, record: dict, columns: list[str], profile_columns: list[str]
) -> Checkpoint:
    """The last checkpoint of the run in ``folder``, its tables cut back to it.

    ``columns`` and ``profile_columns``: those life.csv and profiles.csv must have.

    Raises
    ------
    ModelError
        If ``folder`` holds no life run, a damaged one (or tables of other columns: an
        earlier version's), or one started with other settings (but for a larger
        ``max_growth`` or ``runaway_factor``, or a ``runaway_factor`` of 0) or another model.
    """
    path = folder / CHECKPOINTS / CHECKPOINT
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError):
        where = f"{CHECKPOINTS}/{CHECKPOINT}"
        problem = f"out: {folder} holds no life run to resume (no readable {where}); "
        raise ModelError([problem + "run without --resume to start one"]) from None
    try:
        problems = _differences(folder, data, json.loads(json.dumps(record)))
        counts = [data[key] for key in ("update", "cycles", "simulated_cycles", "wall_s")]
        state_file = data["state"]
    except (AttributeError, KeyError, TypeError) as error:
        raise _damaged(folder, error) from None
    if problems:
        raise ModelError(problems)
    try:
        for name, header in ((TABLE, columns), (PROFILES, profile_columns)):
            _cut(folder / name, header, counts[0] if state_file else -1)
        state = load_run_state(folder / CHECKPOINTS / state_file) if state_file else None
    except Exception as error:  # whatever a damaged table or state file raises
        raise _damaged(folder, error) from None
    return Checkpoint(*counts, state)


def _differences(folder: Path, data: dict, given: dict) -> list[str]:
    """What keeps the run recorded in ``data`` from being continued with ``given``."""
    problems = []
    for key, value in data["settings"].items():
        new = given["settings"].get(key)
        if new == value or (key in LIMITS and _looser(new, value)):  # a looser limit: it goes on
            continue
        problems.append(
            f"{key}: {new!r} differs from the {value!r} the run in {folder} was started with; "
            "give the same settings to resume (max_growth and runaway_factor may be larger, "
            "runaway_factor 0), or start afresh without --resume"
        )
    if data["model"] != given["model"]:
        problems.append(
            f"model: the model (after --set) differs from the one the run in {folder} was "
            "started with (its model.json); give the same model and --set values to resume, "
            "or start afresh without --resume"
        )
    return problems


LIMITS = ("max_growth", "runaway_factor")  # settings a resumed run may loosen (a stop's)


def _looser(new: float, old: float) -> bool:
    """Whether limit ``new`` lets a run go further than ``old`` (0: no limit)."""
    return old != 0 and (new == 0 or new > old)


def _damaged(folder: Path, error: Exception) -> ModelError:
    problem = f"out: the life run in {folder} is damaged and cannot be resumed ({error!r}); "
    return ModelError([problem + "start afresh without --resume"])


def read_tables(folder: Path) -> tuple[pd.DataFrame, pd.DataFrame]:
    """life.csv and profiles.csv, numbers read back exactly."""
    return tuple(pd.read_csv(folder / name) for name in (TABLE, PROFILES))


def cycles_done(folder: Path) -> int:
    """The cycles the last checkpoint of the run in ``folder`` reached; 0 if none."""
    try:
        return int(json.loads((folder / CHECKPOINTS / CHECKPOINT).read_text())["cycles"])
    except (OSError, ValueError, LookupError, TypeError):
        return 0


def forget_checkpoint(folder: Path) -> None:
    """Remove the checkpoint of an earlier run in ``folder`` (one starting afresh does too)."""
    remove(folder / CHECKPOINTS / CHECKPOINT)


def write_band(folder: Path, table: pd.DataFrame) -> None:
    """Write life_band.csv, whole or not at all."""
    write_atomic(folder / BAND_TABLE, lambda p: table.to_csv(p, index=False, float_format="%.12g"))


def write_summary(folder: Path, summary: dict) -> None:
    """Write summary.json, whole or not at all."""
    write_text(folder / SUMMARY, json.dumps(summary, indent=2))


def _cut(path: Path, header: list[str], update: int) -> None:
    """Keep the header and the whole rows of updates up to ``update`` (first column).

    A row cut short by a crash while it was written is not whole.

    Raises
    ------
    ValueError
        If the table's header is not ``header`` (lost, or an earlier version's columns).
    """
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path.name} has lost its header")
    if rows[0] != header:
        raise ValueError(f"{path.name} has other columns than this version of jointwear writes")
    kept = [row for row in rows[1:] if len(row) == len(rows[0]) and int(row[0]) <= update]
    if len(kept) < len(rows) - 1:
        _write_rows(path, rows[0], kept)


def _write_rows(path: Path, header: list[str], rows: list[list]) -> None:
    def write(temporary: Path) -> None:
        with open(temporary, "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(header)
            writer.writerows(rows)

    write_atomic(path, write)
