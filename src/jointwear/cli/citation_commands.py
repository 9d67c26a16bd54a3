"""The ``citations`` command: the papers to cite for a model's method, solver and laws."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from .common import PLAIN, fail, out


def citations(
    model: Annotated[
        Path,
        typer.Argument(
            help="TOML model file, or a results folder (a run's or a life run's).",
            show_default=False,
        ),
    ],
) -> None:
    """Print the references behind MODEL: the method, its formulation, integrator and laws.

    One reference a line, Flores (2009) first, each once; in Python,
    jointwear.citations_for(model).
    """
    from ..citations import citations_for
    from ..model import ModelError

    try:
        texts = citations_for(model)
    except ModelError as error:
        raise fail(error) from None
    for number, text in enumerate(texts, start=1):
        out.print(f"[{number}] {text}", **PLAIN)
