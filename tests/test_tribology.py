"""The tribologist's time series of a revolute clearance joint (``results.tribology``).

Checked against what does not come from them: the Hertz line contact in closed form, and the
friction energy and sliding distance the compiled loop sums step by step.
"""

import math

import numpy as np
import pytest
from runs import CLEARANCE_COLUMNS, EXAMPLES, simulate_ok

import jointwear as jw
from jointwear.results.column_units import column_unit
from jointwear.results.energy_balance import energy_balance, unaccounted

JOINT = "rod_slider"
ENGINE = EXAMPLES / "slider_crank_clearance.toml"


@pytest.fixture(scope="module")
def engine():
    # Rows every 10 us: the integrals below are trapezoids over the rows.
    return simulate_ok(ENGINE, ["solver.t_end=0.024", "solver.output_interval=1e-5"])


def test_the_columns_follow_the_joints_own_with_their_units(engine):
    columns = list(engine.timeseries.columns)
    start = columns.index(f"{JOINT}_fx")
    assert columns[start : start + len(CLEARANCE_COLUMNS)] == [
        f"{JOINT}_{c}" for c in CLEARANCE_COLUMNS
    ]
    units = [column_unit(c, engine.model) for c in columns[start + 7 : start + 17]]
    assert units == ["m/s", "rad", "rad", "m/s", "N", "Pa", "Pa", "Pa m/s", "W", "W"]


def test_pressure_is_the_hertz_line_contact_of_the_normal_force(engine):
    c = engine.model.joint(JOINT).clearance
    df = engine.timeseries
    force = df[f"{JOINT}_fn"].to_numpy()
    loaded = force > 0.0
    assert loaded.sum() > 100
    # Johnson (1985) sec. 4.2, from the radii and moduli of the model file:
    r_star = c.bearing_radius * c.journal_radius / (c.bearing_radius - c.journal_radius)
    (e_b, e_j), (nu_b, nu_j) = c.moduli, c.poisson_ratios
    e_star = 1.0 / ((1.0 - nu_b**2) / e_b + (1.0 - nu_j**2) / e_j)
    b = np.sqrt(4.0 * force[loaded] * r_star / (math.pi * c.width * e_star))
    p_max = df[f"{JOINT}_p_max"].to_numpy()[loaded]
    np.testing.assert_allclose(p_max, 2.0 * force[loaded] / (math.pi * b * c.width), rtol=1e-12)
    p_mean = df[f"{JOINT}_p_mean"].to_numpy()
    np.testing.assert_allclose(p_mean[loaded], math.pi / 4.0 * p_max, rtol=1e-12)
    assert not p_mean[~loaded].any() and not df[f"{JOINT}_pv"].to_numpy()[~loaded].any()
    speed = np.abs(df[f"{JOINT}_vt"].to_numpy())
    np.testing.assert_allclose(df[f"{JOINT}_pv"], p_mean * speed, rtol=1e-12)


def test_friction_power_and_sliding_speed_integrate_to_the_loops_totals(engine):
    """The loop sums friction energy and sliding distance over its steps' midpoints; the rows
    sample the same motion every 10 us. Impacts last tens of microseconds, so the two sums
    agree to about a percent, not to rounding: 3 % is asked."""
    df = engine.timeseries
    whole = engine.summary["clearance_joints"][JOINT]["whole_run"]
    time = df["time"].to_numpy()
    energy = np.trapezoid(df[f"{JOINT}_friction_power"].to_numpy(), time)
    assert energy == pytest.approx(whole["energy_dissipated_friction_j"], rel=0.03)
    in_contact = df[f"{JOINT}_fn"].to_numpy() > 0.0
    sliding = np.trapezoid(np.abs(df[f"{JOINT}_vt"].to_numpy()) * in_contact, time)
    assert sliding == pytest.approx(whole["sliding_distance_m"], rel=0.03)
    damping = np.trapezoid(df[f"{JOINT}_damping_power"].to_numpy(), time)
    assert damping == pytest.approx(whole["energy_dissipated_damping_j"], rel=0.03)


def test_contact_angles_are_the_eccentricity_in_each_bodys_frame(engine):
    df = engine.timeseries
    joint = engine.model.joint(JOINT)
    # Along the line of centres; a centred journal (the first rows) takes its velocity's.
    off_centre = np.hypot(df[f"{JOINT}_ex"], df[f"{JOINT}_ey"]) > 1e-3 * 5e-4
    assert off_centre.mean() > 0.9
    df = df[off_centre]
    direction = np.arctan2(df[f"{JOINT}_ey"], df[f"{JOINT}_ex"])
    for surface, body in (("bearing", joint.bodies[0]), ("journal", joint.bodies[1])):
        expected = direction - df[f"phi_{body}"]
        got = df[f"{JOINT}_theta_{surface}"]
        gap = np.angle(np.exp(1j * (got - expected)))  # wrapped to (-pi, pi]
        assert np.abs(gap).max() < 1e-9, surface


