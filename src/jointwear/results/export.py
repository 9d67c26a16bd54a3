"""A run's tables in one file for other tools: netCDF4 (``.nc``) or MATLAB (``.mat``).

- ``.nc`` (netCDF4, an HDF5 file; xarray with the h5netcdf engine): the time series is the
  main dataset, its columns variables along the dimension ``time``; each other table is a
  group of the same name (``events``, ``wear``, ``wear_snapshots``, ``impacts``,
  ``cycles``), its columns along the dimension ``row``. Every variable has a ``units``
  attribute (``column_units``); the global attributes hold ``summary`` and ``model`` as
  JSON. It opens with ``xarray.open_dataset(path, group=...)``, h5py, and MATLAB's
  ``ncread``/``h5read``.
- ``.mat`` (MATLAB 5, scipy): a struct per table, a column vector per column (text
  columns are cell arrays), field names made valid MATLAB names; ``units`` holds a struct
  per table with each field's unit; ``summary`` and ``model`` are JSON text.

netCDF needs the ``export`` extra, ``pip install 'jointwear[export]'``; scipy, which writes
``.mat``, is a dependency of jointwear.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from ..engine.finite import json_safe
from ..io import write_atomic
from .column_units import TEXT

if TYPE_CHECKING:
    from .run_results import Results

FORMATS = (".nc", ".mat")
INSTALL = "pip install 'jointwear[export]'"
MATLAB_NAME_LENGTH = 63  # namelengthmax


def export(results: Results, path: str | os.PathLike) -> Path:
    """Write ``results`` to ``path`` in the format its suffix names (``FORMATS``)."""
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in FORMATS:
        raise ValueError(
            f"{target}: cannot tell the format from the suffix {suffix or '(none)'!r}; "
            f"export writes {' or '.join(FORMATS)}"
        )
    if suffix == ".nc":
        xr = _xarray()
        return write_atomic(target, lambda temporary: _write_netcdf(xr, results, temporary))
    savemat = _savemat()
    return write_atomic(target, lambda temporary: _write_mat(savemat, results, temporary))


def _xarray():
    """xarray, with the h5netcdf engine; or say how to install them."""
    try:
        import h5netcdf  # noqa: F401  (the engine xarray writes with)
        import xarray
    except ImportError as error:
        raise ImportError(f"exporting to .nc needs xarray and h5netcdf: {INSTALL}") from error
    return xarray


def _savemat():
    """The MATLAB writer of scipy; or say how to install it."""
    try:
        from scipy.io import savemat
    except ImportError as error:
        raise ImportError(f"exporting to .mat needs scipy: {INSTALL}") from error
    return savemat


def _attributes(results: Results) -> dict[str, str]:
    """The file's description: the summary and the model, as JSON."""
    return {
        "title": f"jointwear results: {results.model.name}",
        "jointwear_version": str(results.summary.get("jointwear_version", "")),
        "summary": json.dumps(json_safe(results.summary), allow_nan=False),
        "model": results.model.model_dump_json(),
    }


def _column(values: pd.Series, unit: str) -> np.ndarray:
    """A column as numbers or booleans, or as text if its unit says so (text never None)."""
    if unit != TEXT and values.dtype.kind in "biuf":
        return values.to_numpy()
    if unit != TEXT:  # numbers among None (an empty table read back from CSV is text)
        numbers = pd.to_numeric(values, errors="coerce")
        if values.notna().sum() == numbers.notna().sum():
            return numbers.to_numpy(dtype=float)
    return np.array(["" if pd.isna(v) else str(v) for v in values], dtype=object)


def _write_netcdf(xr, results: Results, path: Path) -> None:
    from .run_results import TABLES

    for group, table in enumerate(TABLES):
        frame = results.to_dataframe(table)
        units = results.units(table)
        dimension = "time" if table == "timeseries" else "row"
        variables = {}
        for column in frame.columns:
            data = _column(frame[column], units[column])
            if data.dtype == object:
                data = data.astype(str)  # a fixed-width string array even when empty
            variables[column] = xr.Variable(dimension, data, {"units": units[column]})
        if table == "timeseries":
            dataset = xr.Dataset(
                {c: v for c, v in variables.items() if c != "time"},
                coords={"time": variables["time"]} if "time" in variables else None,
                attrs=_attributes(results),
            )
        else:
            dataset = xr.Dataset(variables, attrs={"table": table})
        dataset.to_netcdf(
            path,
            mode="w" if group == 0 else "a",
            group=None if table == "timeseries" else table,
            engine="h5netcdf",
        )


def matlab_names(columns: list[str]) -> dict[str, str]:
    """Each column's MATLAB field name: letters, digits and ``_``, a letter first, unique."""
    names: dict[str, str] = {}
    for column in columns:
        name = re.sub(r"\W", "_", column, flags=re.ASCII)
        if not name[:1].isalpha():
            name = f"x{name}"
        name = stem = name[:MATLAB_NAME_LENGTH]
        count = 1
        while name in names.values():
            count += 1
            name = f"{stem[: MATLAB_NAME_LENGTH - len(str(count)) - 1]}_{count}"
        names[column] = name
    return names


def _write_mat(savemat, results: Results, path: Path) -> None:
    from .run_results import TABLES

    content: dict[str, object] = {"units": {}}
    for table in TABLES:
        frame = results.to_dataframe(table)
        units = results.units(table)
        names = matlab_names(list(frame.columns))
        content[table] = {names[c]: _column(frame[c], units[c]) for c in frame.columns}
        content["units"][table] = {names[c]: units[c] for c in frame.columns}
    attributes = _attributes(results)
    content.update(summary=attributes["summary"], model=attributes["model"])
    with open(path, "wb") as file:  # a file: savemat would add ".mat" to the temporary name
        savemat(file, content, oned_as="column", long_field_names=True)
