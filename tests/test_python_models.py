"""Models built in Python from the table classes: values, messages, ``to_toml`` round trips,
and the docs page that builds the paper's four-bar."""

import contextlib
import io
import re
import tomllib
from pathlib import Path

import pint
import pytest
from runs import EXAMPLES

import jointwear as jw
import jointwear.model
from jointwear.joints import KINDS
from jointwear.model.tables import Table

DOCS_PAGE = Path(__file__).parents[1] / "docs" / "python-models.md"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
UREG = pint.UnitRegistry()  # the user's own registry, not jointwear's

CLEARANCE = {  # the paper's Table 2
    "bearing_radius": "10.0 mm",
    "journal_radius": "9.8 mm",
    "width": "20.0 mm",
    "restitution_coefficient": 0.9,
    "friction_coefficient": 0.1,
    "youngs_modulus": "207 GPa",
    "poisson_ratio": 0.3,
    "wear_coefficient": "8e-14 1/Pa",
}


def slider_model(**clearance: object) -> jw.Model:
    """A slider on a spring in a guide with clearance, pushed by a harmonic force."""
    return jw.Model(
        name="slider",
        ground=jw.Ground(points={"anchor": (0.0, 0.0), "guide": (UREG.Quantity(5, "cm"), 0.0)}),
        bodies=[
            jw.Body(
                name="block",
                mass=UREG.Quantity(500, "g"),
                inertia="2e-4 kg*m^2",
                position=("50 mm", 0.0),
                angle=0.0,
                points={"centre": (0.0, 0.0)},
            )
        ],
        joints=[
            jw.TranslationalJoint(
                name="guide",
                bodies=("ground", "block"),
                points=("guide", "centre"),
                axis=(3.0, 4.0),  # any length: a direction
                clearance=jw.TranslationalClearance(**clearance),
            )
        ],
        forces=[
            jw.SpringDamper(
                bodies=("ground", "block"),
                points=("anchor", "centre"),
                stiffness="2 kN/m",
                damping=UREG.Quantity(3, "N*s/m"),
                free_length="40 mm",
            ),
            jw.PointForce(
                name="push",
                body="block",
                point="centre",
                force=(jw.Harmonic(amplitude="5 N", angular_frequency="300 rpm"), 0.0),
            ),
            jw.AppliedTorque(body="block", torque=jw.Polynomial(coefficients=(0.0, 0.5))),
        ],
        solver=jw.Solver(t_end=UREG.Quantity(20, "ms"), output_interval="0.5 ms"),
        events=[jw.Event(name="far", body="block", coordinate="x", value="60 mm")],
    )


SLIDER_CLEARANCE = {
    "slider_length": "20 mm",
    "slider_height": "10 mm",
    "gap": UREG.Quantity(50, "um"),
    "width": "10 mm",
    "youngs_modulus": ("207 GPa", "70 GPa"),
    "poisson_ratio": 0.3,
    "corner_radius": "1 mm",
    "restitution_coefficient": 0.5,
    "friction_coefficient": 0.05,
    "dimensionless_wear_coefficient": 1e-4,
    "hardness": "2 GPa",
}


def test_tables_hold_si_values_from_strings_and_quantities():
    model = slider_model(**SLIDER_CLEARANCE)
    block, guide = model.body("block"), model.joint("guide")
    assert block.mass == 0.5  # 500 g
    assert model.ground.points["guide"] == (0.05, 0.0)
    assert guide.axis == pytest.approx((0.6, 0.8), rel=1e-15)
    assert guide.clearance.gap == pytest.approx(5e-5, rel=1e-15)
    assert guide.clearance.moduli == (207e9, 70e9)
    spring, push, _ = model.forces
    assert spring.stiffness == 2000.0 and spring.damping == 3.0
    assert push.force[0].angular_frequency == pytest.approx(10 * 3.141592653589793, rel=1e-15)
    assert model.solver.t_end == pytest.approx(0.02, rel=1e-15)
    assert model.events[0].value == pytest.approx(0.06, rel=1e-15)


def test_a_model_is_a_model_file_that_loads_back_the_same(tmp_path):
    model = slider_model(**SLIDER_CLEARANCE)
    path = model.to_toml(tmp_path / "slider.toml")
    text = path.read_text()
    assert "null" not in text and "None" not in text  # TOML has no null: left out
    assert "\nwear_coefficient =" not in text  # not given: k comes from K and H
    assert "regularisation_speed" not in text  # a key of a friction law not chosen
    assert jw.load_model(path) == model


def test_a_function_is_read_in_the_units_of_where_it_is_given():
    wave = jw.Harmonic(amplitude="5 N*m", angular_frequency="100 rad/s")
    torque = jw.AppliedTorque(body="block", torque=wave)
    assert torque.torque.amplitude == 5.0
    with pytest.raises(jw.ModelError) as caught:
        jw.AngleDriver(name="motor", body="crank", function=wave)
    assert caught.value.problems == [
        "function.amplitude: '5 N*m' has units of torque; expected an angle, e.g. '90 deg'"
    ]


def test_a_table_of_another_kind_is_named_in_the_message():
    revolute = jw.RevoluteClearance(**CLEARANCE)
    with pytest.raises(jw.ModelError) as caught:
        jw.TranslationalJoint(
            name="guide", bodies=("ground", "a"), points=("p", "q"), axis=(1, 0), clearance=revolute
        )
    assert caught.value.problems == [
        "clearance: got a RevoluteClearance; expected a TranslationalClearance (or a table of "
        "its keys)"
    ]


