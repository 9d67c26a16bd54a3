"""The pin-in-slot clearance joint through the whole engine, against answers found without it.

A disc (the pin body, its centre the pin's) in a slot fixed to the ground is built inline.
Each test compares what comes out with a closed form (free flight, static equilibrium by
hand, Archard's law, the ideal joint driven along a turning slot), a conservation law (energy
through undamped rattling), an independent scipy solution (one impact), or the revolute
clearance joint (a slot of length 0).

The pin starts on the slot's centre line: the assembly holds it as the ideal joint, so an
initial velocity across the slot is projected away while one along it is kept.
"""

import math

import numpy as np
import pytest
from runs import EXAMPLES, disc
from scipy.integrate import solve_ivp
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.model import ModelError, parse_model

MASS, INERTIA = 1.0, 1e-4  # pin body [kg, kg m^2]
R_S, GAP, HALF, WIDTH, E, NU = 10e-3, 1e-4, 20e-3, 0.01, 207e9, 0.3  # [m, m, m, m, Pa, -]
R_P = R_S - GAP
E_STAR = 1.0 / (2.0 * (1.0 - NU**2) / E)  # steel on steel [Pa]
K = 4.0 / 3.0 * E_STAR * math.sqrt(R_S * R_P / GAP)  # one K, sides and ends [N/m^1.5]
G = 9.81


def clearance(**keys) -> dict:
    """Steel pin in a steel slot, frictionless, damped Hertz contact, no wear unless asked."""
    table = {
        "pin_radius": R_P,
        "slot_width": 2.0 * R_S,
        "slot_length": 2.0 * HALF,
        "width": WIDTH,
        "youngs_modulus": E,
        "poisson_ratio": NU,
        "restitution_coefficient": 0.9,
        "friction_coefficient": 0.0,
        "wear_coefficient": 0.0,
    }
    table.update(keys)
    if table.get("damping") == "none":
        del table["restitution_coefficient"]
    return table


def pin_model(joint: dict, forces: list[dict], t_end: float, axis=(1.0, 0.0), **solver) -> dict:
    """The pin in a slot through the ground's origin along ``axis``, with these loads."""
    return {
        "name": "pin",
        "ground": {"points": {"g": [0.0, 0.0]}},
        "bodies": [disc("pin", MASS, INERTIA)],
        "joints": [
            {
                "name": "slot",
                "type": "pin_in_slot",
                "bodies": ["ground", "pin"],
                "points": ["g", "c"],
                "axis": list(axis),
                "clearance": joint,
            }
        ],
        "forces": forces,
        "solver": {
            "integrator": "dopri5",
            "t_end": t_end,
            "rtol": 1e-10,
            "atol": 1e-12,
            "max_step": 1e-4,
            "output_interval": 1e-4,
            **solver,
        },
    }


def gravity(g: float = G) -> dict:
    return {"type": "gravity", "acceleration": [0.0, -g]}


def run(data: dict) -> jw.Results:
    res = jw.simulate(parse_model(data))
    assert res.status == "success", res.message
    return res


def test_free_flight_is_a_free_body():
    # No contact for 40 ms: a force (0, -0.1 N) at the centre and a torque of 1 mN m move the
    # pin as a free body, x = v t, y = -F t^2 / 2m, phi = T t^2 / 2J: at 40 ms it is 80 µm
    # down (the gap is 100 µm) and 8 mm along. Integration at rtol 1e-10 of a polynomial
    # motion: errors at rounding (measured 4e-17 m and 5e-17 rad at most); 1e-12.
    force = {"type": "point_force", "body": "pin", "point": "c", "force": [0.0, -0.1]}
    data = pin_model(
        clearance(), [force, {"type": "torque", "body": "pin", "torque": 1e-3}], t_end=0.04
    )
    data["bodies"][0]["velocity"] = [0.2, 0.0]
    res = run(data)
    df = res.timeseries
    t = df["time"].to_numpy()
    np.testing.assert_allclose(df["slot_along"], 0.2 * t, atol=1e-12)
    np.testing.assert_allclose(df["slot_across"], -0.1 * t**2 / (2 * MASS), atol=1e-12)
    np.testing.assert_allclose(df["phi_pin"], 1e-3 * t**2 / (2 * INERTIA), atol=1e-12)
    assert res.summary["clearance_joints"]["slot"]["impacts"] == 0
    assert (df["slot_fn"] == 0.0).all()


