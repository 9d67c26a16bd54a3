"""Every figure and the animation of a results folder, written in one call."""

from __future__ import annotations

from pathlib import Path

from ..results import Results
from .animation import save_animation
from .clearance import CLEARANCE_FIGURES, save_clearance_figures
from .run import crank_driver, plot_cycle, plot_energy
from .slider import SLIDER_FIGURES, save_slider_figures

ANIMATION = "mechanism.gif"
ALL_FIGURES = {
    "energy.png",
    "cycle.png",
    *(f"{n}.png" for n in CLEARANCE_FIGURES),
    *(f"{n}.png" for n in SLIDER_FIGURES),
    ANIMATION,
}


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
    path.mkdir(parents=True, exist_ok=True)
    figures = {"energy": plot_energy}
    if crank_driver(results) is not None:
        figures["cycle"] = plot_cycle
    written = []
    for name, draw in figures.items():
        draw(results).savefig(path / f"{name}.png", dpi=150)
        written.append(path / f"{name}.png")
    written += save_clearance_figures(results, path, ideal)
    written += save_slider_figures(results, path)
    if animation:
        written.append(save_animation(results, path / ANIMATION))
    kept = {p.name for p in written} | (set() if animation else {ANIMATION})
    for name in ALL_FIGURES - kept:  # left by an earlier run of another model
        (path / name).unlink(missing_ok=True)
    return written
