"""Engine features against closed-form answers: sliders, springs, loads, drivers, assembly.

Each test builds a small model inline (``parse_model``; the slider-crank and four-bar come from
``examples/``), runs it for a fraction of a second at rtol 1e-10, atol 1e-12 and compares the
result with an answer derived by hand: closed-form kinematics, Newton-Euler equations written
body by body, conserved momenta and energy, or (for the body whose moment arm turns with it)
scipy's DOP853 on the three rigid-body equations. Motions prescribed by drivers come out to
~1e-13 of their scale, free motions to the integrator's ~1e-10.
"""

import numpy as np
import pytest
from references import BODY_NAMES, fourbar_states
from runs import EXAMPLES
from scipy.integrate import cumulative_simpson, solve_ivp

import jointwear as jw
from jointwear.mechanism.assembly import assemble
from jointwear.mechanism.system import build_system
from jointwear.model import parse_model

TIGHT = {"rtol": 1e-10, "atol": 1e-12}
INTEGRATORS = ("dopri5", "abm")
G = 9.81  # [m/s^2]


def simulate(data: dict, **solver):
    """Validate an inline model with tight tolerances, run it, insist it finished."""
    model = parse_model({**data, "solver": {**TIGHT, **solver}})
    res = jw.simulate(model)
    assert res.status == "success", res.message
    return res.timeseries


def col(df, name):
    return df[name].to_numpy()


# Agreement asked of an integrated quantity, relative to its scale over the run: a motion
# integrated at rtol 1e-10 over a few periods carries a global error of a few rtol of its
# scale (measured here: 1e-13 to 9e-10), so 1e-8 leaves a margin of 10 or more, while a wrong
# sign, factor or missing term of the physics shows at 1e-4 or above.
REL = 1e-8


def assert_close(actual, expected, scale, rel=REL):
    """|actual - expected| <= rel * scale everywhere."""
    np.testing.assert_allclose(actual, expected, rtol=0, atol=rel * scale)


def rotate(phi, p):
    """A(phi) p for a body point p [m]."""
    c, s = np.cos(phi), np.sin(phi)
    return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])


def oscillator(t, x0, v0, omega, zeta, x_eq=0.0):
    """Free linear oscillator x'' + 2 zeta omega x' + omega^2 (x - x_eq) = 0 (zeta < 1).

    Returns x(t), x'(t).
    """
    wd = omega * np.sqrt(1.0 - zeta**2)
    a = x0 - x_eq
    b = (v0 + zeta * omega * a) / wd
    decay = np.exp(-zeta * omega * t)
    c, s = np.cos(wd * t), np.sin(wd * t)
    x = x_eq + decay * (a * c + b * s)
    v = decay * ((b * wd - zeta * omega * a) * c - (a * wd + zeta * omega * b) * s)
    return x, v


# 1. Translational joint on a tilted axis, driven by a harmonic distance driver --------------

AXIS_ANGLE = np.radians(30.0)
U = np.array([np.cos(AXIS_ANGLE), np.sin(AXIS_ANGLE)])  # along the axis
N = np.array([-U[1], U[0]])  # across it
RAIL = np.array([0.1, -0.05])  # ground point on the line [m]
PIN = np.array([0.03, -0.01])  # slider point on the line, off the centre of mass [m]
SLIDER_MASS, SLIDER_ANGLE = 0.8, 0.3  # [kg], [rad]
S_OFF, S_AMP, S_W, S_PHASE = 0.2, 0.05, 20.0, 0.4  # harmonic slide [m, m, rad/s, rad]


# Constraint 2-norm at the output rows: Baumgarte-stabilised, a fully driven joint stays met
# to rounding and integration error (measured 1e-14 m); the augmented Lagrangian projects to
# 1e-13 of the mechanism's size at each step's end, and rows between ends carry a step's
# drift at rtol 1e-10 (measured 1e-10 m).
VIOLATION = {"baumgarte": 1e-12, "augmented_lagrangian": 2e-10}
# A constant reaction: Baumgarte's multipliers carry only rounding (1e-12 N); the augmented
# Lagrangian iterations stop at a relative change of 1e-10, and the penalty (1e6) scales the
# rounding of the leading matrix's solve: measured 1.8e-9 N of 3.4 N, so 1e-8 N.
REACTION_ATOL = {"baumgarte": 1e-12, "augmented_lagrangian": 1e-8}


@pytest.mark.parametrize("formulation", VIOLATION)
def test_distance_driver_on_tilted_translational_joint(formulation):
    s0 = S_OFF + S_AMP * np.sin(S_PHASE)
    centre0 = RAIL + s0 * U - rotate(SLIDER_ANGLE, PIN)
    df = simulate(
        {
            "ground": {"points": {"rail": RAIL.tolist()}},
            "bodies": [
                {
                    "name": "slider",
                    "mass": SLIDER_MASS,
                    "inertia": 0.002,
                    "position": centre0.tolist(),
                    "angle": SLIDER_ANGLE,
                    "points": {"pin": PIN.tolist()},
                }
            ],
            "joints": [
                {
                    "name": "guide",
                    "type": "translational",
                    "bodies": ["ground", "slider"],
                    "points": ["rail", "pin"],
                    "axis": [2.0 * U[0], 2.0 * U[1]],  # not unit length on purpose
                }
            ],
            "drivers": [
                {
                    "name": "push",
                    "type": "distance",
                    "joint": "guide",
                    "function": {
                        "type": "harmonic",
                        "offset": S_OFF,
                        "amplitude": S_AMP,
                        "angular_frequency": S_W,
                        "phase": S_PHASE,
                    },
                }
            ],
            "forces": [{"type": "gravity", "acceleration": [0.0, -G]}],
        },
        t_end=0.5,
        output_interval=1e-3,
        formulation=formulation,
    )
    t = col(df, "time")
    arg = S_W * t + S_PHASE
    s = S_OFF + S_AMP * np.sin(arg)
    sd = S_AMP * S_W * np.cos(arg)
    sdd = -S_AMP * S_W**2 * np.sin(arg)
    assert col(df, "constraint_violation").max() < VIOLATION[formulation]
    phi = col(df, "phi_slider")
    pin = np.stack([col(df, "x_slider"), col(df, "y_slider")]) + rotate(phi, PIN)
    offset = pin - RAIL[:, None]
    # Prescribed motion: stabilised or projected integration, REL of the scale (0.25 m slide).
    assert_close(offset.T @ U, s, scale=0.25)
    assert_close(offset.T @ N, 0.0, scale=0.25)
    assert_close(phi, SLIDER_ANGLE, scale=SLIDER_ANGLE)
    # The angle is held, so the centre of mass moves as the pin: s' U and s'' U; REL of the
    # speed (1 m/s) and acceleration (20 m/s^2) amplitudes.
    for k, axis in enumerate("xy"):
        assert_close(col(df, f"v{axis}_slider"), sd * U[k], scale=S_AMP * S_W)
        assert_close(col(df, f"a{axis}_slider"), sdd * U[k], scale=S_AMP * S_W**2)
    # Newton along the axis: m s'' = F + m g . U, F being the driver's force on the slider
    # along +U; across it the joint carries -m (g . N) N, there being no motion across.
    gravity = np.array([0.0, -G])
    expected = SLIDER_MASS * (sdd - gravity @ U)
    # Multipliers of the same accurate state: REL of the largest force (~20 N).
    assert_close(col(df, "force_push"), expected, scale=np.abs(expected).max())
    reaction = -SLIDER_MASS * (gravity @ N) * N
    # Constant in time and free of the integration error.
    atol = REACTION_ATOL[formulation]
    np.testing.assert_allclose(col(df, "guide_fx"), reaction[0], rtol=0, atol=atol)
    np.testing.assert_allclose(col(df, "guide_fy"), reaction[1], rtol=0, atol=atol)


