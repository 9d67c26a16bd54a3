"""Edges of the formulations: scales, contradictions and checks that must not cry wolf.

Each case came from hostile testing. The independent answers are closed forms: the
reactions of a bar pinned at one end and turned at constant speed, a wheel spinning freely
on its pin, and the energy of a pendulum at rest in a small swing.
"""

import math

import numpy as np
import pytest
from mechanisms import GRAVITY, bar, parallelogram, pin
from runs import EXAMPLES

import jointwear as jw
from jointwear.model import parse_model

G = 9.81  # [m/s^2]
SPEED = 10.0  # [rad/s]
FORMULATIONS = ("baumgarte", "augmented_lagrangian")


def turned_bar(inertia: float, formulation: str, drivers: int = 1) -> dict:
    """A 1 m, 1 kg bar pinned at one end, turned at SPEED from the horizontal."""
    body = bar("bar", 1.0, 1.0, (0.0, 0.0), 0.0, SPEED)
    body["inertia"] = inertia
    speeds = [SPEED, SPEED * (1 + 1e-5)][:drivers]
    return {
        "ground": {"points": {"o": [0.0, 0.0]}},
        "bodies": [body],
        "joints": [pin("pin", ("ground", "bar"), ("o", "a"))],
        "drivers": [
            {
                "name": f"motor{k}",
                "type": "angle",
                "body": "bar",
                "function": {"type": "constant_speed", "speed": speed},
            }
            for k, speed in enumerate(speeds)
        ],
        "forces": [GRAVITY],
        "solver": {"formulation": formulation, "t_end": 0.1, "output_interval": 1e-3},
    }


@pytest.mark.parametrize("formulation", FORMULATIONS)
def test_a_nearly_point_mass_is_right_or_refused(formulation):
    # Inertia 1e-8 kg m^2 on a 1 kg bar: the augmented Lagrangian's iterations cannot settle
    # (the pin's rows are nearly parallel in the mass metric). It must say so, not report
    # wrong forces. The closed form at t = 0 (bar horizontal, alpha = 0): the motor holds
    # the weight's moment m g L / 2 and the pin carries m g up and m w^2 L / 2 inwards.
    res = jw.simulate(parse_model(turned_bar(1e-8, formulation)))
    if res.status != "success":
        assert res.status == "singular" and formulation == "augmented_lagrangian", res.message
        return
    first = res.timeseries.iloc[0]
    # Multipliers of an exact state at rtol 1e-6: 1e-6 of the 5 N m and 50 N scales.
    assert first["torque_motor0"] == pytest.approx(0.5 * G, rel=1e-6)
    assert first["pin_fy"] == pytest.approx(G, rel=1e-6)  # on the bar: holds its weight
    assert first["pin_fx"] == pytest.approx(-0.5 * SPEED**2, rel=1e-6)


def test_contradicting_drivers_are_refused_at_assembly():
    # Two drivers on one body at speeds 1e-5 apart: the same angle at t = 0, but no motion
    # meets both. The velocity equations have no solution: refused before any step.
    with pytest.raises(jw.ModelError, match="velocity equations contradict each other"):
        jw.simulate(parse_model(turned_bar(1.0 / 12.0, "augmented_lagrangian", drivers=2)))


def test_a_light_wheel_beside_a_heavy_arm_runs():
    # A 100 kg arm swinging under gravity and a 10 g wheel (1e-6 kg m^2) spinning on its own
    # pin: the penalty-scaled leading matrix spans 1e13 between its rows, which a pivot test
    # against the largest diagonal took for a singular matrix. The wheel, unloaded about its
    # pin, keeps its speed exactly.
    wheel = bar("wheel", 0.01, 0.0, (2.0, 0.0), 0.0, SPEED)
    wheel["inertia"] = 1e-6
    wheel["points"] = {"c": [0.0, 0.0]}
    model = {
        "ground": {"points": {"o": [0.0, 0.0], "w": [2.0, 0.0]}},
        "bodies": [bar("arm", 100.0, 1.0, (0.0, 0.0), 0.0), wheel],
        "joints": [
            pin("arm_pin", ("ground", "arm"), ("o", "a")),
            pin("wheel_pin", ("ground", "wheel"), ("w", "c")),
        ],
        "forces": [GRAVITY],
        "solver": {"t_end": 0.1, "output_interval": 1e-3},
    }
    res = jw.simulate(parse_model(model))
    assert res.status == "success", res.message
    # The wheel's speed, integrated at rtol 1e-6 with no torque on it: 1e-9 of its 10 rad/s.
    np.testing.assert_allclose(res.timeseries["omega_wheel"], SPEED, rtol=1e-9)


