"""Hydrodynamic film forces and power loss against hand numbers, closed forms and quadrature.

The independent answers are the Reynolds-equation pressures, written out here (short bearing)
or solved numerically as a boundary-value problem (long bearing), integrated with scipy.
"""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import dblquad, quad, solve_bvp

from jointwear.kernels.laws.lubrication import (
    FilmModel,
    couette_torque,
    film_force_components,
    film_power_loss,
    film_torques,
    long_bearing_forces,
    short_bearing_forces,
)

SHORT, LONG = FilmModel.SHORT_BEARING, FilmModel.LONG_BEARING
FORCES = {SHORT: short_bearing_forces, LONG: long_bearing_forces}

# Round numbers: A = mu R L^3 / (2 c^2) = 0.1 * 0.01 * 8e-6 / 2e-8 = 0.4 N s,
# B = 6 mu L R^3 / c^2 = 6 * 0.1 * 0.02 * 1e-6 / 1e-8 = 1.2 N s.
MU, R, L, C = 0.1, 0.01, 0.02, 1e-4

NO_TABLE = np.zeros(0)  # the short and long bearings read no impedance table


def components(model, eps, eps_dot, gamma_dot, w, *fluid):
    """(f_r, f_t) [N] by the dispatcher."""
    return film_force_components(model, NO_TABLE, eps, eps_dot, gamma_dot, w, *fluid)


def power_loss(model, eps, eps_dot, gamma_dot, w, w_rel, mu, r, width, c):
    """The film's power loss [W] at the model's own force."""
    f_r, f_t = components(model, eps, eps_dot, gamma_dot, w, mu, r, width, c)
    couette = couette_torque(eps, w_rel, mu, r, width, c)
    return film_power_loss(f_r, f_t, couette, eps, eps_dot, gamma_dot, w, w_rel, c)


def torques(model, eps, eps_dot, gamma_dot, w, w_rel, mu, r, width, c):
    """The film's shear torques (journal, bearing) [N m] at the model's own force."""
    _, f_t = components(model, eps, eps_dot, gamma_dot, w, mu, r, width, c)
    return film_torques(f_t, couette_torque(eps, w_rel, mu, r, width, c), c * eps)


# scipy's adaptive quadrature is asked for 1e-11 relative; the integrands are smooth
# (h >= c (1 - 0.9)), so it delivers that, and 1e-8 leaves room for the nested dblquad.
QUAD_REL = 1e-8


def _quad(f, a, b):
    return quad(f, a, b, epsabs=0.0, epsrel=1e-11, limit=200)[0]


def _film(v):
    """The pi-film's half: (0, pi) when w - 2 gamma_dot >= 0, else its mirror (pi, 2 pi)."""
    return (0.0, math.pi) if v >= 0.0 else (math.pi, 2.0 * math.pi)


# ---------------------------------------------------------------- hand numbers

# State: eps = 0.5, eps_dot = 2 1/s, gamma_dot = 10 rad/s, w = 100 rad/s -> v = w - 2 gamma_dot
# = 80 rad/s. 1 - eps^2 = 0.75; 0.75^1.5 = 0.6495191, 0.75^2 = 0.5625, 0.75^2.5 = 0.4871393.
# The squeeze term of f_t carries s = eps v / sqrt((eps v)^2 + (2 eps_dot)^2)
#   = 40 / sqrt(1600 + 16) = 0.99503719.
# Short, A = 0.4:
#   f_r = -0.4 [2 * 0.25 * 80 / 0.5625 + pi * 1.5 * 2 / 0.4871393]
#       = -0.4 [71.111111 + 19.347193] = -36.183322 N
#   f_t =  0.4 [pi * 0.5 * 80 / (2 * 0.6495191) + 0.99503719 * 4 * 0.5 * 2 / 0.5625]
#       =  0.4 [96.735966 + 7.075820] = 41.524714 N
# Long, B = 1.2, 2 + eps^2 = 2.25, pi/2 - 8 / (2.25 pi) = 1.5707963 - 1.1317685 = 0.4390278:
#   f_r = -1.2 [2 * 0.25 * 80 / (2.25 * 0.75) + 2 * 2 * 0.4390278 / 0.6495191]
#       = -1.2 [23.703704 + 2.703710] = -31.688897 N
#   f_t =  1.2 [pi * 0.5 * 80 / (2.25 * 0.8660254) + 0.99503719 * 4 * 0.5 * 2 / (2.25 * 0.75)]
#       =  1.2 [64.490644 + 2.358606] = 80.219100 N
# Power loss with w_rel = 40 rad/s, U = 0.4 m/s:
#   Couette 2 pi * 0.1 * 0.16 * 0.01 * 0.02 / (1e-4 * 0.8660254) = 0.2321663 W
#   short pressure 1e-4 [0.5 * 0.5 * 80 * 41.524714 + 2 * 36.183322] = 0.0902861 W
#   long pressure  1e-4 [0.5 * 0.5 * 80 * 80.219100 + 2 * 31.688897] = 0.1667760 W
HAND = [
    (SHORT, -36.183322, 41.524714, 0.2321663 + 0.0902861),
    (LONG, -31.688897, 80.219100, 0.2321663 + 0.1667760),
]


