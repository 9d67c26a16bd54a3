"""The ``export`` command: a results folder's tables in one netCDF4 or MATLAB file."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .common import PLAIN, err, one_line, out


def export(
    folder: Annotated[Path, typer.Argument(help="Results folder.", show_default=False)],
    path: Annotated[
        Path,
        typer.Argument(
            help="File to write: .nc (netCDF4/HDF5) or .mat (MATLAB).", show_default=False
        ),
    ],
) -> None:
    """Write the tables of the results FOLDER, with units, to PATH (.nc or .mat).

    Needs the export extra (pip install 'jointwear[export]'); in Python,
    jointwear.load_results(FOLDER).export(PATH).
    """
    from ..model import ModelError
    from ..results import load_results

    if not (folder / "summary.json").is_file():
        err.print(f"{folder}: not a results folder (no summary.json)", **PLAIN)
        raise typer.Exit(code=2)
    try:
        results = load_results(folder)
    except (ModelError, OSError, ValueError, LookupError, TypeError) as error:
        reason = one_line(" ".join(str(error).split()))[:300]
        err.print(f"{folder}: cannot read its results ({type(error).__name__}: {reason})", **PLAIN)
        raise typer.Exit(code=2) from None
    try:
        written = results.export(path)
    except (ImportError, ValueError) as error:
        err.print(one_line(str(error)), **PLAIN)
        raise typer.Exit(code=2) from None
    except OSError as error:
        err.print(f"{path}: cannot write it: {one_line(str(error))}", **PLAIN)
        raise typer.Exit(code=3) from None
    out.print(f"wrote {written}", **PLAIN)
