"""Clearance joints in the model and results plumbing: indices, refusals, stale files."""

import importlib

import numpy as np
import pytest
from runs import EXAMPLES

import jointwear as jw
from jointwear.model import parse_model

run_module = importlib.import_module("jointwear.engine.run_file")  # the module, not the function

FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
CLEARANCE = {
    "bearing_radius": "10 mm",
    "journal_radius": "9.8 mm",
    "width": "20 mm",
    "restitution_coefficient": 0.9,
    "friction_coefficient": 0.1,
    "youngs_modulus": "207 GPa",
    "poisson_ratio": 0.3,
    "wear_coefficient": "8e-14 1/Pa",
}


def shaker(clearance_first: bool) -> jw.Model:
    """A block driven along a rail, a flag hinged to it through a clearance joint.

    The block's distance driver names the rail; with the clearance joint listed first the
    rail is the second joint of the file but the first of the kernels' joint table.
    """
    hinge = {
        "name": "hinge", "type": "revolute", "bodies": ["block", "flag"],
        "points": ["pin", "root"], "clearance": CLEARANCE,
    }  # fmt: skip
    rail = {
        "name": "rail", "type": "translational", "bodies": ["ground", "block"],
        "points": ["origin", "centre"], "axis": [1.0, 0.0],
    }  # fmt: skip
    joints = [hinge, rail] if clearance_first else [rail, hinge]
    return parse_model({
        "name": "shaker",
        "ground": {"points": {"origin": [0.0, 0.0]}},
        "bodies": [
            {"name": "block", "mass": 1.0, "inertia": 0.01, "position": [0.0, 0.0], "angle": 0.0,
             "points": {"centre": [0.0, 0.0], "pin": [0.0, 0.0]}},
            {"name": "flag", "mass": 0.5, "inertia": 0.002, "position": [0.0, -0.1],
             "angle": -1.5707963267948966, "points": {"root": [-0.1, 0.0]}},
        ],
        "joints": joints,
        "drivers": [{
            "name": "shake", "type": "distance", "joint": "rail",
            "function": {"type": "harmonic", "amplitude": "2 mm", "angular_frequency": 60.0},
        }],
        "forces": [{"type": "gravity", "acceleration": [0.0, -9.81]}],
        "solver": {"t_end": 0.05},
    })  # fmt: skip


@pytest.mark.parametrize("clearance_first", [False, True])
def test_a_distance_driver_finds_its_rail_whatever_the_joint_order(clearance_first):
    res = jw.simulate(shaker(clearance_first))
    assert res.status == "success", res.message
    t = res.timeseries["time"].to_numpy()
    # The block follows the prescribed slide 2 mm sin(60 t) (harmonic driver, zero phase):
    # Baumgarte-held constraint at the default tolerances, 1e-7 m.
    np.testing.assert_allclose(res.timeseries["x_block"], 2e-3 * np.sin(60.0 * t), atol=1e-7)


def test_both_joint_orders_give_the_same_motion():
    a = jw.simulate(shaker(False)).timeseries
    b = jw.simulate(shaker(True)).timeseries
    # The same equations with the constraint rows in another order: only rounding differs,
    # grown by the impacts to the integration tolerance (measured 1e-7 m). 1e-6 m is 0.5 % of
    # the 0.2 mm clearance; a driver on the wrong joint moves the flag by millimetres.
    for column in ("x_flag", "y_flag"):
        np.testing.assert_allclose(a[column], b[column], rtol=0.0, atol=1e-6)


@pytest.mark.parametrize(
    ("setting", "message"),
    [
        ('contact_tolerance="1 mm"', "must be much smaller than the radial clearance"),
        ('journal_radius="10 mm"', "journal_radius 10 mm must be smaller than bearing_radius"),
        ('contact_stiffness="1e11 N/m"', "give K as a plain number in SI units"),
        ("damping=none", "restitution_coefficient is used by damping"),
        ("normal_law=johnson --set exponent=1.2", "exponent is used by normal_law 'hertz' only"),
        ("normal_law=elastic_foundation", "needs foundation_thickness"),
        ("foundation_thickness='2 mm'", "foundation_thickness is used by normal_law"),
        ("damping=lankarani_nikravesh --set normal_law=hunt_crossley", "and one damping"),
        ("exponent=1.2", "exponent 1.2 needs contact_stiffness"),
    ],
)
def test_inconsistent_clearance_settings_are_refused(setting, message):
    settings = [f"joints.coupler_follower.clearance.{s}" for s in setting.split(" --set ")]
    with pytest.raises(jw.ModelError) as error:
        jw.load_model(FOURBAR, settings)
    assert message in str(error.value)
    assert str(error.value).startswith("joints[2].clearance")  # one line, naming the field


