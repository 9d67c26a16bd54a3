"""Results of a run, and their folder on disk.

A results folder holds ``summary.json`` (status, settings, version, run statistics, and
per clearance joint its contact and wear figures), ``timeseries.csv`` and
``timeseries.parquet`` (the same table), ``events.csv`` and ``model.json`` (the resolved
model, SI), so that it describes itself; with clearance joints also ``wear.csv`` (final
profiles), ``wear_snapshots.csv``, ``impacts.csv`` (``results.clearance``) and
``cycles.csv`` (``results.cycles``).
``load_results`` reads it back. ``Results.export`` writes the tables to one netCDF4 or
MATLAB file (``results.export``), each column's unit from ``results.column_units``.
"""

from __future__ import annotations

import difflib
import html
import json
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib.metadata import entry_points
from pathlib import Path
from typing import TYPE_CHECKING

import pandas as pd
import pyarrow as pa
from pyarrow import csv

from ..engine.finite import json_safe
from ..io import make_folder, remove, write_atomic, write_text
from ..model import Model, parse_model
from .run_state import RunState

PLOTTING = "jointwear.plotting"  # the entry points of the plotting functions (pyproject.toml)

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

IDEAL_FOLDER = "ideal"  # subfolder with the all-ideal companion run of a clearance model


