"""The finite journal bearing and mixed lubrication through the whole engine.

The independent answers: the Reynolds equation solved directly (``film.reynolds``, not the
kernel's interpolated table) for a steadily loaded journal; Archard's law over the rows; the
bodies' energy against what the film, the friction and the damping dissipate; and the
convergence of the lubricated slider-crank as every numerical setting of the mixed model is
halved and doubled. The journal rig is that of test_film_and_foundation_joints.py (Table 2's
journal, 1 kg, turned at 200 rad/s, loaded at its centre).
"""

import math

import numpy as np
import pytest
from runs import EXAMPLES, whole_run
from test_film_and_foundation_joints import MU, OMEGA, R_J, WIDTH, C, bearing_model, run

import jointwear as jw
from jointwear.film import impedance
from jointwear.film.reynolds import film_force
from jointwear.model import ModelError, parse_model

RATIO = WIDTH / (2.0 * R_J)  # L / D = 1.02
SMOOTH = 0.01e-6  # a roughness whose asperities never touch here [m]


def finite(**keys) -> dict:
    """The clearance keys of a finite bearing (no film_breakdown: it has none)."""
    return {"lubrication": "finite_bearing", "roughness": SMOOTH, **keys}


def steady_capacity(eps: float) -> tuple[float, float]:
    """(load [N], attitude angle [deg]) of the steady film at eps, by the Reynolds solver.

    Fixed bearing, journal at OMEGA: V = -(OMEGA / 2) e e_t, |V| = eps c OMEGA / 2, psi =
    -90 deg, F = mu L R^3 |V| / c^3 W.
    """
    w_r, w_t = film_force(eps, -0.5 * math.pi, RATIO)
    speed = eps * C * OMEGA / 2.0
    load = MU * WIDTH * R_J**3 * speed / C**3 * math.hypot(w_r, w_t)
    return load, math.degrees(math.atan2(abs(w_t), abs(w_r)))


def model_with(**keys) -> dict:
    data = bearing_model(1.0, 0.01)
    data["joints"][0]["clearance"].pop("film_breakdown", None)
    data["joints"][0]["clearance"].update(finite(**keys))
    return data


# 1. The steady finite bearing --------------------------------------------------------------


def test_steady_finite_bearing_rests_where_the_reynolds_equation_puts_it():
    # The load the solved film carries at eps = 0.5, applied: the journal must settle at
    # eps = 0.5 with the line of centres at the solver's attitude angle from the load. The
    # run reads the interpolated table, the test the solver on its own grid: they differ
    # by the table's interpolation (the kernel against direct solves: within 0.3 % off the
    # nodes, tests/test_finite_bearing.py) and the dynamics' settling; 0.5 % in eps and
    # 0.3 deg.
    load, attitude = steady_capacity(0.5)
    data = bearing_model(load, 0.3)
    clearance = data["joints"][0]["clearance"]
    clearance.pop("film_breakdown", None)
    clearance.update(finite())
    res = run(data)
    rows = res.timeseries[res.timeseries["time"] >= 0.2]
    assert rows["J_eps"].to_numpy() == pytest.approx(0.5, rel=5e-3)
    gamma = np.degrees(np.arctan2(rows["J_ey"], rows["J_ex"])).to_numpy()
    np.testing.assert_allclose(gamma, -90.0 + attitude, atol=0.3)
    # The film alone carries it, no asperity touches (lambda ~ 1e4), nothing wears.
    np.testing.assert_allclose(rows["J_film_fy"], load, rtol=1e-4)
    assert (res.timeseries["J_fn"] == 0.0).all()
    film = whole_run(res, "J")["film"]
    assert film["asperity_load_share"] == 0.0
    assert film["min_lambda"] > 1e3


# 2. Mixed lubrication: the asperities take over as the film thins; only they wear ---------

RAMP, RAMP_END = 20000.0, 0.1  # load rising at [N/s] for [s]
THIN = 0.005  # [Pa s]
ROUGH = 0.5e-6  # [m]
K_WEAR = 8e-14  # [1/Pa]


