"""Shared helpers for tests that run the engine on the example models."""

from pathlib import Path

import jointwear as jw

EXAMPLES = Path(__file__).parents[1] / "examples"


def simulate_ok(path: Path, overrides: list[str], *, ideal: bool = False) -> jw.Results:
    """Load a model with overrides (all joints ideal if asked), run it, insist it finished."""
    model = jw.load_model(path, overrides=overrides)
    res = jw.simulate(model.ideal() if ideal else model)
    assert res.status == "success", res.message
    return res


def disc(name: str, mass: float, inertia: float, **keys) -> dict:
    """A body at the origin with one point ``c`` at its centre of mass (``keys`` override)."""
    return {
        "name": name,
        "mass": mass,
        "inertia": inertia,
        "position": [0.0, 0.0],
        "angle": 0.0,
        "points": {"c": [0.0, 0.0]},
        **keys,
    }


# The paper four-bar's time-series columns, spelled out from the model's own names.
_FOURBAR_BODIES = [
    "time",
    *(
        f"{c}_{body}"
        for body in ("crank", "coupler", "follower")
        for c in ("x", "y", "phi", "vx", "vy", "omega", "ax", "ay", "alpha")
    ),
    "torque_motor",
]
FOURBAR_IDEAL_COLUMNS = [
    *_FOURBAR_BODIES,
    *(
        f"{joint}_{c}"
        for joint in ("ground_crank", "crank_coupler", "coupler_follower", "ground_follower")
        for c in ("fx", "fy")
    ),
    "energy_kinetic",
    "energy_potential",
    "constraint_violation",
]
CLEARANCE_COLUMNS = (
    *("fx", "fy", "ex", "ey", "delta", "fn", "ft", "vt", "theta_bearing", "theta_journal"),
    *("delta_dot", "fn_elastic", "p_max", "p_mean", "pv", "friction_power", "damping_power"),
)  # a revolute clearance joint's own, then results.tribology's
# As in the example file: coupler_follower has clearance; its columns follow the ideal joints'.
FOURBAR_COLUMNS = [
    *_FOURBAR_BODIES,
    *(
        f"{joint}_{c}"
        for joint in ("ground_crank", "crank_coupler", "ground_follower")
        for c in ("fx", "fy")
    ),
    *(f"coupler_follower_{c}" for c in CLEARANCE_COLUMNS),
    "energy_kinetic",
    "energy_potential",
    "energy_contact",
    "constraint_violation",
]


def whole_run(results: jw.Results, joint: str) -> dict:
    """A clearance joint's summary with the whole run's figures, not the steady state's."""
    entry = results.summary["clearance_joints"][joint]
    return {**entry, **entry["whole_run"]}


PER_METRE = {"nm": 1e9, "µm": 1e6, "mm": 1e3, "m": 1.0}


def drawn_per_metre(label: str) -> float:
    """The count per metre of the unit a figure's label names, as in 'wear depth [nm]'."""
    return PER_METRE[label.split("wear depth [", 1)[1].split("]", 1)[0]]
