"""Self-checks of the reference answers in ``references.py`` against independent numerics.

The physics tests trust these references, so each one is checked here by a different route:
the loop-closure equations themselves, finite differences of the closed-form angles, a
numerical derivative of the total energy, Newton-Euler equations, and a direct ODE solve.
"""

import numpy as np
import pandas as pd
import pytest
from references import (
    CRANK_ANGLE_0,
    CRANK_SPEED,
    PAPER_FOURBAR,
    compound_pendulum_period,
    fourbar_bodies,
    fourbar_kinematics,
    fourbar_newton_euler,
    fourbar_states,
    fourbar_torque_power,
    mechanism_energy,
)
from scipy.integrate import solve_ivp

TURN = 2.0 * np.pi / CRANK_SPEED  # one crank revolution at 1500 rpm [s]


def five_point_derivative(f, t, h):
    """Fourth-order central difference of f at t with step h."""
    return (f(t - 2 * h) - 8 * f(t - h) + 8 * f(t + h) - f(t + 2 * h)) / (12 * h)


@pytest.fixture(scope="module")
def turn_times():
    """Times spanning one crank turn, endpoints excluded so FD stencils stay inside [s]."""
    return np.linspace(0.0, TURN, 721)[1:-1]


def test_loop_closure_residual():
    theta2 = np.linspace(0.0, 4.0 * np.pi, 2001)
    kin = fourbar_kinematics(theta2)
    fb = PAPER_FOURBAR
    o2 = np.array(fb.crank_pivot)
    o4 = np.array(fb.follower_pivot)
    a_pt = o2 + fb.crank * np.stack([np.cos(theta2), np.sin(theta2)], axis=-1)
    b_from_coupler = a_pt + fb.coupler * np.stack(
        [np.cos(kin["theta3"]), np.sin(kin["theta3"])], axis=-1
    )
    b_from_follower = o4 + fb.follower * np.stack(
        [np.cos(kin["theta4"]), np.sin(kin["theta4"])], axis=-1
    )
    residual = np.abs(b_from_coupler - b_from_follower).max()
    # A few ulps of the 0.46 m link: the closed form is exact up to rounding.
    assert residual < 2e-15


def test_initial_pose_is_the_open_branch_of_spec():
    kin = fourbar_kinematics(CRANK_ANGLE_0)
    fb = PAPER_FOURBAR
    b = np.array(fb.follower_pivot) + fb.follower * np.array(
        [np.cos(kin["theta4"]), np.sin(kin["theta4"])]
    )
    # SPEC section 5 gives the joint "at about (0.256, 0.448) m", i.e. to within a millimetre.
    np.testing.assert_allclose(b, [0.256, 0.448], atol=1e-3)
    # Uncrossed quadrilateral O2-A-B-O4: all turns of its boundary have the same sign.
    corners = np.array([fb.crank_pivot, [0.0, fb.crank], b, fb.follower_pivot])
    edges = np.roll(corners, -1, axis=0) - corners
    turns = (
        edges[:, 0] * np.roll(edges, -1, axis=0)[:, 1]
        - edges[:, 1] * np.roll(edges, -1, axis=0)[:, 0]
    )
    assert np.all(turns > 0) or np.all(turns < 0)


def test_angles_are_continuous_and_advance_one_turn_per_crank_turn():
    theta2 = CRANK_ANGLE_0 + np.linspace(0.0, 2.0 * np.pi, 3601)
    kin = fourbar_kinematics(theta2)
    for key in ("theta3", "theta4"):
        # 0.1 degree crank steps move no bar by more than a few tenths of a degree.
        assert np.abs(np.diff(kin[key])).max() < np.radians(1.0)
        # Drag-link: every bar turns fully, so each angle gains exactly 2 pi per crank turn.
        assert kin[key][-1] - kin[key][0] == pytest.approx(2.0 * np.pi, abs=1e-12)


