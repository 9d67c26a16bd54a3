"""Which figures a run's results get, each named rather than held (no matplotlib here).

A ``Drawing`` names its plotting function by module and name, so the process that plans the
figures (a run, which may hand them to helper processes: ``render.py``) never imports
matplotlib; the process that calls the drawing does.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any, NamedTuple

from .names import CLEARANCE_FIGURES, SLIDER_FIGURES

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from ..results import Results

CRANK_FUNCTIONS = ("constant_speed",)  # driver functions that turn a crank
CLEARANCE_PLOTS = (  # in the order of CLEARANCE_FIGURES (clearance.py)
    "plot_dynamics",
    "plot_orbit",
    "plot_wear_sectors",
    "plot_wear_polar",
    "plot_wear_profile",
)
SLIDER_PLOTS = ("plot_slider_motion", "plot_corner_forces", "plot_guide_wear")  # slider.py
WITH_IDEAL = frozenset({"fig7_dynamics"})  # figures that compare with the ideal companion run


class Drawing(NamedTuple):
    """One figure: ``jointwear.figures.<module>.<function>(*args)``, called when drawn."""

    module: str
    function: str
    args: tuple[Any, ...]

    def __call__(self) -> Figure:
        """Import the plotting function's module here, and draw."""
        plot = getattr(import_module(f"{__package__}.{self.module}"), self.function)
        return plot(*self.args)


def crank_driver(results: Results) -> tuple[str, str, float] | None:
    """(driver name, driven body, speed [rad/s]) of the first constant-speed angle driver."""
    for driver in results.model.drivers:
        if driver.type == "angle" and driver.function.type in CRANK_FUNCTIONS:
            return driver.name, driver.body, driver.function.speed
    return None


def figure_plan(results: Results, ideal: Results | None = None) -> dict[str, Drawing]:
    """Every figure that applies to ``results``, by file name without ``.png``.

    The energy; with a crank, one turn; with revolute clearance joints the paper's Fig. 7-10
    (``ideal``: the same mechanism with ideal joints, for Fig. 7); with translational
    clearance joints the slider's motion, corner forces and wear.
    """
    plan = {"energy": Drawing("run", "plot_energy", (results,))}
    if crank_driver(results) is not None:
        plan["cycle"] = Drawing("run", "plot_cycle", (results,))
    return {**plan, **clearance_drawings(results, ideal), **slider_drawings(results)}


def clearance_drawings(results: Results, ideal: Results | None = None) -> dict[str, Drawing]:
    """The revolute clearance figures (paper Figs. 7-10) by file name; none without such joints.

    ``ideal``: the same mechanism with ideal joints, for the comparison of Fig. 7 (a)-(c).
    """
    if not results.model.joints_of("revolute"):
        return {}
    return {
        name: Drawing("clearance", plot, (results, ideal) if name in WITH_IDEAL else (results,))
        for name, plot in zip(CLEARANCE_FIGURES, CLEARANCE_PLOTS, strict=True)
    }


def slider_drawings(results: Results) -> dict[str, Drawing]:
    """The slider figures by file name; none without translational clearance joints."""
    if not results.model.joints_of("translational"):
        return {}
    return {
        name: Drawing("slider", plot, (results,))
        for name, plot in zip(SLIDER_FIGURES, SLIDER_PLOTS, strict=True)
    }
