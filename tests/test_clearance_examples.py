"""The clearance examples: the slider-crank after Flores & Ambrosio, the four-bar with two.

Short runs only (at most 0.02 s simulated). The slider-crank's first instants have answers
of their own: it starts journal-centred at top dead centre, where the slider is free and at
rest while the rod's small end leaves it at r w^2 (1 + r/l), so the journal flies until it
has crossed the radial clearance, and then strikes the bearing as a single impact of the
slider against the rod's end.
"""

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from runs import simulate_ok
from scipy.integrate import solve_ivp
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

EXAMPLES = Path(__file__).parents[1] / "examples"
SLIDER_CRANK = EXAMPLES / "slider_crank_clearance.toml"
TWO_CLEARANCES = EXAMPLES / "fourbar_two_clearances.toml"
CLEARANCE_COLUMNS = ("fx", "fy", "ex", "ey", "delta", "fn", "ft")

# The cited data of the slider-crank (header of examples/slider_crank_clearance.toml).
CRANK = 0.05  # crank length r [m]
ROD = 0.12  # connecting rod length l [m]
SLIDER_MASS = 0.14  # [kg]
CRANK_SPEED = 5000 * 2 * math.pi / 60  # [rad/s]
BEARING_RADIUS, JOURNAL_RADIUS, WIDTH = 10.0e-3, 9.5e-3, 40e-3  # [m]
YOUNGS_MODULUS, POISSON_RATIO, RESTITUTION = 207e9, 0.3, 0.9
RADIAL_CLEARANCE = 0.5e-3  # [m]
WEAR_COEFFICIENT = 8e-14  # [1/Pa], Flores (2009), Table 2


def invoke(*args: object, env: dict | None = None):
    return CliRunner().invoke(app, [str(a) for a in args], env=env)


def internal_cylinder_stiffness() -> float:
    """K [N/m^1.5] = 4/3 E* sqrt(R*) of the slider-crank's joint (both surfaces alike)."""
    e_star = YOUNGS_MODULUS / (2.0 * (1.0 - POISSON_RATIO**2))
    r_star = BEARING_RADIUS * JOURNAL_RADIUS / (BEARING_RADIUS - JOURNAL_RADIUS)
    return 4.0 / 3.0 * e_star * math.sqrt(r_star)


def single_impact(
    mass: float, speed: float, push: float, k: float, n: float, c_e: float
) -> tuple[float, float]:
    """Peak force [N] and penetration [m] of a mass striking a Lankarani-Nikravesh contact.

    The mass meets the contact at `speed` [m/s] while a constant acceleration `push`
    [m/s^2] keeps pressing it in: m delta'' = m push - F,
    F = K delta^n (1 + 3 (1 - c_e^2) / 4 delta' / speed), integrated until the mass leaves.
    """
    chi = 0.75 * (1.0 - c_e * c_e)

    def force(delta: float, rate: float) -> float:
        return max(0.0, k * max(delta, 0.0) ** n * (1.0 + chi * rate / speed))

    def motion(_t, y):
        return [y[1], push - force(y[0], y[1]) / mass]

    def leaves(_t, y):
        return y[0] + 1e-12  # just below zero: not at the start

    leaves.terminal = True
    leaves.direction = -1
    span = 20 * (mass / (k * math.sqrt(speed))) ** 0.4  # many times the contact duration
    sol = solve_ivp(
        motion,
        (0.0, span),
        [0.0, speed],
        events=leaves,
        rtol=1e-10,
        atol=1e-14,
        max_step=span / 2e4,
    )
    forces = [force(d, r) for d, r in sol.y.T]
    return max(forces), float(sol.y[0].max())


def test_single_impact_reference_is_hertz_without_damping_and_push():
    """c_e = 1 and no push: the closed form delta_max = (5 m v^2 / (4 K))^(2/5) (Johnson 1985)."""
    mass, speed, k = 0.14, 4.0, internal_cylinder_stiffness()
    depth = (5.0 * mass * speed**2 / (4.0 * k)) ** 0.4
    peak, reached = single_impact(mass, speed, 0.0, k, 1.5, 1.0)
    assert reached == pytest.approx(depth, rel=1e-6)
    assert peak == pytest.approx(k * depth**1.5, rel=1e-6)


