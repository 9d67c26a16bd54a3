"""``run``: the whole chain from a model file to a results folder with figures."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from .model import load_model
from .plots import save_figures
from .results import Results
from .simulate import Progress, simulate


def run(
    model_path: str | os.PathLike,
    out: str | os.PathLike,
    *,
    overrides: Sequence[str] = (),
    figures: bool = True,
    progress: Progress | None = None,
) -> Results:
    """Load a model file, simulate it and write the results folder ``out``.

    Parameters
    ----------
    model_path
        TOML model file.
    out
        Results folder (created; existing files are replaced).
    overrides
        ``dotted.path=value`` settings applied before validation (as ``--set``).
    figures
        Also draw the figures into ``out/figures``.
    progress
        Called after every chunk with (time reached, end time) [s].
    """
    model = load_model(model_path, overrides)
    results = simulate(model, progress=progress)
    folder = results.save(out)
    if figures and len(results.timeseries) > 1:
        save_figures(results, Path(folder) / "figures")
    return results
