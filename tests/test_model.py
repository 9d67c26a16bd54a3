"""Model files: units, schema, cross-references, messages, overrides, round trip."""

import contextlib
import copy
import json
import math
import pickle
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear.kernels.codes import JointKind, Method
from jointwear.model import Model, ModelError, load_model, parse_model
from jointwear.model.functions import Harmonic
from jointwear.model.overrides import apply_overrides
from jointwear.units import to_si

PENDULUM_TOML = """\
name = "pendulum"

[ground.points]
pivot = [0.0, 0.0]

[[bodies]]
name = "rod"
mass = "1 kg"
inertia = "0.0833 kg*m^2"
position = [0.0, "-500 mm"]
angle = "-90 deg"
[bodies.points]
top = ["0.5 m", 0.0]

[[joints]]
name = "hinge"
type = "revolute"
bodies = ["ground", "rod"]
points = ["pivot", "top"]

[[forces]]
type = "gravity"
acceleration = [0.0, "-9.81 m/s^2"]
"""


def pendulum() -> dict:
    """A rod hung from the ground by a revolute joint, under gravity."""
    return {
        "ground": {"points": {"pivot": [0.0, 0.0]}},
        "bodies": [
            {
                "name": "rod",
                "mass": "1 kg",
                "inertia": "0.0833 kg*m^2",
                "position": [0.0, "-500 mm"],
                "angle": "-90 deg",
                "points": {"top": ["0.5 m", 0.0]},
            }
        ],
        "joints": [
            {
                "name": "hinge",
                "type": "revolute",
                "bodies": ["ground", "rod"],
                "points": ["pivot", "top"],
            }
        ],
        "forces": [{"type": "gravity", "acceleration": [0.0, "-9.81 m/s^2"]}],
    }


def problems(data: dict) -> list[str]:
    with pytest.raises(ModelError) as caught:
        parse_model(data)
    return caught.value.problems


# Units ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("value", "dimension", "expected"),
    [
        ("9.8 mm", "[length]", 0.0098),
        ("1500 rpm", "1/[time]", 157.07963267948966),
        ("90 deg", "[]", math.pi / 2),
        ("207 GPa", "[pressure]", 207e9),
        ("0.042 kg*m^2", "[mass] * [length] ** 2", 0.042),
        ("-9.81 m/s^2", "[length] / [time] ** 2", -9.81),
        ("100 rad/s", "1/[time]", 100.0),
        ("5 N*m", "[force] * [length]", 5.0),
        (3, "[mass]", 3.0),
        (0.5, "[]", 0.5),
    ],
)
def test_to_si_converts(value, dimension, expected):
    assert to_si(value, dimension) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("value", "dimension", "message"),
    [
        ("3 m", "[mass]", "mass: '3 m' has units of length; expected a mass, e.g. '3.12 kg'"),
        ("3", "[mass]", "mass: '3' has no unit; expected a mass"),
        ("90", "[]", "mass: '90' has no unit; expected an angle, e.g. '90 deg'"),
        ("50 Hz", "1/[time]", "use rad/s or rpm"),
        ("3 kgg", "[mass]", "'kgg' is not defined"),
        ("2**9**9 m", "[length]", "cannot read '2**9**9 m' as a number and a unit"),
        (True, "[mass]", "True is not a number"),
        (math.inf, "[mass]", "inf is not a finite number"),
    ],
)
def test_to_si_refuses(value, dimension, message):
    with pytest.raises(ValueError, match=r"^mass: ") as caught:
        to_si(value, dimension, "mass")
    assert message in str(caught.value)


# A valid model ----------------------------------------------------------------------------