@pytest.fixture(scope="module")
def slider_crank() -> jw.Results:
    """The slider-crank up to just past its first impact, with fine output rows."""
    return simulate_ok(SLIDER_CRANK, ["solver.t_end=0.5e-3", "solver.output_interval=0.01 ms"])


@pytest.fixture(scope="module")
def two_clearances(tmp_path_factory) -> Path:
    """``jointwear run`` of the two-clearance four-bar for 0.02 s: the results folder."""
    out = tmp_path_factory.mktemp("fourbar2") / "run"
    result = invoke("run", TWO_CLEARANCES, "--out", out, "--t-end", 0.02, "--no-figures")
    assert result.exit_code == 0, result.output
    return out


# Both examples ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("path", "freed"), [(SLIDER_CRANK, 2), (TWO_CLEARANCES, 4)], ids=["slider_crank", "fourbar"]
)
def test_examples_load_and_assemble(path: Path, freed: int):
    result = invoke("check", path)
    assert result.exit_code == 0, result.output
    text = " ".join(result.stdout.split())  # rich wraps long lines at the terminal's width
    assert f"model '{path.stem}': valid" in text
    assert f"{freed} with drivers, of which {freed} from clearance joints" in text


def test_slider_crank_runs_to_success(slider_crank):
    assert slider_crank.status == "success"
    assert list(slider_crank.summary["clearance_joints"]) == ["rod_slider"]
    assert slider_crank.summary["stats"]["degrees_of_freedom"] == 2


def test_two_clearance_fourbar_runs_and_reports_both_joints(two_clearances):
    res = jw.load_results(two_clearances)
    joints = ("crank_coupler", "coupler_follower")
    assert res.status == "success"
    assert sorted(res.summary["clearance_joints"]) == sorted(joints)
    assert res.summary["stats"]["degrees_of_freedom"] == 4  # 2 per clearance joint
    for joint in joints:
        for column in CLEARANCE_COLUMNS:
            assert f"{joint}_{column}" in res.timeseries.columns, (joint, column)
        entry = res.summary["clearance_joints"][joint]
        assert entry["radial_clearance_m"] == pytest.approx(0.2e-3, rel=1e-9)  # Table 2
        assert entry["max_contact_force_n"] > 0.0
    assert "energy_contact" in res.timeseries.columns
    wear = pd.read_csv(two_clearances / "wear.csv")
    assert wear.groupby(["joint", "surface"]).size().to_dict() == {
        (joint, surface): 36 for joint in joints for surface in ("bearing", "journal")
    }
    ideal = jw.load_results(two_clearances / "ideal")
    assert "clearance_joints" not in ideal.summary
    assert {f"{joint}_fx" for joint in joints} <= set(ideal.timeseries.columns)


def test_slider_crank_has_the_cited_data():
    model = jw.load_model(SLIDER_CRANK)
    clearance = model.joint("rod_slider").clearance
    assert model.joint("rod_slider").bodies == ("rod", "slider")  # bearing in the rod
    assert clearance.radial_clearance == pytest.approx(RADIAL_CLEARANCE, rel=1e-9)
    assert (clearance.bearing_radius, clearance.journal_radius, clearance.width) == (
        pytest.approx(BEARING_RADIUS),
        pytest.approx(JOURNAL_RADIUS),
        pytest.approx(WIDTH),
    )
    assert clearance.moduli == pytest.approx((YOUNGS_MODULUS, YOUNGS_MODULUS))
    assert clearance.restitution_coefficient == RESTITUTION
    assert clearance.wear_coefficient == pytest.approx(WEAR_COEFFICIENT)
    assert clearance.sectors == 36
    assert model.body("slider").mass == pytest.approx(SLIDER_MASS)
    assert model.drivers[0].function.speed == pytest.approx(CRANK_SPEED)
    crank, rod = model.body("crank").points, model.body("rod").points
    assert crank["tip"][0] - crank["pivot"][0] == pytest.approx(CRANK)
    assert rod["slider_end"][0] - rod["crank_end"][0] == pytest.approx(ROD)
    assert clearance.stiffness == pytest.approx(internal_cylinder_stiffness(), rel=1e-12)


