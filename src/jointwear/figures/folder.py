"""Every figure and the animation of a results folder, written in one call."""

from __future__ import annotations

from pathlib import Path

from ..io import remove
from ..results import Results
from .animation import save_animation
from .clearance import save_clearance_figures
from .files import save_png
from .names import ALL_FIGURES, ANIMATION
from .run import crank_driver, plot_cycle, plot_energy
from .slider import save_slider_figures


def save_figures(
    results: Results, folder: str | Path, ideal: Results | None = None, *, animation: bool = True
) -> list[Path]:
    """Draw every figure that applies to ``results`` into ``folder``; return the paths.

    PNGs of the energy and, with a crank, of one turn; with revolute clearance joints the
    paper's Fig. 7-10 (``ideal``: the same mechanism with ideal joints, for Fig. 7); with
    translational clearance joints the slider's motion, corner forces and wear; and, unless
    ``animation`` is false, a GIF of the mechanism (an existing GIF is then kept). Figures of
    ours that do not apply to these results are removed.
    """
    path = Path(folder)
    figures = {"energy": plot_energy}
    if crank_driver(results) is not None:
        figures["cycle"] = plot_cycle
    written = [save_png(draw(results), path / f"{name}.png") for name, draw in figures.items()]
    written += save_clearance_figures(results, path, ideal)
    written += save_slider_figures(results, path)
    if animation:
        written.append(save_animation(results, path / ANIMATION))
    kept = {p.name for p in written} | (set() if animation else {ANIMATION})
    for name in ALL_FIGURES - kept:  # left by an earlier run of another model
        remove(path / name)
    return written
