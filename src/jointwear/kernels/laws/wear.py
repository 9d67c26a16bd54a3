"""Wear of a clearance joint: Hertz line-contact pressure, wear laws, sector accumulation.

| symbol | meaning | unit | paper |
|---|---|---|---|
| f_n | normal contact force | N | Eq. 18 |
| r_star, e_star | relative radius R_B R_J / (R_B - R_J), contact modulus | m, Pa | |
| width | joint width L | m | Table 2 |
| b, p_max | half-width of the contact strip and its peak pressure | m, Pa | |
| p(x) | pressure at arc length x from the patch centre, p_max sqrt(1 - x^2/b^2) | Pa | |
| coef | wear-depth rate per unit pressure, dh/ds = coef p | 1/Pa | Eqs. 9, 13 |
| k_wear | Archard's dimensional wear coefficient (paper: 8e-14) | 1/Pa | Eq. 13 |
| mu, tau | Reye: friction coefficient and shear strength | -, Pa | Eq. 9 |
| ds | sliding distance of one step, abs(v_t) dt | m | Eq. 14 |
| share | fraction of the worn volume taken by this surface (paper: 1/2) | - | Eqs. 21-22 |
| depths | wear depth of each of the N equal sectors of a surface | m | Eq. 20 |
| theta | direction of the contact normal in the surface's body frame | rad | Fig. 4 |
| radius | radius of the surface (R_J or R_B) | m | |

Sector i of a surface covers the angles [i, i + 1) * 2 pi / N of its body frame. The
pressure acts on the arc theta +- b / radius. ``accumulate_wear`` adds to each sector
share * coef * ds times the sector's mean pressure, integrating the ellipse over the overlap in
closed form, int sqrt(1 - u^2) du = (u sqrt(1 - u^2) + asin u) / 2, so that
sum(dh_i * radius * 2 pi / N * width) = share * coef * f_n * ds to rounding (SPEC sec. 4),
whatever N, across 0 / 2 pi, and for patches wider than a sector. The paper-style option
puts share * coef * p_max * ds into the one sector containing theta instead.

References
----------
J.F. Archard, "Contact and rubbing of flat surfaces", J. Appl. Phys. 24 (1953) 981-988.
K.L. Johnson, Contact Mechanics, Cambridge University Press (1985), sec. 4.2 (line contact).
Flores (2009), sec. 3 (Eqs. 9, 13, 14) and sec. 5 (Eqs. 20-22).
"""

import math
from enum import IntEnum

import numpy as np
from numba import njit
from numpy.typing import NDArray

from .dispatch import Dispatch


class WearLaw(IntEnum):
    """Codes of the wear laws (``model.laws.wear.WEAR``, whose records name them)."""

    ARCHARD = 0
    REYE = 1


_TWO_PI = 2.0 * math.pi
_QUARTER_PI = 0.25 * math.pi  # (u sqrt(1 - u^2) + asin u) / 2 at u = 1


@njit(cache=True, no_cfunc_wrapper=True)
def archard(k_wear: float) -> float:
    """Archard's depth-rate coefficient dh/ds / p = k_wear [1/Pa] (paper Eq. 13)."""
    return k_wear


@njit(cache=True, no_cfunc_wrapper=True)
def reye(mu: float, tau: float) -> float:
    """Reye's depth-rate coefficient dh/ds / p = mu / tau [1/Pa] (paper Eq. 9).

    Eq. 8 ties the worn volume to the actual friction force; to honour it where friction is
    reduced (Ambrosio's c_d < 1), pass the effective coefficient abs(f_t) / f_n as mu.
    """
    return mu / tau


# The dispatcher: per code, the law's function and the arguments it takes (``dispatch``).
wear_coefficient = Dispatch(
    "wear_law",
    {WearLaw.ARCHARD: (archard, "p0"), WearLaw.REYE: (reye, "mu p0")},
    "mu p0", np.nan,
)  # fmt: skip
"""Depth-rate coefficient [1/Pa]: mu [-] is the friction acting, abs(f_t) / f_n, which Reye's
law reads; p0 the law's packed parameter (Archard's k_wear [1/Pa], Reye's tau [Pa])."""


