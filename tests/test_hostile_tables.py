"""Tables, series and CSV files a user may bring that floating point or the reader cannot take:
each is refused with a line naming the field, never a crash or a run that stops later."""

import mechanisms
import numpy as np
import pytest
from runs import EXAMPLES

import jointwear as jw
from jointwear.mechanism.system import build_system


def rotor(torque: object) -> jw.Model:
    return jw.parse_model(mechanisms.rotor(torque, solver={"t_end": 1e-3}))


@pytest.mark.parametrize(
    "torque",
    [
        {"type": "table", "x": [0.0, 1.0, 1e308], "y": [0.0, 1.0, 2.0]},  # slopes overflow
        {"type": "table", "x": [0.0, 1e-300, 1.0], "y": [0.0, 1.0, 2.0]},  # 1 / h overflows
        {"type": "fourier", "period": 1e-308, "cosine": [1.0]},  # 2 pi / period overflows
    ],
)
def test_a_function_whose_coefficients_overflow_is_refused_naming_it(torque):
    with pytest.raises(jw.ModelError, match=r"forces\[0\]\.torque: .*not finite"):
        build_system(rotor(torque))


def test_a_header_cell_with_an_unclosed_bracket_is_refused_not_read_as_si(tmp_path):
    (tmp_path / "curve.csv").write_text("time [ms], torque [kN*m\n0, 1\n1, 2\n")
    with pytest.raises(jw.ModelError, match=r"curve.csv: header cell 'torque \[kN\*m'"):
        rotor({"type": "table", "file": str(tmp_path / "curve.csv")})


def test_points_given_as_an_array_quantity_are_read_in_their_units():
    pint = pytest.importorskip("pint")
    units = pint.UnitRegistry()
    table = jw.TableFunction(
        x=units.Quantity(np.array([0.0, 20.0]), "ms"),
        y=units.Quantity(np.array([1.0, 2.0]), "kN*m"),
    )
    torque = rotor(table).forces[0].torque
    assert torque.x == (0.0, 0.02)
    assert torque.y == (1e3, 2e3)


def test_a_file_given_to_a_saved_table_replaces_its_points_in_the_new_file_s_units(tmp_path):
    (tmp_path / "a.csv").write_text("time [ms], torque [N*m]\n0, 1\n10, 2\n")
    (tmp_path / "b.csv").write_text("time [ms], torque [kN*m]\n0, 3\n20, 4\n")
    saved = rotor({"type": "table", "file": str(tmp_path / "a.csv")})  # holds a.csv's points
    torque = saved.with_values({"forces.0.torque.file": str(tmp_path / "b.csv")}).forces[0].torque
    assert (torque.x, torque.y, torque.source) == ((0.0, 0.02), (3e3, 4e3), str(tmp_path / "b.csv"))


def test_x_unit_and_y_unit_give_the_units_of_a_header_without_brackets(tmp_path):
    (tmp_path / "a.csv").write_text("time, torque\n0, 1\n10, 2\n")
    table = {"type": "table", "file": str(tmp_path / "a.csv"), "x_unit": "ms", "y_unit": "kN*m"}
    torque = rotor(table).forces[0].torque
    assert (torque.x, torque.y) == ((0.0, 0.01), (1e3, 2e3))


def test_a_file_under_set_is_named_relative_to_the_extending_file(tmp_path, monkeypatch):
    (tmp_path / "a.csv").write_text("time [ms], torque [N*m]\n0, 1\n10, 2\n")
    rotor({"type": "table", "file": str(tmp_path / "a.csv")}).to_toml(tmp_path / "base.toml")
    (tmp_path / "variants").mkdir()
    (tmp_path / "variants" / "b.csv").write_text("time [ms], torque [N*m]\n0, 3\n10, 4\n")
    (tmp_path / "variants" / "b.toml").write_text(
        'extends = "../base.toml"\n[set]\n"forces.0.torque.file" = "b.csv"\n'
    )
    monkeypatch.chdir(tmp_path)
    torque = jw.load_model("variants/b.toml").forces[0].torque
    assert torque.y == (3.0, 4.0)


@pytest.mark.parametrize("columns", ["torque", ["time", "torque", "speed"], [0, 1]])
def test_columns_must_name_two_columns(tmp_path, columns):
    (tmp_path / "a.csv").write_text("time, torque, speed\n0, 1, 2\n1, 2, 3\n")
    with pytest.raises(jw.ModelError, match=r"forces\[0\]\.torque: columns: .*two"):
        rotor({"type": "table", "file": str(tmp_path / "a.csv"), "columns": columns})


def test_a_driver_named_time_is_refused_where_a_function_of_time_would_hide_it():
    data = mechanisms.rotor(
        {"type": "table", "argument": "time", "x": ["0 deg", "720 deg"], "y": [0.0, 1.0]},
        solver={"t_end": 1e-3},
    )
    data["drivers"] = [{"name": "time", "type": "angle", "body": "disc",
                        "function": {"type": "constant_speed", "speed": 1.0}}]  # fmt: skip
    with pytest.raises(jw.ModelError, match=r"drivers\[0\]\.name: 'time' .* rename"):
        jw.parse_model(data)


def test_a_unit_in_parentheses_is_refused_not_read_as_si(tmp_path):
    (tmp_path / "curve.csv").write_text("time (ms), torque (kN*m)\n0, 1\n1, 2\n")
    with pytest.raises(jw.ModelError, match=r"curve.csv: header cell 'time \(ms\)'.*'time \[ms\]'"):
        rotor({"type": "table", "file": str(tmp_path / "curve.csv")})


def test_a_header_name_with_words_in_parentheses_is_a_name(tmp_path):
    (tmp_path / "curve.csv").write_text("time (run 2) [ms], torque [N*m]\n0, 1\n1, 2\n")
    assert rotor({"type": "table", "file": str(tmp_path / "curve.csv")}).forces[0].torque.x == (
        0.0,
        1e-3,
    )


def test_a_state_table_left_by_a_constrained_mechanism_is_named_in_the_stop_message():
    """The slider-crank's slider passes 1 m/s within 0.1 ms: the table's NaN stops the run."""
    table = {"type": "table", "argument": "slider_guide.slide_speed", "x": [-1.0, 1.0],
             "y": [0.0, 0.0]}  # fmt: skip
    model = jw.load_model(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.003"])
    force = jw.JointForce(joint="slider_guide", force=table)
    results = jw.simulate(model.with_values({"forces": [*model.forces, force]}))
    assert results.status in ("singular", "non_finite")
    assert "forces[1].force is a table of slider_guide.slide_speed from -1 to 1" in (
        results.message
    )
