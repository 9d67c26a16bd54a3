"""Every figure of a results folder, and on request the animation, written in one call."""

from __future__ import annotations

from functools import partial
from pathlib import Path

from ..io import remove
from ..results import Results
from .animation import save_animation
from .clearance import clearance_drawings
from .files import Drawings, save_pngs
from .names import ALL_FIGURES, ANIMATION
from .run import crank_driver, plot_cycle, plot_energy
from .slider import slider_drawings


def save_figures(
    results: Results, folder: str | Path, ideal: Results | None = None, *, animation: bool = False
) -> list[Path]:
    """Draw every figure that applies to ``results`` into ``folder``; return the paths.

    PNGs of the energy and, with a crank, of one turn; with revolute clearance joints the
    paper's Fig. 7-10 (``ideal``: the same mechanism with ideal joints, for Fig. 7); with
    translational clearance joints the slider's motion, corner forces and wear. With
    ``animation``, also a GIF of the mechanism (without, an existing GIF is kept). Figures of
    ours that do not apply to these results are removed.
    """
    path = Path(folder)
    drawings: Drawings = {"energy": partial(plot_energy, results)}
    if crank_driver(results) is not None:
        drawings["cycle"] = partial(plot_cycle, results)
    written = save_pngs(
        {**drawings, **clearance_drawings(results, ideal), **slider_drawings(results)}, path
    )
    if animation:
        written.append(save_animation(results, path / ANIMATION))
    kept = {p.name for p in written} | {ANIMATION}
    for name in ALL_FIGURES - kept:  # left by an earlier run of another model
        remove(path / name)
    return written