@njit(cache=True, no_cfunc_wrapper=True)
def hertz_line_contact(
    f_n: float, r_star: float, e_star: float, width: float
) -> tuple[float, float]:
    """Half-width b [m] and peak pressure p_max [Pa] of a Hertz line contact.

    b = sqrt(4 f_n R* / (pi L E*)), p_max = 2 f_n / (pi b L); (0, 0) without load.

    References
    ----------
    Johnson (1985), sec. 4.2; SPEC sec. 4.
    """
    if f_n <= 0.0:
        return 0.0, 0.0
    b = math.sqrt(4.0 * f_n * r_star / (math.pi * width * e_star))
    return b, 2.0 * f_n / (math.pi * b * width)


@njit(cache=True, no_cfunc_wrapper=True)
def _ellipse_integral(u):
    """(u sqrt(1 - u^2) + asin u) / 2 with u clipped to [-1, 1]."""
    u = min(1.0, max(-1.0, u))
    return 0.5 * (u * math.sqrt(1.0 - u * u) + math.asin(u))


@njit(cache=True, no_cfunc_wrapper=True)
def sector_of(theta: float, n: int) -> int:
    """Index of the sector (of n) containing the angle theta [rad]."""
    return min(math.floor((theta % _TWO_PI) / (_TWO_PI / n)), n - 1)


@njit(cache=True, no_cfunc_wrapper=True)
def spread_wear(
    depths: NDArray[np.float64], theta: float, half_angle: float, peak_depth: float
) -> None:
    """Add an elliptical depth profile, averaged over each sector, to ``depths`` [m] in place.

    The profile is peak_depth sqrt(1 - (phi - theta)^2 / half_angle^2) for angles phi
    within half_angle [rad] of theta [rad]. The added area, sum(dh_i) 2 pi / N, is
    pi / 2 * peak_depth * half_angle to rounding.
    """
    if half_angle <= 0.0 or peak_depth == 0.0:
        return
    n = depths.shape[0]
    sector = _TWO_PI / n
    t = theta % _TWO_PI
    first = math.floor((t - half_angle) / sector)
    last = math.floor((t + half_angle) / sector)
    scale = peak_depth * half_angle / sector
    g_low = -_QUARTER_PI  # the patch's low edge, u = -1
    for j in range(first, last + 1):  # j may run below 0 or past n - 1: wrap-around
        if j == last:
            g_high = _QUARTER_PI
        else:
            g_high = _ellipse_integral(((j + 1) * sector - t) / half_angle)
        depths[j % n] += scale * (g_high - g_low)
        g_low = g_high  # shared edges make the sum telescope to pi / 2 exactly


@njit(cache=True, no_cfunc_wrapper=True)
def accumulate_wear(
    depths: NDArray[np.float64],
    theta: float,
    radius: float,
    width: float,
    f_n: float,
    b: float,
    ds: float,
    coef: float,
    share: float,
    single_sector: bool,
) -> float:
    """Add one step's wear of a surface to its sector depths [m], in place; return its volume.

    The pressure is Hertz's ellipse of half-width b [m] carrying f_n [N] on width [m];
    dh = share * coef * p * ds (paper Eqs. 13-14). Spread over the sectors the patch
    covers (worn volume share * coef * f_n * ds exactly), or with ``single_sector`` the peak
    depth share * coef * p_max * ds into the sector containing theta (paper style; the
    volume is then that depth over the whole sector) [m^3].
    """
    if f_n <= 0.0 or b <= 0.0 or ds <= 0.0:
        return 0.0
    peak = share * coef * ds * 2.0 * f_n / (math.pi * b * width)
    if single_sector:
        n = depths.shape[0]
        depths[sector_of(theta, n)] += peak
        return peak * radius * _TWO_PI / n * width
    spread_wear(depths, theta, b / radius, peak)
    return share * coef * f_n * ds


@njit(cache=True, no_cfunc_wrapper=True)
def depth_at(theta: float, depths: NDArray[np.float64]) -> float:
    """Wear depth [m] of a surface in direction theta [rad].

    Periodic and piecewise linear between the sector centres (i + 1/2) 2 pi / N, so that
    the worn profile, and with it the contact force, stays continuous (SPEC sec. 4).
    """
    n = depths.shape[0]
    s = (theta % _TWO_PI) / (_TWO_PI / n) - 0.5
    below = math.floor(s)
    w = s - below
    i = below % n
    return (1.0 - w) * depths[i] + w * depths[(i + 1) % n]