@pytest.mark.parametrize(("model", "f_r", "f_t", "power"), HAND)
def test_hand_numbers(model, f_r, f_t, power):
    # 1e-6 relative: the hand numbers carry 8 significant digits, rounded.
    got = components(model, 0.5, 2.0, 10.0, 100.0, MU, R, L, C)
    assert got == pytest.approx((f_r, f_t), rel=1e-6)
    assert FORCES[model](0.5, 2.0, 10.0, 100.0, MU, R, L, C) == got
    p = power_loss(model, 0.5, 2.0, 10.0, 100.0, 40.0, MU, R, L, C)
    assert p == pytest.approx(power, rel=1e-6)


# ---------------------------------------------------------------- short bearing


def short_load(eps, w):
    """Steady load capacity of the short bearing (Ocvirk; Hamrock et al. 2004)."""
    q = 1.0 - eps * eps
    root = math.sqrt(math.pi**2 * q + 16.0 * eps * eps)
    return MU * w * R * L**3 * eps * root / (4.0 * C * C * q * q)


def short_attitude(eps):
    """Attitude angle phi, tan phi = pi sqrt(1 - eps^2) / (4 eps)."""
    return math.atan(math.pi * math.sqrt(1.0 - eps * eps) / (4.0 * eps))


@pytest.mark.parametrize("eps", [0.1, 0.3, 0.5, 0.7, 0.9])
def test_short_bearing_steady_load_and_attitude(eps):
    # Fixed bearing, journal at omega = 200 rad/s, steady: w = 200, gamma_dot = eps_dot = 0.
    f_r, f_t = short_bearing_forces(eps, 0.0, 0.0, 200.0, MU, R, L, C)
    # Closed forms against closed forms: equal to rounding, 1e-12.
    assert math.hypot(f_r, f_t) == pytest.approx(short_load(eps, 200.0), rel=1e-12)
    assert f_r < 0.0 and f_t > 0.0
    assert math.atan2(f_t, -f_r) == pytest.approx(short_attitude(eps), abs=1e-12)
    # A downward load W (gravity) is carried with the line of centres at gamma = -pi/2 + phi:
    # the journal centre sits on the +x side, where the bottom of a counter-clockwise journal
    # drags the oil into the narrowing gap, i.e. the line of centres leads the load in the
    # sense of rotation. There the film pushes straight up with W.
    gamma = -0.5 * math.pi + short_attitude(eps)
    w_load = short_load(eps, 200.0)
    f_x = f_r * math.cos(gamma) - f_t * math.sin(gamma)  # f_r e_r + f_t e_t
    f_y = f_r * math.sin(gamma) + f_t * math.cos(gamma)
    assert f_x == pytest.approx(0.0, abs=1e-12 * w_load)
    assert f_y == pytest.approx(w_load, rel=1e-12)


def short_pressure(theta, z, eps, eps_dot, v):
    """Short-bearing pressure [Pa] from d/dz (h^3 dp/dz) = 6 mu v dh/dtheta + 12 mu dh/dt.

    h = c (1 + eps cos theta), dh/dtheta = -c eps sin theta, dh/dt = c eps_dot cos theta;
    integrated twice in z with p = 0 at z = +-L/2.
    """
    h = C * (1.0 + eps * math.cos(theta))
    drive = C * (-v * eps * math.sin(theta) + 2.0 * eps_dot * math.cos(theta))
    return 3.0 * MU / h**3 * (z * z - 0.25 * L * L) * drive


