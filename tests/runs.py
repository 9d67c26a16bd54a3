"""Shared helpers for tests that run the engine on the example models."""

from pathlib import Path

import jointwear as jw

EXAMPLES = Path(__file__).parents[1] / "examples"


def simulate_ok(path: Path, overrides: list[str]) -> jw.Results:
    """Load a model with overrides, run it, and insist that it finished."""
    res = jw.simulate(jw.load_model(path, overrides=overrides))
    assert res.status == "success", res.message
    return res

# The paper four-bar's time-series columns, spelled out from the model's own names.
FOURBAR_COLUMNS = [
    "time",
    *(
        f"{c}_{body}"
        for body in ("crank", "coupler", "follower")
        for c in ("x", "y", "phi", "vx", "vy", "omega", "ax", "ay", "alpha")
    ),
    "torque_motor",
    *(
        f"{joint}_{c}"
        for joint in ("ground_crank", "crank_coupler", "coupler_follower", "ground_follower")
        for c in ("fx", "fy")
    ),
    "energy_kinetic",
    "energy_potential",
    "constraint_violation",
]