def _balance(path, t_end: float, interval: float, joint: str):
    """A run's largest |balance| [J], its energy flows, and what the loop says ``joint``
    dissipated over the whole run [J], with rows every ``interval`` [s]."""
    res = simulate_ok(path, [f"solver.t_end={t_end}", f"solver.output_interval={interval}"])
    assert unaccounted(res.model) is None
    flows = energy_balance(res.model, res.timeseries)
    totals = res.summary["clearance_joints"][joint]
    totals = totals.get("whole_run", totals)  # a run without settling has its figures only
    dissipated = totals["energy_dissipated_damping_j"] + totals["energy_dissipated_friction_j"]
    return np.abs(flows["balance"]).max(), flows, dissipated


def test_the_energy_balance_closes_as_the_rows_get_finer():
    """Energy conservation: stored + dissipated - driver work stays constant. The rows carry
    the powers, integrated by the trapezoidal rule, so the balance closes as they get finer
    (measured: 61, 8.5 and 1.9 J at 100, 20 and 10 us rows, against swings of the driver's
    work of 10 kJ a turn)."""
    fourbar = EXAMPLES / "flores2009_fourbar.toml"
    drift = {}
    for interval in (2e-5, 1e-5):
        drift[interval], flows, dissipated = _balance(fourbar, 0.2, interval, "coupler_follower")
        swing = np.ptp(flows["driver_work"])
        assert swing > 1e4
        assert flows["dissipated"].iloc[-1] == pytest.approx(dissipated, rel=0.02)
    assert drift[1e-5] < 1e-3 * swing
    assert drift[1e-5] < 0.5 * drift[2e-5]
    # Without clearance joints the torque is smooth: 1e-4 of the swing at the default rows.
    ideal = simulate_ok(fourbar, ["solver.t_end=0.2"], ideal=True)
    flows = energy_balance(ideal.model, ideal.timeseries)
    assert np.abs(flows["balance"]).max() < 1e-3 * np.ptp(flows["driver_work"])


def test_no_balance_where_a_flow_is_not_in_the_time_series():
    fourbar = jw.load_model(EXAMPLES / "flores2009_fourbar.toml")
    assert unaccounted(fourbar) is None
    torque = {"type": "torque", "body": "follower", "torque": "5 N*m"}
    loaded = fourbar.with_values({"forces": [*fourbar.model_dump()["forces"], torque]})
    assert "applied torque" in unaccounted(loaded)


PISTON = EXAMPLES / "slider_crank_piston_clearance.toml"
SLIDER = "piston"


def test_a_sliders_powers_integrate_to_the_loops_totals():
    """As for the revolute joint above: the rows (every 10 us) against the loop's step sums."""
    res = simulate_ok(PISTON, ["solver.t_end=0.06", "solver.output_interval=1e-5"])
    df, time = res.timeseries, res.timeseries["time"].to_numpy()
    joint = res.summary["clearance_joints"][SLIDER]
    whole = joint.get("whole_run", joint)  # the whole run (no settling without a period)
    for power, total in (("friction", "friction"), ("damping", "damping")):
        energy = np.trapezoid(df[f"{SLIDER}_{power}_power"].to_numpy(), time)
        assert energy == pytest.approx(whole[f"energy_dissipated_{total}_j"], rel=0.03), power
    corners = ("front_top", "front_bottom", "rear_top", "rear_bottom")
    sliding = sum(
        np.trapezoid(np.abs(df[f"{SLIDER}_vt_{c}"]) * (df[f"{SLIDER}_fn_{c}"] > 0.0), time)
        for c in corners
    )  # the guide's edges did not touch the slider here
    assert sliding == pytest.approx(whole["sliding_distance_m"], rel=0.03)
    assert column_unit(f"{SLIDER}_vt_front_top", res.model) == "m/s"


def test_a_free_sliders_energy_balance_closes_as_the_rows_get_finer():
    """The piston example has no driver: kinetic + potential + contact energy + what the slider
    dissipates stays constant, to the rows' trapezoids (measured: 4.5, 1.1 and 0.28 mJ at 20,
    10 and 5 us rows, second order, against 0.27 J dissipated in 0.1 s)."""
    drift = {}
    for interval in (2e-5, 1e-5):
        drift[interval], flows, dissipated = _balance(PISTON, 0.1, interval, SLIDER)
        assert flows["dissipated"].iloc[-1] == pytest.approx(dissipated, rel=0.01)
    assert drift[1e-5] < 1e-2 * dissipated
    assert drift[1e-5] < 0.5 * drift[2e-5]
