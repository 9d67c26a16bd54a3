"""The compound pendulum example: large-amplitude period and energy conservation.

A uniform 1 m, 1 kg bar pinned at one end and released horizontally swings with a 90 degree
amplitude. Its exact period (elliptic integral, ``references.compound_pendulum_period``) is
1.9333 s, 18 % longer than the small-swing 1.6379 s, so timing the swings tests the nonlinear
dynamics, not just the linearisation. Undriven and undamped, it must conserve energy.
"""

import numpy as np
import pytest
from references import compound_pendulum_period, mechanism_energy
from runs import EXAMPLES, simulate_ok
from scipy.interpolate import CubicHermiteSpline

INTEGRATORS = ("dopri5", "abm")
MASS, LENGTH, INERTIA = 1.0, 1.0, 1.0 / 12.0  # [kg], [m], about the centre [kg m^2]
DISTANCE = 0.5 * LENGTH  # pivot to centre of mass [m]
PIVOT_INERTIA = INERTIA + MASS * DISTANCE**2  # m L^2 / 3 [kg m^2]
G = 9.81  # [m/s^2]
PERIOD = compound_pendulum_period(PIVOT_INERTIA, MASS, DISTANCE, 0.5 * np.pi, G)  # [s]
BOTTOM = -0.5 * np.pi  # phi of the hanging bar [rad]


@pytest.fixture(scope="module")
def default_runs():
    """The file as is (10 s, about 5 periods, default tolerances), per integrator."""
    return {
        integrator: simulate_ok(EXAMPLES / "pendulum.toml", [f"solver.integrator={integrator}"])
        for integrator in INTEGRATORS
    }