@pytest.fixture(scope="module")
def ramp_run() -> jw.Results:
    data = bearing_model({"type": "polynomial", "coefficients": [0.0, -RAMP]}, RAMP_END)
    clearance = data["joints"][0]["clearance"]
    clearance.pop("film_breakdown", None)
    clearance.update(finite(viscosity=THIN, roughness=ROUGH, friction_coefficient=0.1))
    data["solver"].update(rtol=1e-8, atol=1e-12)
    return run(data)


def test_asperities_touch_below_four_sigma_and_share_the_load(ramp_run):
    df = ramp_run.timeseries
    lam = df["J_lambda"].to_numpy()
    fn = df["J_fn"].to_numpy()
    # Solid contact exactly where the film is thinner than 4 sigma, the fit's end.
    assert (fn[lam >= 4.0] == 0.0).all()
    assert (fn[lam < 4.0] > 0.0).all()
    assert (lam < 4.0).any() and (lam > 4.0).any()
    # The film still carries part of the load at the end, and the asperities the rest: the
    # sum balances the load (quasi-static: the journal's inertia force m a is below 1 N).
    end = df.iloc[-1]
    load = RAMP * end["time"]
    total = math.hypot(end["J_fx"] + end["J_film_fx"], end["J_fy"] + end["J_film_fy"])
    assert total == pytest.approx(load, rel=1e-3)
    assert 0.05 < end["J_asperity_share"] < 0.95


def test_only_the_solid_load_wears_by_archards_law(ramp_run):
    df = ramp_run.timeseries
    summary = whole_run(ramp_run, "J")
    time = df["time"].to_numpy()
    # Archard over the rows: k int F_N |v_t| dt with F_N the solid load (asperities and any
    # bulk contact), v_t the sliding speed; the trapezoid rule on rows 1e-4 s apart against
    # the steps' midpoint sums, measured 2e-6 apart; 1e-4. The film's load does not wear.
    rate = df["J_fn"].to_numpy() * np.abs(df["J_vt"].to_numpy())
    expected = K_WEAR * np.trapezoid(rate, time)
    assert expected > 0.0
    assert summary["worn_volume_m3"] == pytest.approx(expected, rel=1e-4)


# 3. Energy ----------------------------------------------------------------------------------


def test_a_free_journal_loses_what_film_friction_and_damping_dissipate():
    # No driver: the journal starts spinning at OMEGA under 400 N in thin oil; it sinks
    # through the film onto its asperities, which rub (friction 0.1) while the film shears.
    # What the load did plus the kinetic and contact energy lost is what the film, the
    # friction and the damping dissipated; to the integration's error at rtol 1e-9 (the
    # short bearing's free journal closes to 4e-7); 1e-5.
    data = bearing_model(400.0, 0.1)
    clearance = data["joints"][0]["clearance"]
    clearance.pop("film_breakdown", None)
    clearance.update(finite(viscosity=THIN, roughness=ROUGH, friction_coefficient=0.1))
    data["drivers"] = []
    data["bodies"][0].update(inertia=1e-4, angular_velocity=OMEGA)
    res = run(data)
    df = res.timeseries
    entry = whole_run(res, "J")
    assert entry["contact_time_fraction"] > 0.2  # the asperities do carry load
    stored = (df["energy_kinetic"] + df["energy_contact"]).to_numpy()
    work = 400.0 * (df["y_shaft"].iloc[0] - df["y_shaft"].iloc[-1])
    lost = sum(
        entry[k]
        for k in (
            "energy_dissipated_film_j",
            "energy_dissipated_friction_j",
            "energy_dissipated_damping_j",
        )
    )
    assert lost == pytest.approx(stored[0] - stored[-1] + work, rel=1e-5)


# 4. Numerical settings do not decide the answer ---------------------------------------------

LUBRICATED = EXAMPLES / "slider_crank_lubricated.toml"