@pytest.mark.parametrize("law", ["lankarani_nikravesh", "hunt_crossley", "flores2011"])
def test_a_damping_law_as_normal_law_is_hertz_with_that_damping(law):
    """Model files written before damping was its own key keep their meaning."""
    old = jw.load_model(FOURBAR, [f"joints.coupler_follower.clearance.normal_law={law}"])
    new = jw.load_model(FOURBAR, [f"joints.coupler_follower.clearance.damping={law}"])
    assert old.joints[2].clearance == new.joints[2].clearance
    assert (new.joints[2].clearance.normal_law, new.joints[2].clearance.damping) == ("hertz", law)


def test_absurd_wear_snapshot_count_is_refused_up_front():
    with pytest.raises(jw.ModelError, match="wear snapshots; at most 10000"):
        jw.load_model(FOURBAR, ['solver.wear_snapshot_interval="1e-12 s"'])


def test_a_reused_folder_keeps_nothing_of_the_earlier_run(tmp_path):
    out = tmp_path / "out"
    jw.run(FOURBAR, out, overrides=["solver.t_end=0.002"], figures=False)
    assert (out / "wear.csv").is_file() and (out / "ideal" / "summary.json").is_file()
    pendulum = jw.run(EXAMPLES / "pendulum.toml", out, overrides=["solver.t_end=0.01"])
    assert not (out / "wear.csv").exists() and not (out / "impacts.csv").exists()
    assert not (out / "ideal").exists()
    assert not (out / "figures" / "fig8_wear_sectors.png").exists()
    loaded = jw.load_results(out)
    assert loaded.wear.empty and loaded.impacts.empty
    assert loaded.summary == pendulum.summary


def test_an_unfinished_ideal_companion_is_reported_not_saved(tmp_path, monkeypatch):
    real = run_module.simulate

    def interrupt_the_ideal_run(model, **kwargs):
        results = real(model, **kwargs)
        if not model.has_clearance:  # the companion
            results.summary["status"] = "interrupted"
        return results

    monkeypatch.setattr(run_module, "simulate", interrupt_the_ideal_run)
    results = jw.run(FOURBAR, tmp_path / "out", overrides=["solver.t_end=0.002"], figures=False)
    assert results.status == "success"
    assert results.summary["ideal_comparison"] == {"folder": "ideal", "status": "interrupted"}
    assert not (tmp_path / "out" / "ideal").exists()


def test_the_radial_clearance_can_be_given_directly(tmp_path):
    path = "joints.coupler_follower.clearance"
    model = jw.load_model(FOURBAR, [f"{path}.radial_clearance=0.1 mm"])
    c = model.joint("coupler_follower").clearance
    assert c.journal_radius == pytest.approx(9.8e-3, rel=1e-12)  # the file's, kept
    assert c.radial_clearance == pytest.approx(1e-4, rel=1e-9)
    for value, words in (("-1 mm", "must be > 0"), ("3 kg", "has units of mass")):
        with pytest.raises(jw.ModelError, match=words):
            jw.load_model(FOURBAR, [f"{path}.radial_clearance={value}"])
    # A sweep over it: the summary's clearance is the one asked for, case by case.
    swept = jw.sweep(FOURBAR, tmp_path, vary={f"{path}.radial_clearance": ["0.1 mm", "0.3 mm"]},
                     overrides=["solver.t_end=0.004"], workers=1, figures=False)  # fmt: skip
    np.testing.assert_allclose(swept.table["coupler_follower.radial_clearance_m"], [1e-4, 3e-4])