def test_constant_speed_distance_driver_starts_at_the_guessed_slide():
    # constant_speed without `initial` starts from the slide of the pose guess, measured along
    # the normalised axis (given here 3 units long): s = s0 + v t, with no force needed.
    s0, speed = 0.15, 0.4  # [m], [m/s]
    df = simulate(
        {
            "ground": {"points": {"rail": RAIL.tolist()}},
            "bodies": [
                {
                    "name": "slider",
                    "mass": SLIDER_MASS,
                    "inertia": 0.002,
                    "position": (RAIL + s0 * U).tolist(),
                    "angle": 0.0,
                    "points": {"pin": [0.0, 0.0]},
                }
            ],
            "joints": [
                {
                    "name": "guide",
                    "type": "translational",
                    "bodies": ["ground", "slider"],
                    "points": ["rail", "pin"],
                    "axis": [3.0 * U[0], 3.0 * U[1]],
                }
            ],
            "drivers": [
                {
                    "name": "push",
                    "type": "distance",
                    "joint": "guide",
                    "function": {"type": "constant_speed", "speed": speed},
                }
            ],
        },
        t_end=0.2,
        output_interval=1e-3,
    )
    t = col(df, "time")
    slide = (np.stack([col(df, "x_slider"), col(df, "y_slider")]) - RAIL[:, None]).T @ U
    # Prescribed motion: REL of the 0.23 m slide and the 0.4 m/s speed.
    assert_close(slide, s0 + speed * t, scale=0.23)
    assert_close(col(df, "vx_slider"), speed * U[0], scale=speed)
    # Uniform motion without gravity needs no force: rounding only (measured 2e-14 N).
    np.testing.assert_allclose(col(df, "force_push"), 0.0, rtol=0, atol=1e-10)


def perp(v):
    """v turned by +90 degrees; v has x, y along its first axis."""
    return np.stack([-v[1], v[0]])


def cross(a, b):
    """z component of a x b; a, b have x, y along their first axis."""
    return a[0] * b[1] - a[1] * b[0]


@pytest.mark.parametrize("formulation", VIOLATION)
def test_slider_on_a_rotating_arm(formulation):
    # A translational joint whose first body moves: an arm turning about the ground origin
    # (angle driver, theta = polynomial) carries a slider driven along a track on it (distance
    # driver, s = harmonic). Every joint point is off its body's centre of mass and the track
    # is skew to the arm's x axis. In the arm frame the slider's centre sits at w = c + s a
    # (c constant, a the unit track axis), so globally r = R w, v = R (w' + theta' J w) and
    # acceleration R (w'' + 2 theta' J w' + theta'' J w - theta'^2 w), J the +90 degree turn.
    # Newton along R a and across it gives the driver force and the joint's normal force;
    # the angular-momentum balance about the origin gives the arm's motor torque.
    theta_c = (0.4, 3.0, 5.0)  # theta = c0 + c1 t + c2 t^2 [rad, rad/s, rad/s^2]
    s_off, s_amp, s_w, s_phase = 0.3, 0.1, 9.0, 0.2  # [m, m, rad/s, rad]
    m_arm, j_arm, m_slider, j_slider = 2.0, 0.05, 0.6, 0.003
    pivot = np.array([-0.1, 0.02])  # arm point on the ground origin [m]
    track = np.array([0.05, -0.03])  # arm point on the track line [m]
    axis = np.array([np.cos(0.3), np.sin(0.3)])  # track direction in the arm frame
    pin = np.array([0.02, 0.01])  # slider point on the track line [m]
    delta = 0.25  # slider angle minus arm angle, held by the joint [rad]
    c = track - pivot - rotate(delta, pin)
    s0 = s_off + s_amp * np.sin(s_phase)
    df = simulate(
        {
            "ground": {"points": {"origin": [0.0, 0.0]}},
            "bodies": [
                {
                    "name": "arm",
                    "mass": m_arm,
                    "inertia": j_arm,
                    "position": (-rotate(theta_c[0], pivot)).tolist(),
                    "angle": theta_c[0],
                    "points": {"pivot": pivot.tolist(), "track": track.tolist()},
                },
                {
                    "name": "slider",
                    "mass": m_slider,
                    "inertia": j_slider,
                    "position": rotate(theta_c[0], c + s0 * axis).tolist(),
                    "angle": theta_c[0] + delta,
                    "points": {"pin": pin.tolist()},
                },
            ],
            "joints": [
                {
                    "name": "hub",
                    "type": "revolute",
                    "bodies": ["ground", "arm"],
                    "points": ["origin", "pivot"],
                },
                {
                    "name": "slide",
                    "type": "translational",
                    "bodies": ["arm", "slider"],
                    "points": ["track", "pin"],
                    "axis": axis.tolist(),
                },
            ],
            "drivers": [
                {
                    "name": "turn",
                    "type": "angle",
                    "body": "arm",
                    "function": {"type": "polynomial", "coefficients": list(theta_c)},
                },
                {
                    "name": "extend",
                    "type": "distance",
                    "joint": "slide",
                    "function": {
                        "type": "harmonic",
                        "offset": s_off,
                        "amplitude": s_amp,
                        "angular_frequency": s_w,
                        "phase": s_phase,
                    },
                },
            ],
            "forces": [{"type": "gravity", "acceleration": [0.0, -G]}],
        },
        t_end=0.5,
        output_interval=1e-3,
        formulation=formulation,
    )
    t = col(df, "time")
    c0, c1, c2 = theta_c
    th, thd, thdd = c0 + c1 * t + c2 * t**2, c1 + 2 * c2 * t, 2 * c2 + 0 * t
    arg = s_w * t + s_phase
    s = s_off + s_amp * np.sin(arg)
    sd = s_amp * s_w * np.cos(arg)
    sdd = -s_amp * s_w**2 * np.sin(arg)
    w = c[:, None] + s * axis[:, None]
    wd, wdd = sd * axis[:, None], sdd * axis[:, None]
    r_slider = rotate(th, w)
    v_slider = rotate(th, wd + thd * perp(w))
    a_slider = rotate(th, wdd + 2 * thd * perp(wd) + thdd * perp(w) - thd**2 * w)
    expected = {
        "x": r_slider[0],
        "y": r_slider[1],
        "phi": th + delta,
        "vx": v_slider[0],
        "vy": v_slider[1],
        "omega": thd,
        "ax": a_slider[0],
        "ay": a_slider[1],
        "alpha": thdd,
    }
    for name, value in expected.items():
        # Prescribed motion: stabilised or projected integration, REL of each scale.
        assert_close(col(df, f"{name}_slider"), value, scale=np.abs(value).max())
    assert col(df, "constraint_violation").max() < VIOLATION[formulation]
    gravity = np.array([[0.0], [-G]])
    along, across = rotate(th, axis), rotate(th, perp(axis))  # global track directions
    force = m_slider * ((a_slider - gravity) * along).sum(axis=0)  # m a.e = F + m g.e
    normal = m_slider * ((a_slider - gravity) * across).sum(axis=0)  # m a.n = N + m g.n
    # Multipliers of the same accurate state: REL of the largest force (~8 N).
    assert_close(col(df, "force_extend"), force, scale=np.abs(force).max())
    assert_close(col(df, "slide_fx"), normal * across[0], scale=np.abs(normal).max())
    assert_close(col(df, "slide_fy"), normal * across[1], scale=np.abs(normal).max())
    # dH/dt about the origin = T + sum r x m g (the pin force there has no moment), with
    # H = (J_arm + J_slider) theta' + sum m r x v.
    r_arm = rotate(th, -pivot[:, None] + 0 * t)
    a_arm = rotate(th, -thdd * perp(pivot[:, None]) + thd**2 * pivot[:, None])
    torque = (
        (j_arm + j_slider) * thdd
        + m_arm * cross(r_arm, a_arm - gravity)
        + m_slider * cross(r_slider, a_slider - gravity)
    )
    assert_close(col(df, "torque_turn"), torque, scale=np.abs(torque).max())


