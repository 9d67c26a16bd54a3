"""The paper's four-bar with ideal joints against closed-form kinematics and inverse dynamics.

One crank turn at 1500 rpm lasts 0.04 s. With tight tolerances the simulated follower motion,
crank torque and joint reactions must match the independent answers of ``references.py``
(closed-form loop closure, power balance, Newton-Euler) to 1e-6 of each quantity's largest
magnitude over the turn, for both integrators.
"""

import numpy as np
import pytest
from references import (
    BODY_NAMES,
    CRANK_SPEED,
    JOINT_NAMES,
    fourbar_newton_euler,
    fourbar_states,
    fourbar_torque_power,
)
from runs import EXAMPLES, simulate_ok

INTEGRATORS = ("dopri5", "abm")
TURN = 2.0 * np.pi / CRANK_SPEED  # one crank turn [s] (0.04 s)
TIGHT = ["solver.t_end=0.04", "solver.rtol=1e-10", "solver.atol=1e-12"]
# Closed-form agreement asked of a tight run: relative to the largest magnitude over the turn.
# A prototype Baumgarte/RK45 solve at rtol 1e-10 lands at ~1e-9 (acceleration) and below, so
# 1e-6 leaves three decades for a different error norm or step controller.
REL_TOL = 1e-6


def rel_err(actual, expected) -> float:
    """Largest absolute difference over the largest magnitude of the expected values."""
    expected = np.asarray(expected, dtype=float)
    return float(np.abs(np.asarray(actual, dtype=float) - expected).max() / np.abs(expected).max())


@pytest.fixture(scope="module")
def tight_runs():
    """One crank turn per integrator at rtol 1e-10, atol 1e-12: {integrator: timeseries}."""
    runs = {}
    for integrator in INTEGRATORS:
        res = simulate_ok(
            EXAMPLES / "flores2009_fourbar.toml",
            [*TIGHT, f"solver.integrator={integrator}"],
            ideal=True,
        )
        df = res.timeseries
        # The run covers the whole turn (the last row is within one output interval of t_end).
        assert df["time"].iloc[0] == 0.0
        assert df["time"].iloc[-1] >= TURN - 1e-4 - 1e-12
        assert res.summary["stats"]["accepted_steps"] > 0
        runs[integrator] = df
    return runs


def test_initial_pose_is_the_open_branch(tight_runs):
    df = tight_runs["dopri5"]
    ref = fourbar_states(df["time"].to_numpy()[:1])
    for body in BODY_NAMES:
        for coord in ("x", "y", "phi"):
            # Assembly converges to 1e-10 m; over the 0.13 m half coupler that is < 1e-9 rad.
            assert df[f"{coord}_{body}"].iloc[0] == pytest.approx(
                ref[f"{coord}_{body}"][0], abs=1e-9
            )
        for rate in ("vx", "vy", "omega"):
            # Velocity analysis is one linear solve: exact but for the pose's 1e-9 error.
            assert df[f"{rate}_{body}"].iloc[0] == pytest.approx(
                ref[f"{rate}_{body}"][0], rel=1e-8, abs=1e-8
            )


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_all_body_states_match_loop_closure(tight_runs, integrator):
    df = tight_runs[integrator]
    ref = fourbar_states(df["time"].to_numpy())
    for quantity in ("x", "y", "phi", "vx", "vy", "omega", "ax", "ay", "alpha"):
        # One scale per quantity over the whole mechanism (alpha_crank is identically zero).
        scale = max(np.abs(ref[f"{quantity}_{body}"]).max() for body in BODY_NAMES)
        for body in BODY_NAMES:
            column = f"{quantity}_{body}"
            # REL_TOL: see its definition (1e-6 of the largest magnitude over the turn).
            assert np.abs(df[column] - ref[column]).max() < REL_TOL * scale, column


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_follower_angle_velocity_acceleration(tight_runs, integrator):
    # The paper's Fig. 7 (a), (b) quantities, stated on their own for a clear failure message.
    df = tight_runs[integrator]
    ref = fourbar_states(df["time"].to_numpy())
    errors = {
        q: rel_err(df[f"{q}_follower"], ref[f"{q}_follower"]) for q in ("phi", "omega", "alpha")
    }
    # REL_TOL: 1e-6 of the largest magnitude over the turn (see its definition).
    assert max(errors.values()) < REL_TOL, errors


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_crank_torque_matches_power_balance(tight_runs, integrator):
    # The paper's Fig. 7 (c): the moment that keeps the crank at 50 pi rad/s.
    df = tight_runs[integrator]
    expected = fourbar_torque_power(fourbar_states(df["time"].to_numpy()))
    # REL_TOL: 1e-6 of the largest torque over the turn (about 1.5e4 N m).
    assert rel_err(df["torque_motor"], expected) < REL_TOL


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_joint_reactions_match_newton_euler(tight_runs, integrator):
    df = tight_runs[integrator]
    expected = fourbar_newton_euler(fourbar_states(df["time"].to_numpy()))
    for joint in JOINT_NAMES:
        for comp in ("fx", "fy"):
            column = f"{joint}_{comp}"
            # Reactions come from the same multipliers as the torque: same REL_TOL.
            assert rel_err(df[column], expected[column]) < REL_TOL, column