def test_pendulum_resolves_to_si():
    model = parse_model(pendulum(), name="pendulum")
    rod = model.body("rod")
    assert model.name == "pendulum"
    assert model.body_names == ("rod",)
    assert (rod.mass, rod.inertia, rod.angle) == (1.0, 0.0833, -math.pi / 2)
    assert rod.position == (0.0, -0.5)
    assert model.point("rod", "top") == (0.5, 0.0)
    assert model.point("ground", "pivot") == (0.0, 0.0)
    assert model.joint("hinge").kind is JointKind.REVOLUTE
    assert model.forces[0].acceleration == (0.0, -9.81)
    assert model.solver.method is Method.ABM  # the default integrator
    assert model.solver.t_end == 1.0


def test_load_model_reads_toml_and_names_it_after_the_file(tmp_path):
    path = tmp_path / "swing.toml"
    path.write_text(PENDULUM_TOML.replace('name = "pendulum"\n', ""))
    model = load_model(path, overrides=["solver.t_end=0.5 ms"])
    assert model.name == "swing"
    assert model.solver.t_end == pytest.approx(5e-4)
    assert model == parse_model(pendulum(), name="swing").model_copy(
        update={"solver": model.solver}
    )


def test_round_trip_through_json():
    data = pendulum()
    data["bodies"][0]["points"]["bottom"] = ["-0.5 m", 0.0]
    data["drivers"] = [
        {
            "name": "motor",
            "type": "angle",
            "body": "rod",
            "function": {"type": "constant_speed", "speed": "60 rpm"},
        }
    ]
    data["forces"] += [
        {
            "name": "push",
            "type": "point_force",
            "body": "rod",
            "point": "bottom",
            "force": [{"type": "polynomial", "coefficients": [0, 2]}, "-3 N"],
        },
        {
            "type": "torque",
            "body": "rod",
            "torque": {"type": "harmonic", "amplitude": "5 N*m", "angular_frequency": "10 rad/s"},
        },
        {
            "type": "rotational_spring_damper",
            "bodies": ["ground", "rod"],
            "stiffness": "10 N*m/rad",
            "damping": "0.1 N*m*s/rad",
        },
    ]
    data["events"] = [{"name": "bottom", "body": "rod", "coordinate": "phi", "value": "-90 deg"}]
    data["solver"] = {"integrator": "abm", "max_step": "0.5 ms"}
    model = parse_model(data, name="pendulum")
    assert isinstance(model.forces[2].torque, Harmonic)
    assert model.forces[1].force[1] == -3.0
    saved = json.loads(json.dumps(model.model_dump(mode="json")))
    assert parse_model(saved) == model


# Messages -----------------------------------------------------------------------------------


def _set(path: str, value):
    """A mutation of the pendulum dict: set the item at a Python-style path."""

    def mutate(data):
        *parents, last = path.split("/")
        for key in parents:
            data = data[int(key)] if key.isdigit() else data[key]
        data[int(last) if last.isdigit() else last] = value

    return mutate


def _delete(path: str):
    def mutate(data):
        *parents, last = path.split("/")
        for key in parents:
            data = data[int(key)] if key.isdigit() else data[key]
        del data[last]

    return mutate