def short_forces_by_quadrature(eps, eps_dot, v):
    """f_r = R int p cos theta, f_t = R int p sin theta over the pi-film, by scipy dblquad."""
    a, b = _film(v)

    def force(trig):  # epsabs: a floor for f_t = 0 at eps = 0, far below every other force
        def integrand(z, t):
            return short_pressure(t, z, eps, eps_dot, v) * trig(t)

        return R * dblquad(integrand, a, b, -0.5 * L, 0.5 * L, epsabs=1e-9, epsrel=1e-11)[0]

    return force(math.cos), force(math.sin)


STATES = [  # (eps, eps_dot, v = w - 2 gamma_dot)
    (0.1, 0.0, 150.0),
    (0.6, 0.0, 150.0),
    (0.9, 0.0, 150.0),
    (0.3, 4.0, 0.0),
    (0.8, -3.0, 0.0),
    (0.6, 2.5, 60.0),
    (0.6, 2.5, -60.0),
    (0.5, 10.0, 15.0),  # squeeze and wedge of one size: s = 0.35
]


def model_by_quadrature(by_quadrature, eps, eps_dot, v):
    """The model's (f_r, f_t) from pi-film quadratures: the wedge's film plus the squeeze's.

    The wedge part is the pi-film of v, the squeeze part the (0, pi) film at v = 0 with its f_t
    turned by s = cos beta, beta = atan2(2 eps_dot, eps v) (lubrication module docstring).
    """
    wedge_r, wedge_t = by_quadrature(eps, 0.0, v)
    squeeze_r, squeeze_t = by_quadrature(eps, eps_dot, 0.0)
    side = math.cos(math.atan2(2.0 * eps_dot, eps * v))
    return wedge_r + squeeze_r, wedge_t + side * squeeze_t


@pytest.mark.parametrize(("eps", "eps_dot", "v"), STATES)
def test_short_bearing_against_reynolds_pressure(eps, eps_dot, v):
    # w = v + 2 gamma_dot with gamma_dot = 7: only w - 2 gamma_dot matters.
    got = short_bearing_forces(eps, eps_dot, 7.0, v + 14.0, MU, R, L, C)
    expected = model_by_quadrature(short_forces_by_quadrature, eps, eps_dot, v)
    assert got == pytest.approx(expected, rel=QUAD_REL, abs=1e-9)


@pytest.mark.parametrize("model", [SHORT, LONG])
@pytest.mark.parametrize("v", [-1e-3, -1e-9, 0.0, 1e-9, 1e-3])
def test_squeeze_term_continuous_through_zero_wedge_speed(model, v):
    # An orbiting journal passes w - 2 gamma_dot = 0 while it approaches the wall. With the
    # squeeze term's sign taken as a sign, f_t would jump there by twice that term, 0.7 |f_r|;
    # smoothed, it is within 2e-3 |f_r| of 0 (both terms are ~ 4e-5 |f_r| at |v| = 1e-3).
    f_r, f_t = FORCES[model](0.6, 2.5, 0.0, v, MU, R, L, C)
    at_zero = FORCES[model](0.6, 2.5, 0.0, 0.0, MU, R, L, C)
    assert at_zero[1] == 0.0
    assert f_r == pytest.approx(at_zero[0], rel=1e-3)
    assert abs(f_t) <= 2e-3 * abs(at_zero[0])