def test_velocities_match_finite_differences_of_angles(turn_times):
    h = 1e-6  # [s]; 5-point stencil: truncation ~ h^4 |theta^(5)| and rounding ~ 1e-16 / h.

    def angles(t, key):
        return fourbar_kinematics(CRANK_ANGLE_0 + CRANK_SPEED * t)[key]

    kin = fourbar_kinematics(CRANK_ANGLE_0 + CRANK_SPEED * turn_times)
    for angle_key, rate_key in (("theta3", "omega3"), ("theta4", "omega4")):
        fd = five_point_derivative(lambda t, k=angle_key: angles(t, k), turn_times, h)
        scale = np.abs(kin[rate_key]).max()
        # Rounding ~ 1e-16 * 7 rad / 1e-6 s ~ 1e-9 rad/s against a scale of ~ 100 rad/s.
        assert np.abs(fd - kin[rate_key]).max() < 1e-9 * scale


def test_accelerations_match_finite_differences_of_velocities(turn_times):
    h = 1e-6  # [s]

    def rates(t, key):
        return fourbar_kinematics(CRANK_ANGLE_0 + CRANK_SPEED * t)[key]

    kin = fourbar_kinematics(CRANK_ANGLE_0 + CRANK_SPEED * turn_times)
    for rate_key, acc_key in (("omega3", "alpha3"), ("omega4", "alpha4")):
        fd = five_point_derivative(lambda t, k=rate_key: rates(t, k), turn_times, h)
        scale = np.abs(kin[acc_key]).max()
        # Rounding ~ 1e-16 * 300 rad/s / 1e-6 s ~ 3e-8 rad/s^2 against ~ 1e4 rad/s^2.
        assert np.abs(fd - kin[acc_key]).max() < 1e-9 * scale


def test_crank_acceleration_enters_correctly():
    # With a crank angle law theta2(t) = t^2 (so alpha2 = 2), compare against FD in time.
    t = np.linspace(1.0, 3.0, 201)
    h = 1e-5

    def kin_at(tt):
        return fourbar_kinematics(tt**2, 2.0 * tt, 2.0)

    kin = kin_at(t)
    for rate_key, acc_key in (("omega3", "alpha3"), ("omega4", "alpha4")):
        fd = five_point_derivative(lambda tt, k=rate_key: kin_at(tt)[k], t, h)
        # Slow motion (rates of a few rad/s): rounding ~ 1e-16 * 10 / 1e-5 ~ 1e-10.
        assert np.abs(fd - kin[acc_key]).max() < 1e-8 * np.abs(kin[acc_key]).max()


def test_body_states_match_finite_differences(turn_times):
    h = 1e-6  # [s]
    states = fourbar_states(turn_times)
    for body in ("crank", "coupler", "follower"):
        for pos, vel, acc in (("x", "vx", "ax"), ("y", "vy", "ay")):

            def col(t, name, b=body):
                return fourbar_states(t)[f"{name}_{b}"].to_numpy()

            fd_v = five_point_derivative(lambda t, c=pos: col(t, c), turn_times, h)
            fd_a = five_point_derivative(lambda t, c=vel: col(t, c), turn_times, h)
            # Positions ~ 0.5 m, speeds ~ 60 m/s, accelerations ~ 1e4 m/s^2: FD rounding
            # ~ 1e-16 * value / 1e-6 s is below 1e-9 of each scale.
            v_ref, a_ref = states[f"{vel}_{body}"], states[f"{acc}_{body}"]
            assert np.abs(fd_v - v_ref).max() < 1e-9 * np.abs(v_ref).max()
            assert np.abs(fd_a - a_ref).max() < 1e-9 * np.abs(a_ref).max()


def test_power_torque_matches_derivative_of_total_energy(turn_times):
    h = 1e-6  # [s]
    bodies = fourbar_bodies()

    def energy(t):
        kinetic, potential = mechanism_energy(fourbar_states(t), bodies, PAPER_FOURBAR.gravity)
        return kinetic + potential

    de_dt = five_point_derivative(energy, turn_times, h)
    torque = fourbar_torque_power(fourbar_states(turn_times))
    scale = np.abs(torque).max()
    # Energy ~ 1e3 J: rounding ~ 1e-16 * 1e3 / 1e-6 = 1e-7 W, i.e. < 1e-9 N m after / 157 rad/s.
    assert np.abs(de_dt / CRANK_SPEED - torque).max() < 1e-9 * scale


def test_power_torque_matches_newton_euler(turn_times):
    states = fourbar_states(turn_times)
    torque_power = fourbar_torque_power(states)
    torque_ne = fourbar_newton_euler(states)["torque"]
    # Two exact formulations of the same dynamics; differ only by rounding.
    np.testing.assert_allclose(
        torque_ne, torque_power, rtol=0, atol=1e-11 * np.abs(torque_power).max()
    )


