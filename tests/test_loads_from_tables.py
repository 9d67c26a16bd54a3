"""Loads as users bring them, through whole runs: a table or a series gives the same motion as
the same load written as a polynomial or a harmonic; a load of the crank angle the same as of
time; a piston's pressure load does its p-V work; a motor's torque-speed curve sets the crank's
mean speed."""

import itertools
import math

import numpy as np
import pytest
from mechanisms import rotor
from runs import EXAMPLES
from scipy.integrate import quad, trapezoid

import jointwear as jw
from jointwear.engine.state_tables import _state_value
from jointwear.model.arguments import resolve

RUN = {"t_end": 0.4, "rtol": 1e-10, "atol": 1e-12, "output_interval": 0.01}


def motion(*torques: object) -> np.ndarray:
    """The rotor's angle and angular speed under ``torques`` [rad, rad/s], row by row."""
    results = jw.simulate(jw.parse_model(rotor(*torques, solver=RUN)))
    assert results.status == "success", results.message
    return results.timeseries[["phi_disc", "omega_disc"]].to_numpy()


def test_a_cubic_table_of_a_cubic_polynomial_moves_the_rotor_alike():
    """A not-a-knot cubic spline reproduces a cubic exactly: the runs agree to round-off."""
    coefficients = [0.2, 3.0, -1.5, 0.4]
    t = np.linspace(0.0, RUN["t_end"], 9)
    spline = {"type": "table", "x": list(t), "y": list(np.polyval(coefficients[::-1], t)),
              "interpolation": "cubic"}  # fmt: skip
    polynomial = {"type": "polynomial", "coefficients": coefficients}
    assert np.allclose(motion(spline), motion(polynomial), rtol=1e-12, atol=1e-12)


def test_a_fourier_series_of_one_harmonic_moves_the_rotor_as_the_harmonic():
    offset, amplitude, omega, phase = 0.1, 0.5, 40.0, 0.7
    harmonic = {"type": "harmonic", "offset": offset, "amplitude": amplitude,
                "angular_frequency": omega, "phase": phase}  # fmt: skip
    series = {"type": "fourier", "period": 2.0 * math.pi / omega, "mean": offset,
              "cosine": [amplitude * math.sin(phase)],
              "sine": [amplitude * math.cos(phase)]}  # fmt: skip
    assert np.allclose(motion(series), motion(harmonic), rtol=1e-12, atol=1e-12)


def test_a_motor_curve_brings_the_rotor_to_its_balance_speed_as_the_closed_form():
    """T(w) = T0 (1 - w / w0) against a load T_L from rest: w = w* (1 - exp(-t / tau)),
    w* = w0 (1 - T_L / T0), tau = I w0 / T0."""
    t0, w0, load, inertia = 2.0, 100.0, 0.5, 0.01
    motor = {"type": "table", "argument": "disc.angular_speed", "x": ["0 rad/s", "100 rad/s"],
             "y": [t0, 0.0], "interpolation": "linear"}  # fmt: skip
    omega = motion(motor, -load)[:, 1]
    t = np.arange(omega.size) * RUN["output_interval"]
    tau = inertia * w0 / t0
    expected = w0 * (1.0 - load / t0) * (1.0 - np.exp(-t / tau))
    assert np.max(np.abs(omega - expected)) < 1e-7 * w0


def slider_crank(pressure: dict, **solver) -> jw.Model:
    """The ideal slider-crank example at 3000 rpm with a gas pressure on its piston (50 cm^2)."""
    model = jw.load_model(EXAMPLES / "slider_crank.toml")
    data = model.model_dump(mode="json")
    data["drivers"][0]["function"]["speed"] = "3000 rpm"
    data["forces"].append({"type": "joint_pressure", "name": "gas", "joint": "slider_guide",
                           "area": "50 cm^2", "pressure": pressure})  # fmt: skip
    data["solver"] |= {"rtol": 1e-10, "atol": 1e-12, **solver}
    return jw.parse_model(data)


