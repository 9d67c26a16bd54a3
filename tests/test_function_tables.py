"""Tables and Fourier series as functions: the kernel's values against scipy and numpy, and the
model file's checks of points, periods, arguments, units and CSV files."""

import math

import mechanisms
import numpy as np
import pytest
from scipy.interpolate import CubicSpline, PchipInterpolator

import jointwear as jw
from jointwear.kernels.functions import evaluate
from jointwear.mechanism.system import build_system

RNG = np.random.default_rng(7)
X = np.concatenate([[0.0], np.cumsum(RNG.uniform(0.2, 1.0, 11))])  # uneven spacing [s]
Y = RNG.normal(0.0, 3.0, 12)  # [N m]
PERIOD = X[-1] - X[0] + 0.6  # the table's last point is not its first one period on


def rotor(torque: object, **solver) -> dict:
    """A disc on a pin loaded by ``torque`` (a model-file value), up to the table's end."""
    return mechanisms.rotor(torque, solver={"t_end": float(X[-1]), **solver})


def kernel_function(torque: dict):
    """f, f', f'' of the torque's row as the compiled loop evaluates them."""
    mech = build_system(jw.parse_model(rotor(torque))).mechanism
    k = mech.force_function[0, 0]

    def f(x: float) -> np.ndarray:
        kind, param = mech.function_kind[k], mech.function_param[k]
        return np.array(evaluate(kind, param, mech.function_data, x))

    return f


def table(interpolation: str, periodic: bool) -> dict:
    spec = {"type": "table", "x": list(X), "y": list(Y), "interpolation": interpolation}
    return spec | ({"period": PERIOD} if periodic else {})


def closed() -> tuple[np.ndarray, np.ndarray]:
    return np.append(X, X[0] + PERIOD), np.append(Y, Y[0])


INSIDE = np.linspace(X[0], X[-1], 997)


def test_linear_table_is_numpy_interp():
    f = kernel_function(table("linear", False))
    values = np.array([f(x) for x in INSIDE])
    assert np.allclose(values[:, 0], np.interp(INSIDE, X, Y), rtol=0, atol=1e-12)
    assert np.all(values[:, 2] == 0.0)


@pytest.mark.parametrize(
    ("interpolation", "reference"),
    [("cubic", CubicSpline(X, Y)), ("pchip", PchipInterpolator(X, Y))],
)
def test_cubic_and_pchip_tables_are_scipys(interpolation, reference):
    f = kernel_function(table(interpolation, False))
    values = np.array([f(x) for x in INSIDE])
    for order in range(3):
        expected = reference(INSIDE, order)
        assert np.allclose(values[:, order], expected, rtol=0, atol=1e-9 * np.abs(expected).max())


def test_periodic_cubic_table_is_scipys_periodic_spline_in_every_period():
    xc, yc = closed()
    reference = CubicSpline(xc, yc, bc_type="periodic")
    f = kernel_function(table("cubic", True))
    for shift in (-2, 0, 3):
        values = np.array([f(x + shift * PERIOD) for x in INSIDE])
        for order in range(3):
            expected = reference(INSIDE, order)
            scale = np.abs(expected).max()
            assert np.allclose(values[:, order], expected, rtol=0, atol=1e-9 * scale)


def test_periodic_pchip_table_is_pchip_of_the_repeated_table():
    """Pchip is local (a node's slope from its neighbours): three periods of points give the
    periodic interpolant exactly in the middle one."""
    end = closed()[0][-1]
    repeated_x = np.concatenate([X - PERIOD, X, X + PERIOD])
    reference = PchipInterpolator(repeated_x, np.tile(Y, 3))
    f = kernel_function(table("pchip", True))
    inside = np.linspace(X[0], end, 997)
    for shift in (-1, 0, 4):
        values = np.array([f(x + shift * PERIOD) for x in inside])
        for order in range(2):
            expected = reference(inside, order)
            scale = np.abs(expected).max()
            assert np.allclose(values[:, order], expected, rtol=0, atol=1e-9 * scale)


def test_table_without_period_is_nan_outside_its_points():
    f = kernel_function(table("pchip", False))
    assert np.all(np.isnan(f(X[0] - 1e-9))) and np.all(np.isnan(f(X[-1] + 1e-9)))
    assert np.allclose(f(X[-1])[0], Y[-1], rtol=1e-12)


def test_fourier_series_is_its_sum():
    cosine, sine, period, mean = [1.5, -0.2, 0.05], [0.3, 0.7], 0.37, 2.0
    f = kernel_function(
        {"type": "fourier", "period": period, "mean": mean, "cosine": cosine, "sine": sine}
    )
    t = np.linspace(-1.0, 2.0, 301)
    w = 2.0 * math.pi / period
    k = np.arange(1, 4)[:, None]
    a = np.array(cosine)[:, None]
    b = np.array([*sine, 0.0])[:, None]
    series = mean + (a * np.cos(k * w * t) + b * np.sin(k * w * t)).sum(axis=0)
    rate = (k * w * (b * np.cos(k * w * t) - a * np.sin(k * w * t))).sum(axis=0)
    curvature = -((k * w) ** 2 * (a * np.cos(k * w * t) + b * np.sin(k * w * t))).sum(axis=0)
    values = np.array([f(x) for x in t])
    assert np.allclose(values[:, 0], series, rtol=0, atol=1e-12)
    assert np.allclose(values[:, 1], rate, rtol=0, atol=1e-10)
    assert np.allclose(values[:, 2], curvature, rtol=0, atol=1e-8)


# The model file's checks ---------------------------------------------------------------------


def problems(torque: object, **solver) -> str:
    with pytest.raises(jw.ModelError) as error:
        jw.parse_model(rotor(torque, **solver))
    return str(error.value)


