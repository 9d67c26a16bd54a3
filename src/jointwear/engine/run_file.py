"""``run``: the whole chain from a model file to a results folder with figures."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Sequence
from pathlib import Path

from ..io import check_folder, claim, remove, remove_folder
from ..model import load_model
from ..results import IDEAL_FOLDER, Results
from ..results.run_results import CLEARANCE_FILES
from ..results.run_results import FILES as RESULT_FILES
from .interrupts import stop_requests
from .simulate import Progress, simulate
from .status import INTERRUPTED, SUCCESS

FIGURES = "figures"  # subfolder of the figures and the animation
RESCUE_PREFIX = "jointwear-rescued-"  # results that could not be written where asked go to a
# new folder of the system's temporary folder with this prefix (summary "not_written")


def run(
    model_path: str | os.PathLike,
    out: str | os.PathLike,
    *,
    overrides: Sequence[str] = (),
    figures: bool = True,
    animation: bool = False,
    ideal: bool = True,
    progress: Progress | None = None,
) -> Results:
    """Load a model file, simulate it and write the results folder ``out``.

    Parameters
    ----------
    model_path
        TOML model file.
    out
        Results folder (created). Only files jointwear wrote there are replaced
        (``jointwear.io``); if it cannot be written when the run ends, the results go to a
        new temporary folder, named with the error in the summary's ``not_written``.
    overrides
        ``dotted.path=value`` settings applied before validation (as ``--set``).
    figures
        Also draw the figures into ``out/figures``.
    animation
        With ``figures``, also write the mechanism's animation (``figures/mechanism.gif``,
        a few seconds more); without, an earlier run's animation is removed.
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
    claim(folder, _files(model.has_clearance, figures, ideal and model.has_clearance))
    # One block from the first step to the last file: a Ctrl-C or SIGTERM at any moment in it
    # is a request the runs act on, so nothing computed is lost to it (interrupts.py).
    with stop_requests():
        results = simulate(model, progress=progress)
        drawing = None
        if figures and len(results.timeseries) > 1:
            from ..figures.folder import FigureDrawing

            drawing = FigureDrawing(results)  # the helpers draw while the rest goes on
        companion = None
        if ideal and model.has_clearance and results.status == SUCCESS:
            try:
                # the same all-ideal mechanism as the run's own lock-up check, which it passed
                companion = simulate(model.ideal(), check_lock_up=False)
                status = companion.status
            except KeyboardInterrupt:  # during its set-up: the run above is kept
                status = INTERRUPTED
            results.summary["ideal_comparison"] = {"folder": IDEAL_FOLDER, "status": status}
            if status != SUCCESS:
                companion = None
        try:
            _save(results, companion, folder)
        except OSError as error:  # unwritable now, or a file that appeared since the claim
            rescue = Path(tempfile.mkdtemp(prefix=RESCUE_PREFIX))
            results.summary["not_written"] = {
                "folder": str(folder),
                "error": _describe(error),
                "saved_in": str(rescue),
            }
            _save(results, companion, rescue)
            return results
        if drawing is not None:
            from ..figures.names import ANIMATION

            try:
                drawing.save(folder / FIGURES, ideal=companion, animation=animation)
                if not animation:  # an earlier run's: it would show another run
                    remove(folder / FIGURES / ANIMATION)
            except OSError as error:
                results.summary["not_written"] = {
                    "folder": str(folder / FIGURES),
                    "error": _describe(error),
                    "saved_in": None,
                }
    return results


def _save(results: Results, companion: Results | None, folder: Path) -> None:
    results.save(folder)
    remove_folder(folder / IDEAL_FOLDER)  # an earlier run's: never mix two runs
    if companion is not None:
        companion.save(folder / IDEAL_FOLDER)


def _files(clearance: bool, figures: bool, ideal: bool) -> list[str]:
    """Every file a run may write in its folder, relative to it."""
    from ..figures.names import ALL_FIGURES

    tables = RESULT_FILES if clearance else RESULT_FILES[: -len(CLEARANCE_FILES)]
    names = [*tables, f"{IDEAL_FOLDER}/"]
    if ideal:  # the companion has no clearance joints
        names += [f"{IDEAL_FOLDER}/{name}" for name in RESULT_FILES[: -len(CLEARANCE_FILES)]]
    if figures:
        names += [f"{FIGURES}/{name}" for name in sorted(ALL_FIGURES)]
    return names


def _describe(error: OSError) -> str:
    """An OSError in one line: what failed, and on which file."""
    where = f": {error.filename}" if error.filename else ""
    return " ".join(f"{error.strerror or error}{where}".split())
