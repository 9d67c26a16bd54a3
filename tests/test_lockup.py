"""Lock-up: a driven mechanism that cannot follow its drivers is caught, not ground through.

The slider-crank example with its connecting rod shortened to 40 mm, below the 50 mm crank:
the rod's far end must stay on the slider's line, so the crank can turn only while its tip
is within 40 mm of that line, up to asin(40 / 50) = 53.13 deg from the start.
"""

import math

import pytest
from runs import EXAMPLES
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

CRANK, ROD = 0.05, 0.04  # [m]
SPEED = 5000.0 * 2.0 * math.pi / 60.0  # the example's 5000 rpm [rad/s]
LIMIT = math.asin(ROD / CRANK)  # [rad] the crank angle where the rod is vertical
SHORT_ROD = [
    f"bodies.1.points.crank_end=[{-ROD / 2}, 0.0]",
    f"bodies.1.points.slider_end=[{ROD / 2}, 0.0]",
    f"bodies.1.position=[{CRANK + ROD / 2}, 0.0]",
    f"bodies.2.position=[{CRANK + ROD}, 0.0]",
]
SETS = [a for s in SHORT_ROD for a in ("--set", s)]
MODELS = ["slider_crank.toml", "slider_crank_clearance.toml"]


@pytest.mark.parametrize("name", MODELS)
def test_check_names_the_lock_up_and_where(name):
    result = CliRunner().invoke(app, ["check", str(EXAMPLES / name), *SETS])
    assert result.exit_code == 2, result.output
    (line,) = result.output.strip().splitlines()
    assert line.startswith("drivers: the mechanism locks up at t = ")
    angle = float(line.split("driver 'motor' at ")[1].split(" deg")[0])
    # Bisection to 30 halvings of a 1-degree step, and 4 significant digits printed.
    assert angle == pytest.approx(math.degrees(LIMIT), abs=0.01)


@pytest.mark.parametrize("name", MODELS)
def test_run_stops_at_the_lock_up_with_its_status(name):
    model = jw.load_model(EXAMPLES / name, overrides=[*SHORT_ROD, "solver.t_end=0.01"])
    res = jw.simulate(model)
    assert res.status == "lock_up", res.message
    assert "53.13 deg" in res.message
    # It stops at the lock-up (the crank's angle there over its speed), not grinding past it.
    assert res.summary["stats"]["t_reached"] == pytest.approx(LIMIT / SPEED, rel=1e-4)
    assert res.summary["stats"]["accepted_steps"] < 100_000


@pytest.mark.parametrize(
    "name", [*MODELS, "flores2009_fourbar.toml", "fourbar_two_clearances.toml"]
)
def test_mechanisms_that_turn_are_not_locked(name):
    result = CliRunner().invoke(app, ["check", str(EXAMPLES / name)])
    assert result.exit_code == 0, result.output


def test_without_the_check_the_run_meets_the_lock_up_unnamed():
    # check_lock_up=False is for a mechanism known to pass (run.py's ideal companion); here
    # it shows the check is what names the lock-up: the run ends at the same pose, singular.
    model = jw.load_model(
        EXAMPLES / "slider_crank.toml", overrides=[*SHORT_ROD, "solver.t_end=0.01"]
    )
    res = jw.simulate(model, check_lock_up=False)
    assert res.status == "singular", res.message
    assert res.summary["stats"]["t_reached"] == pytest.approx(LIMIT / SPEED, rel=1e-4)