def test_rest_on_a_side_and_in_an_end_by_hand():
    # Gravity and a 20 N load press the pin onto the lower side of a level slot; damping
    # (restitution 0.3, Flores et al. 2011) settles it. At rest, by hand: F_N = m g + P, the
    # force on the pin (0, F_N), and the centre c + delta below the centre line with
    # delta = (F_N / K)^(2/3). The same in a slot tilted 30 degrees, the pin started at an end
    # centre: it falls into that end and rests at its bottom, F_N = m g, the centre at
    # c + delta from the end centre straight down: along -l - (c + delta) sin 30,
    # across -(c + delta) cos 30. Measured at 0.2 s: on the side 6e-15 relative at most; in
    # the end the force still rings at 8e-10 of m g (the pin's speed 2e-13 m/s), the place
    # 7e-14; 1e-9 on the side, 1e-8 in the end.
    load = 20.0
    flat = pin_model(
        clearance(damping="flores2011", restitution_coefficient=0.3),
        [gravity(), {"type": "point_force", "body": "pin", "point": "c", "force": [0.0, -load]}],
        t_end=0.2,
    )
    last = run(flat).timeseries.iloc[-1]
    total = MASS * G + load
    delta = (total / K) ** (2.0 / 3.0)
    assert last["slot_fn"] == pytest.approx(total, rel=1e-9)
    assert last["slot_fy"] == pytest.approx(total, rel=1e-9)
    assert abs(last["slot_fx"]) < 1e-9 * total
    assert last["slot_across"] == pytest.approx(-(GAP + delta), rel=1e-9)
    tilt = math.radians(30.0)
    tilted = pin_model(
        clearance(damping="flores2011", restitution_coefficient=0.3),
        [gravity()],
        t_end=0.2,
        axis=(math.cos(tilt), math.sin(tilt)),
    )
    tilted["bodies"][0]["position"] = [-HALF * math.cos(tilt), -HALF * math.sin(tilt)]
    last = run(tilted).timeseries.iloc[-1]
    reach = GAP + (MASS * G / K) ** (2.0 / 3.0)
    assert last["slot_fn"] == pytest.approx(MASS * G, rel=1e-8)
    assert last["slot_fy"] == pytest.approx(MASS * G, rel=1e-8)
    assert last["slot_along"] == pytest.approx(-HALF - reach * math.sin(tilt), rel=1e-8)
    assert last["slot_across"] == pytest.approx(-reach * math.cos(tilt), rel=1e-8)


def pendulum(joint_type: str, joint: dict) -> dict:
    """A 0.2 m bar hung by its end 'a' from the ground's origin, level at the start, gravity."""
    bar = disc("bar", 1.0, 1.0 * 0.2**2 / 12.0, position=[0.1, 0.0],
               points={"a": [-0.1, 0.0], "b": [0.1, 0.0]})  # fmt: skip
    model = pin_model(joint, [gravity()], t_end=0.05, output_interval=1e-5)
    model["bodies"] = [bar]
    model["joints"][0] |= {"type": joint_type, "bodies": ["ground", "bar"], "points": ["g", "a"]}
    if joint_type == "revolute":
        del model["joints"][0]["axis"]
    return model