def test_names_between_tables_are_checked():
    body = jw.Body(name="arm", mass=1.0, inertia=0.01, position=(0, 0), angle=0.0)
    pin = jw.RevoluteJoint(name="pin", bodies=("ground", "amr"), points=("o", "top"))
    with pytest.raises(jw.ModelError) as caught:
        jw.Model(name="swing", bodies=[body], joints=[pin])
    assert caught.value.problems[0] == (
        "joints[0].bodies[1]: unknown body 'amr'; bodies are ground, arm (did you mean 'arm'?)"
    )


# The same bad value in a file and in a table built in Python: (path of the table in the
# file, its class, the keys it is built with, the key changed, the bad value as TOML text).
FOURBAR_TABLES = {
    "bodies[0]": (
        jw.Body,
        {"name": "crank", "mass": "3.120 kg", "inertia": "0.042 kg*m^2",
         "position": (0.0, 0.2), "angle": "90 deg",
         "points": {"pivot": (-0.2, 0.0), "tip": (0.2, 0.0)}},
    ),
    "joints[2].clearance": (jw.RevoluteClearance, {**CLEARANCE, "sectors": 36}),
    "solver": (
        jw.Solver,
        {"integrator": "abm", "formulation": "baumgarte", "t_end": 1.0,
         "output_interval": "0.1 ms", "wear_snapshot_interval": "0.2 s"},
    ),
}  # fmt: skip


@pytest.mark.parametrize(
    ("table", "key", "toml"),
    [
        ("bodies[0]", "mass", "-1.0"),
        ("bodies[0]", "mass", '"1.5 m"'),
        ("bodies[0]", "angle", '"90 kg"'),
        ("bodies[0]", "colour", '"red"'),
        ("joints[2].clearance", "width", '"20 N"'),
        ("joints[2].clearance", "friction_law", '"colomb"'),
        ("joints[2].clearance", "journal_radius", '"12 mm"'),
        ("joints[2].clearance", "restitution_coefficient", "1.5"),
        ("joints[2].clearance", "regularisation_speed", '"1 mm/s"'),
        ("solver", "initial_step", '"1 s"'),
        ("solver", "integrator", '"rk4"'),
    ],
)
def test_a_bad_value_gets_the_message_a_file_gets(tmp_path, table, key, toml):
    cls, keys = FOURBAR_TABLES[table]
    value = tomllib.loads(f"v = {toml}")["v"]
    with pytest.raises(jw.ModelError) as in_python:
        cls(**{**keys, key: value})
    path = tmp_path / "bad.toml"
    path.write_text(f'extends = "{FOURBAR}"\n[set]\n"{_dotted(table)}.{key}" = {toml}\n')
    with pytest.raises(jw.ModelError) as in_file:
        jw.load_model(path)
    assert len(in_python.value.problems) == len(in_file.value.problems) == 1
    where, message = in_python.value.problems[0].split(": ", 1)
    # the file names the table by its path; in Python a line about the whole table names its class
    expected = table if where == cls.__name__ else f"{table}.{where}"
    assert in_file.value.problems[0] == f"{expected}: {message}"


def _dotted(table: str) -> str:
    """``joints[2].clearance`` as an override path of the four-bar: items by name."""
    names = {"bodies[0]": "bodies.crank", "joints[2]": "joints.coupler_follower"}
    for item, name in names.items():
        table = table.replace(item, name)
    return table


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_every_example_written_with_to_toml_loads_back_the_same(path, tmp_path):
    model = jw.load_model(path)
    assert jw.load_model(model.to_toml(tmp_path / "written.toml")) == model


def test_every_public_table_documents_each_of_its_keys():
    tables = [getattr(jw, name) for name in jointwear.model.__all__]
    tables = [cls for cls in tables if isinstance(cls, type) and issubclass(cls, Table)]
    assert {jw.Model, jw.Body, jw.PinInSlotClearance, jw.Harmonic} <= set(tables)
    for cls in tables:
        assert getattr(jw, cls.__name__) is cls  # exported from the package too
        text = "".join(base.__doc__ or "" for base in cls.__mro__ if issubclass(base, Table))
        assert "Attributes\n" in text, f"{cls.__name__}: no Attributes section"
        missing = [key for key in cls.model_fields if key != "type" and key not in text]
        assert missing == [], f"{cls.__name__} does not document {missing}"


def test_the_docs_page_builds_the_paper_four_bar(tmp_path, monkeypatch):
    page = DOCS_PAGE.read_text()
    code = "\n".join(re.findall(r"```python\n(.*?)```", page, re.S))
    shown = "".join(re.findall(r"```text\n(.*?)```", page, re.S))
    monkeypatch.chdir(tmp_path)  # the page writes its model file here
    printed = io.StringIO()
    namespace: dict = {}
    with contextlib.redirect_stdout(printed):
        exec(compile(code, str(DOCS_PAGE), "exec"), namespace)
    assert printed.getvalue() == shown  # the messages the page shows are those printed
    model = namespace["model"]
    expected = jw.load_model(FOURBAR)
    assert model.name != expected.name
    assert model == expected.model_copy(update={"name": model.name})
    assert (tmp_path / "fourbar_from_python.toml").is_file()
    by_hardness = namespace["by_hardness"].joint("coupler_follower").clearance
    assert by_hardness.wear_coefficient is None
    assert by_hardness.dimensionless_wear_coefficient / by_hardness.hardness == pytest.approx(
        8e-14, rel=1e-15
    )


def test_every_joint_type_is_public_with_its_clearance_table():
    for kind in KINDS:
        clearance = kind.schema.model_fields["clearance"].annotation.__args__[0]
        assert getattr(jw, kind.schema.__name__) is kind.schema
        assert getattr(jw, clearance.__name__) is clearance