@dataclass(frozen=True)
class Results:
    """Outcome of ``simulate``: time series, event log and summary of one model.

    ``wear``, ``wear_snapshots``, ``impacts`` and ``cycles`` are empty without clearance
    joints. In a notebook: ``results`` shows a short description,
    ``results.to_dataframe("impacts")`` a table, ``results.units()`` each column's unit,
    ``results.plot("omega_follower")`` a figure and ``results.export("run.nc")`` writes a
    file for other tools.
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

    def __repr__(self) -> str:
        return describe(self)

    def _repr_html_(self) -> str:
        return f"<pre>{html.escape(describe(self))}</pre>"

    def to_dataframe(self, table: str = "timeseries") -> pd.DataFrame:
        """A copy of one of the run's tables.

        Parameters
        ----------
        table
            ``timeseries`` (one row per output time, SI columns named after the model's
            bodies, drivers and joints), ``events``, ``wear`` (final profiles [m]),
            ``wear_snapshots``, ``impacts`` or ``cycles``.

        Returns
        -------
        pandas.DataFrame
            The table (empty where the model has no clearance joints); changing it leaves the
            results as they were.

        Raises
        ------
        ValueError
            For any other table name.
        """
        return getattr(self, _table_name(table)).copy()

    def units(self, table: str = "timeseries") -> dict[str, str]:
        """The unit of each column of a table, read from the column names.

        Parameters
        ----------
        table
            One of ``TABLES``, as for ``to_dataframe``.

        Returns
        -------
        dict[str, str]
            Column name -> unit: ``"m"``, ``"rad/s"``, ``"N m"``, ...; ``"1"`` for a
            dimensionless number or a count, ``""`` for text (a joint's name), ``"?"`` for a
            column jointwear does not know.
        """
        from .column_units import table_units

        return table_units(list(getattr(self, _table_name(table)).columns), self.model)

    def plot(self, *columns: str, x: str = "time", ax: Axes | None = None) -> Figure:
        """Plot time-series columns against ``x``, the axes labelled with their units.

        Parameters
        ----------
        *columns
            Time-series column names (``"omega_follower"``, ``"coupler_follower_fn"``).
        x
            The column along the horizontal axis (default time [s]).
        ax
            matplotlib Axes to draw on; a new Figure (without pyplot) if None.

        Returns
        -------
        matplotlib.figure.Figure
            The figure drawn on: ``fig.savefig("omega.png")`` writes it.

        Raises
        ------
        ValueError
            If no column is given, or a name is not a time-series column (with the closest
            names).
        """
        if not columns:
            raise ValueError("plot: name at least one time-series column, e.g. plot('time')")
        for name in (*columns, x):
            _check_column(name, list(self.timeseries.columns))
        return _plotter("columns")(self, tuple(columns), x=x, ax=ax)

    def export(self, path: str | os.PathLike) -> Path:
        """Write every table to one file, in the format its suffix names.

        Parameters
        ----------
        path
            ``*.nc``: netCDF4 (HDF5) for xarray, h5py and MATLAB's ``ncread``: the time
            series along dimension ``time``, each other table a group, every variable with
            a ``units`` attribute, the summary as JSON in the global attribute ``summary``.
            ``*.mat``: MATLAB 5, a struct per table, a ``units`` struct, ``summary`` JSON.

        Returns
        -------
        Path
            The file written.

        Raises
        ------
        ImportError
            Without the ``export`` extra: ``pip install 'jointwear[export]'``.
        ValueError
            For another suffix.
        """
        from .export import export

        return export(self, path)

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
CSV_BATCH_ROWS = 1024  # pyarrow's batch of rows turned into text at a time
CSV_BATCH_VALUES = 2**22  # at most this many values a batch (170 MB of text)
TABLES = ("timeseries", "events", *_CLEARANCE_TABLES)  # Results.to_dataframe's names
CLEARANCE_FILES = tuple(f"{name}.csv" for name in _CLEARANCE_TABLES)
FILES = (  # what a results folder may hold, clearance tables last, for ``jointwear.io.claim``
    "summary.json", "model.json", "timeseries.csv", "timeseries.parquet", "events.csv",
    *CLEARANCE_FILES,
)  # fmt: skip
# Read as floats even when every value is whole ("5" is still 5.0).
_FLOAT_COLUMNS = {"angle_deg": float, "position_m": float, "guide_position_m": float,
                  "depth_m": float, "time_s": float}  # fmt: skip


def _table_name(table: str) -> str:
    """``table`` if it names one of the tables, else a ValueError naming them."""
    if table not in TABLES:
        raise ValueError(f"no table {table!r}; the tables are {', '.join(TABLES)}")
    return table


def _check_column(name: str, columns: list[str]) -> None:
    """A ValueError unless ``name`` is one of ``columns``, with the closest names."""
    if name in columns:
        return
    close = difflib.get_close_matches(name, columns, n=5, cutoff=0.5)
    hint = f"did you mean {', '.join(map(repr, close))}?" if close else "see results.units()"
    raise ValueError(f"no time-series column {name!r}; {hint}")


def describe(results: Results) -> str:
    """A few lines about a run: model, status, time reached, tables, clearance joints."""
    summary, series = results.summary, results.timeseries
    t_reached = summary.get("stats", {}).get("t_reached")
    if t_reached is None and "time" in series and len(series):
        t_reached = float(series["time"].iloc[-1])
    reached = "?" if t_reached is None else f"{t_reached:.6g} s"
    lines = [
        f"Results of {results.model.name!r}: {results.status} ({results.message})",
        f"  time reached {reached}; timeseries {len(series)} rows x {series.shape[1]} columns",
    ]
    joints = summary.get("clearance_joints", {})
    if joints:
        steady = summary.get("steady_state", {})
        span = (
            f"steady state from {steady['from_s']:.6g} s"
            if steady.get("from_s") is not None
            else "whole run"
        )
        lines.append(f"  clearance joints ({span}):")
        for name, entry in joints.items():
            lines.append(
                f"    {name} ({entry.get('type', '?')}): max contact force "
                f"{entry.get('max_contact_force_n', float('nan')):.4g} N, "
                f"{entry.get('impacts', 0)} impacts"
            )
    tables = TABLES if results.has_clearance else TABLES[:2]
    rows = ", ".join(f"{t} ({_rows(len(getattr(results, t)))})" for t in tables[1:])
    lines.append(f"  tables: timeseries, {rows}; .to_dataframe(name), .units(name)")
    return "\n".join(lines)


def _rows(count: int) -> str:
    return f"{count} row{'' if count == 1 else 's'}"


def _write_csv(table: pd.DataFrame, path: Path) -> None:
    """Write ``table`` as CSV, numbers in their shortest exact form.

    pyarrow's writer is ten times faster than pandas' on a time series. It turns a batch of
    rows into text at a time, about 40 bytes a value: a wide table (the 22,000 columns of a
    2,000-link chain) goes in batches of fewer rows than its 1,024, ``CSV_BATCH_VALUES`` values.
    """
    arrow = pa.Table.from_pandas(table, preserve_index=False)
    rows = max(1, min(CSV_BATCH_ROWS, CSV_BATCH_VALUES // max(1, table.shape[1])))
    options = csv.WriteOptions(quoting_style="needed", batch_size=rows)
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


def _plotter(name: str) -> Callable[..., Figure]:
    """The plotting function registered as ``name`` (``PLOTTING``; matplotlib when loaded)."""
    points = entry_points(group=PLOTTING, name=name)
    if not points:
        raise RuntimeError(
            f"no plotting function '{name}' is registered ({PLOTTING} entry points): jointwear's "
            "installation is out of date; install it again (make install, or pip install -e .)"
        )
    return next(iter(points)).load()