def test_a_slot_of_length_zero_is_the_revolute_clearance_joint():
    # The same pendulum hung by a revolute clearance joint (R_B = R_s, R_J = R_p) and by a
    # pin in a slot of length 0: the same contact law, K, friction and wear, so the same
    # motion. Wear feedback is off: the revolute joint spreads a step's wear over the Hertz
    # patch, the slot puts it into one cell, which changes the worn profile (not its volume).
    # The two kernels share their geometry (``journal_geometry``) and laws: measured
    # identical to the last bit over 50 ms and 8 impacts; 1e-12 of each column's range and
    # relative, in case a kernel reorders its arithmetic.
    shared = {"width": WIDTH, "youngs_modulus": E, "poisson_ratio": NU,
              "restitution_coefficient": 0.9, "friction_coefficient": 0.1,
              "wear_coefficient": 1e-13, "wear_feedback": False}  # fmt: skip
    journal = run(pendulum("revolute", {"bearing_radius": R_S, "journal_radius": R_P, **shared}))
    slot = run(pendulum("pin_in_slot", clearance(slot_length=0.0, **shared)))
    a, b = journal.timeseries, slot.timeseries
    assert len(a) == len(b)
    pairs = {"slot_ex": "slot_along", "slot_ey": "slot_across", "slot_fx": "slot_fx",
             "slot_fy": "slot_fy", "slot_fn": "slot_fn", "slot_vt": "slot_vt",
             "x_bar": "x_bar", "y_bar": "y_bar", "phi_bar": "phi_bar",
             "omega_bar": "omega_bar"}  # fmt: skip
    for column, twin in pairs.items():
        scale = np.ptp(a[column].to_numpy())
        np.testing.assert_allclose(b[twin], a[column], rtol=0.0, atol=1e-12 * scale, err_msg=twin)
    ja, jb = journal.summary["clearance_joints"]["slot"], slot.summary["clearance_joints"]["slot"]
    assert ja["impacts"] == jb["impacts"] >= 3
    for key in ("max_contact_force_n", "worn_volume_m3", "energy_dissipated_damping_j",
                "energy_dissipated_friction_j", "sliding_distance_m"):  # fmt: skip
        assert jb[key] == pytest.approx(ja[key], rel=1e-12), key


def test_undamped_frictionless_rattling_conserves_energy():
    # The pin falls 0.1 mm onto the lower side under 100 m/s^2 while sliding at 0.2 m/s along
    # a 10 mm slot: it bounces on the side and off both ends. Without damping and friction
    # the contact is conservative: kinetic + potential + elastic energy stays constant.
    # The drift over the 142 impacts (up to 6 kN) is the integration's: measured 1.1e-6 of
    # the energy in play (the kinetic energy, 0.02 J) at rtol 1e-10 and 6.6e-8 at rtol 1e-12,
    # which this runs at; 5e-7.
    data = pin_model(
        clearance(damping="none", slot_length=0.01), [gravity(100.0)], t_end=0.2, rtol=1e-12
    )
    data["bodies"][0]["velocity"] = [0.2, 0.0]
    res = run(data)
    df = res.timeseries
    energy = df["energy_kinetic"] + df["energy_potential"] + df["energy_contact"]
    summary = res.summary["clearance_joints"]["slot"]
    assert summary["impacts"] >= 10
    assert summary["energy_dissipated_damping_j"] == 0.0
    impacts = set(res.impacts["contact"])
    assert {"side_minus_v", "end_plus_u", "end_minus_u"} <= impacts
    assert np.ptp(energy) < 5e-7 * 0.5 * MASS * 0.2**2


CHI = {  # hysteresis factor of each damping law, from its paper (laws.normal)
    "lankarani_nikravesh": lambda c_e: 0.75 * (1.0 - c_e**2),
    "hunt_crossley": lambda c_e: 1.5 * (1.0 - c_e),
    "flores2011": lambda c_e: 1.6 * (1.0 - c_e) / c_e,
}


