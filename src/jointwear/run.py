"""``run``: the whole chain from a model file to a results folder with figures."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from .interrupts import stop_requests
from .io import check_folder
from .model import load_model
from .results import IDEAL_FOLDER, Results
from .simulate import Progress, simulate
from .status import INTERRUPTED, SUCCESS


def run(
    model_path: str | os.PathLike,
    out: str | os.PathLike,
    *,
    overrides: Sequence[str] = (),
    figures: bool = True,
    ideal: bool = True,
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
    ideal
        When the model has clearance joints and its run succeeds, also simulate the same
        mechanism with every joint ideal into ``out/ideal``, for the comparison figures.
    progress
        Called after every chunk with (time reached, end time) [s].

    Returns
    -------
    Results
        Those of the model as given (with its clearance joints). With a companion run, the
        summary's ``ideal_comparison`` gives its folder and status; one that did not finish
        (e.g. interrupted) is neither saved nor drawn.
    """
    model = load_model(model_path, overrides)
    folder = Path(out)
    check_folder(folder)
    # One block from the first step to the last file: a Ctrl-C or SIGTERM at any moment in it
    # is a request the runs act on, so nothing computed is lost to it (interrupts.py).
    with stop_requests():
        results = simulate(model, progress=progress)
        companion = None
        if ideal and model.has_clearance and results.status == SUCCESS:
            try:
                companion = simulate(model.ideal())
                status = companion.status
            except KeyboardInterrupt:  # during its set-up: the run above is kept
                status = INTERRUPTED
            results.summary["ideal_comparison"] = {"folder": IDEAL_FOLDER, "status": status}
            if status != SUCCESS:
                companion = None
        results.save(folder)
        _remove_companion(folder / IDEAL_FOLDER)  # an earlier run's: never mix two runs
        if companion is not None:
            companion.save(folder / IDEAL_FOLDER)
        if figures and len(results.timeseries) > 1:
            from .figures.folder import save_figures  # matplotlib only when figures are wanted

            save_figures(results, folder / "figures", ideal=companion)
    return results


def _remove_companion(folder: Path) -> None:
    """Remove an earlier companion results folder (only files a results folder holds)."""
    if not (folder / "model.json").is_file():
        return
    for file in folder.iterdir():
        if file.is_file() and file.suffix in (".json", ".csv", ".parquet"):
            file.unlink()
    if not any(folder.iterdir()):
        folder.rmdir()
