"""Which figures a run's results get, each named rather than held (no matplotlib here).

A ``Drawing`` names its plotting function by module and name, so the process that plans the
figures (a run, which may hand them to helper processes: ``render.py``) never imports
matplotlib; the process that calls the drawing does.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any, NamedTuple

from ..joints import KINDS, ClearanceKind

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..results import Results

CRANK_FUNCTIONS = ("constant_speed",)  # driver functions that turn a crank
RUN_FIGURES = "jointwear.figures.run"  # the figures of every run
WITH_IDEAL = frozenset(
    name for kind in KINDS for name in kind.figures_with_ideal
)  # figures that compare with the ideal companion run


class Drawing(NamedTuple):
    """One figure: ``<module>.<function>(*args)`` (a module's full name), called when drawn."""

    module: str
    function: str
    args: tuple[Any, ...]

    def __call__(self) -> Figure:
        """Import the plotting function's module here, and draw."""
        plot = getattr(import_module(self.module), self.function)
        return plot(*self.args)


def crank_driver(results: Results) -> tuple[str, str, float] | None:
    """(driver name, driven body, speed [rad/s]) of the first constant-speed angle driver."""
    for driver in results.model.drivers:
        if driver.type == "angle" and driver.function.type in CRANK_FUNCTIONS:
            return driver.name, driver.body, driver.function.speed
    return None


def figure_plan(results: Results, ideal: Results | None = None) -> dict[str, Drawing]:
    """Every figure that applies to ``results``, by file name without ``.png``.

    The energy; with a crank, one cycle; the applied loads; then each joint type's with
    clearance (for a revolute joint the paper's Figs. 7-10, with ``ideal``, the same mechanism
    with ideal joints, for Fig. 7; for a translational one the slider's motion, corner forces
    and wear).
    """
    plan = {"energy": Drawing(RUN_FIGURES, "plot_energy", (results,))}
    if crank_driver(results) is not None:
        plan["cycle"] = Drawing(RUN_FIGURES, "plot_cycle", (results,))
    if any(load.type != "gravity" for load in results.model.forces):
        plan["loads"] = Drawing(RUN_FIGURES, "plot_loads", (results,))
    for kind in KINDS:
        plan |= kind_drawings(kind, results, ideal)
    return plan


def kind_drawings(
    kind: ClearanceKind, results: Results, ideal: Results | None = None
) -> dict[str, Drawing]:
    """The figures of ``kind`` that ``results`` get, by file name; none without its joints.

    ``ideal``: the same mechanism with ideal joints, for the figures that compare with it.
    """
    if not kind.joints(results.model):
        return {}
    return {
        name: Drawing(
            kind.figures_module,
            plot,
            (results, ideal) if name in kind.figures_with_ideal else (results,),
        )
        for name, plot in kind.figures
        if kind.draws(name, results.model)
    }