ANGLES = [0.0, 30.0, 170.0, 190.0, 350.0, 370.0, 400.0, 500.0, 600.0]  # [deg]
PRESSURES = [1.0, 1.2, 20.0, 60.0, 40.0, 8.0, 3.0, 1.1, 0.9]  # [bar]
OMEGA = 3000.0 * math.pi / 30.0  # [rad/s]
CYCLE = 4.0 * math.pi / OMEGA  # two crank turns [s]


def test_a_table_of_the_crank_angle_loads_the_piston_as_the_same_table_of_time():
    of_angle = {"type": "table", "argument": "motor", "x": ANGLES, "x_unit": "deg",
                "y": PRESSURES, "y_unit": "bar", "period": "720 deg"}  # fmt: skip
    of_time = of_angle | {"argument": "time", "x": [math.radians(a) / OMEGA for a in ANGLES],
                          "x_unit": None, "period": CYCLE}  # fmt: skip
    runs = [jw.simulate(slider_crank(p, t_end=0.01)) for p in (of_angle, of_time)]
    columns = ["x_slider", "torque_motor", "load_gas_force"]
    first, second = (r.timeseries[columns].to_numpy() for r in runs)
    assert np.allclose(first, second, rtol=1e-9, atol=1e-9 * np.abs(first).max(axis=0))
    assert np.abs(first[:, 2]).max() > 20e5 * 50e-4  # the load was applied


def test_the_pressure_load_does_its_p_v_work_over_a_cycle():
    """W = integral of p dV, V = A s(theta), s = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)) for
    the crank r = 50 mm and rod l = 120 mm; the run's force times the piston's speed."""
    area, r, rod = 50e-4, 0.05, 0.12
    pressure = {"type": "table", "argument": "motor", "x": ANGLES, "x_unit": "deg",
                "y": PRESSURES, "y_unit": "bar", "period": "720 deg",
                "interpolation": "linear"}  # fmt: skip
    run = jw.simulate(slider_crank(pressure, t_end=CYCLE, output_interval=CYCLE / 20000))
    assert run.status == "success", run.message
    rows = run.timeseries
    simulated = trapezoid(rows["load_gas_force"] * rows["vx_slider"], rows["time"])

    nodes = np.radians([*ANGLES, 720.0])
    values = np.array([*PRESSURES, PRESSURES[0]]) * 1e5

    def integrand(theta: float) -> float:
        slide_rate = -r * math.sin(theta) - r * r * math.sin(theta) * math.cos(theta) / math.sqrt(
            rod * rod - (r * math.sin(theta)) ** 2
        )
        return np.interp(theta, nodes, values) * area * slide_rate

    expected = sum(quad(integrand, a, b, epsabs=0.0, epsrel=1e-12)[0]
                   for a, b in itertools.pairwise(nodes))  # fmt: skip
    assert abs(expected) > 100.0  # [J] a cycle that does work
    assert simulated == pytest.approx(expected, rel=1e-6)


def test_a_motor_driven_crank_turns_at_the_torque_speed_balance_on_the_crank_angle_average():
    """Over a turn of the periodic state the kinetic and potential energies come back, so the
    motor's and the load's work cancel: for T(w) = T0 (1 - w / w0) and a load torque T_L, the
    crank speed averaged over the crank angle is w0 (1 - T_L / T0), however much it fluctuates."""
    t0, w0, load = 200.0, 200.0, 100.0
    model = jw.load_model(EXAMPLES / "slider_crank.toml")
    data = model.model_dump(mode="json")
    data["drivers"] = []
    data["bodies"][0] |= {"inertia": 0.01, "angular_velocity": 100.0}  # a small flywheel
    motor = {"type": "table", "argument": "crank.angular_speed", "x": [0.0, 400.0],
             "y": [t0, -t0], "interpolation": "linear"}  # fmt: skip
    data["forces"] += [
        {"type": "torque", "name": "motor", "body": "crank", "torque": motor},
        {"type": "torque", "name": "brake", "body": "crank", "torque": -load},
    ]
    data["solver"] |= {"t_end": 1.0, "rtol": 1e-10, "atol": 1e-12, "output_interval": 1e-5}
    run = jw.simulate(jw.parse_model(data))
    assert run.status == "success", run.message
    rows = run.timeseries
    phi, omega, t = rows["phi_crank"], rows["omega_crank"], rows["time"]
    last = phi >= phi.iloc[-1] - 2.0 * math.pi  # the last whole turn (tau = 0.01 s, long gone)
    average = trapezoid(omega[last] ** 2, t[last]) / trapezoid(omega[last], t[last])
    assert omega[last].max() - omega[last].min() > 1.0  # [rad/s] the speed fluctuates
    assert average == pytest.approx(w0 * (1.0 - load / t0), rel=1e-5)