@pytest.mark.parametrize("formulation", FORMULATIONS)
def test_a_tiny_swing_is_not_an_energy_drift(formulation):
    # A pendulum 1e-6 rad off the vertical: kinetic energy of order 1e-12 J beside a potential
    # of -4.9 J, so rounding alone moves the total by 1e-3 of the swing's own energy scale.
    # That is no wrong motion; the check allows for the energies' rounding.
    hanging = bar("bar", 1.0, 1.0, (0.0, 0.0), -0.5 * math.pi + 1e-6)
    model = {
        "ground": {"points": {"o": [0.0, 0.0]}},
        "bodies": [hanging],
        "joints": [pin("pin", ("ground", "bar"), ("o", "a"))],
        "forces": [GRAVITY],
        "solver": {"formulation": formulation, "t_end": 0.3, "output_interval": 1e-3},
    }
    res = jw.simulate(parse_model(model))
    assert res.status == "success", res.message
    assert res.summary["energy"]["conservative"] is True


@pytest.mark.parametrize("integrator", ("abm", "dopri5"))
def test_a_driven_parallelogram_runs_through_its_flat_positions(integrator):
    # The left crank driven at 7 rad/s: 22 flat (singular) positions in 5 s. The exact motion
    # is theta = pi/4 + 7 t for both cranks, the coupler level. Near each flat position the
    # iterations settle slowly; that must not stop the run.
    solver = {"integrator": integrator, "t_end": 5.0, "output_interval": 0.01}
    model = parallelogram(("left", "right"), 1.0, 0.3, 1.5, 2.0, 0.25 * math.pi, 7.0, solver)
    model["drivers"] = [
        {
            "name": "motor",
            "type": "angle",
            "body": "crank_left",
            "function": {"type": "constant_speed", "speed": 7.0, "initial": 0.25 * math.pi},
        }
    ]
    res = jw.simulate(parse_model(model))
    assert res.status == "success", res.message
    df = res.timeseries
    exact = 0.25 * math.pi + 7.0 * df["time"].to_numpy()
    # The driver holds the left crank to the projection tolerance; the right one and the
    # coupler follow on the parallelogram branch: a branch change costs about 1 rad, the
    # integration (rtol 1e-6) some 1e-6 rad over 5 s. 1e-5 rad.
    for body, expected in (("crank_left", exact), ("crank_right", exact), ("coupler", 0.0)):
        np.testing.assert_allclose(df[f"phi_{body}"], expected, rtol=0, atol=1e-5)


def test_statuses_of_drift_and_summary_entries():
    # The pendulum example (conservative): its summary carries the constraint and energy
    # checks; a bound below what any run meets stops it with the named status, and the rows
    # computed so far are kept.
    model = jw.load_model(EXAMPLES / "pendulum.toml", overrides=["solver.t_end=0.2"])
    res = jw.simulate(model)
    assert res.status == "success", res.message
    constraints, energy = res.summary["constraints"], res.summary["energy"]
    assert constraints["formulation"] == "augmented_lagrangian"
    assert constraints["redundant_equations"] == 0
    assert 0.0 <= constraints["max_violation"] <= constraints["bound"]
    assert energy["conservative"] is True
    assert energy["relative_change"] == pytest.approx(energy["max_change_j"] / energy["scale_j"])
    assert energy["relative_change"] < energy["bound"] and energy["exceeded_at_s"] is None
    for key, status in (
        ("max_constraint_violation", "constraint_drift"),
        ("max_energy_error", "energy_drift"),
    ):
        # Loose steps: integration errors well above the rounding the energy check forgives
        overrides = ["solver.t_end=0.2", "solver.rtol=1e-2", "solver.max_step=0.05"]
        overrides.append(f"solver.{key}=1e-300")
        tight = jw.load_model(EXAMPLES / "pendulum.toml", overrides=overrides)
        stopped = jw.simulate(tight)
        assert stopped.status == status, stopped.message
        assert len(stopped.timeseries) >= 1
    driven = jw.simulate(jw.load_model(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.01"]))
    assert driven.summary["energy"] == {
        "conservative": False,
        "not_monitored_because": "drivers do work on it",
    }


def test_the_paper_fourbar_in_both_formulations():
    # The paper's four-bar with its clearance joint, 0.05 s (a turn and a quarter): the two
    # formulations integrate the same equations to rtol 1e-6; the peak contact force and the
    # worn volume agree to 1e-3 (measured over 1 s: 1.5e-4 and 1.2e-5).
    figures = []
    for formulation in FORMULATIONS:
        overrides = ["solver.t_end=0.05", f"solver.formulation={formulation}"]
        res = jw.simulate(jw.load_model(EXAMPLES / "flores2009_fourbar.toml", overrides))
        assert res.status == "success", res.message
        joint = res.summary["clearance_joints"]["coupler_follower"]
        figures.append((joint["max_contact_force_n"], joint["worn_volume_m3"]))
    (force_a, volume_a), (force_b, volume_b) = figures
    assert force_a == pytest.approx(force_b, rel=1e-3)
    assert volume_a == pytest.approx(volume_b, rel=1e-3)
