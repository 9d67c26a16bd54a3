"""The figures of a life-run folder, drawn again from its files."""

from __future__ import annotations

import json
import os
from pathlib import Path

from ...model import ModelError, load_model
from . import files
from .records import figure_options


def redraw_life_figures(folder: str | os.PathLike) -> list[Path]:
    """Draw the figures of the life-run folder ``folder`` again; return their paths.

    Raises
    ------
    ModelError
        If the folder is not a complete life-run folder (model, summary and tables).
    """
    path = Path(folder)
    model = load_model(path)  # its model.json
    try:
        summary = json.loads((path / files.SUMMARY).read_text())
        driver, period = summary["driver"], summary["period_s"]
        table, profiles = files.read_tables(path)
    except (OSError, ValueError, LookupError, TypeError) as error:
        raise ModelError(
            [f"{path}: not a complete life-run folder ({type(error).__name__})"]
        ) from None
    from ...figures.life import save_life_figures  # matplotlib only when drawing

    options = figure_options(model, driver, period)
    return save_life_figures(
        model, driver, table, profiles, path / files.FIGURES, runaway=summary.get("runaway"),
        **options,
    )  # fmt: skip