# The slider-crank's first instants ------------------------------------------------------------

# Relative acceleration of the free journal at the start: the rod's small end at top dead
# centre moves like the ideal slider would, r w^2 (1 + r/l) towards the crank; the slider,
# free along the guide, stays at rest.
START_ACCELERATION = CRANK * CRANK_SPEED**2 * (1.0 + CRANK / ROD)
FLIGHT_TIME = math.sqrt(2.0 * RADIAL_CLEARANCE / START_ACCELERATION)


def test_journal_flies_until_it_has_crossed_the_clearance(slider_crank):
    first = slider_crank.impacts.iloc[0]
    # It cannot touch earlier: the relative acceleration is largest at dead centre.
    assert FLIGHT_TIME * (1 - 1e-3) <= first.time_s <= FLIGHT_TIME * 1.01
    assert first.penetration_velocity_m_s == pytest.approx(
        START_ACCELERATION * FLIGHT_TIME, rel=0.02
    )
    assert first.bearing_angle_deg < 5.0 or first.bearing_angle_deg > 355.0  # along the rod
    ts = slider_crank.timeseries
    flight = ts[ts.time < first.time_s]
    assert len(flight) > 10
    assert (flight.rod_slider_fn == 0.0).all() and (flight.rod_slider_ft == 0.0).all()
    assert (flight.rod_slider_delta < 0.0).all()
    gap = np.hypot(flight.rod_slider_ex, flight.rod_slider_ey)
    expected = 0.5 * START_ACCELERATION * flight.time**2
    assert gap.to_numpy() == pytest.approx(expected.to_numpy(), rel=0.02, abs=1e-9)
    after = ts[ts.time > first.time_s]
    assert (after.rod_slider_fn > 0.0).any()


def test_first_impact_is_a_single_impact_of_the_slider(slider_crank):
    assert len(slider_crank.impacts) == 1, "the run should end before the second impact"
    speed = slider_crank.impacts.iloc[0].penetration_velocity_m_s
    # At dead centre the driven crank holds the rod's end rigidly along the stroke; that end,
    # accelerating towards the crank, runs into the slider, free along the guide and at rest:
    # a mass struck by a wall that keeps accelerating into it.
    peak, depth = single_impact(
        SLIDER_MASS, speed, START_ACCELERATION, internal_cylinder_stiffness(), 1.5, RESTITUTION
    )
    joint = slider_crank.summary["clearance_joints"]["rod_slider"]
    assert joint["max_contact_force_n"] == pytest.approx(peak, rel=0.03)
    assert joint["max_penetration_m"] == pytest.approx(depth, rel=0.03)


# Errors -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("key", "wrong", "what", "known", "meant"),
    [
        (
            "normal_law",
            "jonson",
            "normal law",
            "hertz, johnson, liu, elastic_foundation",
            "johnson",
        ),
        (
            "damping",
            "lankarani_nikravesch",
            "damping law",
            "none, lankarani_nikravesh, hunt_crossley, flores2011",
            "lankarani_nikravesh",
        ),
        ("friction_law", "ambrosia", "friction law", "coulomb, ambrosio, stick_slip", "ambrosio"),
        ("wear_law", "archad", "wear law", "archard, reye", "archard"),
    ],
)
def test_misspelled_law_is_one_line_listing_the_known_laws(key, wrong, what, known, meant):
    result = invoke(
        "check", SLIDER_CRANK, "--set", f"joints.rod_slider.clearance.{key}={wrong}",
        env={"COLUMNS": "60"},
    )  # fmt: skip
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert result.stderr.splitlines() == [
        f"joints[2].clearance.{key}: unknown {what} '{wrong}'; known {what}s are {known} "
        f"(did you mean '{meant}'?); a law of your own must be registered before the model is "
        "loaded (jointwear.register_law)"
    ]
