"""Greenwood-Tripp asperity contact of a rough journal in its rough bearing (mixed lubrication).

| symbol | meaning | unit | paper |
|---|---|---|---|
| h, h_min | separation of the surfaces' mean planes, its minimum over the contact | m | GT |
| sigma | combined standard deviation of the two surfaces' summit heights | m | GT |
| eta, beta | asperity density and summit radius of each surface | 1/m^2, m | GT |
| k_gt | (16 sqrt(2) pi / 15) (eta sigma beta)^2 sqrt(sigma / beta) | - | GT |
| e_prime | E', 1/E' = (1 - nu1^2) / E1 + (1 - nu2^2) / E2, the contact modulus E* | Pa | GT |
| lam | h / sigma (at the minimum gap: the film parameter, lambda ratio) | - | |
| F_n(lam) | (1/sqrt(2 pi)) int_lam^inf (s - lam)^n exp(-s^2/2) ds | - | GT |
| p_a | asperity contact pressure k_gt E' F_5/2(h / sigma) | Pa | GT |
| r_star, width | relative radius R_B R_J / (R_B - R_J) (or see Load) and joint width L | m | |

Pressure. Greenwood and Tripp (1970-71) give the mean pressure the asperities of two rough
surfaces carry at mean-plane separation h as p_a = k_gt E' F_5/2(h / sigma). E' is the contact
modulus of the Hertz law, 1/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (the code's ``contact_modulus``
E*; the factor between them is 1): summing Hertz contacts (4/3) E' sqrt(beta / 2) w^(3/2) of
pairs of summits of radius beta, offset r, overlap w = s - h - r^2 / (4 beta), over
2 pi eta^2 r dr and over the summed height s ~ N(0, sigma^2), gives exactly the factor
16 sqrt(2) pi / 15 of k_gt; with twice E* it would be half that (tests/test_asperity.py
integrates the pairs by quadrature). F_5/2 has no elementary form; ``f52`` is the common
power-law fit 4.4086e-5 (4 - lam)^6.804 for lam < 4, 0 beyond (Hu et al. 1994, used by
Arcoumanis et al. 1997 and most mixed-lubrication papers since). Measured against quadrature
it is 1.5 % to 11.4 % short of F_5/2 for -1 <= lam <= 2, and further in the tail: -35 % at
lam = 2.5, -74 % at 3, -98 % at 3.5, at most 5e-4 in absolute terms (0.08 % of F_5/2(0))
(docs/theory.md; benchmarks/asperity_fit.py).

Load. The load a journal's asperities carry needs no fit. Across the contact the gap is
h(x) = h_min + x^2 / (2 R*) (the circles' gap to order (x / R)^2), so with u = x / sqrt(2 R*
sigma), lam(u) = lam_min + u^2 and F_5/2 written as its defining integral,

    int F_5/2(lam_min + u^2) du = int phi(s) int (s - lam_min - u^2)_+^(5/2) du ds
                                = B(1/2, 7/2) F_3(lam_min),

because int (a^2 - u^2)_+^(5/2) du = B(1/2, 7/2) a^6. B(1/2, 7/2) = 5 pi / 16, and the integer
moments are elementary: with Q = erfc(lam / sqrt 2) / 2 and phi = exp(-lam^2 / 2) / sqrt(2 pi),
F_0 = Q, F_1 = phi - lam Q and F_(n+1) = n F_(n-1) - lam F_n (integration by parts). So

    W = L int p_a dx = (5 pi / 16) L k_gt E' sqrt(2 R* sigma) F_3(h_min / sigma),

exact for the parabolic gap, smooth, for every h_min (negative: the mean planes overlap), and
dW/dh_min = -(15 pi / 16) L k_gt E' sqrt(2 R* / sigma) F_2 < 0. Against the circles' exact gap
(R_B - e cos a - sqrt(R_J^2 - e^2 sin^2 a) along the bearing's radius) it is within
(|lam_min| / 2 + 1/2) sigma / c: the gap's curvature at eccentricity e is e (R_J + e) /
(R_J R_B^2), 1 / R* only at e = c, which accounts for lam_min sigma / (2 c); passing that
curvature's radius as r_star leaves terms of order R* sigma / R^2 ~ sigma / c, measured below
0.3 sigma / c. The same substitution gives
the pressure's second moment across the contact, int x^2 p_a dx / int p_a dx = R* sigma F_4 /
(4 F_3) (with B(3/2, 7/2) / B(1/2, 7/2) = 1/8); ``asperity_half_width`` is the half-width of the
Hertz ellipse with that moment, sqrt(R* sigma F_4 / F_3), for spreading the wear.

Mean gap. The expected local film thickness between two surfaces of combined Gaussian
roughness sigma at mean-plane separation h is E[max(h - z, 0)] = sigma (lam Phi(lam) +
phi(lam)) = sigma F_1(-lam) (the average gap of Patir and Cheng 1978): positive for every h
(in floating point down to h = -38 sigma, where it underflows), -> h for h >> sigma and -> 0
as h -> -inf.

References
----------
J.A. Greenwood, J.H. Tripp, "The contact of two nominally flat rough surfaces", Proc. Instn
Mech. Engrs 185 (1970-71) 625-633, doi:10.1243/PIME_PROC_1970_185_069_02.
Y. Hu, H.S. Cheng, T. Arai, Y. Kobayashi, S. Aoyama, "Numerical simulation of piston ring in
mixed lubrication - a nonaxisymmetrical analysis", J. Tribol. 116 (1994) 470-478.
C. Arcoumanis, P. Ostovar, R. Mortier, "Mixed lubrication modelling of Newtonian and shear
thinning liquids in a piston-ring configuration", SAE Technical Paper 972924 (1997).
N. Patir, H.S. Cheng, "An average flow model for determining effects of three-dimensional
roughness on partial hydrodynamic lubrication", J. Lubr. Technol. 100 (1978) 12-17.
"""

