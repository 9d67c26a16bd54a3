"""Shared helpers for tests that run the engine on the example models."""

from pathlib import Path

import jointwear as jw

EXAMPLES = Path(__file__).parents[1] / "examples"


def simulate_ok(path: Path, overrides: list[str]) -> jw.Results:
    """Load a model with overrides, run it, and insist that it finished."""
    res = jw.simulate(jw.load_model(path, overrides=overrides))
    assert res.status == "success", res.message
    return res