@pytest.mark.parametrize("eps", [0.0, 0.4, 0.9])
def test_pure_squeeze_forces(eps):
    # No rotation: w = gamma_dot = 0, the journal approaches the wall at eps_dot = 3 1/s.
    a = MU * R * L**3 / (2.0 * C * C)
    q = 1.0 - eps * eps
    f_r, f_t = short_bearing_forces(eps, 3.0, 0.0, 0.0, MU, R, L, C)
    assert f_r == pytest.approx(-a * math.pi * (1.0 + 2.0 * eps * eps) * 3.0 / q**2.5, rel=1e-12)
    assert f_r < 0.0  # pushed back
    # Straight at the wall the journal is not pushed sideways: f_t = 0 by symmetry. The pi-films
    # (0, pi) and (pi, 2 pi) have the same f_r and opposite f_t (the quadrature of the Reynolds
    # pressure over each); s = 0 weights them equally.
    assert f_t == 0.0
    first_r, first_t = short_forces_by_quadrature(eps, 3.0, 0.0)
    assert f_r == pytest.approx(first_r, rel=QUAD_REL)
    second_r, second_t = short_forces_by_quadrature(eps, 3.0, -1e-300)  # the mirror half
    assert second_r == pytest.approx(first_r, rel=QUAD_REL)
    assert second_t == pytest.approx(-first_t, rel=QUAD_REL, abs=1e-9)
    # Long bearing, the same against its closed form (derived in the module docstring).
    f_r, f_t = long_bearing_forces(eps, 3.0, 0.0, 0.0, MU, R, L, C)
    b = 6.0 * MU * L * R**3 / (C * C)
    s = 2.0 + eps * eps
    squeeze = 2.0 * 3.0 * (math.pi / 2.0 - 8.0 / (math.pi * s)) / q**1.5
    assert f_r == pytest.approx(-b * squeeze, rel=1e-12)
    assert f_t == 0.0


# ---------------------------------------------------------------- long bearing


def long_film(eps, eps_dot, v):
    """Long-bearing pi-film, solved by scipy's solve_bvp.

    d/dtheta (h^3 dp/dtheta) = 6 mu R^2 (v dh/dtheta + 2 dh/dt), p = 0 at both ends of the
    pi-film. Unknowns y = (p, h^3 dp/dtheta). Returns the solution and h(theta).
    """
    a, b = _film(v)

    def h(t):
        return C * (1.0 + eps * np.cos(t))

    def rhs(t, y):
        drive = v * (-C * eps * np.sin(t)) + 2.0 * C * eps_dot * np.cos(t)
        return np.vstack([y[1] / h(t) ** 3, 6.0 * MU * R * R * drive])

    mesh = np.linspace(a, b, 401)
    sol = solve_bvp(
        rhs, lambda ya, yb: np.array([ya[0], yb[0]]), mesh, np.zeros((2, 401)), tol=1e-6
    )
    assert sol.status == 0
    return sol, h


def long_forces_by_quadrature(eps, eps_dot, v):
    sol, _ = long_film(eps, eps_dot, v)
    a, b = _film(v)
    f_r = R * L * _quad(lambda t: sol.sol(t)[0] * math.cos(t), a, b)
    f_t = R * L * _quad(lambda t: sol.sol(t)[0] * math.sin(t), a, b)
    return f_r, f_t


# solve_bvp with tol = 1e-6 on its collocation residual gives the forces to about 1e-9
# relative here (it agrees with tol = 1e-9 runs to that level); 1e-7 is the bound we assert.
BVP_REL = 1e-7


@pytest.mark.parametrize(("eps", "eps_dot", "v"), STATES)
def test_long_bearing_against_reynolds_pressure(eps, eps_dot, v):
    got = long_bearing_forces(eps, eps_dot, 7.0, v + 14.0, MU, R, L, C)
    expected = model_by_quadrature(long_forces_by_quadrature, eps, eps_dot, v)
    assert got == pytest.approx(expected, rel=BVP_REL, abs=1e-9)


@pytest.mark.parametrize("eps", [0.1, 0.5, 0.9])
def test_long_bearing_wedge_is_half_sommerfeld(eps):
    # Classic half-Sommerfeld load, W = 6 mu U R^2 L eps sqrt(pi^2 (1 - eps^2) + 4 eps^2)
    # / (c^2 (2 + eps^2)(1 - eps^2)), U = R w, tan phi = pi sqrt(1 - eps^2) / (2 eps).
    f_r, f_t = long_bearing_forces(eps, 0.0, 0.0, 200.0, MU, R, L, C)
    assert math.hypot(f_r, f_t) == pytest.approx(long_load(eps, 200.0), rel=1e-12)
    assert math.atan2(f_t, -f_r) == pytest.approx(long_attitude(eps), abs=1e-12)


def long_load(eps, w):
    """Half-Sommerfeld steady load (Hamrock et al. 2004)."""
    q = 1.0 - eps * eps
    load = 6.0 * MU * w * R**3 * L * eps * math.sqrt(math.pi**2 * q + 4.0 * eps * eps)
    return load / (C * C * (2.0 + eps * eps) * q)