@pytest.mark.parametrize(
    ("mutate", "line"),
    [
        (
            _set("joints/0/bodies/1", "rdo"),
            "joints[0].bodies[1]: unknown body 'rdo'; bodies are ground, rod (did you mean 'rod'?)",
        ),
        (
            _set("joints/0/points/1", "tpo"),
            "joints[0].points[1]: unknown point 'tpo'; points of 'rod' are top "
            "(did you mean 'top'?)",
        ),
        (
            _set("bodies/0/mass", "3 m"),
            "bodies[0].mass: '3 m' has units of length; expected a mass, e.g. '3.12 kg'",
        ),
        (_set("bodies/0/mass", "-1 kg"), "bodies[0].mass: got '-1 kg'; must be >= 1e-20"),
        (_delete("bodies/0/inertia"), "bodies[0].inertia: missing required key"),
        (
            _set("bodies/0/mas", 3),
            "bodies[0]: unknown key 'mas'; known keys are name, mass, inertia, position, angle, "
            "velocity, angular_velocity, points (did you mean 'mass'?)",
        ),
        (_set("bodies/0/name", "2rod"), "bodies[0].name: '2rod' is not a valid name"),
        (_set("bodies/0/name", "ground"), "bodies[0].name: 'ground' is reserved"),
        (
            _set("solver", {"integrator": "rk45"}),
            "solver.integrator: unknown integrator 'rk45'; known integrators are dopri5, abm",
        ),
        (
            _set("solver", {"min_step": "1 ms", "initial_step": "1 us"}),
            "solver: min_step 0.001, initial_step 1e-06, max_step 0.001 [s] are out of order",
        ),
        (
            _set("joints/0/type", "revolut"),
            "joints[0].type: unknown type 'revolut'; types are revolute, translational, "
            "pin_in_slot (did you mean 'revolute'?)",
        ),
        (_set("joints/0/bodies", ["rod", "rod"]), "joints[0].bodies: both are 'rod'"),
        (
            _set("forces/0/acceleration", [0.0, -9.81, 0.0]),
            "forces[0].acceleration: has 3 items; expected at most 2",
        ),
        (_set("bodies", []), "bodies: has 0 items; expected at least 1"),
        (
            _set(
                "drivers",
                [
                    {
                        "name": "motor",
                        "type": "angle",
                        "body": "rod",
                        "function": {"type": "constant_speed", "speed": "50 Hz"},
                    }
                ],
            ),
            "drivers[0].function.speed: '50 Hz' is ambiguous",
        ),
        (
            _set(
                "drivers",
                [
                    {
                        "name": "slide",
                        "type": "distance",
                        "joint": "hinge",
                        "function": {"type": "polynomial", "coefficients": [0.0]},
                    }
                ],
            ),
            "drivers[0].joint: 'hinge' is revolute; a distance driver needs an ideal "
            "translational or pin_in_slot joint",
        ),
        (
            _set(
                "forces/0",
                {"type": "torque", "body": "rod", "torque": {"type": "sine", "amplitude": 1.0}},
            ),
            "forces[0].torque.type: unknown type 'sine'; types are polynomial, harmonic",
        ),
        (
            _set("events", [{"name": "low", "body": "rod", "coordinate": "y", "value": "1 deg"}]),
            "events[0].value: '1 deg' has units of angle; expected a length",
        ),
    ],
)
def test_bad_field_gives_one_clear_line(mutate, line):
    data = pendulum()
    mutate(data)
    found = problems(data)
    assert any(problem.startswith(line) for problem in found), found
    assert not any("pydantic" in problem or "http" in problem for problem in found)


def test_duplicate_names_are_reported():
    data = pendulum()
    data["bodies"].append(copy.deepcopy(data["bodies"][0]))
    assert problems(data) == ["bodies[1].name: duplicate name 'rod'; bodies[0] has it already"]


