"""Elastic-foundation contact and wear against closed forms, limits and hand numbers."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear.kernels.laws.foundation import (
    contact_half_angle,
    foundation_load,
    foundation_points,
    interference,
    spread_foundation_wear,
)
from jointwear.model.laws.normal import foundation_modulus

TWO_PI = 2.0 * math.pi
NONE = np.empty(0)  # no wear feedback: an unworn surface

# Paper (Flores 2009) Table 2 geometry; a steel layer 1 mm thick.
R_B, R_J, WIDTH, E, NU = 0.010, 0.0098, 0.020, 207e9, 0.3
C = R_B - R_J
K_OVER_H = foundation_modulus(E, NU) / 1e-3

# Rounding floor for the force checks: u = e cos(a) - c loses digits to cancellation when
# the penetration delta is tiny (delta = 1e-9 m against c = 2e-4 m: ~1e-16 * c / delta
# = 2e-11 relative), and so do the closed forms (alpha0 - sin alpha0 cos alpha0 ~ alpha0^3
# from terms ~ alpha0: 1e-16 / alpha0^2 ~ 2e-11 at alpha0 = 3e-3). 1e-9 is far above both
# and far below any quadrature or modelling error tested.
ROUNDING = 1e-9


def arc_points(alpha0, m):
    """The midpoints the kernels use, written out independently."""
    step = 2.0 * alpha0 / m
    return -alpha0 + (np.arange(m) + 0.5) * step


# ---------------------------------------------------------------- foundation modulus


def test_foundation_modulus_hand_numbers():
    # (1 - 0.3) 207 GPa / ((1.3)(0.4)) = 144.9 GPa / 0.52 = 278.653846153846... GPa.
    assert foundation_modulus(207e9, 0.3) == pytest.approx(278.653846153846e9, rel=1e-14)
    # nu = 0: no lateral constraint to stiffen the layer, k_f = E.
    assert foundation_modulus(207e9, 0.0) == 207e9
    # nu = 0.25: 0.75 E / (1.25 * 0.5) = 1.2 E.
    assert foundation_modulus(1.0, 0.25) == pytest.approx(1.2, rel=1e-15)


# ---------------------------------------------------------------- arc and points


def test_contact_half_angle():
    assert contact_half_angle(1e-4, 2e-4) == 0.0
    assert contact_half_angle(2e-4, 2e-4) == 0.0
    assert contact_half_angle(4e-4, 2e-4) == pytest.approx(math.pi / 3, rel=1e-15)
    assert contact_half_angle(0.0, -1e-6) == math.pi  # press fit, all round
    assert contact_half_angle(1e-6, -2e-6) == math.pi


def test_foundation_points():
    # alpha0 = pi/4 over 360 sectors: 4 * 360 * (1/4) = 360 points, spacing pi/720 = 1/4 sector.
    assert foundation_points(math.pi / 4, 360) == 360
    assert foundation_points(1e-3, 360) == 32  # narrow arc: the floor
    assert foundation_points(math.pi, 3600) == 2048  # cap
    for alpha0 in np.linspace(0.01, 3.0, 37):
        for n in (4, 7, 90, 361):
            m = foundation_points(alpha0, n)
            assert m % 2 == 0
            assert 32 <= m <= 2048
            if 32 < m < 2048:
                assert 2 * alpha0 / m <= TWO_PI / n / 4 * (1 + 1e-12)


# ---------------------------------------------------------------- unworn circles


def midpoint_excess(alpha0, step, f_prime):
    """Leading midpoint-rule error, sum - integral = (h^2/24)(f'(-alpha0) - f'(alpha0)).

    Euler-Maclaurin for the composite midpoint rule; the next term is
    -(7 h^4 / 5760)(f'''(-alpha0) - f'''(alpha0)), a fraction ~ h^2 / 30 of this one
    (below 3e-4 for h <= 0.1), hence the 1 % allowance on it below.
    """
    return step**2 / 24.0 * (f_prime(-alpha0) - f_prime(alpha0))


DELTAS = [1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 5e-5, 1e-4, 0.9 * C]


@pytest.mark.parametrize("delta", DELTAS)
@pytest.mark.parametrize("m", [32, 256, 2048])
def test_unworn_force_and_total_closed_forms(delta, m):
    # Unworn: u = e cos a - c on |a| < alpha0 = acos(c / e), where e cos alpha0 = c.
    #   f_n / (k R L) = int (e cos a - c) cos a da = e (alpha0 + sin alpha0 cos alpha0)
    #                   - 2 c sin alpha0 = e (alpha0 - sin alpha0 cos alpha0)
    #   total / (k R L) = int (e cos a - c) da = 2 e sin alpha0 - 2 c alpha0
    #                   = 2 e (sin alpha0 - alpha0 cos alpha0)
    e = C + delta
    alpha0 = math.acos(C / e)
    krl = K_OVER_H * R_J * WIDTH
    exact_f = krl * e * (alpha0 - math.sin(alpha0) * math.cos(alpha0))
    exact_t = 2.0 * krl * e * (math.sin(alpha0) - alpha0 * math.cos(alpha0))
    f_n, total, peak = foundation_load(e, C, 0.3, NONE, 2.0, NONE, R_J, WIDTH, K_OVER_H, m)
    # The integrands vanish at the arc ends and are smooth: the midpoint rule's error is
    # O(h^2), relative ~ 1 / (2 m^2) on narrow arcs. Check the error itself against its
    # leading term (sign and size): f'(a) = -e sin 2a + c sin a for f_n, -e sin a for total.
    step = 2.0 * alpha0 / m
    lead_f = krl * midpoint_excess(alpha0, step, lambda a: -e * math.sin(2 * a) + C * math.sin(a))
    lead_t = krl * midpoint_excess(alpha0, step, lambda a: -e * math.sin(a))
    assert abs((f_n - exact_f) - lead_f) <= 0.01 * abs(lead_f) + ROUNDING * exact_f
    assert abs((total - exact_t) - lead_t) <= 0.01 * abs(lead_t) + ROUNDING * exact_t
    # The peak interference is at the point nearest the normal, a = +-h/2.
    assert peak == pytest.approx(e * math.cos(step / 2) - C, rel=ROUNDING)
    assert peak < delta


@pytest.mark.parametrize("delta", [1e-9, 1e-8, 1e-7, 1e-6, 2e-6])
def test_unworn_force_small_penetration_limit(delta):
    # alpha0 small: cos alpha0 = c / (c + delta) gives alpha0^2 = 2x - (5/3) x^2 + ...,
    # x = delta / c, and alpha0 - sin alpha0 cos alpha0 = (2/3) alpha0^3 - (2/15) alpha0^5
    # + ..., so f_n = k R L c (1 + x)(2/3)(2x)^(3/2)(1 - 1.65 x + ...)
    #             = k R L (4 sqrt(2) / 3) c^(-1/2) delta^(3/2) (1 - 0.65 x + O(x^2)).
    # The O(x^2) coefficient is 0.587 (evaluated from the closed form), so x^2 bounds the
    # remainder; the m = 2048 midpoint error adds 1 / (2 m^2) = 1.2e-7 relative.
    x = delta / C
    f_n, _, _ = foundation_load(C + delta, C, 0.0, NONE, 0.0, NONE, R_J, WIDTH, K_OVER_H, 2048)
    limit = K_OVER_H * R_J * WIDTH * 4.0 * math.sqrt(2.0) / 3.0 * C**-0.5 * delta**1.5
    assert abs(f_n / limit - (1.0 - 0.65 * x)) <= x**2 + 1.0 / (2 * 2048**2) + ROUNDING


def test_no_contact_inside_the_clearance():
    assert foundation_load(C, C, 0.0, NONE, 0.0, NONE, R_J, WIDTH, K_OVER_H, 64) == (0, 0, 0)
    assert foundation_load(0.0, C, 0.0, NONE, 0.0, NONE, R_J, WIDTH, K_OVER_H, 64) == (0, 0, 0)


# ---------------------------------------------------------------- uniform interference


@pytest.mark.parametrize(
    ("c", "depth"),
    [(-3e-6, 0.0), (-5e-6, 2e-6)],  # a press fit; a worn press fit with u = -c - d
)
def test_ring_and_pin_uniform_pressure(c, depth):
    # e = 0: g = c + d all round, so u = -(c + d) = 3e-6 m at every angle, alpha0 = pi.
    n, m = 36, 72
    wear_b = np.full(n, depth)
    u0 = -(c + depth)
    alphas = arc_points(math.pi, m)
    for a in alphas:
        u = interference(a, 0.0, c, 0.7, wear_b, 1.9, NONE)
        # depth_at blends two equal depths: exact to an ulp of d.
        assert K_OVER_H * u == pytest.approx(K_OVER_H * u0, rel=1e-9)
    f_n, total, peak = foundation_load(0.0, c, 0.7, wear_b, 1.9, NONE, R_J, WIDTH, K_OVER_H, m)
    # Uniform p = k u0 over the whole circle: total = k u0 R L 2 pi; f_n = 0 because the
    # midpoint rule sums cos over m equally spaced angles of a full period to zero.
    assert total == pytest.approx(K_OVER_H * u0 * R_J * WIDTH * TWO_PI, rel=1e-9)
    assert abs(f_n) <= 1e-12 * total
    assert peak == pytest.approx(u0, rel=1e-9)
    # Uniform pressure wears uniformly: m = 2 n points, theta = 0, so each sector holds
    # exactly two points of equal pressure.
    dh = np.zeros(n)
    volume = 1e-12
    added = spread_foundation_wear(dh, 0.0, R_B, WIDTH, volume, 0.0, c, 0.7, wear_b, 1.9, NONE, m)
    assert added == volume
    per_sector = volume / (R_B * WIDTH * TWO_PI)
    np.testing.assert_allclose(dh, per_sector, rtol=1e-9)


# ---------------------------------------------------------------- worn profiles


@pytest.mark.parametrize("depth", [1e-6, 2e-5, 1e-4])
@pytest.mark.parametrize("on_journal", [False, True])
def test_uniform_wear_is_a_larger_clearance(depth, on_journal):
    # Uniform wear d anywhere adds d to the gap everywhere: same force as an unworn joint
    # with clearance c + d, whose closed form is that of the unworn test. The arc the
    # kernel integrates is acos(c / e), wider than the contact acos((c + d) / e): the
    # integrand is then continuous with a kink at each contact end, where a cell errs by at
    # most h^2 |f'| / 8; the smooth part errs by at most (2 alpha0) h^2 / 24 max|f''|,
    # |f''| <= 2e + c + d. Their sum is the tolerance.
    e, m = C + 1.5e-4, 2048
    cd = C + depth
    wear = np.full(97, depth)
    wear_b, wear_j = (NONE, wear) if on_journal else (wear, NONE)
    f_n, _, _ = foundation_load(e, C, 1.0, wear_b, 4.0, wear_j, R_J, WIDTH, K_OVER_H, m)
    krl = K_OVER_H * R_J * WIDTH
    a_c = math.acos(cd / e)
    exact = krl * e * (a_c - math.sin(a_c) * math.cos(a_c))
    alpha0 = math.acos(C / e)
    step = 2 * alpha0 / m
    bound = krl * (2 * alpha0 * step**2 / 24 * (2 * e + cd) + 2 * step**2 / 8 * cd * math.sin(a_c))
    assert abs(f_n - exact) <= bound + ROUNDING * exact


def test_worn_profile_pointwise_gap():
    # Each body's profile is read in its own frame: with theta_j = theta_b + 3 sectors, the
    # angle a that lands on bearing sector i's centre lands on journal sector i + 3's
    # centre, where depth_at returns the stored depths themselves.
    n = 8
    sector = TWO_PI / n
    wear_b = np.arange(n) * 1e-6
    wear_j = np.arange(n)[::-1] * 1e-7
    theta_b, e = 0.2, C + 4e-5
    theta_j = theta_b + 3 * sector
    for i in range(n):
        a = (i + 0.5) * sector - theta_b
        expected = e * math.cos(a) - C - wear_b[i] - wear_j[(i + 3) % n]
        got = interference(a, e, C, theta_b, wear_b, theta_j, wear_j)
        assert got == pytest.approx(max(0.0, expected), rel=1e-12, abs=1e-18)


# ---------------------------------------------------------------- spreading the wear


def sector_meets_arc(n, theta, alpha0):
    """Which sectors overlap the arc theta +- alpha0 (circular distance of centres)."""
    centres = (np.arange(n) + 0.5) * TWO_PI / n
    dist = np.abs((centres - theta + math.pi) % TWO_PI - math.pi)
    return dist < alpha0 + math.pi / n


@settings(max_examples=300, deadline=None)
@given(
    n=st.integers(4, 3600),
    n_other=st.integers(4, 3600),
    delta=st.floats(1e-9, 0.9 * C),
    theta=st.floats(-10.0, 10.0),
    theta_other=st.floats(-10.0, 10.0),
    worn=st.booleans(),
    on_journal=st.booleans(),
    volume=st.floats(1e-18, 1e-9),
    seed=st.integers(0, 2**32 - 1),
)
def test_spread_volume_is_exact(
    n, n_other, delta, theta, theta_other, worn, on_journal, volume, seed
):
    # The depths are scaled by the total of the same pressures they are spread by, so
    # sum(dh) R 2pi/N L = volume up to the rounding of <= 2048 additions and one division
    # (~1e-13 relative at worst): 1e-12. Spreading into a fresh array keeps the measured dh
    # free of cancellation against existing depths.
    rng = np.random.default_rng(seed)
    e = C + delta
    own = rng.uniform(0, 2 * delta, n) if worn else NONE  # the surface being worn
    other = rng.uniform(0, 2 * delta, n_other) if worn else NONE
    if on_journal:
        args = (e, C, theta_other, other, theta, own)
        radius = R_J
    else:
        args = (e, C, theta, own, theta_other, other)
        radius = R_B
    alpha0 = contact_half_angle(e, C)
    m = foundation_points(alpha0, max(n, n_other))
    dh = np.zeros(n)
    added = spread_foundation_wear(dh, theta, radius, WIDTH, volume, *args, m)
    _, _, peak = foundation_load(*args, radius, WIDTH, K_OVER_H, m)
    if peak == 0.0:  # worn deeper than the penetration: no contact, no wear
        assert added == 0.0
        assert not dh.any()
        return
    assert added == volume
    assert dh.min() >= 0.0
    assert dh.sum() * radius * TWO_PI / n * WIDTH == pytest.approx(volume, rel=1e-12)
    # No sector outside the contact arc is worn.
    assert not dh[~sector_meets_arc(n, theta, alpha0)].any()


@pytest.mark.parametrize("n", [4, 36, 360, 3600])
@pytest.mark.parametrize("boundary", [0, 1, 3])  # 0: the 0 / 2 pi wrap-around
@pytest.mark.parametrize("delta", [1e-8, 1e-6, 1e-4])
def test_symmetric_arc_wears_symmetrically(n, boundary, delta):
    # theta on the boundary between sectors b - 1 and b, unworn surfaces: the pressure is
    # even in alpha and the kernel's points are exactly antisymmetric, so sector b - 1 - i
    # mirrors sector b + i to rounding. The arcs range from a fraction of a sector
    # (delta = 1e-8, n = 4: alpha0 = 0.01 rad) to many sectors (delta = 1e-4, n = 3600).
    e = C + delta
    theta = boundary * TWO_PI / n
    alpha0 = contact_half_angle(e, C)
    m = foundation_points(alpha0, n)
    dh = np.zeros(n)
    volume = 1e-12
    spread_foundation_wear(dh, theta, R_B, WIDTH, volume, e, C, theta, NONE, 2.0, NONE, m)
    mirrored = dh[(2 * boundary - 1 - np.arange(n)) % n]
    np.testing.assert_allclose(dh, mirrored, rtol=1e-12, atol=1e-15 * dh.max())
    assert dh[boundary - 1] > 0.0
    assert dh[boundary] == pytest.approx(dh[boundary - 1], rel=1e-12)
    assert not dh[~sector_meets_arc(n, theta, alpha0)].any()


def test_spread_follows_pressure_inside_one_sector_pair():
    # A narrow arc inside one sector: all the wear lands there.
    n = 12
    theta = 2.5 * TWO_PI / n  # the centre of sector 2
    e = C + 1e-7  # alpha0 = 0.03 rad, a sector is 0.52 rad
    dh = np.zeros(n)
    spread_foundation_wear(dh, theta, R_B, WIDTH, 1e-12, e, C, theta, NONE, 0.0, NONE, 32)
    assert np.flatnonzero(dh).tolist() == [2]
    assert dh[2] * R_B * TWO_PI / n * WIDTH == pytest.approx(1e-12, rel=1e-12)


def test_spread_reads_the_profile_before_changing_it():
    # depths may be the worn profile itself: the result equals spreading into a copy.
    rng = np.random.default_rng(7)
    n = 90
    wear_b = rng.uniform(0, 2e-5, n)
    e, theta_b = C + 3e-5, 1.3
    m = foundation_points(contact_half_angle(e, C), n)
    dh = np.zeros(n)
    spread_foundation_wear(dh, theta_b, R_B, WIDTH, 1e-10, e, C, theta_b, wear_b, 0.4, NONE, m)
    expected = wear_b + dh
    spread_foundation_wear(wear_b, theta_b, R_B, WIDTH, 1e-10, e, C, theta_b, wear_b, 0.4, NONE, m)
    # In place, each point's share is added to the old depth one by one rather than as one
    # sum: a few ulps apart. Reading a half-updated profile instead would move the pressure
    # by dh ~ 7e-6 m, the size of the depths themselves.
    np.testing.assert_allclose(wear_b, expected, rtol=1e-14)


def test_spread_without_contact_or_volume_adds_nothing():
    dh = np.zeros(10)
    assert spread_foundation_wear(dh, 0.0, R_B, WIDTH, 1e-12, C, C, 0.0, NONE, 0.0, NONE, 32) == 0
    e = C + 1e-6
    assert spread_foundation_wear(dh, 0.0, R_B, WIDTH, 0.0, e, C, 0.0, NONE, 0.0, NONE, 32) == 0
    deep = np.full(10, 2e-6)  # worn deeper than the penetration
    assert spread_foundation_wear(dh, 0.0, R_B, WIDTH, 1e-12, e, C, 0.0, deep, 0.0, NONE, 32) == 0
    assert not dh.any()