def long_attitude(eps):
    return math.atan(math.pi * math.sqrt(1.0 - eps * eps) / (2.0 * eps))


# ---------------------------------------------------------------- both models


@pytest.mark.parametrize("model", [SHORT, LONG])
def test_rigid_corotation_gives_no_force_and_no_loss(model):
    # Journal, bearing and line of centres all turn at 30 rad/s: the film is at rest relative
    # to both surfaces, so w - 2 gamma_dot = 60 - 60 = 0 and w_rel = 0.
    assert components(model, 0.7, 0.0, 30.0, 60.0, MU, R, L, C) == (0.0, 0.0)
    assert power_loss(model, 0.7, 0.0, 30.0, 60.0, 0.0, MU, R, L, C) == 0.0


@pytest.mark.parametrize("model", [SHORT, LONG])
def test_mirrored_film_for_negative_wedge_speed(model):
    # Reversing w - 2 gamma_dot mirrors the film: f_r keeps its value, f_t changes sign.
    f_r, f_t = FORCES[model](0.6, 2.5, 0.0, 60.0, MU, R, L, C)
    assert FORCES[model](0.6, 2.5, 0.0, -60.0, MU, R, L, C) == (f_r, -f_t)


@pytest.mark.parametrize("model", [SHORT, LONG])
def test_no_force_at_the_centre_without_squeeze(model):
    assert components(model, 0.0, 0.0, 5.0, 300.0, MU, R, L, C) == (0.0, 0.0)
    # Near the centre the force vanishes linearly in eps.
    small = [math.hypot(*FORCES[model](e, 0.0, 5.0, 300.0, MU, R, L, C)) / e for e in (1e-3, 1e-6)]
    assert small[1] == pytest.approx(small[0], rel=1e-5)


@pytest.mark.parametrize("model", [SHORT, LONG])
@pytest.mark.parametrize(("eps_dot", "v"), [(0.0, 100.0), (1.0, 0.0)])
def test_force_grows_without_bound_towards_the_wall(model, eps_dot, v):
    eps = [0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999, 0.9999]
    size = [math.hypot(*FORCES[model](e, eps_dot, 0.0, v, MU, R, L, C)) for e in eps]
    assert all(b > a for a, b in itertools.pairwise(size))
    # The slowest growth, the long-bearing wedge (f_r ~ eps^2 / (1 - eps^2)), is ~ 3900 times
    # its eps = 0.5 value at eps = 0.9999; the others grow faster.
    assert size[-1] > 1e3 * size[2]


# ---------------------------------------------------------------- torques and power loss

STEADY = {SHORT: (short_load, short_attitude), LONG: (long_load, long_attitude)}


@pytest.mark.parametrize("model", [SHORT, LONG])
@pytest.mark.parametrize("eps", [0.2, 0.7])
def test_steady_torques_are_the_classic_ones(model, eps):
    # Fixed bearing, journal at 200 rad/s under the steady load W at attitude phi: the journal
    # feels -(T_c + e W sin phi / 2), the bearing T_c - e W sin phi / 2, with Petroff's
    # T_c = 2 pi mu R^3 L w / (c sqrt(1 - eps^2)) (Hamrock et al. 2004, journal and bearing
    # friction torques). W and phi from the closed forms, not from the force functions.
    load, attitude = STEADY[model]
    couette = 2.0 * math.pi * MU * R**3 * L * 200.0 / (C * math.sqrt(1.0 - eps * eps))
    offset = 0.5 * eps * C * load(eps, 200.0) * math.sin(attitude(eps))
    t_journal, t_bearing = torques(model, eps, 0.0, 0.0, 200.0, 200.0, MU, R, L, C)
    assert t_journal == pytest.approx(-(couette + offset), rel=1e-12)
    assert t_bearing == pytest.approx(couette - offset, rel=1e-12)


