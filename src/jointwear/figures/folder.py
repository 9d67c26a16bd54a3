"""Every figure of a results folder, and on request the animation (no matplotlib here)."""

from __future__ import annotations

from pathlib import Path

from ..io import remove
from ..results import Results
from .files import write_pngs
from .names import ALL_FIGURES, ANIMATION
from .plan import WITH_IDEAL, figure_plan
from .render import start_pngs


class FigureDrawing:
    """A results folder's figures, begun at once; those comparing with the ideal run wait.

    Within ``render.drawing_helper`` the helper processes draw the figures of ``results``
    while the caller goes on (e.g. runs the ideal companion and writes the tables); ``save``
    adds the comparisons, waits and writes every file.
    """

    def __init__(self, results: Results) -> None:
        self.results = results
        self._begun = {n: d for n, d in figure_plan(results).items() if n not in WITH_IDEAL}
        self._images = start_pngs(list(self._begun.values()))

    def save(
        self, folder: str | Path, ideal: Results | None = None, *, animation: bool = False
    ) -> list[Path]:
        """Write every figure that applies into ``folder``; return the paths.

        ``ideal``: the same mechanism with ideal joints, for the comparison of Fig. 7. With
        ``animation``, also a GIF of the mechanism (without, an existing GIF is kept).
        Figures of ours that do not apply to these results are removed.
        """
        path = Path(folder)
        plan = figure_plan(self.results, ideal)
        rest = {n: d for n, d in plan.items() if n not in self._begun}
        rest_images = start_pngs(list(rest.values()))
        images = dict(zip(self._begun, self._images(), strict=True))
        images.update(zip(rest, rest_images(), strict=True))
        written = write_pngs({name: images[name] for name in plan}, path)
        if animation:
            from .animation import save_animation  # matplotlib here, only for the animation

            written.append(save_animation(self.results, path / ANIMATION))
        kept = {p.name for p in written} | {ANIMATION}
        for name in ALL_FIGURES - kept:  # left by an earlier run of another model
            remove(path / name)
        return written


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
    return FigureDrawing(results).save(folder, ideal, animation=animation)