def test_integrators_agree(tight_runs):
    a, b = tight_runs["dopri5"], tight_runs["abm"]
    np.testing.assert_allclose(a["time"], b["time"], rtol=0, atol=1e-12)
    for column in ("phi_follower", "omega_follower", "alpha_follower", "torque_motor"):
        # Each run is within REL_TOL of the closed form, so they agree within twice that.
        assert rel_err(b[column], a[column]) < 2 * REL_TOL, column


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_error_decreases_as_rtol_tightens(integrator):
    tolerances = (("1e-5", "1e-7"), ("1e-7", "1e-9"), ("1e-9", "1e-11"))  # (rtol, atol)
    errors = []
    for rtol, atol in tolerances:
        df = simulate_ok(
            EXAMPLES / "flores2009_fourbar.toml",
            [
                "solver.t_end=0.04",
                f"solver.rtol={rtol}",
                f"solver.atol={atol}",
                f"solver.integrator={integrator}",
            ],
            ideal=True,
        ).timeseries
        ref = fourbar_states(df["time"].to_numpy())
        err = max(
            rel_err(df[f"{q}_follower"], ref[f"{q}_follower"]) for q in ("phi", "omega", "alpha")
        )
        # Tolerance proportionality: over one turn the global error is a modest multiple of
        # rtol (a prototype gives up to ~20 rtol for the acceleration); 100 rtol is the limit.
        assert err < 100 * float(rtol), (rtol, err)
        errors.append(err)
    # Monotone convergence as the tolerance tightens.
    assert errors[0] > errors[1] > errors[2], errors
    # Four decades of rtol must buy at least two decades of error (a prototype gets ~3;
    # at rtol 1e-5 the 1 ms max step, not the tolerance, limits the step).
    assert errors[0] > 100 * errors[2], errors


@pytest.mark.slow
def test_constraint_violation_stays_bounded():
    path = EXAMPLES / "flores2009_fourbar.toml"
    res = simulate_ok(path, [], ideal=True)  # the file as is: 1 s (25 turns), default tolerances
    df = res.timeseries
    violation = df["constraint_violation"].to_numpy()
    time = df["time"].to_numpy()
    # The ideal joints must not wander by as much as the 0.2 mm radial clearance the paper
    # studies; a prototype (RK45, rtol 1e-6, alpha = beta = 5) plateaus at ~6e-5 m.
    assert violation.max() < 2e-4
    assert res.summary["stats"]["max_constraint_violation"] < 2e-4
    # Bounded, not drifting: Baumgarte (time constant 1/beta = 0.2 s) levels the violation
    # off, so the last quarter second barely exceeds the one before (prototype: 8 %); an
    # unchecked drift growing linearly from t = 0 would give 33 %. 1e-7 m floor for noise.
    third = violation[(time >= 0.5) & (time < 0.75)].max()
    fourth = violation[time >= 0.75].max()
    assert fourth <= 1.25 * third + 1e-7, (third, fourth)
    # And the stabilisation is what bounds it: without it the drift is far larger (prototype:
    # 13 times at 1 s).
    free = simulate_ok(
        path,
        [
            "solver.baumgarte_alpha=0.0",
            "solver.baumgarte_beta=0.0",
            "solver.max_constraint_violation=1.0",  # let it drift, to measure the drift
        ],
        ideal=True,
    )
    assert violation.max() < 0.25 * free.timeseries["constraint_violation"].max()