def test_reference_period_is_the_large_amplitude_one():
    # Guard on the reference itself: 90 degrees lengthens the period by K(1/2) / (pi/2).
    small = 2.0 * np.pi * np.sqrt(PIVOT_INERTIA / (MASS * G * DISTANCE))
    assert PERIOD / small == pytest.approx(1.18034, abs=1e-5)


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_period_from_events(integrator):
    t_end = 4.0  # about two periods: crossings at T/4, 3T/4, 5T/4, 7T/4
    res = simulate_ok(
        EXAMPLES / "pendulum.toml",
        [
            f"solver.t_end={t_end}",
            "solver.rtol=1e-10",
            "solver.atol=1e-12",
            f"solver.integrator={integrator}",
        ],
    )
    events = res.events[res.events["event"] == "bottom"].reset_index(drop=True)
    n = np.arange(int(np.floor((t_end - 0.25 * PERIOD) / (0.5 * PERIOD))) + 1)
    assert len(events) == len(n)
    # Out through the bottom (phi falling) at T/4, back (rising) at 3T/4, and so on.
    assert list(events["direction"]) == ["falling" if k % 2 == 0 else "rising" for k in n]
    expected = 0.25 * PERIOD + 0.5 * PERIOD * n
    # Events sit on the dense output at rtol 1e-10: timing errors ~1e-10 s; 1e-7 of the period
    # leaves three decades of margin and is still 1e6 times finer than the 18 % amplitude effect.
    np.testing.assert_allclose(events["time"], expected, rtol=0, atol=1e-7 * PERIOD)
    # The period itself, from crossings in the same direction.
    periods = events["time"].to_numpy()[2:] - events["time"].to_numpy()[:-2]
    # Same bound as the crossing times (a difference of two of them).
    np.testing.assert_allclose(periods, PERIOD, rtol=2e-7)


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_period_from_time_series(default_runs, integrator):
    df = default_runs[integrator].timeseries
    time = df["time"].to_numpy()
    # Cubic Hermite through (phi, omega) at the 1 ms output rows; its error near the bottom is
    # ~h^4 omega0^4 / 384 ~ 1e-12 rad, far below the integration error.
    spline = CubicHermiteSpline(
        time, df["phi_pendulum"].to_numpy() - BOTTOM, df["omega_pendulum"].to_numpy()
    )
    crossings = spline.roots(extrapolate=False)
    crossings = np.unique(np.round(crossings, 12))  # a root on a knot can be reported twice
    n = np.arange(len(crossings))
    assert len(crossings) == int(np.floor((time[-1] - 0.25 * PERIOD) / (0.5 * PERIOD))) + 1
    # Default rtol 1e-6 with the 1 ms max step; the phase error after 5 periods stays well
    # below 1e-5 of a period (prototype: ~1e-14), the bound being ten times rtol.
    np.testing.assert_allclose(
        crossings, 0.25 * PERIOD + 0.5 * PERIOD * n, rtol=0, atol=1e-5 * PERIOD
    )


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_energy_is_conserved(default_runs, integrator):
    df = default_runs[integrator].timeseries
    total = (df["energy_kinetic"] + df["energy_potential"]).to_numpy()
    scale = MASS * G * LENGTH  # energy scale m g L = 9.8 J (the swing exchanges m g d = 4.9 J)
    # Bound: rtol * m g L = 1e-5 J. The controller keeps each step's local error below rtol of
    # the state, and with h <= 1 ms (h omega0 ~ 4e-3) the fifth-order steps' true errors are
    # orders below that, so 1e4 steps do not add up to one rtol of the energy scale (prototype
    # RK45: 2e-13 J). Baumgarte forces (beta^2 Phi + 2 alpha Phi_dot per unit mass) act only on
    # the ~1e-15 m violation, so the work they do is negligible.
    assert np.abs(total - total[0]).max() < 1e-6 * scale
    # Swinging, not resting: all of m g d turns kinetic at the bottom. The nearest 1 ms row is
    # within 0.5 ms (2.7e-3 rad at 5.4 rad/s) of it, where the kinetic energy is short by at
    # most 4e-6 of m g d; hence 1e-5.
    assert df["energy_kinetic"].max() == pytest.approx(MASS * G * DISTANCE, rel=1e-5)


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_energy_columns_match_the_state(default_runs, integrator):
    df = default_runs[integrator].timeseries
    kinetic, potential = mechanism_energy(df, {"pendulum": (MASS, INERTIA)}, (0.0, -G))
    # Same formula on the same numbers: only rounding differs (energies are a few J).
    np.testing.assert_allclose(df["energy_kinetic"], kinetic, rtol=0, atol=1e-12)
    # The zero of the potential is a convention: compare up to a constant.
    offset = df["energy_potential"].to_numpy() - potential
    np.testing.assert_allclose(offset, offset[0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("formulation", ("augmented_lagrangian", "baumgarte"))
@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_rows_at_step_ends_report_their_own_state(integrator, formulation):
    # Rows every 1 ms, as far apart as the largest step: once the steps grow to it they end on
    # the rows' times and each row reuses the step's last evaluation instead of its own.
    res = simulate_ok(
        EXAMPLES / "pendulum.toml",
        [
            "solver.t_end=1.0",
            f"solver.integrator={integrator}",
            f"solver.formulation={formulation}",
        ],
    )
    stats = res.summary["stats"]
    per_step = {"abm": 2, "dopri5": 6}[integrator]  # evaluations of an accepted step
    attempts = per_step * stats["accepted_steps"] + per_step * stats["rejected_steps"] + 1
    rows_evaluated = stats["rhs_evaluations"] - attempts
    # A rejected abm step costs one evaluation, not two: rows_evaluated is at most this.
    assert rows_evaluated <= 0.05 * len(res.timeseries)
    # Each row is still the dynamics at its own state: the pivot torque -m g d cos(phi) over
    # the pivot inertia, and the pivot reaction m (a_G - g). The state is the integrator's (off
    # the constraints by ~1e-12 m): the closed form at that state agrees to ~1e-9 rad/s^2.
    df = res.timeseries
    phi, omega = df["phi_pendulum"].to_numpy(), df["omega_pendulum"].to_numpy()
    alpha = -MASS * G * DISTANCE * np.cos(phi) / PIVOT_INERTIA
    np.testing.assert_allclose(df["alpha_pendulum"], alpha, rtol=0, atol=1e-7)
    # The centre's acceleration about the fixed pivot, then the pin's force on the bar [N].
    ax = DISTANCE * (-alpha * np.sin(phi) - omega**2 * np.cos(phi))
    ay = DISTANCE * (alpha * np.cos(phi) - omega**2 * np.sin(phi))
    np.testing.assert_allclose(df["pin_fx"], MASS * ax, rtol=0, atol=1e-7)
    np.testing.assert_allclose(df["pin_fy"], MASS * (ay + G), rtol=0, atol=1e-7)