def test_newton_euler_satisfies_global_balances(turn_times):
    fb = PAPER_FOURBAR
    states = fourbar_states(turn_times)
    ne = fourbar_newton_euler(states)
    g = np.array(fb.gravity)
    bodies = fourbar_bodies()
    # Whole mechanism: only the ground joints and gravity act from outside.
    external = np.stack(
        [
            ne["ground_crank_fx"] + ne["ground_follower_fx"],
            ne["ground_crank_fy"] + ne["ground_follower_fy"],
        ],
        axis=-1,
    )
    momentum_rate = np.zeros_like(external)
    moment_rate = np.zeros(len(states))
    external_moment = ne["torque"].copy()
    o4 = np.array(fb.follower_pivot)
    external_moment += o4[0] * ne["ground_follower_fy"] - o4[1] * ne["ground_follower_fx"]
    for b, (m, j) in bodies.items():
        r = states[[f"x_{b}", f"y_{b}"]].to_numpy()
        a = states[[f"ax_{b}", f"ay_{b}"]].to_numpy()
        external += m * g
        momentum_rate += m * a
        # Moments about the origin (the crank pivot, where F12 has no arm).
        external_moment += m * (r[:, 0] * g[1] - r[:, 1] * g[0])
        moment_rate += m * (r[:, 0] * a[:, 1] - r[:, 1] * a[:, 0]) + j * states[f"alpha_{b}"]
    force_scale = np.abs(momentum_rate).max()
    moment_scale = np.abs(moment_rate).max()
    # Internal forces cancel exactly; only rounding remains.
    assert np.abs(external - momentum_rate).max() < 1e-11 * force_scale
    assert np.abs(external_moment - moment_rate).max() < 1e-11 * moment_scale


@pytest.mark.parametrize("amplitude_deg", [5.0, 45.0, 90.0, 150.0, 175.0])
def test_pendulum_period_matches_direct_integration(amplitude_deg):
    mass, length = 1.0, 1.0
    distance = 0.5 * length
    pivot_inertia = mass * length**2 / 3.0
    w2 = mass * 9.81 * distance / pivot_inertia
    theta0 = np.radians(amplitude_deg)

    def rhs(_t, y):
        return [y[1], -w2 * np.sin(y[0])]

    def bottom(_t, y):
        return y[0]

    bottom.terminal = True
    bottom.direction = -1
    sol = solve_ivp(
        rhs, (0.0, 100.0), [theta0, 0.0], method="DOP853", rtol=1e-12, atol=1e-12, events=bottom
    )
    quarter = sol.t_events[0][0]
    period = compound_pendulum_period(pivot_inertia, mass, distance, theta0)
    # From the release at the turning point to the bottom is exactly a quarter period;
    # DOP853 at rtol 1e-12 times it to ~1e-11 relative.
    assert 4.0 * quarter == pytest.approx(period, rel=1e-9)


def test_pendulum_period_small_amplitude_limit():
    # K(0) = pi/2, so the period tends to 2 pi sqrt(I / (m g d)).
    small = compound_pendulum_period(1.0 / 3.0, 1.0, 0.5, 1e-6)
    assert small == pytest.approx(2.0 * np.pi * np.sqrt((1.0 / 3.0) / (9.81 * 0.5)), rel=1e-12)


def test_mechanism_energy_of_a_spinning_bar():
    # Uniform 1 m, 1 kg bar pinned at the origin at angle phi, spinning at w:
    # T = 1/2 (m L^2/3) w^2, V = m g y_c.
    phi = np.array([0.0, -np.pi / 2, 1.0])
    w = np.array([0.0, 5.0, -3.0])
    table = pd.DataFrame(
        {
            "x_bar": 0.5 * np.cos(phi),
            "y_bar": 0.5 * np.sin(phi),
            "vx_bar": -0.5 * w * np.sin(phi),
            "vy_bar": 0.5 * w * np.cos(phi),
            "omega_bar": w,
        }
    )
    kinetic, potential = mechanism_energy(table, {"bar": (1.0, 1.0 / 12.0)})
    np.testing.assert_allclose(kinetic, 0.5 * w**2 / 3.0, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(potential, 9.81 * 0.5 * np.sin(phi), rtol=1e-14, atol=1e-15)
