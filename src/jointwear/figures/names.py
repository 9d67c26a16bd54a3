"""The file names the figures of a results folder are written under (no matplotlib here).

The commands check them before a run (``jointwear.io.claim``), so a user's file of the same
name stops the run at once instead of being overwritten.
"""

from ..joints import KINDS

ANIMATION = "mechanism.gif"
LIFE_FIGURES = ("life_wear.png", "life_profiles.png")  # a life run's (figures.life)
ALL_FIGURES = frozenset(
    {
        "energy.png",
        "cycle.png",
        "loads.png",
        *(f"{name}.png" for kind in KINDS for name, _ in kind.figures),
        ANIMATION,
    }
)  # every file a run's figures folder may hold