# 2. Slider-crank kinematics (examples/slider_crank.toml) -------------------------------------

CRANK, ROD, OFFSET = 0.05, 0.12, 0.0  # crank radius, rod length, slider line offset [m]
CRANK_SPEED = 5000.0 * 2.0 * np.pi / 60.0  # [rad/s]


def slider_position(theta):
    """Slider x (pin on the line y = OFFSET) and its first two derivatives in theta."""
    h = CRANK * np.sin(theta) - OFFSET  # rod's rise from crank pin to slider pin, negated
    hd = CRANK * np.cos(theta)
    hdd = -CRANK * np.sin(theta)
    d = np.sqrt(ROD**2 - h**2)
    x = CRANK * np.cos(theta) + d
    xd = -CRANK * np.sin(theta) - h * hd / d
    xdd = -CRANK * np.cos(theta) - (hd**2 + h * hdd) / d - h**2 * hd**2 / d**3
    return x, xd, xdd


def test_slider_crank_reference_derivatives():
    # Guard on the hand derivatives: complex step (exact to rounding) on x and x'.
    theta = np.linspace(0.0, 2.0 * np.pi, 97)
    step = 1e-30
    _, xd, xdd = slider_position(theta)
    np.testing.assert_allclose(xd, slider_position(theta + 1j * step)[0].imag / step, atol=1e-15)
    np.testing.assert_allclose(xdd, slider_position(theta + 1j * step)[1].imag / step, atol=1e-15)


def test_slider_crank_follows_the_closed_form():
    turn = 2.0 * np.pi / CRANK_SPEED  # 12 ms
    model = jw.load_model(
        EXAMPLES / "slider_crank.toml",
        [f"solver.t_end={turn}", "solver.rtol=1e-10", "solver.atol=1e-12"],
    )
    res = jw.simulate(model)
    assert res.status == "success", res.message
    df = res.timeseries
    theta = CRANK_SPEED * col(df, "time")
    x, xd, xdd = slider_position(theta)
    # Prescribed motion (driven, no freedom left): Baumgarte-stabilised integration to REL of
    # the scales: stroke 0.17 m, speed r w = 26 m/s, acceleration r w^2 (1 + r/l) = 1.9e4 m/s^2.
    assert_close(col(df, "x_slider"), x, scale=np.abs(x).max())
    assert_close(col(df, "vx_slider"), CRANK_SPEED * xd, scale=CRANK_SPEED * np.abs(xd).max())
    assert_close(
        col(df, "ax_slider"), CRANK_SPEED**2 * xdd, scale=CRANK_SPEED**2 * np.abs(xdd).max()
    )
    # On the guide line and not turning: the translational joint's two rows (0.17 m scale).
    assert_close(col(df, "y_slider"), OFFSET, scale=0.17)
    assert_close(col(df, "phi_slider"), 0.0, scale=1.0)
    # Rod angle from the crank pin to the slider pin (+-0.43 rad).
    rod = np.arctan2(OFFSET - CRANK * np.sin(theta), x - CRANK * np.cos(theta))
    assert_close(col(df, "phi_rod"), rod, scale=np.abs(rod).max())


# 3. Translational spring-damper ----------------------------------------------------------------

SPRING_K, SPRING_L0, SPRING_MASS = 1000.0, 0.1, 0.5  # [N/m], [m], [kg]
SPRING_OMEGA = np.sqrt(SPRING_K / SPRING_MASS)  # 44.7 rad/s, period 0.14 s
SPRING_DIR = np.array([np.cos(0.5), np.sin(0.5)])  # line of the free-body case