@pytest.mark.parametrize(
    ("law", "c_e"), [("lankarani_nikravesh", 0.9), ("flores2011", 0.5), ("hunt_crossley", 0.8)]
)
def test_one_impact_reproduces_the_damping_law(law, c_e):
    # The pin slides at 0.5 m/s along the centre line into the +u end, head on: one contact
    # along the axis, m x'' = -K delta^1.5 (1 + chi delta' / v_in). Its rebound speed over
    # the approach speed, against scipy's solution of that equation (DOP853, rtol 1e-12):
    # measured 1e-8 at most; 5e-8. How close that comes to c_e is the law's own accuracy, not
    # the joint's: measured 0.913 for 0.9, 0.470 for 0.5 and 0.833 for 0.8; 7 %.
    speed = 0.5
    data = pin_model(clearance(damping=law, restitution_coefficient=c_e, slot_length=0.01),
                     [], t_end=0.015, output_interval=1e-5)  # fmt: skip
    data["bodies"][0]["velocity"] = [speed, 0.0]
    res = run(data)
    impacts = res.impacts
    assert list(impacts["contact"]) == ["end_plus_u"]
    assert impacts["end_angle_deg"].iloc[0] == pytest.approx(0.0, abs=1e-9)
    v_in = impacts["penetration_velocity_m_s"].iloc[0]
    assert v_in == pytest.approx(speed, rel=1e-8)  # the onset's rate, at 1-2 tolerances deep
    rebound = -res.timeseries["vx_pin"].iloc[-1]
    chi = CHI[law](c_e)

    def rhs(t, y):
        elastic = K * max(y[0], 0.0) ** 1.5
        return [y[1], -max(elastic * (1.0 + chi * y[1] / v_in), 0.0) / MASS]

    def apart(t, y):
        return y[0]

    apart.terminal, apart.direction = True, -1.0
    ref = solve_ivp(rhs, [0.0, 1e-3], [0.0, v_in], method="DOP853", rtol=1e-12, atol=1e-20,
                    events=apart, max_step=1e-7)  # fmt: skip
    expected = -ref.y_events[0][0][1] / v_in
    assert rebound / speed == pytest.approx(expected, rel=5e-8)
    assert rebound / speed == pytest.approx(c_e, rel=0.07)


def test_archard_closed_form_pressed_and_sliding():
    # The pin slides at 0.2 m/s along the slot, frictionless (so it does not turn and nothing
    # has to pull it), while a 50 N load presses it onto the lower side. Archard:
    # V = k v integral(F_N) dt, and the normal impulse is the load's, P T, less the pin's
    # final momentum across (zero at rest): V = k v P T. Every side segment the pin crosses
    # whole after landing takes (1 - share) k P / w deep, and the pin's one touched sector the
    # rest, share V over its area. The wear takes each step's force at its midpoint, which
    # through the landing's impacts is off by measured 5.5e-7; 5e-6. A step's wear goes into
    # the segment of its midpoint, so a segment's boundary is placed to within one step's
    # travel, v max_step = 0.02 mm of the 2 mm segments: 1e-2 (measured 1.2e-3).
    v, load, t_end, k, share, segments = 0.2, 50.0, 0.15, 1e-13, 0.3, 20
    data = pin_model(
        clearance(wear_coefficient=k, pin_wear_share=share, segments=segments, sectors=30,
                  damping="flores2011", restitution_coefficient=0.3),
        [{"type": "point_force", "body": "pin", "point": "c", "force": [0.0, -load]}],
        t_end=t_end,
    )  # fmt: skip
    data["bodies"][0]["position"] = [-0.015, 0.0]
    data["bodies"][0]["velocity"] = [v, 0.0]
    res = run(data)
    summary = res.summary["clearance_joints"]["slot"]
    volume = k * v * load * t_end
    assert summary["worn_volume_m3"] == pytest.approx(volume, rel=5e-6)
    wear = res.wear.set_index(["surface", "sector"])["depth_m"]
    # From x = -15 mm to +15 mm over segments of 2 mm from -20 mm: 3-16 crossed whole, the
    # first while the pin still bounces after landing (2 ms after the start, 0.4 mm on).
    np.testing.assert_allclose(
        wear["side_minus_v"].to_numpy()[4:15], (1 - share) * k * load / WIDTH, rtol=1e-2
    )
    assert (wear["side_plus_v"] == 0.0).all() and (wear["end_plus_u"] == 0.0).all()
    pin = wear["pin"].to_numpy()
    sector_area = 2.0 * math.pi * R_P / 30 * WIDTH
    assert pin.max() == pytest.approx(share * volume / sector_area, rel=5e-6)
    assert np.count_nonzero(pin) == 1
    # the pin's bottom, 270 degrees round from its x axis: the middle of sector 22 of 30
    assert summary["max_wear_position_pin_m"] == pytest.approx(0.75 * 2 * math.pi * R_P)


