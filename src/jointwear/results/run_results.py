"""Results of a run, and their folder on disk.

A results folder holds ``summary.json`` (status, settings, version, run statistics, and
per clearance joint its contact and wear figures), ``timeseries.csv`` and
``timeseries.parquet`` (the same table), ``events.csv`` and ``model.json`` (the resolved
model, SI), so that it describes itself; with clearance joints also ``wear.csv`` (final
profiles), ``wear_snapshots.csv``, ``impacts.csv`` (``results.clearance``) and
``cycles.csv`` (``results.cycles``).
``load_results`` reads it back.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd
import pyarrow as pa
from pyarrow import csv

from ..finite import json_safe
from ..io import make_folder, remove, write_atomic, write_text
from ..model import Model, parse_model
from .run_state import RunState

IDEAL_FOLDER = "ideal"  # subfolder with the all-ideal companion run of a clearance model


@dataclass(frozen=True)
class Results:
    """Outcome of ``simulate``: time series, event log and summary of one model.

    ``wear``, ``wear_snapshots``, ``impacts`` and ``cycles`` are empty without clearance
    joints.
    """

    model: Model
    timeseries: pd.DataFrame
    events: pd.DataFrame
    summary: dict
    wear: pd.DataFrame = field(default_factory=pd.DataFrame)
    wear_snapshots: pd.DataFrame = field(default_factory=pd.DataFrame)
    impacts: pd.DataFrame = field(default_factory=pd.DataFrame)
    cycles: pd.DataFrame = field(default_factory=pd.DataFrame)  # results.cycles.CYCLE_COLUMNS
    final: RunState | None = None  # where the run ended (None once loaded from a folder)

    @property
    def has_clearance(self) -> bool:
        """Whether the model has clearance joints (and so wear and impact tables)."""
        return "clearance_joints" in self.summary

    @property
    def status(self) -> str:
        """``success``, ``interrupted``, ``singular``, ... (``jointwear.status``)."""
        return self.summary["status"]

    @property
    def message(self) -> str:
        """Human-readable explanation of the status."""
        return self.summary["message"]

    def save(self, folder: str | os.PathLike) -> Path:
        """Write the results folder (created if needed); return its path."""
        path = make_folder(folder)
        remove(path / "summary.json")  # until rewritten, not a complete folder
        write_text(path / "model.json", self.model.model_dump_json(indent=2))
        _write_csv(self.timeseries, path / "timeseries.csv")
        write_atomic(
            path / "timeseries.parquet", lambda p: self.timeseries.to_parquet(p, index=False)
        )
        _write_csv(self.events, path / "events.csv")
        for name in _CLEARANCE_TABLES:
            if self.has_clearance:
                _write_csv(getattr(self, name), path / f"{name}.csv")
            else:  # an earlier run's, with clearance joints
                remove(path / f"{name}.csv")
        summary = json.dumps(json_safe(self.summary), indent=2, allow_nan=False)
        write_text(path / "summary.json", summary)  # last: the folder is complete
        return path


_CLEARANCE_TABLES = ("wear", "wear_snapshots", "impacts", "cycles")
CLEARANCE_FILES = tuple(f"{name}.csv" for name in _CLEARANCE_TABLES)
FILES = (  # what a results folder may hold, clearance tables last, for ``jointwear.io.claim``
    "summary.json", "model.json", "timeseries.csv", "timeseries.parquet", "events.csv",
    *CLEARANCE_FILES,
)  # fmt: skip
# Read as floats even when every value is whole ("5" is still 5.0).
_FLOAT_COLUMNS = {"angle_deg": float, "position_m": float, "guide_position_m": float,
                  "depth_m": float, "time_s": float}  # fmt: skip


def _write_csv(table: pd.DataFrame, path: Path) -> None:
    """Write ``table`` as CSV, numbers in their shortest exact form.

    pyarrow's writer is ten times faster than pandas' on a time series.
    """
    arrow = pa.Table.from_pandas(table, preserve_index=False)
    options = csv.WriteOptions(quoting_style="needed")
    write_atomic(path, lambda temporary: csv.write_csv(arrow, temporary, options))


def load_results(folder: str | os.PathLike) -> Results:
    """Read a results folder written by ``Results.save``."""
    path = Path(folder)
    model_data = json.loads((path / "model.json").read_text())
    summary = json.loads((path / "summary.json").read_text())
    tables = {}
    if "clearance_joints" in summary:
        tables = {
            name: pd.read_csv(path / f"{name}.csv", dtype=_FLOAT_COLUMNS)
            for name in _CLEARANCE_TABLES
            if name != "cycles" or (path / "cycles.csv").is_file()  # not before version 0.2
        }
    return Results(
        model=parse_model(model_data),
        timeseries=pd.read_parquet(path / "timeseries.parquet"),
        events=pd.read_csv(path / "events.csv"),
        summary=summary,
        **tables,
    )
