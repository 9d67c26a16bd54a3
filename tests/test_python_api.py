"""The model side of the Python API: models built in Python, pint Quantities, changed values,
and studies of a model object."""

import json

import pint
import pytest
from runs import EXAMPLES

import jointwear as jw

FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
UREG = pint.UnitRegistry()  # the user's own registry, not jointwear's


def pendulum_data(mass: object) -> dict:
    return {
        "name": "swing",
        "ground": {"points": {"pivot": [0.0, 0.0]}},
        "bodies": [
            {
                "name": "arm",
                "mass": mass,
                "inertia": "0.01 kg m^2",
                "position": [0.25, 0.0],
                "angle": 0.0,
                "points": {"top": ["-250 mm", 0.0]},
            }
        ],
        "joints": [
            {
                "name": "pin",
                "type": "revolute",
                "bodies": ["ground", "arm"],
                "points": ["pivot", "top"],
            }
        ],
        "forces": [{"type": "gravity", "acceleration": [0.0, -9.81]}],
        "solver": {"t_end": UREG.Quantity(20, "ms")},
    }


def test_a_model_built_in_python_takes_pint_quantities():
    model = jw.parse_model(pendulum_data(UREG.Quantity(1500, "g")))
    assert model.body("arm").mass == 1.5
    assert model.body("arm").points["top"] == (-0.25, 0.0)
    assert model.solver.t_end == pytest.approx(0.02, rel=1e-15)
    assert jw.simulate(model).status == "success"


@pytest.mark.parametrize(
    ("value", "words"),
    [
        (UREG.Quantity(1.5, "m"), "has units of length; expected a mass"),
        (UREG.Quantity([1.0, 2.0], "kg"), "is not one number; expected a mass"),
        (-1.0, r"bodies\[0\]\.mass: got -1.0"),
    ],
)
def test_a_python_model_is_checked_as_a_file_is(value, words, tmp_path):
    with pytest.raises(jw.ModelError, match=words) as from_python:
        jw.parse_model(pendulum_data(value))
    if not hasattr(value, "units"):  # the same lines as the same value in a model file
        text = FOURBAR.read_text().replace('mass = "3.120 kg"', f"mass = {value}", 1)
        assert text != FOURBAR.read_text()
        path = tmp_path / "fourbar.toml"
        path.write_text(text)
        with pytest.raises(jw.ModelError) as from_file:
            jw.load_model(path)
        assert str(from_python.value).splitlines()[0] in str(from_file.value).splitlines()


def test_with_values_changes_values_without_override_strings():
    model = jw.load_model(FOURBAR)
    changed = model.with_values(
        {
            "bodies.crank.mass": UREG.Quantity(3, "kg"),
            "joints.coupler_follower.clearance.wear_coefficient": 8e-17,
            "drivers.motor.function.speed": UREG.Quantity(5000, "rpm"),
            "solver.t_end": "50 ms",
        }
    )
    assert changed.body("crank").mass == 3.0
    assert changed.joint("coupler_follower").clearance.wear_coefficient == 8e-17
    assert changed.drivers[0].function.speed == pytest.approx(5000 * 2 * 3.141592653589793 / 60)
    assert changed.solver.t_end == pytest.approx(0.05)
    assert model.body("crank").mass != 3.0  # the original is left as it was
    assert changed.name == model.name
    # The same as --set gives:
    assert jw.load_model(FOURBAR, ["bodies.crank.mass=3 kg"]).body("crank") == changed.body("crank")
    with pytest.raises(jw.ModelError, match="did you mean 'mass'"):
        model.with_values({"bodies.crank.mas": 1.0})
    with pytest.raises(jw.ModelError, match="no item 'crnk'"):
        model.with_values({"bodies.crnk.mass": 1.0})


def test_load_model_applies_overrides_to_a_model_object():
    model = jw.load_model(FOURBAR)
    assert jw.load_model(model) is model
    assert jw.load_model(model, ["solver.t_end=0.5"]).solver.t_end == 0.5


def test_sweep_and_life_take_a_model_object(tmp_path):
    model = jw.load_model(FOURBAR).with_values({"solver.t_end": "4 ms"})
    swept = jw.sweep(model, tmp_path / "sweep", vary={"bodies.crank.mass": [1.0, 2.0]}, workers=1)
    assert list(swept.table["status"]) == ["success", "success"]
    saved = json.loads((tmp_path / "sweep" / "model.json").read_text())
    assert jw.parse_model(saved) == model
    life = jw.life(model, tmp_path / "life", cycles=2, figures=False)
    assert life.summary["cycles_reached"] == 2
