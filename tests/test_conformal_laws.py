"""Conformal contact laws (Johnson, Liu, elastic foundation) against hand numbers and calculus.

Paper joint (Flores 2009, Table 2): R_B 10 mm, R_J 9.8 mm, dR = 0.2 mm, L = 20 mm, steel
E = 207 GPa, nu = 0.3 on both sides, so E* = 207e9 / (2 * 0.91) = 1.137363e11 Pa.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq

from jointwear.kernels.laws.normal import (
    Damping,
    ElasticLaw,
    damped_by,
    elastic_energy,
    elastic_force,
    elastic_stiffness,
    hysteresis_factor,
    johnson_load,
    johnson_penetration,
    johnson_switch,
)
from jointwear.model.laws.normal import foundation_modulus

E_STAR = 207e9 / 1.82  # [Pa]
D_R = 2e-4  # [m]
WIDTH = 0.02  # [m]
K_F = 0.7 * 207e9 / (1.3 * 0.4)  # (1 - nu) E / ((1 + nu)(1 - 2 nu)) = 2.786538e11 Pa
K_FOUNDATION = K_F / 2e-3 * 0.010  # (K_f / h) R_B with a 2 mm layer [Pa]
LAWS = {  # code: (k, n) as the joint packs them
    ElasticLaw.HERTZ: (579.6e9 / 5.46, 1.5),
    ElasticLaw.JOHNSON: (0.0, 1.5),
    ElasticLaw.LIU: (0.0, 1.5),
    ElasticLaw.ELASTIC_FOUNDATION: (K_FOUNDATION, 1.5),
}


def force(law, delta):
    k, n = LAWS[law]
    return elastic_force(law, delta, k, n, E_STAR, D_R, WIDTH)


def stiffness(law, delta):
    k, n = LAWS[law]
    return elastic_stiffness(law, delta, k, n, E_STAR, D_R, WIDTH)


def test_hand_numbers():
    # Johnson at f = 1e6 N/m: ln(4 pi E* dR / f) = ln(4 pi 1.137363e11 2e-4 / 1e6)
    #   = ln(285.8504) = 5.655469; delta = 1e6 / (pi 1.137363e11) (5.655469 - 1)
    #   = 2.798667e-6 * 4.655469 = 1.302910e-5 m. So F(1.302910e-5 m) = 1e6 * 0.02 = 2e4 N.
    assert johnson_penetration(1e6, E_STAR, D_R) == pytest.approx(1.302910e-5, rel=1e-6)
    assert force(ElasticLaw.JOHNSON, 1.302910e-5) == pytest.approx(2e4, rel=1e-5)
    # Liu at delta = 2e-5 m: sqrt(2e-5 / (2 * 2.2e-4)) = sqrt(0.04545455) = 0.2132007;
    #   (pi / 2) 1.137363e11 0.02 2e-5 = 7.146260e4;  F = 7.146260e4 * 0.2132007 = 1.523588e4 N
    assert force(ElasticLaw.LIU, 2e-5) == pytest.approx(1.523588e4, rel=1e-6)
    # Foundation at delta = 2e-5 m: e = 2.2e-4, a0 = acos(2 / 2.2) = 0.4296997 rad,
    #   sin a0 cos a0 = 0.4165978 * 0.9090909 = 0.3787253; a0 - that = 0.0509744;
    #   (K_f / h) R = 2.786538e11 / 2e-3 * 0.01 = 1.393269e12 Pa;
    #   F = 1.393269e12 * 0.02 * 2.2e-4 * 0.0509744 = 3.124927e5 N
    assert force(ElasticLaw.ELASTIC_FOUNDATION, 2e-5) == pytest.approx(3.124927e5, rel=1e-6)
    assert foundation_modulus(207e9, 0.3) == pytest.approx(2.786538e11, rel=1e-6)


@pytest.mark.parametrize("delta", np.geomspace(1e-14, 0.3975 * D_R, 40))
def test_johnson_solution_satisfies_its_equation(delta):
    # The Newton solve returns f with delta(f) = delta to rounding: 1e-12 relative.
    f = johnson_load(delta, E_STAR, D_R)
    assert johnson_penetration(f, E_STAR, D_R) == pytest.approx(delta, rel=1e-12)


def test_johnson_beyond_its_range_follows_its_tangent():
    f_s, delta_s = johnson_switch(E_STAR, D_R)
    # f_s = 4 pi E* dR e^-3 and delta_s = 8 dR e^-3 lie on the law, where its slope is pi E* L.
    assert johnson_penetration(f_s, E_STAR, D_R) == pytest.approx(delta_s, rel=1e-14)
    below = force(ElasticLaw.JOHNSON, delta_s * (1 - 1e-9))
    above = force(ElasticLaw.JOHNSON, delta_s * (1 + 1e-9))
    assert below == pytest.approx(above, rel=1e-8)  # continuous
    slopes = [stiffness(ElasticLaw.JOHNSON, delta_s * (1 + s)) for s in (-1e-7, 1e-7)]
    assert slopes[0] == pytest.approx(math.pi * E_STAR * WIDTH, rel=1e-5)  # C1
    assert slopes[1] == math.pi * E_STAR * WIDTH
    # Beyond delta_max = 4 dR e^-2 the implicit law has no solution at all: it peaks there.
    f_max = 4 * math.pi * E_STAR * D_R * math.exp(-2)
    assert johnson_penetration(f_max, E_STAR, D_R) == pytest.approx(4 * D_R * math.exp(-2))
    assert johnson_penetration(1.5 * f_max, E_STAR, D_R) < 4 * D_R * math.exp(-2)


@pytest.mark.parametrize("law", list(LAWS))
@pytest.mark.parametrize("share", [1e-4, 1e-3, 0.01, 0.1, 0.3, 0.39, 0.5, 0.9, 1.0])
def test_stiffness_is_the_derivative_of_the_force(law, share):
    # Central differences with step 1e-6 delta: truncation ~ F''' h^2 / 6 ~ 1e-12 relative
    # for these smooth laws, rounding ~ 1e-16 / 1e-6 = 1e-10; 1e-6 allows both with margin.
    delta = share * D_R
    h = 1e-6 * delta
    numeric = (force(law, delta + h) - force(law, delta - h)) / (2 * h)
    assert stiffness(law, delta) == pytest.approx(numeric, rel=1e-6)


@pytest.mark.parametrize("law", list(LAWS))
@pytest.mark.parametrize("share", [1e-3, 0.05, 0.3, 0.6, 1.0])
def test_energy_is_the_integral_of_the_force(law, share):
    # scipy's adaptive quadrature (to 1e-13) against the kernel's closed form or its 12-point
    # Gauss rule in sqrt(delta); 1e-9 covers the Gauss rule's error on these smooth
    # integrands (measured below 1e-12).
    delta = share * D_R
    expected, _ = quad(lambda d: force(law, d), 0.0, delta, epsabs=0.0, epsrel=1e-13, limit=200)
    k, n = LAWS[law]
    energy = elastic_energy(law, delta, k, n, E_STAR, D_R, WIDTH)
    assert energy == pytest.approx(expected, rel=1e-9)


def test_small_penetration_limits():
    delta = 1e-12 * D_R
    # Liu: F -> (pi / 2) E* L delta^1.5 / sqrt(2 dR), corrections of order delta / dR.
    liu_limit = 0.5 * math.pi * E_STAR * WIDTH * delta**1.5 / math.sqrt(2 * D_R)
    assert force(ElasticLaw.LIU, delta) == pytest.approx(liu_limit, rel=1e-9)
    # Foundation: F -> (4 sqrt(2) / 3) (K_f / h) R L delta^1.5 / sqrt(dR), corrections
    # of order delta / dR (the series of a0 - sin a0 cos a0 = 2 a0^3 / 3 - ...).
    foundation_limit = 4 * math.sqrt(2) / 3 * K_FOUNDATION * WIDTH * delta**1.5 / math.sqrt(D_R)
    assert force(ElasticLaw.ELASTIC_FOUNDATION, delta) == pytest.approx(foundation_limit, rel=1e-6)
    # Johnson: F / L = pi E* delta / (ln(4 pi E* dR L / F) - 1), a logarithmically softened
    # linear law: the stiffness at small delta is far below pi E* L and rises with delta.
    assert stiffness(ElasticLaw.JOHNSON, delta) < 0.05 * math.pi * E_STAR * WIDTH
    deltas = np.geomspace(1e-12, 0.39, 30) * D_R
    slopes = [stiffness(ElasticLaw.JOHNSON, d) for d in deltas]
    assert np.all(np.diff(slopes) > 0)


def test_penetration_approaching_the_clearance():
    # Liu at delta = dR: F = (pi / 2) E* L dR sqrt(1 / 4) = (pi / 4) E* L dR, and beyond it
    # the law tends to the line (pi / (2 sqrt 2)) E* L delta.
    assert force(ElasticLaw.LIU, D_R) == pytest.approx(math.pi / 4 * E_STAR * WIDTH * D_R)
    far = 1e4 * D_R
    assert force(ElasticLaw.LIU, far) / far == pytest.approx(
        math.pi / (2 * math.sqrt(2)) * E_STAR * WIDTH, rel=1e-4
    )
    # Foundation at delta = dR: e = 2 dR, a0 = pi / 3: F = k L 2 dR (pi/3 - sqrt(3)/4).
    expected = K_FOUNDATION * WIDTH * 2 * D_R * (math.pi / 3 - math.sqrt(3) / 4)
    assert force(ElasticLaw.ELASTIC_FOUNDATION, D_R) == pytest.approx(expected, rel=1e-12)
    # Every law keeps rising through dR: a contact never gives way.
    for law in LAWS:
        deltas = np.linspace(0.01, 1.5, 60) * D_R
        assert np.all(np.diff([force(law, d) for d in deltas]) > 0)


def restitution_closed_form(chi: float) -> float:
    """Point mass on any elastic law with F = f_e (1 + chi v / v-): m v dv / (1 + chi v / v-)
    = -f_e d(delta), whose right side integrates to zero over a contact, so that
    chi (1 + e) = ln((1 + chi) / (1 - chi e)) for every elastic law f_e."""
    top = min(1.0, (1.0 - 1e-12) / chi)  # 1 - chi e > 0
    return brentq(lambda e: chi * (1 + e) - math.log((1 + chi) / (1 - chi * e)), 1e-9, top)


@pytest.mark.parametrize("law", list(LAWS))
@pytest.mark.parametrize(
    ("damping", "c_e"),
    [(Damping.LANKARANI_NIKRAVESH, 0.9), (Damping.HUNT_CROSSLEY, 0.8), (Damping.FLORES2011, 0.5)],
)
def test_single_impact_restitution_with_every_elastic_law(law, damping, c_e):
    mass, v_minus = 2.0, 0.5
    k, n = LAWS[law]

    def rhs(t, y):
        elastic = elastic_force(law, y[0], k, n, E_STAR, D_R, WIDTH)
        return [y[1], -damped_by(elastic, y[1], v_minus, hysteresis_factor(damping, c_e)) / mass]

    def separation(t, y):
        return y[0]

    separation.terminal = True
    separation.direction = -1
    sol = solve_ivp(
        rhs, [0.0, 1.0], [0.0, v_minus], method="DOP853", rtol=1e-12, atol=1e-18,
        events=separation, first_step=1e-12,
    )  # fmt: skip
    assert sol.status == 1
    e = -sol.y_events[0][0, 1] / v_minus
    # The closed form holds exactly; DOP853 at rtol 1e-12 reproduces it to ~1e-10.
    assert e == pytest.approx(restitution_closed_form(hysteresis_factor(damping, c_e)), abs=1e-8)