@settings(max_examples=200, deadline=None)
@given(
    model=st.sampled_from([SHORT, LONG]),
    eps=st.floats(0.0, 0.999),
    eps_dot=st.floats(-1e3, 1e3),
    gamma_dot=st.floats(-1e3, 1e3),
    omega_j=st.floats(-2e3, 2e3),
    omega_b=st.floats(-2e3, 2e3),
)
def test_bodies_lose_what_the_film_dissipates(model, eps, eps_dot, gamma_dot, omega_j, omega_b):
    # Power of the film on the bodies: its force at the journal's centre against the bearing's
    # (f . de/dt, de/dt = c eps_dot e_r + c eps gamma_dot e_t) and both shear torques. The film
    # stores nothing, so what the bodies lose is what it dissipates.
    w, w_rel = omega_j + omega_b, omega_j - omega_b
    f_r, f_t = components(model, eps, eps_dot, gamma_dot, w, MU, R, L, C)
    t_j, t_b = torques(model, eps, eps_dot, gamma_dot, w, w_rel, MU, R, L, C)
    on_bodies = f_r * C * eps_dot + f_t * C * eps * gamma_dot + t_j * omega_j + t_b * omega_b
    loss = power_loss(model, eps, eps_dot, gamma_dot, w, w_rel, MU, R, L, C)
    scale = abs(f_r * C * eps_dot) + abs(f_t * C * eps * gamma_dot)
    scale += abs(t_j * omega_j) + abs(t_b * omega_b)
    # Subnormal powers (below 2.2e-308 W) keep fewer digits than 1e-12: a floor of 1e-300 W.
    assert -on_bodies == pytest.approx(loss, rel=1e-12, abs=1e-12 * scale + 1e-300)
    assert t_j + t_b == pytest.approx(-C * eps * f_t, rel=1e-12, abs=1e-12 * abs(t_j) + 1e-300)


@settings(max_examples=200, deadline=None)
@given(
    model=st.sampled_from([SHORT, LONG]),
    eps=st.floats(0.0, 0.999),
    film_eps=st.floats(0.0, 0.999),
    eps_dot=st.floats(-1e3, 1e3),
    gamma_dot=st.floats(-1e3, 1e3),
    omega_j=st.floats(-2e3, 2e3),
    omega_b=st.floats(-2e3, 2e3),
)
def test_a_film_at_another_eccentricity_still_balances(
    model, eps, film_eps, eps_dot, gamma_dot, omega_j, omega_b
):
    # The joint evaluates a film at another eccentricity ratio than the journal's (the short
    # and long bearings held at film_breakdown, a mixed film at its mean gap): the force and
    # the Couette torque are the film's, the pressure part of the power and the torques'
    # offset take the journal's own e. The moments then sum to zero (the force pair's couple
    # is e f_t with the real e) and the bodies lose what the film is said to dissipate.
    w, w_rel = omega_j + omega_b, omega_j - omega_b
    f_r, f_t = components(model, film_eps, eps_dot, gamma_dot, w, MU, R, L, C)
    couette = couette_torque(film_eps, w_rel, MU, R, L, C)
    t_j, t_b = film_torques(f_t, couette, C * eps)
    loss = film_power_loss(f_r, f_t, couette, eps, eps_dot, gamma_dot, w, w_rel, C)
    on_bodies = f_r * C * eps_dot + f_t * C * eps * gamma_dot + t_j * omega_j + t_b * omega_b
    scale = abs(f_r * C * eps_dot) + abs(f_t * C * eps * gamma_dot)
    scale += abs(t_j * omega_j) + abs(t_b * omega_b)
    assert -on_bodies == pytest.approx(loss, rel=1e-12, abs=1e-12 * scale + 1e-300)
    assert t_j + t_b == pytest.approx(-C * eps * f_t, rel=1e-12, abs=1e-12 * abs(t_j) + 1e-300)


# ---------------------------------------------------------------- power loss


def couette_by_quadrature(eps, w_rel):
    u = R * w_rel
    return (
        MU * u * u * R * L * _quad(lambda t: 1.0 / (C * (1.0 + eps * math.cos(t))), 0, 2 * math.pi)
    )


def short_pressure_loss_by_quadrature(eps, eps_dot, v):
    """int h^3 / (12 mu) (dp/dz)^2 R dtheta dz over the pi-film, dp/dz differentiated by hand."""
    a, b = _film(v)

    def integrand(z, t):
        h = C * (1.0 + eps * math.cos(t))
        drive = C * (-v * eps * math.sin(t) + 2.0 * eps_dot * math.cos(t))
        dp_dz = 6.0 * MU / h**3 * z * drive
        return h**3 / (12.0 * MU) * dp_dz * dp_dz * R

    return dblquad(integrand, a, b, -0.5 * L, 0.5 * L, epsabs=0.0, epsrel=1e-11)[0]