def spring_model(damping: float, guided: bool, x0: float) -> dict:
    """A body on a spring-damper from a ground anchor to its centre of mass.

    Guided: on a translational joint along global x, under gravity (taken by the joint).
    Free: no joint and no gravity, released on the line SPRING_DIR through the anchor.
    """
    direction = np.array([1.0, 0.0]) if guided else SPRING_DIR
    data = {
        "ground": {"points": {"anchor": [0.0, 0.0]}},
        "bodies": [
            {
                "name": "mass",
                "mass": SPRING_MASS,
                "inertia": 1e-3,
                "position": (x0 * direction).tolist(),
                "angle": 0.0,
                "points": {"pin": [0.0, 0.0]},
            }
        ],
        "forces": [
            {
                "type": "spring_damper",
                "bodies": ["ground", "mass"],
                "points": ["anchor", "pin"],
                "stiffness": SPRING_K,
                "damping": damping,
                "free_length": SPRING_L0,
            }
        ],
    }
    if guided:
        data["joints"] = [
            {
                "name": "rail",
                "type": "translational",
                "bodies": ["ground", "mass"],
                "points": ["anchor", "pin"],
                "axis": [1.0, 0.0],
            }
        ]
        data["forces"].append({"type": "gravity", "acceleration": [0.0, -G]})
    return data


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("guided", [True, False], ids=["guided", "free"])
@pytest.mark.parametrize("zeta", [0.0, 0.05])
def test_spring_damper_oscillator(guided, zeta, integrator):
    damping = 2.0 * zeta * np.sqrt(SPRING_K * SPRING_MASS)
    stretch = 0.03  # released from rest 30 mm beyond the free length [m]
    x0 = SPRING_L0 + stretch
    df = simulate(
        spring_model(damping, guided, x0), t_end=0.3, output_interval=1e-3, integrator=integrator
    )
    t = col(df, "time")
    x, v = oscillator(t, x0, 0.0, SPRING_OMEGA, zeta, SPRING_L0)
    direction = np.array([1.0, 0.0]) if guided else SPRING_DIR
    across = np.array([-direction[1], direction[0]])
    pos = np.stack([col(df, "x_mass"), col(df, "y_mass")])
    vel = np.stack([col(df, "vx_mass"), col(df, "vy_mass")])
    # Two periods of a free oscillation: REL of the 30 mm amplitude and of the 1.3 m/s speed.
    assert_close(direction @ pos, x, scale=stretch)
    assert_close(direction @ vel, v, scale=SPRING_OMEGA * stretch)
    # Nothing pushes it off the line or turns it: zero but for rounding (1e-12 m, rad).
    np.testing.assert_allclose(across @ pos, 0.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(col(df, "phi_mass"), 0.0, rtol=0, atol=1e-12)
    # Energies 1/2 m v^2 and 1/2 k (L - L0)^2; gravity adds m g y = 0 on the guide. Their
    # errors are those of x and v times k (x - L0) or m v: REL of the 0.45 J stored.
    energy = 0.5 * SPRING_K * stretch**2
    assert_close(col(df, "energy_kinetic"), 0.5 * SPRING_MASS * v**2, scale=energy)
    assert_close(col(df, "energy_potential"), 0.5 * SPRING_K * (x - SPRING_L0) ** 2, scale=energy)
    if guided:
        # The rail holds the weight and nothing else (the spring acts along it): rounding only.
        np.testing.assert_allclose(col(df, "rail_fx"), 0.0, rtol=0, atol=1e-12)
        np.testing.assert_allclose(col(df, "rail_fy"), SPRING_MASS * G, rtol=1e-14, atol=0)
    if zeta == 0.0:
        # Undamped: the total is conserved, to the same bound.
        assert_close(col(df, "energy_kinetic") + col(df, "energy_potential"), energy, scale=energy)


@pytest.mark.parametrize("damping", [0.0, 0.5])
def test_spring_damper_between_two_free_bodies(damping):
    # Two free bodies (no joints, no gravity) joined by a spring-damper between points off
    # their centres of mass, both spinning: no closed form, but the pair of forces is equal,
    # opposite and collinear, so linear and angular momentum are conserved, and the energy
    # lost equals the damper's work, the integral of c L'^2 (L the length between the points).
    k, free_length = 200.0, 0.3  # [N/m], [m]
    s_a, s_b = np.array([0.05, 0.02]), np.array([-0.04, 0.03])  # spring ends [m]
    bodies = {  # mass, inertia, position, angle, velocity, angular velocity
        "a": (0.5, 0.002, [0.0, 0.0], 0.2, [0.1, -0.2], 1.0),
        "b": (0.8, 0.004, [0.4, 0.1], -0.3, [-0.3, 0.2], -2.0),
    }
    df = simulate(
        {
            "bodies": [
                {
                    "name": name,
                    "mass": m,
                    "inertia": j,
                    "position": r,
                    "angle": phi,
                    "velocity": v,
                    "angular_velocity": w,
                    "points": {"end": end.tolist()},
                }
                for (name, (m, j, r, phi, v, w)), end in zip(
                    bodies.items(), (s_a, s_b), strict=True
                )
            ],
            "forces": [
                {
                    "type": "spring_damper",
                    "bodies": ["a", "b"],
                    "points": ["end", "end"],
                    "stiffness": k,
                    "damping": damping,
                    "free_length": free_length,
                }
            ],
        },
        t_end=0.5,
        output_interval=2.5e-4,
    )
    t = col(df, "time")
    momentum = np.zeros((2, len(t)))
    angular = np.zeros(len(t))
    ends, end_rates = [], []
    for name, end in zip(bodies, (s_a, s_b), strict=True):
        m, j = bodies[name][:2]
        r = np.stack([col(df, f"x_{name}"), col(df, f"y_{name}")])
        v = np.stack([col(df, f"vx_{name}"), col(df, f"vy_{name}")])
        w = col(df, f"omega_{name}")
        momentum += m * v
        angular += j * w + m * cross(r, v)
        arm = rotate(col(df, f"phi_{name}"), end)
        ends.append(r + arm)
        end_rates.append(v + w * perp(arm))
    # Equal and opposite forces keep the linear momentum exactly (a linear invariant of the
    # Runge-Kutta steps): rounding only, 1e-14 N s against ~0.3 N s per body.
    np.testing.assert_allclose(momentum - momentum[:, :1], 0.0, rtol=0, atol=1e-14)
    # Angular momentum (about the origin) is quadratic in the state: conserved to the
    # integration error, REL of its scale m |r| |v| + J w ~ 0.1 N m s.
    assert_close(angular, angular[0], scale=np.abs(angular).max())
    span = ends[1] - ends[0]
    length = np.hypot(*span)
    rate = (span * (end_rates[1] - end_rates[0])).sum(axis=0) / length
    # The spring's energy from the output state: the same formula, rounding only.
    spring = 0.5 * k * (length - free_length) ** 2
    np.testing.assert_allclose(col(df, "energy_potential"), spring, rtol=1e-12, atol=1e-15)
    energy = col(df, "energy_kinetic") + col(df, "energy_potential")
    lost = cumulative_simpson(damping * rate**2, x=t, initial=0.0)
    # Energy E(0) - E(t) equals the damper's work (zero when undamped); Simpson on 0.25 ms
    # rows adds ~h^4 of error, below the integration error: REL of the initial energy.
    assert_close(energy[0] - energy, lost, scale=energy[0])
    assert lost[-1] > 0.1 * energy[0] or damping == 0.0  # the damper does take energy out


# 4. Rotational spring-damper ------------------------------------------------------------------

ROT_K, ROT_J, ROT_FREE = 10.0, 0.01, 0.2  # [N m/rad], [kg m^2], [rad]
ROT_OMEGA = np.sqrt(ROT_K / ROT_J)  # 31.6 rad/s, period 0.2 s
DISC_MASS, DISC_PIVOT = 0.7, [0.2, 0.1]  # [kg], ground pivot at the centre of mass [m]


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("ground_first", [True, False], ids=["ground_first", "ground_second"])
@pytest.mark.parametrize("zeta", [0.0, 0.05])
def test_rotational_spring_to_ground(zeta, ground_first, integrator):
    damping = 2.0 * zeta * np.sqrt(ROT_K * ROT_J)
    phi0, omega0 = ROT_FREE + 0.5, 3.0  # [rad], [rad/s]
    pin_bodies = ["ground", "disc"] if ground_first else ["disc", "ground"]
    pin_points = ["pivot", "centre"] if ground_first else ["centre", "pivot"]
    df = simulate(
        {
            "ground": {"points": {"pivot": DISC_PIVOT}},
            "bodies": [
                {
                    "name": "disc",
                    "mass": DISC_MASS,
                    "inertia": ROT_J,
                    "position": DISC_PIVOT,
                    "angle": phi0,
                    "angular_velocity": omega0,
                    "points": {"centre": [0.0, 0.0]},
                }
            ],
            "joints": [
                {"name": "pin", "type": "revolute", "bodies": pin_bodies, "points": pin_points}
            ],
            "forces": [
                {"type": "gravity", "acceleration": [0.0, -G]},
                {
                    "type": "rotational_spring_damper",
                    "bodies": ["ground", "disc"],
                    "stiffness": ROT_K,
                    "damping": damping,
                    "free_angle": ROT_FREE,
                },
            ],
        },
        t_end=0.4,
        output_interval=1e-3,
        integrator=integrator,
    )
    t = col(df, "time")
    phi, omega = oscillator(t, phi0, omega0, ROT_OMEGA, zeta, ROT_FREE)
    amplitude = np.hypot(0.5, omega0 / ROT_OMEGA)  # [rad]
    # Two periods of a free oscillation: REL of the amplitude and of the peak rate.
    assert_close(col(df, "phi_disc"), phi, scale=amplitude)
    assert_close(col(df, "omega_disc"), omega, scale=ROT_OMEGA * amplitude)
    # Pinned at its centre of mass, the pin carries the weight and nothing else: up on the
    # disc, down on the ground when that is the joint's second body. Rounding only.
    weight = DISC_MASS * G if ground_first else -DISC_MASS * G
    np.testing.assert_allclose(col(df, "pin_fx"), 0.0, rtol=0, atol=1e-12)
    np.testing.assert_allclose(col(df, "pin_fy"), weight, rtol=1e-14, atol=0)
    # Energies: 1/2 J omega^2; 1/2 k (phi - free angle)^2 plus the constant m g y_pivot.
    # Errors of phi and omega times k phi or J omega: REL of the energy at release.
    energy = 0.5 * ROT_J * omega0**2 + 0.5 * ROT_K * 0.5**2
    potential = 0.5 * ROT_K * (phi - ROT_FREE) ** 2 + DISC_MASS * G * DISC_PIVOT[1]
    assert_close(col(df, "energy_kinetic"), 0.5 * ROT_J * omega**2, scale=energy)
    assert_close(col(df, "energy_potential"), potential, scale=energy)


def test_rotational_spring_between_two_bodies():
    # Two wheels, each pinned to the ground at its centre of mass, joined by a rotational
    # spring: the relative angle oscillates at sqrt(k (J1 + J2) / (J1 J2)) while the total
    # angular momentum J1 w1 + J2 w2 = H stays constant, so
    # J1 phi1 + J2 phi2 = C + H t, phi2 - phi1 = theta(t).
    j1, j2 = 0.01, 0.03
    omega = np.sqrt(ROT_K * (j1 + j2) / (j1 * j2))
    phi1_0, phi2_0, w1_0, w2_0 = 0.1, 0.9, 2.0, -1.0
    wheels = [
        {
            "name": name,
            "mass": 1.0,
            "inertia": j,
            "position": [x, 0.0],
            "angle": phi,
            "angular_velocity": w,
            "points": {"centre": [0.0, 0.0]},
        }
        for name, j, x, phi, w in (("one", j1, 0.0, phi1_0, w1_0), ("two", j2, 1.0, phi2_0, w2_0))
    ]
    df = simulate(
        {
            "ground": {"points": {"axle1": [0.0, 0.0], "axle2": [1.0, 0.0]}},
            "bodies": wheels,
            "joints": [
                {
                    "name": f"pin{k}",
                    "type": "revolute",
                    "bodies": ["ground", name],
                    "points": [f"axle{k}", "centre"],
                }
                for k, name in ((1, "one"), (2, "two"))
            ],
            "forces": [
                {
                    "type": "rotational_spring_damper",
                    "bodies": ["one", "two"],
                    "stiffness": ROT_K,
                    "free_angle": ROT_FREE,
                }
            ],
        },
        t_end=0.3,
        output_interval=1e-3,
    )
    t = col(df, "time")
    theta, theta_d = oscillator(t, phi2_0 - phi1_0, w2_0 - w1_0, omega, 0.0, ROT_FREE)
    momentum = j1 * w1_0 + j2 * w2_0
    phi1 = (j1 * phi1_0 + j2 * phi2_0 + momentum * t - j2 * theta) / (j1 + j2)
    w1 = (momentum - j2 * theta_d) / (j1 + j2)
    amplitude = np.hypot(phi2_0 - phi1_0 - ROT_FREE, (w2_0 - w1_0) / omega)  # of theta [rad]
    # Nearly two periods (0.17 s each) of a free oscillation: REL of the swing and its peak rate.
    assert_close(col(df, "phi_one"), phi1, scale=amplitude)
    assert_close(col(df, "phi_two"), phi1 + theta, scale=amplitude)
    assert_close(col(df, "omega_one"), w1, scale=omega * amplitude)
    assert_close(col(df, "omega_two"), w1 + theta_d, scale=omega * amplitude)
    # Equal and opposite torques make J1 w1 + J2 w2 a linear invariant, which Runge-Kutta
    # steps keep exactly: rounding only, 1e-14 N m s against J2 w2 ~ 0.2 N m s.
    h = j1 * col(df, "omega_one") + j2 * col(df, "omega_two")
    np.testing.assert_allclose(h, momentum, rtol=0, atol=1e-14)


# 5. Applied loads on free bodies (no joints, no gravity) ---------------------------------------

SPIN_J, SPIN_TORQUE = 0.02, (0.3, -2.0)  # [kg m^2]; torque c0 + c1 t [N m, N m/s]
PUSH_MASS, PUSH_FX = 0.4, 1.2  # [kg], constant [N]
PUSH_FY = (0.5, 2.0, 15.0, 0.3)  # harmonic: offset [N], amplitude [N], [rad/s], phase [rad]


def test_torque_and_central_force_on_free_bodies():
    phi0, w0 = 0.2, 1.5  # spinner [rad], [rad/s]
    r0, v0 = np.array([0.3, -0.1]), np.array([0.1, -0.2])  # pushed body [m], [m/s]
    off, amp, w, phase = PUSH_FY
    df = simulate(
        {
            "bodies": [
                {
                    "name": "spinner",
                    "mass": 1.0,
                    "inertia": SPIN_J,
                    "position": [0.0, 0.0],
                    "angle": phi0,
                    "angular_velocity": w0,
                },
                {
                    "name": "pushed",
                    "mass": PUSH_MASS,
                    "inertia": 0.01,
                    "position": r0.tolist(),
                    "angle": 0.0,
                    "velocity": v0.tolist(),
                    "points": {"centre": [0.0, 0.0]},
                },
            ],
            "forces": [
                {
                    "type": "torque",
                    "body": "spinner",
                    "torque": {"type": "polynomial", "coefficients": list(SPIN_TORQUE)},
                },
                {
                    "type": "point_force",
                    "body": "pushed",
                    "point": "centre",
                    "force": [
                        PUSH_FX,
                        {
                            "type": "harmonic",
                            "offset": off,
                            "amplitude": amp,
                            "angular_frequency": w,
                            "phase": phase,
                        },
                    ],
                },
            ],
        },
        t_end=0.5,
        output_interval=1e-3,
    )
    t = col(df, "time")
    c0, c1 = SPIN_TORQUE
    phi = phi0 + w0 * t + (c0 * t**2 / 2 + c1 * t**3 / 6) / SPIN_J
    omega = w0 + (c0 * t + c1 * t**2 / 2) / SPIN_J
    x = r0[0] + v0[0] * t + PUSH_FX * t**2 / (2 * PUSH_MASS)
    # y'' = (off + amp sin(w t + phase)) / m, integrated twice from (r0, v0).
    y = (
        r0[1]
        + v0[1] * t
        + (
            off * t**2 / 2
            + amp / w**2 * (np.sin(phase) - np.sin(w * t + phase) + w * t * np.cos(phase))
        )
        / PUSH_MASS
    )
    # phi and x are polynomials of degree <= 3 in t, which fifth-order steps integrate
    # exactly, and y follows a harmonic force: REL of each scale (phi ~ 1 rad, x ~ 0.7 m).
    assert_close(col(df, "phi_spinner"), phi, scale=np.abs(phi).max())
    assert_close(col(df, "omega_spinner"), omega, scale=np.abs(omega).max())
    assert_close(col(df, "x_pushed"), x, scale=np.abs(x).max())
    assert_close(col(df, "y_pushed"), y, scale=np.abs(y).max())
    # Neither body is pushed off its own axis: exactly zero (no force and no torque there).
    np.testing.assert_array_equal(col(df, "x_spinner"), 0.0)
    np.testing.assert_array_equal(col(df, "phi_pushed"), 0.0)


ARM = np.array([0.1, 0.05])  # force point off the centre of mass [m]


def test_off_centre_force_turns_the_body():
    # A force at a body point whose moment arm turns with the body: the moment
    # (A(phi) ARM) x F depends on phi, so phi(t) has no elementary closed form. The reference
    # is scipy's DOP853 on m r'' = F(t), J phi'' = (A(phi) ARM) x F(t).
    mass, inertia = 0.6, 0.004
    y0 = np.array([0.0, 0.0, 0.4, 0.2, 0.0, 4.0])  # x, y, phi, vx, vy, omega
    fx = (0.0, 1.5, 12.0, 0.0)  # harmonic [N, N, rad/s, rad]
    fy = -2.0  # [N]

    def force(t):
        return np.array([fx[0] + fx[1] * np.sin(fx[2] * t + fx[3]), fy])

    def rigid_body(t, state):
        f = force(t)
        arm = rotate(state[2], ARM)
        moment = arm[0] * f[1] - arm[1] * f[0]
        return np.concatenate([state[3:], [f[0] / mass, f[1] / mass, moment / inertia]])

    df = simulate(
        {
            "bodies": [
                {
                    "name": "plate",
                    "mass": mass,
                    "inertia": inertia,
                    "position": y0[:2].tolist(),
                    "angle": y0[2],
                    "velocity": y0[3:5].tolist(),
                    "angular_velocity": y0[5],
                    "points": {"arm": ARM.tolist()},
                }
            ],
            "forces": [
                {
                    "type": "point_force",
                    "body": "plate",
                    "point": "arm",
                    "force": [
                        {
                            "type": "harmonic",
                            "offset": fx[0],
                            "amplitude": fx[1],
                            "angular_frequency": fx[2],
                            "phase": fx[3],
                        },
                        fy,
                    ],
                }
            ],
        },
        t_end=0.5,
        output_interval=1e-3,
    )
    t = col(df, "time")
    ref = solve_ivp(
        rigid_body, (0.0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-12, atol=1e-14
    ).y
    for k, name in enumerate(("x", "y", "phi", "vx", "vy", "omega")):
        # jointwear at rtol 1e-10 against DOP853 at 1e-12 over half a second: REL of each scale.
        assert_close(col(df, f"{name}_plate"), ref[k], scale=np.abs(ref[k]).max())
    # The output acceleration is the right-hand side at the output state: REL as well.
    expected_alpha = np.array([rigid_body(ti, yi)[5] for ti, yi in zip(t, ref.T, strict=True)])
    assert_close(col(df, "alpha_plate"), expected_alpha, scale=np.abs(expected_alpha).max())


# 6. Relative angle driver -------------------------------------------------------------------

ELBOW = (0.5, 2.0, -3.0)  # phi_B - phi_A = c0 + c1 t + c2 t^2 [rad, rad/s, rad/s^2]
ARM_A = {"mass": 1.2, "inertia": 0.009, "half": 0.15}  # upper arm, pinned at the ground
ARM_B = {"mass": 0.5, "inertia": 0.0017, "half": 0.10}  # forearm, driven relative to A


@pytest.mark.parametrize("formulation", VIOLATION)
def test_relative_angle_driver(formulation):
    # A double pendulum under gravity whose elbow is driven: phi_fore - phi_upper = f(t),
    # while the upper arm swings freely.
    phi_a = -0.3
    phi_b = phi_a + ELBOW[0]
    centre_a = rotate(phi_a, [ARM_A["half"], 0.0])
    centre_b = 2.0 * centre_a + rotate(phi_b, [ARM_B["half"], 0.0])
    bodies = []
    for name, arm, centre, phi in (
        ("upper", ARM_A, centre_a, phi_a),
        ("fore", ARM_B, centre_b, phi_b),
    ):
        h = arm["half"]
        bodies.append(
            {
                "name": name,
                "mass": arm["mass"],
                "inertia": arm["inertia"],
                "position": centre.tolist(),
                "angle": phi,
                "points": {"base": [-h, 0.0], "tip": [h, 0.0]},
            }
        )
    df = simulate(
        {
            "ground": {"points": {"shoulder": [0.0, 0.0]}},
            "bodies": bodies,
            "joints": [
                {
                    "name": "shoulder",
                    "type": "revolute",
                    "bodies": ["ground", "upper"],
                    "points": ["shoulder", "base"],
                },
                {
                    "name": "elbow",
                    "type": "revolute",
                    "bodies": ["upper", "fore"],
                    "points": ["tip", "base"],
                },
            ],
            "drivers": [
                {
                    "name": "motor",
                    "type": "angle",
                    "body": "fore",
                    "relative_to": "upper",
                    "function": {"type": "polynomial", "coefficients": list(ELBOW)},
                }
            ],
            "forces": [{"type": "gravity", "acceleration": [0.0, -G]}],
        },
        t_end=0.6,
        output_interval=2.5e-4,  # fine rows for the Simpson integral of the power below
        formulation=formulation,
    )
    t = col(df, "time")
    c0, c1, c2 = ELBOW
    # Prescribed relative motion: stabilised or projected integration, REL of each scale.
    rel = col(df, "phi_fore") - col(df, "phi_upper")
    assert_close(rel, c0 + c1 * t + c2 * t**2, scale=1.0)
    rel_rate = col(df, "omega_fore") - col(df, "omega_upper")
    assert_close(rel_rate, c1 + 2 * c2 * t, scale=2.0)
    # The augmented Lagrangian meets each acceleration row to SETTLED (1e-10) of its terms,
    # here |alpha_fore| + |alpha_upper| (a few hundred rad/s^2): REL of that scale instead.
    alphas = np.abs(col(df, "alpha_fore")) + np.abs(col(df, "alpha_upper"))
    scale = 6.0 if formulation == "baumgarte" else max(6.0, alphas.max())
    assert_close(col(df, "alpha_fore") - col(df, "alpha_upper"), 2 * c2, scale=scale)
    assert col(df, "constraint_violation").max() < VIOLATION[formulation]

    # Newton-Euler on the forearm alone, from its own motion: the elbow pin force
    # F = m (a - g) and the driver torque T = J alpha - (A s_base) x F.
    m, j = ARM_B["mass"], ARM_B["inertia"]
    acc = np.stack([col(df, "ax_fore"), col(df, "ay_fore")])
    pin_force = m * (acc - np.array([[0.0], [-G]]))
    base = rotate(col(df, "phi_fore"), [-ARM_B["half"], 0.0])
    torque = j * col(df, "alpha_fore") - (base[0] * pin_force[1] - base[1] * pin_force[0])
    force_scale = np.abs(pin_force).max()
    # Same state, different route (the forearm's equations vs. the multipliers of the whole
    # system): only rounding separates them, relative to the largest force or torque.
    np.testing.assert_allclose(col(df, "elbow_fx"), pin_force[0], rtol=0, atol=1e-12 * force_scale)
    np.testing.assert_allclose(col(df, "elbow_fy"), pin_force[1], rtol=0, atol=1e-12 * force_scale)
    torque_scale = np.abs(torque).max()
    np.testing.assert_allclose(col(df, "torque_motor"), torque, rtol=0, atol=1e-12 * torque_scale)

    # Power balance: gravity is in the potential and the pins do no work, so the change of
    # total energy is the work of the driver, T * (omega_B - omega_A), integrated here by
    # Simpson's rule on the output rows.
    energy = col(df, "energy_kinetic") + col(df, "energy_potential")
    work = cumulative_simpson(col(df, "torque_motor") * rel_rate, x=t, initial=0.0)
    # Simpson's error falls as h^4 (7e-10 of the work at 1 ms rows, 4e-12 at 0.25 ms): REL.
    assert_close(energy - energy[0], work, scale=np.abs(work).max())


# 7. Gravity and assembly ------------------------------------------------------------------------


def test_free_fall_under_oblique_gravity():
    gravity = np.array([1.5, -G])  # [m/s^2]
    mass, r0, v0, phi0, w0 = 0.9, np.array([0.2, 1.0]), np.array([-0.4, 2.0]), 0.1, -3.0
    df = simulate(
        {
            "bodies": [
                {
                    "name": "stone",
                    "mass": mass,
                    "inertia": 0.003,
                    "position": r0.tolist(),
                    "angle": phi0,
                    "velocity": v0.tolist(),
                    "angular_velocity": w0,
                }
            ],
            "forces": [{"type": "gravity", "acceleration": gravity.tolist()}],
        },
        t_end=0.5,
        output_interval=1e-3,
    )
    t = col(df, "time")
    for k, axis in enumerate("xy"):
        r = r0[k] + v0[k] * t + 0.5 * gravity[k] * t**2
        # Quadratic and linear in t, integrated exactly by fifth-order steps: REL of the scale.
        assert_close(col(df, f"{axis}_stone"), r, scale=np.abs(r).max())
        assert_close(col(df, f"v{axis}_stone"), v0[k] + gravity[k] * t, scale=5.0)
        # m g / m: rounding only.
        np.testing.assert_allclose(col(df, f"a{axis}_stone"), gravity[k], rtol=1e-15)
    assert_close(col(df, "phi_stone"), phi0 + w0 * t, scale=1.5)
    # Potential -m g . r from the same state: rounding only.
    potential = -mass * (gravity[0] * col(df, "x_stone") + gravity[1] * col(df, "y_stone"))
    np.testing.assert_allclose(col(df, "energy_potential"), potential, rtol=1e-14, atol=1e-14)
    total = col(df, "energy_kinetic") + col(df, "energy_potential")
    # Conserved: REL of the energy scale m |g| x 1 m.
    assert_close(total, total[0], scale=mass * G)


FOURBAR = EXAMPLES / "flores2009_fourbar.toml"


def test_assembly_closes_a_loop_from_a_rough_guess():
    # The example's guesses are good to 4 digits; push coupler and follower a few mm and
    # degrees off. Newton must land on the closed-form pose of the same (open) branch.
    model = jw.load_model(
        FOURBAR,
        [
            "bodies.coupler.position=[0.132, 0.420]",
            'bodies.coupler.angle="13 deg"',
            "bodies.follower.position=[0.198, 0.228]",
            'bodies.follower.angle="74 deg"',
        ],
    )
    assembly = assemble(model, build_system(model, ideal=True))
    assert assembly.iterations > 1
    assert assembly.dof == 0 and assembly.dof_without_drivers == 1
    # The Newton iteration stops at max |Phi| <= 1e-10 m (the default assembly tolerance).
    assert assembly.residual <= 1e-10
    ref = fourbar_states(np.array([0.0]))
    for b, body in enumerate(BODY_NAMES):
        for k, (coord, rate) in enumerate((("x", "vx"), ("y", "vy"), ("phi", "omega"))):
            # |Phi| <= 1e-10 m, times the loop's modest conditioning away from dead centre:
            # 1e-9 m or rad (measured 1e-12).
            assert assembly.y0[3 * b + k] == pytest.approx(ref[f"{coord}_{body}"][0], abs=1e-9)
            # One linear solve at that pose: a 1e-9 pose error times rates up to 157 rad/s
            # shifts the velocities by < 1e-6 (measured 3e-11).
            assert assembly.y0[9 + 3 * b + k] == pytest.approx(ref[f"{rate}_{body}"][0], abs=1e-6)


def test_assembly_reports_a_loop_that_cannot_close():
    # A 20 mm coupler: the crank tip, held at (0, 0.4) by the driver, is 0.427 m from the
    # follower pivot, so the 0.46 m follower's circle passes no nearer than 33 mm to it.
    model = jw.load_model(
        FOURBAR,
        [
            "bodies.coupler.points.crank_end=[-0.01, 0.0]",
            "bodies.coupler.points.follower_end=[0.01, 0.0]",
        ],
    )
    with pytest.raises(jw.ModelError) as error:
        assemble(model, build_system(model, ideal=True))
    message = str(error.value)
    assert message.startswith("assembly: the constraints cannot be met")
    # The gap is shared by the coupler's two pins, which the message names.
    assert "joint 'crank_coupler'" in message and "joint 'coupler_follower'" in message


def _double_pin(formulation: str, pins: tuple[str, ...] = ("pin_a", "pin_b")) -> dict:
    """A bar pinned to the ground at one end by each of ``pins``, all at the same point."""
    return {
        "ground": {"points": {"o": [0.0, 0.0]}},
        "bodies": [
            {
                "name": "bar",
                "mass": 1.0,
                "inertia": 0.1,
                "position": [0.503, 0.004],  # a few mm off: Newton runs first
                "angle": 0.0,
                "points": {"end": [-0.5, 0.0]},
            }
        ],
        "joints": [
            {"name": name, "type": "revolute", "bodies": ["ground", "bar"], "points": ["o", "end"]}
            for name in pins
        ],
        "forces": [{"type": "gravity", "acceleration": [0.0, -G]}],
        "solver": {"formulation": formulation, **TIGHT, "t_end": 0.5, "output_interval": 1e-2},
    }


def test_baumgarte_assembly_reports_redundant_joints():
    # Two pins between the ground and the bar at the same point: four equations, rank 2.
    model = parse_model(_double_pin("baumgarte"))
    with pytest.raises(jw.ModelError) as error:
        assemble(model, build_system(model))
    message = str(error.value)
    assert "redundant" in message
    assert "rank 2 for 4 equations" in message
    assert "joint 'pin_a'" in message and "joint 'pin_b'" in message
    assert "augmented_lagrangian" in message


def test_augmented_lagrangian_runs_redundant_joints_with_shared_reactions():
    # The same bar with one pin is the independent answer: the same motion, and the two
    # redundant pins' reactions sum to its one reaction; the least-norm multipliers share it
    # equally between identical pins (docs/model-format.md, "Formulations").
    model = parse_model(_double_pin("augmented_lagrangian"))
    assembly = assemble(model, build_system(model))
    assert (assembly.redundant, assembly.dof) == (2, 1)
    double = jw.simulate(model)
    single = jw.simulate(parse_model(_double_pin("augmented_lagrangian", ("pin_a",))))
    assert double.status == single.status == "success"
    one, two = single.timeseries, double.timeseries
    # Both integrate the same pendulum at rtol 1e-10: REL of the angle's scale (1 rad).
    assert_close(col(two, "phi_bar"), col(one, "phi_bar"), scale=1.0)
    for k in ("fx", "fy"):
        scale = np.abs(col(one, f"pin_a_{k}")).max()  # about m g = 9.81 N
        # The sum: REL of the force scale, like every multiplier of an accurate state.
        assert_close(col(two, f"pin_a_{k}") + col(two, f"pin_b_{k}"), col(one, f"pin_a_{k}"),
                     scale=scale)  # fmt: skip
        # The split: equal to the iterations' settling (1e-10 relative) and rounding.
        np.testing.assert_allclose(col(two, f"pin_a_{k}"), col(two, f"pin_b_{k}"),
                                   rtol=0, atol=1e-8 * scale)  # fmt: skip