def test_points_in_units_and_in_si_are_the_same_table():
    in_units = {"type": "table", "x": [0, 0.5, 1.0], "x_unit": "ms", "y": ["1 N*m", 2, 3],
                "y_unit": "N*cm"}  # fmt: skip
    model = jw.parse_model(rotor(in_units))
    assert model.forces[0].torque.x == pytest.approx((0.0, 5e-4, 1e-3), rel=1e-15)
    assert model.forces[0].torque.y == pytest.approx((1.0, 0.02, 0.03), rel=1e-15)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"x": [0, 2, 1]}, "x[2] = 1 does not follow x[1] = 2"),
        ({"y": [1, 2]}, "x has 3 points and y 2"),
        ({"x": ["0 s", "1 deg", "2 s"]}, "units of different kinds"),
        ({"x": ["0 deg", "1 deg", "2 deg"]}, "units of angle; expected a time"),
        ({"period": 1.5}, "more than the period 1.5"),
        ({"period": 2.0, "y": [1, 2, 3]}, "y ends at 3 and starts at 1"),
        ({"interpolation": "spline"}, "expected 'linear', 'cubic' or 'pchip'"),
        ({"argument": "disk.angular_speed"}, "no body 'disk' with angular speed"),
        ({"argument": "crank"}, "unknown argument 'crank'"),
    ],
)
def test_bad_tables_are_refused_with_what_is_allowed(change, message):
    spec = {"type": "table", "x": [0, 1, 2], "y": [1, 2, 1]} | change
    assert message in problems(spec)


def test_a_table_the_run_outlives_is_refused_before_the_run():
    model = jw.parse_model(rotor({"type": "table", "x": [0, 0.5], "y": [1, 2]}))
    with pytest.raises(jw.ModelError, match=r"forces\[0\].torque: its points cover time from 0"):
        build_system(model)


def test_driver_tables_are_of_time_or_of_another_driver_and_smooth():
    data = rotor(0.0)
    data["drivers"] = [
        {"name": "spin", "type": "angle", "body": "disc",
         "function": {"type": "table", "x": [0, 1, 2], "y": [0, 1, 0], "period": 2.0,
                      "interpolation": "linear", "argument": "disc.angle"}},
    ]  # fmt: skip
    with pytest.raises(jw.ModelError) as error:
        jw.parse_model(data)
    assert "drivers[0].function.argument: 'disc.angle' is of the mechanism's state" in str(
        error.value
    )
    assert "drivers[0].function.interpolation: 'linear' gives a driver a speed" in str(error.value)


def test_a_load_of_a_720_degree_table_of_the_crank_repeats_every_two_turns():
    data = rotor({"type": "table", "argument": "spin", "x": [0, 90, 400], "x_unit": "deg",
                  "y": [0, 1, 2], "period": "720 deg"})  # fmt: skip
    data["drivers"] = [{"name": "spin", "type": "angle", "body": "disc",
                        "function": {"type": "constant_speed", "speed": "3000 rpm"}}]  # fmt: skip
    assert jw.parse_model(data).cycle == pytest.approx(0.04, rel=1e-12)


def test_points_are_read_from_a_csv_file_beside_the_model(tmp_path):
    (tmp_path / "curve.csv").write_text(
        "# measured\ntime [ms], other, torque [N*cm]\n0, 9, 100\n0.5, 9, 200\n1, 9, 150\n"
    )
    (tmp_path / "rotor.toml").write_text(
        '[ground.points]\no = [0, 0]\n[[bodies]]\nname = "disc"\nmass = 1\ninertia = 0.01\n'
        'position = [0, 0]\nangle = 0\npoints = { c = [0, 0] }\n[[forces]]\ntype = "torque"\n'
        'body = "disc"\ntorque = { type = "table", file = "curve.csv", '
        'columns = ["time", "torque"] }\n[solver]\nt_end = 0.001\n'
    )
    torque = jw.load_model(tmp_path / "rotor.toml").forces[0].torque
    assert torque.x == pytest.approx((0.0, 5e-4, 1e-3), rel=1e-15)
    assert torque.y == pytest.approx((1.0, 2.0, 1.5), rel=1e-15)
    assert torque.source == str(tmp_path / "curve.csv")
    (tmp_path / "curve.csv").write_text("time [s], torque [N*m]\n0, 1\n0.5, two\n")
    with pytest.raises(jw.ModelError, match=r"curve.csv, row 3, column 'torque': 'two' is not"):
        jw.load_model(tmp_path / "rotor.toml")


@pytest.mark.parametrize("separator", [";", "\t"])
def test_a_spreadsheet_s_semicolons_or_tabs_separate_the_cells(tmp_path, separator):
    path = tmp_path / "curve.csv"
    path.write_text(f"time [ms]{separator}torque [N*cm]\n0{separator}100\n1{separator}150\n")
    spec = {"type": "table", "file": str(path)}
    torque = jw.parse_model(rotor(spec, t_end=0.001)).forces[0].torque
    assert torque.x == pytest.approx((0.0, 1e-3)) and torque.y == pytest.approx((1.0, 1.5))


def test_a_table_built_in_python_has_its_units_checked_where_it_is_used():
    model = jw.parse_model(rotor(0.0))
    degrees = jw.TableFunction(x=["0 deg", "90 deg"], y=[1.0, 2.0])  # for a time argument
    with pytest.raises(jw.ModelError, match=r"forces\[0\].torque.x: '0 deg' has units of angle"):
        jw.Model(name="rotor", ground=model.ground, bodies=model.bodies, joints=model.joints,
                 forces=[jw.AppliedTorque(body="disc", torque=degrees)])  # fmt: skip