def test_a_state_table_left_during_the_run_stops_it_naming_the_table():
    spring = {"type": "table", "argument": "disc.angle", "x": [-1.0, 1.0], "y": [1.0, 1.0]}
    results = jw.simulate(jw.parse_model(rotor(spring, solver={"t_end": 2.0})))
    assert results.status == "non_finite"
    last = results.timeseries["phi_disc"].iloc[-1]
    assert 0.9 < last <= 1.0  # a constant torque of 1 N m turns it to the table's end
    assert "forces[0].torque is a table of disc.angle from -1 to 1 (SI) without a period" in (
        results.message
    )


def test_the_slide_a_stopped_run_reports_is_the_slider_s_position_and_speed():
    """The slider-crank's guide runs along x through the origin: its slide is the slider's x."""
    model = jw.load_model(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.003"])
    results = jw.simulate(model)
    y, last = results.final.y, results.timeseries.iloc[-1]
    slide, speed = (
        _state_value(model, resolve(f"slider_guide.{q}", model.drivers, model.bodies,
                                    model.joints), y[:9], y[9:])
        for q in ("slide", "slide_speed")
    )  # fmt: skip
    # the last row is the integrator's dense output at t_end, the state its step's end
    assert slide == pytest.approx(last["x_slider"], rel=1e-8)
    assert speed == pytest.approx(last["vx_slider"], rel=1e-8)


def test_a_cam_table_of_the_crank_angle_drives_a_slider_with_the_chain_rule():
    """A distance driver whose table is of an angle driver's value: s(theta(t)), with
    s' theta' and s'' theta'^2 as its speed and acceleration. A not-a-knot cubic spline of a
    cubic is that cubic, so the closed form holds to round-off."""
    coefficients = [0.01, 0.002, -0.0003, 0.00001]  # s(theta) [m], theta [rad]
    omega, theta = 10.0, np.linspace(0.0, 5.0, 11)
    lift = {"type": "table", "argument": "crank", "x": list(theta),
            "y": list(np.polyval(coefficients[::-1], theta)), "interpolation": "cubic"}  # fmt: skip
    data = rotor(0.0, solver={"t_end": 0.4, "output_interval": 0.01})
    data["ground"]["points"]["rail"] = [0.0, 1.0]
    data["bodies"].append({"name": "slider", "mass": 0.5, "inertia": 1e-4, "angle": 0.0,
                           "position": [0.01, 1.0], "points": {"c": [0.0, 0.0]}})  # fmt: skip
    data["joints"].append({"name": "rail", "type": "translational", "bodies": ["ground", "slider"],
                           "points": ["rail", "c"], "axis": [1.0, 0.0]})  # fmt: skip
    data["drivers"] = [
        {"name": "crank", "type": "angle", "body": "disc",
         "function": {"type": "constant_speed", "speed": omega, "initial": 0.0}},
        {"name": "lift", "type": "distance", "joint": "rail", "function": lift},
    ]  # fmt: skip
    results = jw.simulate(jw.parse_model(data))
    assert results.status == "success", results.message
    rows = results.timeseries
    angle = omega * rows["time"].to_numpy()
    poly = np.polynomial.Polynomial(coefficients)
    assert np.allclose(rows["x_slider"], poly(angle), rtol=0, atol=1e-12)
    assert np.allclose(rows["vx_slider"], poly.deriv()(angle) * omega, rtol=0, atol=1e-10)
    assert np.allclose(rows["ax_slider"], poly.deriv(2)(angle) * omega**2, rtol=0, atol=1e-8)
