"""Elastic-foundation (Winkler) contact of worn, non-circular journal and bearing surfaces.

| symbol | meaning | unit | source |
|---|---|---|---|
| e, n | eccentricity of the journal centre and its unit direction | m, - | |
| c | radial clearance R_B - R_J (negative: press fit) | m | |
| alpha | angle from n; the global direction theta_n + alpha | rad | |
| theta_b, theta_j | direction of n in the bearing's and the journal's body frame | rad | |
| w_B, w_J | wear depth of each surface, ``depth_at`` of its sector depths | m | |
| g(alpha) | local gap c + w_B(theta_b + alpha) + w_J(theta_j + alpha) - e cos alpha | m | |
| u | interference max(0, -g) | m | |
| young, nu | Young's modulus and Poisson's ratio of the elastic layer | Pa, - | |
| k_f | foundation modulus (1 - nu) E / ((1 + nu)(1 - 2 nu)) (``model.laws``) | Pa | Johnson 1985 |
| h | thickness of the elastic layer on its rigid substrate | m | |
| k_over_h | foundation stiffness per unit thickness k_f / h; p = k_over_h u | Pa/m | |
| alpha0 | half-angle of the arc where contact is possible, acos(c / e) | rad | |
| m | number of integration points (midpoints of m equal cells of the arc) | - | |
| f_n | int p cos(alpha) R L dalpha, the force along n pushing the journal back | N | |
| total | int p R L dalpha, the sum of the pressures over the contact | N | |

The gap is linearised for c << R: both surfaces are circles of nearly equal radius R, and
the journal displaced by e along n closes the gap in direction alpha by e cos alpha. Wear
only deepens a surface (w >= 0), so u > 0 needs e cos alpha > c, i.e. |alpha| < alpha0:
no contact when e <= c, the whole circle (alpha0 = pi) when c <= -e. The integrals run
over that arc with the composite midpoint rule. Where the interference is a smooth
function of alpha that vanishes at the arc ends (unworn surfaces), the rule's error is
second order: for an integrand f the sum exceeds the integral by
(h_a^2 / 24)(f'(-alpha0) - f'(alpha0)) + O(h_a^4), cell width h_a = 2 alpha0 / m, about
1 / (2 m^2) of f_n on narrow arcs. A worn profile has kinks at the sector centres and at
the contact ends, each cell with a kink erring by at most h_a^2 / 8 times the jump of f':
the same order.

Each integration point is a spring of the bed of springs: its pressure is k_over_h u with
no coupling to its neighbours (Winkler), so the pressure follows the worn shape point by
point. ``spread_foundation_wear`` distributes one step's worn volume of one surface in
proportion to this pressure, each point's share going to the sector of that surface's
frame that contains the point's direction.

What was checked of Mukras et al. (2010): their abstract (ASME J. Tribol. 132, 031604,
and the IDETC 2010 conference version DETC2010-28750) states that joint forces and contact
pressures come from the elastic foundation model with hysteresis damping, with the joint
clearance shaped by the wear, but the body of the paper (the definition of their
foundation modulus, layer thickness and which body carries the layer) could not be read
through the search tool, so those details are not confirmed here. The modulus above is the
one of a thin elastic layer bonded to a rigid substrate under uniaxial strain (Johnson
1985, not re-read here); the same formula, for "a uniform layer of elastic material over a
rigid substrate", was read in Simbody's ``ElasticFoundationForce`` documentation
(simbody/simbody, Simbody/include/simbody/internal/ElasticFoundationForce.h). This module
takes k_over_h as one number so that the caller chooses: a layer on one body, or two
layers in series (1 / k_over_h = h_1 / k_f1 + h_2 / k_f2).

References
----------
E. Winkler, Die Lehre von der Elasticitaet und Festigkeit, Dominicus, Prag (1867).
K.L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 5, the "simple
elastic foundation" model (section number not checked here).
S.M. Mukras, N.H. Kim, N.A. Mauntler, T.L. Schmitz, W.G. Sawyer, "Comparison between
elastic foundation and contact force models in wear analysis of planar multibody system",
J. Tribol. 132 (2010) 031604.
"""

import math

import numpy as np
from numba import njit
from numpy.typing import NDArray

from .wear import depth_at, sector_of

_TWO_PI = 2.0 * math.pi
_MIN_POINTS = 32
_MAX_POINTS = 2048


@njit(cache=True, no_cfunc_wrapper=True)
def contact_half_angle(e: float, c: float) -> float:
    """Half-angle alpha0 [rad] of the arc where contact is possible, acos(c / e).

    0 when e <= c (no contact), pi when c <= -e (a press fit touching all round).
    """
    if e <= c:
        return 0.0
    if e <= -c:
        return math.pi
    return math.acos(c / e)