def long_pressure_loss_by_quadrature(eps, eps_dot, v):
    """int h^3 / (12 mu) (dp / (R dtheta))^2 R L dtheta, h^3 dp/dtheta from the BVP."""
    sol, h = long_film(eps, eps_dot, v)
    a, b = _film(v)
    return L / (12.0 * MU * R) * _quad(lambda t: sol.sol(t)[1] ** 2 / h(t) ** 3, a, b)


PRESSURE_LOSS = {
    SHORT: (short_pressure_loss_by_quadrature, QUAD_REL),
    LONG: (long_pressure_loss_by_quadrature, BVP_REL),
}


@pytest.mark.parametrize("model", [SHORT, LONG])
def test_centred_spinning_journal_dissipates_petroff_power(model):
    # eps = 0, fixed bearing, journal at 250 rad/s: 2 pi mu U^2 R L / c, U = 2.5 m/s:
    # 2 pi * 0.1 * 6.25 * 0.01 * 0.02 / 1e-4 = 7.853982 W.
    petroff = 2.0 * math.pi * MU * 2.5**2 * R * L / C
    assert petroff == pytest.approx(7.853982, rel=1e-7)
    assert power_loss(model, 0.0, 0.0, 0.0, 250.0, 250.0, MU, R, L, C) == pytest.approx(
        petroff, rel=1e-14
    )


@pytest.mark.parametrize("model", [SHORT, LONG])
@pytest.mark.parametrize("eps", [0.0, 0.5, 0.9])
@pytest.mark.parametrize("eps_dot", [2.0, -2.0])
def test_pure_squeeze_loss_is_the_power_done_on_the_film(model, eps, eps_dot):
    # No rotation: the only power input is the journal pushing the film, -f_r c eps_dot, and
    # with p = 0 on the film's edges it is all dissipated by the pressure flow.
    f_r, _ = components(model, eps, eps_dot, 0.0, 0.0, MU, R, L, C)
    loss = power_loss(model, eps, eps_dot, 0.0, 0.0, 0.0, MU, R, L, C)
    assert loss == pytest.approx(-f_r * C * eps_dot, rel=1e-13)
    by_quadrature, rel = PRESSURE_LOSS[model]
    assert by_quadrature(eps, eps_dot, 0.0) == pytest.approx(-f_r * C * eps_dot, rel=rel)


@pytest.mark.parametrize("model", [SHORT, LONG])
@pytest.mark.parametrize(("eps", "eps_dot", "v"), [x for x in STATES if x[1] * x[2] == 0.0])
def test_power_loss_against_quadrature(model, eps, eps_dot, v):
    # Pure wedge or pure squeeze, where the model's film is a pi-film (s = +-1, or v = 0).
    w_rel = 90.0
    expected = couette_by_quadrature(eps, w_rel)
    by_quadrature, rel = PRESSURE_LOSS[model]
    expected += by_quadrature(eps, eps_dot, v)
    got = power_loss(model, eps, eps_dot, 7.0, v + 14.0, w_rel, MU, R, L, C)
    assert got == pytest.approx(expected, rel=rel)


@settings(max_examples=300, deadline=None)
@given(
    model=st.sampled_from([SHORT, LONG]),
    eps=st.floats(0.0, 0.999),
    eps_dot=st.floats(-1e3, 1e3),
    gamma_dot=st.floats(-1e3, 1e3),
    w=st.floats(-2e3, 2e3),
    w_rel=st.floats(-2e3, 2e3),
)
def test_power_loss_never_negative_and_pushback(model, eps, eps_dot, gamma_dot, w, w_rel):
    loss = power_loss(model, eps, eps_dot, gamma_dot, w, w_rel, MU, R, L, C)
    assert math.isfinite(loss)
    assert loss >= 0.0
    f_r, f_t = components(model, eps, eps_dot, gamma_dot, w, MU, R, L, C)
    assert math.isfinite(f_r) and math.isfinite(f_t)
    if eps_dot >= 0.0:
        assert f_r <= 0.0  # an approaching (or steady) journal is never pulled to the wall