def slider_crank(overrides: list[str]) -> tuple[float, float]:
    """(time in solid contact [-], wear per crank turn [m^3]) of the steady state."""
    model = jw.load_model(LUBRICATED, overrides=["solver.t_end=0.036", *overrides])
    res = jw.simulate(model)
    assert res.status == "success", res.message
    entry = res.summary["clearance_joints"]["rod_slider"]
    turns = res.summary["steady_state"]["windows"]
    return entry["contact_time_fraction"], entry["worn_volume_m3"] / turns


@pytest.fixture(scope="module")
def reference() -> tuple[float, float]:
    return slider_crank([])


def scaled_table(nodes: float, cells: float):
    """The default impedance table with its nodes scaled by ``nodes``, the film's cells by
    ``cells`` (even counts kept even)."""

    def size(default: int, factor: float, even: bool) -> int:
        n = round(default * factor)
        return n + n % 2 if even else n

    scaled = {
        "n_s": round((impedance.N_S - 1) * nodes) + 1,
        "n_chi": size(impedance.N_CHI, nodes, True),
        "n_angle": size(impedance.N_ANGLE, cells, True),
        "n_axial": size(impedance.N_AXIAL, cells, False),
    }
    return lambda ratio: impedance.build_table(ratio, **scaled)


# rtol and atol halved and doubled; the table's nodes and the film's cells halved, and its
# nodes doubled (the cells' own convergence: tests/test_finite_bearing.py). Measured
# (benchmarks/tribology_examples.py, five turns): the contact time moves by 0.08 % at most,
# the wear per turn by 0.7 % (rtol halved), 2.2 % (doubled), 2.0 % (table halved) and 0.1 %
# (nodes doubled): the wear integrates a load that rises as (4 - lambda)^7.3 by the steps'
# midpoints. 5 %.
SETTINGS = {
    "tolerances halved": (["solver.rtol=5e-7", "solver.atol=5e-9"], None),
    "tolerances doubled": (["solver.rtol=2e-6", "solver.atol=2e-8"], None),
    "table halved": ([], (0.5, 0.5)),
    "table nodes doubled": ([], (2.0, 1.0)),
}


@pytest.mark.parametrize("name", list(SETTINGS))
def test_contact_time_and_wear_converge(name, reference, monkeypatch):
    overrides, table = SETTINGS[name]
    if table is not None:
        monkeypatch.setattr(impedance, "impedance_table", scaled_table(*table))
    contact, wear = slider_crank(overrides)
    base_contact, base_wear = reference
    assert base_contact > 0.3 and base_wear > 0.0
    assert contact == pytest.approx(base_contact, rel=0.05)
    assert wear == pytest.approx(base_wear, rel=0.05)


# 5. The model file --------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("keys", "message"),
    [
        ({"roughness": None}, "finite_bearing': needs roughness"),
        ({"film_breakdown": 0.99}, "film_breakdown is used by lubrication 'short_bearing' or "),
        ({"lubrication": "short_bearing", "viscosity": 0.1}, "roughness is used by lubrication"),
        ({"roughness": 0.06e-3}, "its asperities would touch with the journal centred"),
        ({"width": 0.5}, "L/D = 25.51 is beyond the finite bearing's 20"),
        ({"roughness": float("nan")}, "roughness"),
        ({"asperity_slope": 2.0}, "asperity_slope"),
        ({"wear_distribution": "elastic_foundation"}, 'choose wear_distribution "hertz"'),
    ],
)
def test_a_mixed_film_is_asked_for_what_it_needs_and_nothing_else(keys, message):
    data = model_with(**{k: v for k, v in keys.items() if k != "width"})
    clearance = data["joints"][0]["clearance"]
    clearance.update({k: v for k, v in keys.items() if k == "width"})
    for key in [k for k, v in keys.items() if v is None]:
        clearance.pop(key)
    with pytest.raises(ModelError) as error:
        parse_model(data)
    assert message in str(error.value)