import math

from numba import njit

_FIT_SCALE = 4.4086e-5  # Hu et al. (1994)
_FIT_EXPONENT = 6.804
_FIT_END = 4.0  # lam beyond which the fit is 0
_BETA_HALF_SEVEN_HALVES = 5.0 * math.pi / 16.0  # B(1/2, 7/2) = Gamma(1/2) Gamma(7/2) / Gamma(4)
_INV_SQRT_2PI = 1.0 / math.sqrt(2.0 * math.pi)
_INV_SQRT_2 = 1.0 / math.sqrt(2.0)
_LAM_APART = 20.0  # beyond it F_3 < 1e-92 and the recurrence loses digits: no contact


@njit(cache=True)
def f52(lam: float) -> float:
    """Greenwood-Tripp integral F_5/2(lam) [-] by the fit of Hu et al. (1994).

    4.4086e-5 (4 - lam)^6.804 for lam < 4, 0 beyond; lam = h / sigma [-]. Up to 11.4 %
    short of the integral for -1 <= lam <= 2, further beyond (module docstring).
    """
    if lam >= _FIT_END:
        return 0.0
    return _FIT_SCALE * (_FIT_END - lam) ** _FIT_EXPONENT


@njit(cache=True)
def asperity_pressure(h: float, sigma: float, k_gt: float, e_prime: float) -> float:
    """Greenwood-Tripp asperity pressure p_a = k_gt E' F_5/2(h / sigma) [Pa].

    h [m] is the local mean-plane separation, sigma [m] the combined roughness, k_gt [-] the
    constant of ``film.asperity.asperity_constant``, e_prime [Pa] the contact modulus E*.
    """
    return k_gt * e_prime * f52(h / sigma)


@njit(cache=True)
def gaussian_moments(lam: float) -> tuple[float, float, float, float, float]:
    """The Greenwood-Tripp integrals F_0 ... F_4 at lam [-], in closed form.

    F_n(lam) = (1/sqrt(2 pi)) int_lam^inf (s - lam)^n exp(-s^2 / 2) ds: F_0 = Q,
    F_1 = phi - lam Q, F_(n+1) = n F_(n-1) - lam F_n, Q = erfc(lam / sqrt 2) / 2,
    phi = exp(-lam^2 / 2) / sqrt(2 pi). The recurrence cancels digits for large lam: relative
    error below 1e-10 (F_1) and 1e-4 (F_4) up to lam = 20; all underflow near lam = 38.
    """
    f0 = 0.5 * math.erfc(lam * _INV_SQRT_2)
    f1 = _INV_SQRT_2PI * math.exp(-0.5 * lam * lam) - lam * f0
    f2 = f0 - lam * f1
    f3 = 2.0 * f1 - lam * f2
    f4 = 3.0 * f2 - lam * f3
    return f0, f1, f2, f3, f4


@njit(cache=True)
def asperity_load(
    h_min: float, sigma: float, k_gt: float, e_prime: float, r_star: float, width: float
) -> float:
    """Total asperity load [N] on a journal with minimum mean-plane gap h_min [m].

    W = (5 pi / 16) L k_gt E' sqrt(2 R* sigma) F_3(h_min / sigma): the Greenwood-Tripp
    pressure integrated exactly over the gap h_min + x^2 / (2 R*) (module docstring); 0 for
    h_min >= 20 sigma (F_3 < 1e-92 there). h_min may be negative (the mean planes overlap);
    sigma [m], k_gt [-], e_prime [Pa], r_star [m], width [m].
    """
    lam = h_min / sigma
    if lam >= _LAM_APART:
        return 0.0
    f3 = gaussian_moments(lam)[3]
    return _BETA_HALF_SEVEN_HALVES * width * k_gt * e_prime * math.sqrt(2.0 * r_star * sigma) * f3


@njit(cache=True)
def asperity_half_width(h_min: float, sigma: float, r_star: float) -> float:
    """Half-width [m] of the Hertz ellipse with the asperity pressure's second moment.

    sqrt(R* sigma F_4 / F_3) at lam = h_min / sigma (module docstring); 0 where
    ``asperity_load`` is (no load to spread). h_min, sigma, r_star [m].
    """
    lam = h_min / sigma
    if lam >= _LAM_APART:
        return 0.0
    _, _, _, f3, f4 = gaussian_moments(lam)
    return math.sqrt(r_star * sigma * f4 / f3)


@njit(cache=True)
def mean_gap(h: float, sigma: float) -> float:
    """Expected local gap E[max(h - z, 0)] = sigma (lam Phi(lam) + phi(lam)) [m], lam = h / sigma.

    z ~ N(0, sigma^2) is the combined roughness [m] (Patir and Cheng 1978's average gap),
    sigma F_1(-lam): -> h for h >> sigma, -> 0 as h -> -inf, > 0 down to h = -38 sigma,
    where it underflows.
    """
    return sigma * gaussian_moments(-h / sigma)[1]
