"""Range warnings of the translational clearance joint: penetration against the gap and the
Hertz patch of a corner against its radius (``outside_law_ranges``), checked against the run's
own peaks and Johnson's line-contact formula.

The piston example with the gap narrowed to 50 µm and 2 mm corners: the slap pushes a corner
deeper than a tenth of the gap (the Hertz law's range), which the run must report.
"""

import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

PISTON = Path(__file__).parents[1] / "examples" / "slider_crank_piston_clearance.toml"
NARROW = ["joints.piston.clearance.gap=50 um", "joints.piston.clearance.corner_radius=2 mm",
          "solver.t_end=20 ms"]  # fmt: skip
E, NU, WIDTH, RADIUS, GAP = 207e9, 0.3, 0.05, 2e-3, 50e-6  # the example's and NARROW's


@pytest.fixture(scope="module")
def narrow() -> jw.Results:
    return jw.simulate(jw.load_model(PISTON, NARROW))


def test_a_corner_deeper_than_the_laws_range_is_reported(narrow):
    joint = narrow.summary["clearance_joints"]["piston"]
    whole = joint.get("whole_run", joint)
    depth = joint["outside_law_ranges"]["penetration_over_gap"]
    assert depth["limit"] == 0.1
    # The largest ratio is over the steps' midpoints; the peak penetration also over their
    # ends, so it bounds the ratio from above, and a step changes it by a few per cent at most.
    assert depth["largest"] * GAP <= whole["max_penetration_m"] * (1 + 1e-12)
    assert depth["largest"] * GAP == pytest.approx(whole["max_penetration_m"], rel=0.05)
    assert depth["largest"] > 0.1 and 0.0 < depth["time_beyond_s"] <= 0.02
    assert depth["time_fraction_beyond"] == pytest.approx(depth["time_beyond_s"] / 0.02)


def test_the_corners_patch_follows_johnsons_line_contact(narrow):
    joint = narrow.summary["clearance_joints"]["piston"]
    force = joint.get("whole_run", joint)["max_contact_force_n"]
    e_star = E / (2.0 * (1.0 - NU**2))  # two equal steels (Johnson 1985, eq. 4.22)
    b = math.sqrt(4.0 * force * RADIUS / (math.pi * WIDTH * e_star))  # (Johnson 1985, eq. 4.45)
    patch = joint["outside_law_ranges"]["hertz_half_width_over_corner_radius"]
    assert patch["largest"] <= b / RADIUS * (1 + 1e-12)  # the same midpoint/end argument
    assert patch["largest"] == pytest.approx(b / RADIUS, rel=0.05)
    assert patch["time_beyond_s"] == 0.0  # 0.5 % of the radius: far inside


def test_without_a_corner_radius_only_the_penetration_is_checked():
    data = jw.load_model(PISTON, ["solver.t_end=2 ms"]).model_dump(mode="json")
    piston = next(joint for joint in data["joints"] if joint["name"] == "piston")
    piston["clearance"] = {**piston["clearance"], "corner_radius": None,
                           "contact_stiffness": 1e10}  # fmt: skip
    model = jw.parse_model(data)
    ranges = jw.simulate(model).summary["clearance_joints"]["piston"]["outside_law_ranges"]
    assert set(ranges) == {"penetration_over_gap"}


def test_run_warns_of_it(tmp_path):
    args = ["run", str(PISTON), "--out", str(tmp_path / "out"), "--no-figures", "--no-ideal"]
    args += [a for setting in NARROW for a in ("--set", setting)]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "warning: joint 'piston': penetration / gap reached 0.1" in result.output