def test_toml_syntax_error_gives_line_and_column(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text(PENDULUM_TOML.replace('mass = "1 kg"', "mass = 1 kg"))
    with pytest.raises(ModelError) as caught:
        load_model(path)
    (line,) = caught.value.problems
    assert line.startswith(f"{path}:8:10: invalid TOML")


def test_missing_file_is_a_model_error(tmp_path):
    with pytest.raises(ModelError, match="cannot read the file"):
        load_model(tmp_path / "nowhere.toml")


def test_model_error_pickles():
    error = ModelError(["a: b; c", "d: e; f"])
    assert pickle.loads(pickle.dumps(error)).problems == error.problems


# Overrides ----------------------------------------------------------------------------------


def test_override_by_name_and_by_index():
    data = apply_overrides(pendulum(), ["bodies.rod.mass=2 kg", "joints.0.points.1=top"])
    assert data["bodies"][0]["mass"] == "2 kg"
    assert parse_model(data).body("rod").mass == 2.0


def test_override_values_are_toml_or_strings():
    data = apply_overrides(
        pendulum(),
        ["solver.t_end=0.5", 'solver.integrator="abm"', "bodies.rod.position=[0.0, -0.4]"],
    )
    assert data["solver"] == {"t_end": 0.5, "integrator": "abm"}
    assert parse_model(data).body("rod").position == (0.0, -0.4)


def test_override_does_not_touch_its_input():
    data = pendulum()
    apply_overrides(data, ["bodies.rod.mass=2"])
    assert data == pendulum()


@pytest.mark.parametrize(
    ("override", "line"),
    [
        (
            "bodies.rdo.mass=2",
            "bodies.rdo: no item 'rdo'; names are rod; indices 0 to 0 (did you mean 'rod'?)",
        ),
        ("joints.3.type=revolute", "joints.3: no item '3'; names are hinge; indices 0 to 0"),
        ("bodies.rod.mass.value=2", "bodies.rod.mass.value: bodies.rod.mass is a value"),
        ("solver.t_end", "--set solver.t_end: expected path=value"),
    ],
)
def test_bad_override_path(override, line):
    with pytest.raises(ModelError) as caught:
        apply_overrides(pendulum(), [override])
    assert caught.value.problems[0].startswith(line)


def test_new_key_from_override_is_judged_by_the_schema():
    data = apply_overrides(pendulum(), ["solver.t_edn=2"])
    assert problems(data)[0].startswith("solver: unknown key 't_edn'")


# Files that extend another -------------------------------------------------------------------

EXAMPLES = Path(__file__).parents[1] / "examples"


@pytest.mark.parametrize(
    ("example", "overrides"),
    [
        ("flores2009_fourbar_johnson", ["normal_law=johnson"]),
        ("flores2009_fourbar_lubricated", ["lubrication=short_bearing", "viscosity=0.01"]),
    ],
)
def test_extending_example_is_its_base_with_the_changes(example, overrides):
    key = "joints.coupler_follower.clearance."
    expected = load_model(EXAMPLES / "flores2009_fourbar.toml", [key + o for o in overrides])
    got = load_model(EXAMPLES / f"{example}.toml")
    assert got.name == example
    assert got.description != expected.description
    assert got.model_dump(exclude={"name", "description"}) == expected.model_dump(
        exclude={"name", "description"}
    )


def write(path, text: str):
    path.write_text(text)
    return path


def test_extends_chains_and_takes_the_name_from_the_file(tmp_path):
    write(tmp_path / "base.toml", PENDULUM_TOML)
    write(tmp_path / "heavy.toml", 'extends = "base.toml"\n[set.bodies.rod]\nmass = "3 kg"\n')
    sub = tmp_path / "sub"
    sub.mkdir()
    write(sub / "short.toml", 'extends = "../heavy.toml"\n[set.solver]\nt_end = 0.25\n')
    model = load_model(sub / "short.toml", ["bodies.rod.inertia=0.1"])
    assert model.name == "short"
    assert model.body("rod").mass == 3.0
    assert model.body("rod").inertia == 0.1  # --set applies after the file's own changes
    assert model.solver.t_end == 0.25


@pytest.mark.parametrize(
    ("files", "line"),
    [
        (
            {"a.toml": 'extends = "b.toml"', "b.toml": 'extends = "a.toml"'},
            "a.toml: extends 'b.toml': ",  # ... b.toml: extends: the files extend each other
        ),
        ({"a.toml": 'extends = "a.toml"'}, "a.toml: extends: the files extend each other"),
        ({"a.toml": 'extends = "missing.toml"'}, "a.toml: extends 'missing.toml': "),
        ({"a.toml": "extends = 3"}, "a.toml: extends: expected the path of a model file"),
        (
            {"a.toml": 'extends = "base.toml"\n[solver]\nt_end = 1.0'},
            "a.toml: solver: a file that extends another may only give extends, unset, set, name",
        ),
        ({"a.toml": "[set.solver]\nt_end = 1.0"}, "a.toml: set: only a file with 'extends'"),
        ({"a.toml": 'unset = ["solver.t_end"]'}, "a.toml: unset: only a file with 'extends'"),
        (
            {"a.toml": 'extends = "base.toml"\nunset = "solver.t_end"'},
            "a.toml: unset: expected an array of dotted paths",
        ),
        (
            {"a.toml": 'extends = "base.toml"\n[set]\nunset = ["solver.t_end"]'},
            "a.toml: set.unset: write the unset array above [set]",
        ),
        (
            {"a.toml": 'extends = "base.toml"\nunset = ["bodies.rod.colour"]'},
            "bodies.rod.colour: no key 'colour' to remove; the keys there are name, mass,",
        ),
        (
            {"a.toml": 'extends = "base.toml"\n[set.bodies.rdo]\nmass = 2.0'},
            "bodies.rdo: no item 'rdo'; names are rod",
        ),
    ],
)
def test_bad_extending_file(tmp_path, files, line):
    write(tmp_path / "base.toml", PENDULUM_TOML)
    for name, text in files.items():
        write(tmp_path / name, text)
    with pytest.raises(ModelError) as caught:
        load_model(tmp_path / "a.toml")
    (problem,) = caught.value.problems
    assert problem.removeprefix(f"{tmp_path}/").startswith(line), problem


# Fuzz ---------------------------------------------------------------------------------------

WORDS = ["rod", "ground", "hinge", "top", "revolute", "translational", "harmonic", "abm"]
WORDS += ["3 kg", "9.8 mm", "90 deg", "1500 rpm", "50 Hz", "-1 N", "1e999 m", "2**9**9 m"]
KEYS = ["name", "type", "mass", "bodies", "points", "function", "speed", "axis", "value"]
LEAVES = (
    st.none()
    | st.booleans()
    | st.integers(-(10**20), 10**20)
    | st.floats()
    | st.text(max_size=12)
    | st.sampled_from(WORDS)
)
VALUES = st.recursive(
    LEAVES,
    lambda inner: (
        st.lists(inner, max_size=3)
        | st.dictionaries(st.sampled_from(KEYS) | st.text(max_size=6), inner, max_size=3)
    ),
    max_leaves=6,
)


def _slots(node) -> list[tuple[object, object]]:
    """Every (container, key) pair inside a nested dict/list structure."""
    keys = range(len(node)) if isinstance(node, list) else node if isinstance(node, dict) else ()
    found = []
    for key in keys:
        found.append((node, key))
        found.extend(_slots(node[key]))
    return found


@settings(max_examples=300, deadline=None)
@given(st.data())
def test_mutated_models_raise_only_model_errors(data):
    model = pendulum()
    model["drivers"] = [
        {
            "name": "motor",
            "type": "angle",
            "body": "rod",
            "function": {"type": "constant_speed", "speed": "1 rad/s"},
        },
    ]
    for _ in range(data.draw(st.integers(1, 4))):
        container, key = data.draw(st.sampled_from(_slots(model)))
        action = data.draw(st.sampled_from(["replace", "delete", "insert"]))
        if action == "replace":
            container[key] = data.draw(VALUES)
        elif action == "delete":
            del container[key]
        elif isinstance(container, dict):
            container[data.draw(st.sampled_from(KEYS) | st.text(max_size=6))] = data.draw(VALUES)
        else:
            container.insert(key, data.draw(VALUES))
    try:
        result = parse_model(model)
    except ModelError as error:
        assert error.problems and all(isinstance(line, str) for line in error.problems)
    else:
        assert isinstance(result, Model)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.text(max_size=30) | st.sampled_from(["bodies.rod.mass=2", "a.b=1"])))
def test_random_overrides_raise_only_model_errors(overrides):
    with contextlib.suppress(ModelError):
        parse_model(apply_overrides(pendulum(), overrides))
