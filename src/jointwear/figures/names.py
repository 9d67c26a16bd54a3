"""The file names the figures of a results folder are written under (no matplotlib here).

The commands check them before a run (``jointwear.io.claim``), so a user's file of the same
name stops the run at once instead of being overwritten.
"""

CLEARANCE_FIGURES = (
    "fig7_dynamics",
    "fig7d_orbit",
    "fig8_wear_sectors",
    "fig9_wear_polar",
    "fig10_profile",
)  # the file names (.png) save_clearance_figures writes
SLIDER_FIGURES = (
    "slider_motion",
    "slider_corner_forces",
    "slider_wear",
)  # the file names (.png) save_slider_figures writes
ANIMATION = "mechanism.gif"
ALL_FIGURES = frozenset(
    {
        "energy.png",
        "cycle.png",
        *(f"{n}.png" for n in CLEARANCE_FIGURES),
        *(f"{n}.png" for n in SLIDER_FIGURES),
        ANIMATION,
    }
)  # every file a run's figures folder may hold