@njit(cache=True, no_cfunc_wrapper=True)
def foundation_points(alpha0: float, sectors: int) -> int:
    """Number of integration points m over the arc of half-angle alpha0 [rad].

    The smallest even m with a spacing 2 alpha0 / m of at most a quarter sector
    (2 pi / sectors / 4), so that every sector the arc covers gets at least four
    samples of the pressure and the kinks of the worn profile (at the sector centres)
    are resolved; pass the larger sector count of the two surfaces. m is clipped to
    [32, 2048]: 32 keeps the force's relative quadrature error below about
    1 / (2 * 32^2) = 5e-4 on a narrow arc, 2048 bounds the cost per call (so with
    more than 1024 sectors and wide arcs the spacing exceeds a quarter sector). Even,
    so that no point sits on the arc's centre line. m changes in steps as alpha0
    changes; for a force continuous in time, keep one m per joint.
    """
    m = math.ceil(4.0 * sectors * alpha0 / math.pi)
    m = min(_MAX_POINTS, max(_MIN_POINTS, m))
    return m + m % 2


@njit(cache=True, no_cfunc_wrapper=True)
def _wear_depth(theta: float, depths: NDArray[np.float64]) -> float:
    """``depth_at``, or 0 for an empty array (a surface without wear feedback) [m]."""
    if depths.shape[0] == 0:
        return 0.0
    return depth_at(theta, depths)


@njit(cache=True, no_cfunc_wrapper=True)
def interference(
    alpha: float,
    e: float,
    c: float,
    theta_b: float,
    wear_b: NDArray[np.float64],
    theta_j: float,
    wear_j: NDArray[np.float64],
) -> float:
    """Interference u = max(0, -g) [m] at angle alpha [rad] from the normal.

    g = c + w_B(theta_b + alpha) + w_J(theta_j + alpha) - e cos alpha, the linearised
    gap; an empty wear array counts as an unworn surface.
    """
    gap = (
        c
        + _wear_depth(theta_b + alpha, wear_b)
        + _wear_depth(theta_j + alpha, wear_j)
        - e * math.cos(alpha)
    )
    return max(0.0, -gap)


@njit(cache=True, no_cfunc_wrapper=True)
def foundation_load(
    e: float,
    c: float,
    theta_b: float,
    wear_b: NDArray[np.float64],
    theta_j: float,
    wear_j: NDArray[np.float64],
    radius: float,
    width: float,
    k_over_h: float,
    points: int,
) -> tuple[float, float, float]:
    """Normal force f_n [N], pressure sum ``total`` [N] and peak interference [m].

    p = k_over_h u [Pa] (Winkler), integrated over the arc |alpha| < alpha0 by the
    midpoint rule with ``points`` cells: f_n = int p cos(alpha) R L dalpha along n,
    total = int p R L dalpha. The peak is the largest u at the points. radius [m] is
    that of the contact (R_J or R_B, equal to within c), width [m] the joint width L;
    e, c [m], theta_b, theta_j [rad] and the sector depths wear_b, wear_j [m] (empty:
    unworn) as in ``interference``. (0, 0, 0) when e <= c.
    """
    alpha0 = contact_half_angle(e, c)
    if alpha0 == 0.0:
        return 0.0, 0.0, 0.0
    step = 2.0 * alpha0 / points
    along_n = 0.0
    total = 0.0
    peak = 0.0
    for k in range(points):
        alpha = (k + 0.5 - 0.5 * points) * step  # exactly antisymmetric about 0
        u = interference(alpha, e, c, theta_b, wear_b, theta_j, wear_j)
        if u > 0.0:
            along_n += u * math.cos(alpha)
            total += u
            peak = max(peak, u)
    scale = k_over_h * radius * width * step
    return scale * along_n, scale * total, peak


@njit(cache=True, no_cfunc_wrapper=True)
def spread_foundation_wear(
    depths: NDArray[np.float64],
    theta: float,
    radius: float,
    width: float,
    volume: float,
    e: float,
    c: float,
    theta_b: float,
    wear_b: NDArray[np.float64],
    theta_j: float,
    wear_j: NDArray[np.float64],
    points: int,
) -> float:
    """Add a worn volume [m^3] to one surface's sector depths [m] in place; return it.

    The volume is spread in proportion to the foundation pressure at the ``points``
    integration points of ``foundation_load`` (same e, c, theta_b, wear_b, theta_j,
    wear_j): point alpha adds to the sector of ``depths`` containing theta + alpha, where
    theta [rad] is the direction of n in this surface's frame (theta_b or theta_j). The
    depths are scaled so that sum(dh_i) * radius * 2 pi / N * width = volume to rounding,
    radius [m] being this surface's. The caller sets the volume, e.g.
    share * coef * f_n * ds; a pointwise Archard law would give share * coef * total * ds.
    The pressure is evaluated once, before any depth changes, so ``depths`` may be wear_b
    or wear_j itself. Nothing is added, and 0 returned, without contact or volume.
    """
    alpha0 = contact_half_angle(e, c)
    if alpha0 == 0.0 or volume <= 0.0:
        return 0.0
    step = 2.0 * alpha0 / points
    u = np.empty(points)
    u_sum = 0.0
    for k in range(points):
        u[k] = interference((k + 0.5 - 0.5 * points) * step, e, c, theta_b, wear_b, theta_j, wear_j)
        u_sum += u[k]
    if u_sum <= 0.0:
        return 0.0
    n = depths.shape[0]
    scale = volume / (radius * (_TWO_PI / n) * width * u_sum)
    for k in range(points):
        if u[k] > 0.0:
            depths[sector_of(theta + (k + 0.5 - 0.5 * points) * step, n)] += scale * u[k]
    return volume