@pytest.mark.parametrize(("segments", "sectors"), [(4, 8), (37, 50)])
def test_worn_volume_does_not_depend_on_the_cells(segments, sectors):
    # A pin dropped into a tilted slot with friction and Archard wear but no feedback slides
    # into the lower end, rattles and turns: the motion is the same whatever the cells, and
    # the volume in the wear table (sum of depth x cell area, sides, ends and pin) is the
    # volume worn. Against 20 segments and 36 sectors: 1e-12 relative.
    def worn(n: int, m: int) -> tuple[float, float]:
        data = pin_model(
            clearance(wear_coefficient=1e-13, friction_coefficient=0.3, wear_feedback=False,
                      segments=n, sectors=m, slot_length=0.01),
            [gravity(100.0)], t_end=0.05, axis=(math.cos(0.3), math.sin(0.3)),
        )  # fmt: skip
        data["bodies"][0]["velocity"] = [-0.2 * math.cos(0.3), -0.2 * math.sin(0.3)]
        res = run(data)
        areas = {
            "side_plus_v": 0.01 / n,
            "side_minus_v": 0.01 / n,
            "pin": 2 * math.pi * R_P / m,
            "end_plus_u": math.pi * R_S / (m // 2),
            "end_minus_u": math.pi * R_S / (m // 2),
        }
        table = res.wear.groupby("surface")["depth_m"].sum()
        assert set(table[table > 0.0].index) >= {"pin", "end_minus_u", "side_minus_v"}
        mapped = sum(table[s] * areas[s] * WIDTH for s in areas)
        return mapped, res.summary["clearance_joints"]["slot"]["worn_volume_m3"]

    mapped, total = worn(segments, sectors)
    assert mapped == pytest.approx(total, rel=1e-12)
    assert total == pytest.approx(worn(20, 36)[1], rel=1e-12)


def test_the_ideal_joint_driven_along_a_turning_slot():
    # The ideal joint: a bar turning at 10 rad/s about the ground carries the slot; a distance
    # driver moves the pin along it, s = 0.1 + 0.02 sin(30 t). No gravity. The pin's centre
    # is then at s along the turning axis (the constraint holds it there: measured 8e-14 m;
    # 1e-10), and its acceleration is (s'' - s w^2) u + 2 s' w v: the driver's force along
    # the slot is m (s'' - s w^2) and the joint's reaction m 2 s' w, normal to the slot.
    # Measured: the reaction along the slot 2e-13 N, the forces 7e-9 N off, of up to 30 N;
    # 1e-7 of the largest.
    omega, s0, amplitude, frequency = 10.0, 0.1, 0.02, 30.0
    bar = disc("bar", 2.0, 0.02, angular_velocity=omega)
    slider = disc("pin", MASS, INERTIA, position=[s0, 0.0],
                  velocity=[amplitude * frequency, s0 * omega])  # fmt: skip
    model = {
        "name": "turning slot",
        "ground": {"points": {"g": [0.0, 0.0]}},
        "bodies": [bar, slider],
        "joints": [
            {"name": "hub", "type": "revolute", "bodies": ["ground", "bar"], "points": ["g", "c"]},
            {
                "name": "slot",
                "type": "pin_in_slot",
                "bodies": ["bar", "pin"],
                "points": ["c", "c"],
                "axis": [1.0, 0.0],
            },
        ],
        "drivers": [
            {
                "name": "turn",
                "type": "angle",
                "body": "bar",
                "function": {"type": "constant_speed", "speed": omega},
            },
            {
                "name": "push",
                "type": "distance",
                "joint": "slot",
                "function": {
                    "type": "harmonic",
                    "offset": s0,
                    "amplitude": amplitude,
                    "angular_frequency": frequency,
                },
            },
        ],
        "solver": {"t_end": 0.3, "output_interval": 1e-3, "rtol": 1e-10, "atol": 1e-12},
    }
    df = run(model).timeseries
    t = df["time"].to_numpy()
    s = s0 + amplitude * np.sin(frequency * t)
    ds = amplitude * frequency * np.cos(frequency * t)
    dds = -amplitude * frequency**2 * np.sin(frequency * t)
    u = np.column_stack([np.cos(omega * t), np.sin(omega * t)])
    v = np.column_stack([-u[:, 1], u[:, 0]])
    np.testing.assert_allclose(df["x_pin"], s * u[:, 0], atol=1e-10)
    np.testing.assert_allclose(df["y_pin"], s * u[:, 1], atol=1e-10)
    reaction = df[["slot_fx", "slot_fy"]].to_numpy()
    scale = MASS * max(np.abs(dds - s * omega**2).max(), 2 * np.abs(ds).max() * omega)
    np.testing.assert_allclose(np.sum(reaction * u, axis=1), 0.0, atol=1e-7 * scale)
    np.testing.assert_allclose(
        np.abs(np.sum(reaction * v, axis=1)), MASS * 2 * np.abs(ds) * omega, atol=1e-7 * scale
    )
    np.testing.assert_allclose(
        np.abs(df["force_push"]), MASS * np.abs(dds - s * omega**2), atol=1e-7 * scale
    )


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"pin_radius": R_S}, "must be smaller than half the slot_width"),
        ({"slot_length": -0.01}, "slot_length: got -0.01; must be >= 0"),
        ({"sectors": 35}, "give an even number"),
        ({"normal_law": "johnson"}, "applies to a journal in its bearing only"),
        ({"lubrication": "short_bearing", "viscosity": 0.02}, "touches a flat side"),
    ],
)
def test_bad_clearance_keys_say_what_is_wrong(change, message):
    with pytest.raises(ModelError, match=message):
        parse_model(pin_model(clearance(**change), [], t_end=0.01))


