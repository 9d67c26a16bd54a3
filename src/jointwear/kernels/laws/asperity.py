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

Load. Across the contact the gap is h(x) = h_min + x^2 / (2 R*) (the circles' gap to order
(x / R)^2), so with u = x / sqrt(2 R* sigma) and lam(u) = lam_min + u^2 the fit integrates in
closed form: with a^2 = 4 - lam_min, int A (a^2 - u^2)_+^m du = A B(1/2, m + 1) a^(2m + 1), so

    W = L int p_a dx = L k_gt E' sqrt(2 R* sigma) A B(1/2, m + 1) (4 - lam_min)^(m + 1/2),

A = 4.4086e-5, m = 6.804, for lam_min < 4 (h_min may be negative: the mean planes overlap),
and 0 beyond, where no asperity of the fit reaches across: the asperities touch from
lam_min = 4 on, with the load and its first six derivatives rising from 0. Its potential is
U = int_h_min^(4 sigma) W dh = sigma (4 - lam_min) W / (m + 3/2). The fit carries its own
error into W: against the Gaussian load, W(lam) = (5 pi / 16) L k_gt E' sqrt(2 R* sigma)
F_3(lam) exactly (int F_5/2(lam + u^2) du = B(1/2, 7/2) F_3(lam), F_3 elementary), it is 3 to
16 % short for -1 <= lam <= 2 and further in the tail
(tests/test_asperity.py): within the spread of the asperity data themselves (eta sigma beta
0.03 to 0.05 moves W by a factor 2.8). Against the circles' exact gap (R_B - e cos a -
sqrt(R_J^2 - e^2 sin^2 a) along the bearing's radius) the parabola is within (|lam_min| / 2 +
1/2) sigma / c: the gap's curvature at eccentricity e is e (R_J + e) / (R_J R_B^2), 1 / R*
only at e = c.

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
_FIT_END = 4.0  # lam beyond which the fit is 0: the asperities touch from there on
_FIT_ACROSS = (
    _FIT_SCALE * math.gamma(0.5) * math.gamma(_FIT_EXPONENT + 1.0) / math.gamma(_FIT_EXPONENT + 1.5)
)  # A B(1/2, m + 1): the fit integrated across the parabolic gap
ASPERITY_START = _FIT_END  # the film thickness / sigma below which the asperities touch [-]
_INV_SQRT_2PI = 1.0 / math.sqrt(2.0 * math.pi)
_INV_SQRT_2 = 1.0 / math.sqrt(2.0)


@njit(cache=True, no_cfunc_wrapper=True)
def f52(lam: float) -> float:
    """Greenwood-Tripp integral F_5/2(lam) [-] by the fit of Hu et al. (1994).

    4.4086e-5 (4 - lam)^6.804 for lam < 4, 0 beyond; lam = h / sigma [-]. Up to 11.4 %
    short of the integral for -1 <= lam <= 2, further beyond (module docstring).
    """
    if lam >= _FIT_END:
        return 0.0
    return _FIT_SCALE * (_FIT_END - lam) ** _FIT_EXPONENT


@njit(cache=True, no_cfunc_wrapper=True)
def asperity_load(h_min: float, sigma: float, scale: float, r_star: float, width: float) -> float:
    """Total asperity load W [N] on a journal with minimum mean-plane gap h_min [m].

    W = L scale sqrt(2 R* sigma) A B(1/2, m + 1) (4 - h_min / sigma)^(m + 1/2) for
    h_min < 4 sigma, else 0: the fitted Greenwood-Tripp pressure integrated over the gap
    h_min + x^2 / (2 R*) (module docstring). sigma [m]; scale = k_gt E' [Pa]; r_star,
    width [m].
    """
    reach = _FIT_END - h_min / sigma
    if reach <= 0.0:
        return 0.0
    return (
        width
        * scale
        * math.sqrt(2.0 * r_star * sigma)
        * _FIT_ACROSS
        * reach ** (_FIT_EXPONENT + 0.5)
    )


@njit(cache=True, no_cfunc_wrapper=True)
def asperity_energy(h_min: float, sigma: float, scale: float, r_star: float, width: float) -> float:
    """Elastic energy [J] the asperities store at minimum gap h_min [m] (arguments as the load).

    U = int_h_min^(4 sigma) W dh = sigma (4 - h_min / sigma) W / (m + 3/2).
    """
    reach = _FIT_END - h_min / sigma
    if reach <= 0.0:
        return 0.0
    load = asperity_load(h_min, sigma, scale, r_star, width)
    return sigma * reach * load / (_FIT_EXPONENT + 1.5)


@njit(cache=True, no_cfunc_wrapper=True)
def mean_gap(h: float, sigma: float) -> float:
    """Expected local gap E[max(h - z, 0)] = sigma (lam Phi(lam) + phi(lam)) [m], lam = h / sigma.

    z ~ N(0, sigma^2) is the combined roughness [m] (Patir and Cheng 1978's average gap):
    -> h for h >> sigma, -> 0 as h -> -inf, > 0 down to h = -38 sigma, where it underflows.
    """
    lam = h / sigma
    below = 0.5 * math.erfc(-lam * _INV_SQRT_2)  # Phi(lam)
    return sigma * (lam * below + _INV_SQRT_2PI * math.exp(-0.5 * lam * lam))


@njit(cache=True, no_cfunc_wrapper=True)
def film_eccentricity(delta: float, gap: float, sigma: float) -> float:
    """The mixed film's eccentricity ratio [-]: 1 - mean_gap(max(-delta, 0), sigma) / gap.

    delta [m]: the penetration (minus the film thickness); gap [m]: the local clearance;
    sigma [m]: the roughness. Below touching mean planes the film keeps their mean gap
    (docs/theory.md, section 6); never below 0.
    """
    return max(0.0, 1.0 - mean_gap(max(-delta, 0.0), sigma) / gap)