def test_a_pin_beyond_the_slot_end_is_refused():
    data = pin_model(clearance(), [], t_end=0.01)
    data["bodies"][0]["position"] = [HALF + 2 * GAP, 0.0]
    with pytest.raises(ModelError, match="the pin starts beyond the slot's end"):
        jw.simulate(parse_model(data))


def test_the_slotted_link_example_checks_and_runs():
    # The example's quick return: check shows the joint's table, and a tenth of a turn runs.
    path = EXAMPLES / "slotted_link.toml"
    result = CliRunner().invoke(app, ["check", str(path)], env={"COLUMNS": "120"})
    assert result.exit_code == 0, result.output
    assert "pin-in-slot clearance joint 'crank_pin'" in result.output
    assert "gap c = slot_width / 2 - R_p" in result.output
    res = jw.simulate(jw.load_model(path, overrides=["solver.t_end=0.04"]))
    assert res.status == "success", res.message
    assert res.summary["clearance_joints"]["crank_pin"]["type"] == "pin_in_slot"


def test_the_life_measures_by_hand():
    # Uniform depths d_s on every slot cell and d_p on the pin: the volume is the depths
    # times the surfaces' areas; the growth bound is the deepest slot cell plus the deepest
    # pin cell; a pin worn past its radius leaves the model.
    from jointwear.joints.pin_in_slot import KIND, SURFACES

    data = pin_model(clearance(segments=10, sectors=12), [], 1e-3)
    joint = parse_model(data).joints[0]
    wear = np.zeros((5, 12))
    d_s, d_p = 2e-6, 3e-6
    wear[:4, :10] = d_s  # sides' 10 segments; the ends' 6 sectors are the first 6 columns
    wear[4, :12] = d_p
    area_slot = WIDTH * (2 * 2 * HALF + 2 * math.pi * R_S)  # two sides, two half circles
    area_pin = WIDTH * 2 * math.pi * R_P
    assert KIND.worn_volume(joint, wear) == pytest.approx(d_s * area_slot + d_p * area_pin)
    wear[2, 3] = 5e-6  # one deeper end cell
    assert KIND.clearance_growth(joint, wear, []) == pytest.approx(5e-6 + d_p)
    assert KIND.worn_through(joint, wear, "at 10 cycles") is None
    wear[4, 0] = R_P
    assert "the pin would be worn" in KIND.worn_through(joint, wear, "at 10 cycles")
    assert set(KIND.mapped_surfaces(joint)) == set(SURFACES)
