"""Normal contact force of a clearance joint: elastic laws, hysteresis damping, stiffness.

| symbol | meaning | unit | paper |
|---|---|---|---|
| delta | penetration, e - c_local | m | Flores 2009, Eq. 15 |
| delta_dot | penetration rate (> 0 while approaching) | m/s | Eq. 18 |
| delta_dot_minus | penetration rate at contact onset (> 0) | m/s | Eq. 18 |
| k, n | stiffness K and exponent of a power law K delta^n | N/m^n, - | Eq. 18 |
| c_e | coefficient of restitution, 0 < c_e <= 1 | - | Table 2 |
| chi | hysteresis factor of a damping law, chi(c_e) | - | |
| e_star | contact modulus E*, 1/E* = (1 - nu_B^2)/E_B + (1 - nu_J^2)/E_J | Pa | |
| d_r | radial clearance Delta R = R_B - R_J | m | |
| width | joint width L | m | |
| f | force per unit width F / L | N/m | |
| f_e, f_n | elastic force; normal force, never negative (a contact never pulls) | N | Eq. 17 |

The force is an elastic law times a damping factor, chosen separately:
F = f_e(delta) (1 + chi delta_dot / delta_dot_minus), clamped at zero. ``delta_dot_minus``
must be positive; the caller floors it (SPEC sec. 3). A non-positive value means no recorded
approach speed, and the force is then the elastic one.

The damping laws were derived for Hertz's K delta^n, but to first order in (1 - c_e) the energy
they dissipate in an impact does not depend on the elastic law: with x = delta_dot /
delta_dot_minus ~ sqrt(1 - U(delta) / U_max), U the elastic energy, the loop integral of
chi f_e x d(delta) is (4/3) chi U_max for any f_e. So each damping law keeps its restitution
with every elastic law below (tests/test_conformal_laws.py measures it).

References
----------
H.M. Lankarani, P.E. Nikravesh, "A contact force model with hysteresis damping for impact
analysis of multibody systems", J. Mech. Des. 112 (1990) 369-376.
K.H. Hunt, F.R.E. Crossley, "Coefficient of restitution interpreted as damping in
vibroimpact", J. Appl. Mech. 42 (1975) 440-445.
P. Flores, M. Machado, M.T. Silva, J.M. Martins, "On the continuous contact force models
for soft materials in multibody dynamics", Multibody Syst. Dyn. 25 (2011) 357-375.
K.L. Johnson, Contact Mechanics, Cambridge University Press (1985), secs. 4.2 and 5.3.
C.S. Liu, K. Zhang, R. Yang, "The FEM analysis and approximate model for cylindrical joints
with clearances", Mech. Mach. Theory 42 (2007) 183-197.
C.M. Pereira, A.L. Ramalho, J.A. Ambrosio, "A critical overview of internal and external
cylinder contact force models", Nonlinear Dyn. 63 (2011) 681-697.
M. Mukras, N.H. Kim, N.A. Mauntler, T.L. Schmitz, W.G. Sawyer, "Comparison between elastic
foundation and contact force models in wear analysis of planar multibody system", J. Tribol.
132 (2010) 031604.

Pereira et al.'s own internal-contact law, F = (a dR + b) L E* delta^n / dR with a = 0.965,
b = 0.0965 and n fitted in dR, is not offered: the paper's text of the fit (the expression
of n, its ranges, and the unit dR enters in) could not be read to confirm it; the only
version found was a third-party implementation, whose two branches use different units.
"""

import math
from enum import IntEnum

import numpy as np
from numba import njit

from .dispatch import Dispatch

# Gauss-Legendre nodes and weights on [0, 1], for the elastic energy of Liu's law.
GAUSS_NODES, GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(12)
GAUSS_NODES = 0.5 * (GAUSS_NODES + 1.0)
GAUSS_WEIGHTS = 0.5 * GAUSS_WEIGHTS


class ElasticLaw(IntEnum):
    """Codes of the elastic laws (``model.laws.normal.NORMAL``, whose records name them)."""

    HERTZ = 0
    JOHNSON = 1
    LIU = 2
    ELASTIC_FOUNDATION = 3


class Damping(IntEnum):
    """Codes of the damping laws (``model.laws.normal.DAMPING``)."""

    NONE = 0
    LANKARANI_NIKRAVESH = 1
    HUNT_CROSSLEY = 2
    FLORES2011 = 3


# ----------------------------------------------------------------------- elastic laws


@njit(cache=True, no_cfunc_wrapper=True)
def hertz(delta: float, k: float, n: float) -> float:
    """Power-law force K delta^n [N] (zero without penetration).

    References
    ----------
    Flores (2009), Eq. 18 with D = 0.
    """
    if delta <= 0.0:
        return 0.0
    return k * delta**n


@njit(cache=True, no_cfunc_wrapper=True)
def johnson_switch(e_star: float, d_r: float) -> tuple[float, float]:
    """(f_s [N/m], delta_s [m]) where Johnson's law hands over to its tangent line.

    f_s = 4 pi E* dR e^-3, delta_s = 8 dR e^-3 (about 0.40 dR): there the law's stiffness
    is pi E* L. See ``johnson``.
    """
    f_s = 4.0 * math.pi * e_star * d_r * math.exp(-3.0)
    return f_s, 8.0 * d_r * math.exp(-3.0)


@njit(cache=True, no_cfunc_wrapper=True)
def johnson_penetration(f: float, e_star: float, d_r: float) -> float:
    """Penetration [m] of Johnson's law under force per width f [N/m], for 0 < f <= f_s."""
    return f / (math.pi * e_star) * (math.log(4.0 * math.pi * e_star * d_r / f) - 1.0)


@njit(cache=True, no_cfunc_wrapper=True)
def johnson_load(delta: float, e_star: float, d_r: float) -> float:
    """Force per unit width f [N/m] of Johnson's conformal law at penetration delta [m].

    Solves delta = f / (pi E*) [ln(4 pi E* dR / f) - 1] for f by Newton's method in
    x = ln f, safeguarded by bisection. With a = ln(4 pi E* dR), G(x) = e^x (a - x - 1)
    - pi E* delta rises and is convex for x <= a - 3 (f <= f_s), so Newton's iterates from
    a start above the root fall monotonically onto it; the start is the root of the
    equation with f replaced by pi E* delta inside the logarithm, which lies above it.
    Beyond delta_s (``johnson_switch``) the load follows the tangent line there.
    """
    if delta <= 0.0:
        return 0.0
    f_s, delta_s = johnson_switch(e_star, d_r)
    if delta >= delta_s:
        return f_s + math.pi * e_star * (delta - delta_s)
    a = math.log(4.0 * math.pi * e_star * d_r)
    target = math.pi * e_star * delta
    hi = a - 3.0  # G(hi) >= 0 here, since delta < delta_s
    lo = -np.inf
    x = min(hi, math.log(target / max(math.log(4.0 * d_r / delta) - 1.0, 2.0)))
    for _ in range(100):
        g = math.exp(x) * (a - x - 1.0) - target
        if g > 0.0:
            hi = x
        else:
            lo = x
        step = g / (math.exp(x) * (a - x - 2.0))
        x_new = x - step
        if not lo < x_new < hi:  # Newton left the bracket: bisect (lo may be -inf)
            x_new = 0.5 * (lo + hi) if lo > -np.inf else hi - 2.0 * (hi - x + 1.0)
        if abs(x_new - x) <= 1e-15 * max(1.0, abs(x)):
            return math.exp(x_new)
        x = x_new
    return math.exp(x)


@njit(cache=True, no_cfunc_wrapper=True)
def johnson(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Johnson's force [N] of a cylinder in a conforming cylindrical seat.

    delta = f / (pi E*) [ln(4 pi E* dR / f) - 1], f = F / L, dR = R_B - R_J (Johnson 1985,
    sec. 5.3, as used by Pereira et al. 2011). Checked: the same form, per unit width, in
    an independent open implementation (ladisk/DyS, contact_model_cylinder.py); the
    papers' own text was not readable, so E* is taken as defined above.

    delta(f) rises only up to f_max = 4 pi E* dR e^-2, delta_max = 4 dR e^-2 (about
    0.54 dR), where its stiffness becomes infinite; past it the law has no solution. So
    from delta_s = 8 dR e^-3 (about 0.40 dR, where f = f_max / e and the stiffness is
    pi E* L) the force continues along its tangent, F = L f_s + pi E* L (delta - delta_s):
    continuous with its slope, and reported as outside the law's range.
    """
    return width * johnson_load(delta, e_star, d_r)


@njit(cache=True, no_cfunc_wrapper=True)
def liu(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Liu et al.'s force [N] of a cylinder in a conforming cylindrical seat.

    F = (pi / 2) E* L delta sqrt(delta / (2 (dR + delta))) (Liu, Zhang and Yang 2007, from
    finite-element fits). Checked: the same form in an independent open implementation
    (ladisk/DyS); the paper's own definition of E* could not be read, and is taken as
    above (for equal materials E / (2 (1 - nu^2)), the usual one). Small delta: Hertz-like,
    F ~ delta^1.5; large delta: linear.
    """
    if delta <= 0.0:
        return 0.0
    return 0.5 * math.pi * e_star * width * delta * math.sqrt(delta / (2.0 * (d_r + delta)))


@njit(cache=True, no_cfunc_wrapper=True)
def foundation_on_circles(delta: float, k: float, d_r: float, width: float) -> float:
    """Elastic-foundation force [N] of an unworn journal in an unworn bearing.

    A Winkler layer, p = (K_f / h) u, u the radial interference. In the small-clearance
    geometry the gap at angle a from the line of centres is dR - e cos a (e = dR + delta), so
    F = (K_f / h) R L int_{-a0}^{a0} (e cos a - dR) cos a da = k L e (a0 - sin a0 cos a0),
    cos a0 = dR / e, k = (K_f / h) R [Pa]. Small delta: F ~ (4 sqrt(2) / 3) k L
    delta^1.5 / sqrt(dR). References: Johnson (1985), sec. 5.3 (elastic foundation);
    Mukras et al., J. Tribol. 132 (2010) 031604.
    """
    if delta <= 0.0:
        return 0.0
    e = d_r + delta
    x = 2.0 * math.acos(d_r / e)  # a0 - sin a0 cos a0 = (x - sin x) / 2
    if x < 0.1:  # the series, free of the cancellation (next term x^11 / 4e7: 1e-18 x^3)
        x2 = x * x
        shape = x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0)))
    else:
        shape = x - math.sin(x)
    return k * width * e * 0.5 * shape


@njit(cache=True, no_cfunc_wrapper=True)
def hertz_stiffness(delta: float, k: float, n: float) -> float:
    """Stiffness dF/d(delta) = K n delta^(n - 1) [N/m] of the power law (0 without contact)."""
    if delta <= 0.0:
        return 0.0
    return k * n * delta ** (n - 1.0)


@njit(cache=True, no_cfunc_wrapper=True)
def hertz_energy(delta: float, k: float, n: float) -> float:
    """Elastic energy K delta^(n + 1) / (n + 1) [J] of the power law (0 without contact)."""
    if delta <= 0.0:
        return 0.0
    return k * delta ** (n + 1.0) / (n + 1.0)


@njit(cache=True, no_cfunc_wrapper=True)
def johnson_stiffness(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Stiffness [N/m] of Johnson's law: pi E* L / (ln(4 pi E* dR / f) - 2), pi E* L beyond f_s."""
    if delta <= 0.0:
        return 0.0
    f = johnson_load(delta, e_star, d_r)
    f_s, _ = johnson_switch(e_star, d_r)
    if f >= f_s:
        return math.pi * e_star * width
    return math.pi * e_star * width / (math.log(4.0 * math.pi * e_star * d_r / f) - 2.0)


@njit(cache=True, no_cfunc_wrapper=True)
def johnson_energy(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Elastic energy [J] of Johnson's law, U(f) = L f^2 / (2 pi E*) [ln(4 pi E* dR / f) - 3/2].

    Beyond delta_s the tangent line's energy is added.
    """
    if delta <= 0.0:
        return 0.0
    f_s, delta_s = johnson_switch(e_star, d_r)
    f = min(johnson_load(delta, e_star, d_r), f_s)
    u = (
        width
        * f
        * f
        / (2.0 * math.pi * e_star)
        * (math.log(4.0 * math.pi * e_star * d_r / f) - 1.5)
    )
    over = max(0.0, delta - delta_s)
    return u + width * (f_s * over + 0.5 * math.pi * e_star * over * over)


@njit(cache=True, no_cfunc_wrapper=True)
def liu_stiffness(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Stiffness [N/m] of Liu et al.'s law, the derivative of ``liu``."""
    if delta <= 0.0:
        return 0.0
    c = 0.5 * math.pi * e_star * width / math.sqrt(2.0)
    return c * math.sqrt(delta) * (1.5 * d_r + delta) / (d_r + delta) ** 1.5


@njit(cache=True, no_cfunc_wrapper=True)
def liu_energy(delta: float, e_star: float, d_r: float, width: float) -> float:
    """Elastic energy [J] of Liu et al.'s law, by quadrature of its force (``quadrature_node``)."""
    energy = 0.0
    for i in range(GAUSS_NODES.shape[0]):
        s, weight = quadrature_node(delta, i)
        energy += weight * liu(s, e_star, d_r, width)
    return energy


@njit(cache=True, no_cfunc_wrapper=True)
def foundation_stiffness(delta: float, k: float, d_r: float, width: float) -> float:
    """Stiffness [N/m] of the foundation on unworn circles, k L (a0 + sin a0 cos a0)."""
    if delta <= 0.0:
        return 0.0
    e = d_r + delta
    a = math.acos(d_r / e)
    return k * width * (a + math.sin(a) * math.cos(a))


@njit(cache=True, no_cfunc_wrapper=True)
def foundation_energy(delta: float, k: float, d_r: float, width: float) -> float:
    """Elastic energy [J] of the foundation on unworn circles, by quadrature of its force."""
    energy = 0.0
    for i in range(GAUSS_NODES.shape[0]):
        s, weight = quadrature_node(delta, i)
        energy += weight * foundation_on_circles(s, k, d_r, width)
    return energy


@njit(cache=True, no_cfunc_wrapper=True)
def quadrature_node(delta: float, i: int) -> tuple[float, float]:
    """Node i of the integral of a force from 0 to delta [m]: (s [m], weight [m]).

    The sum of weight F(s) over the 12 nodes is the integral, by Gauss-Legendre in t with
    s = delta t^2, where the integrand 2 delta t F(delta t^2) is smooth; 0 for delta <= 0.
    """
    t = GAUSS_NODES[i]
    weight = GAUSS_WEIGHTS[i] * 2.0 * delta * t if delta > 0.0 else 0.0
    return delta * t * t, weight


# The dispatchers: per code, the law's function and the arguments it takes (``dispatch``).
_ARGUMENTS = "delta k n e_star d_r width"
_HERTZ, _CONFORMAL, _FOUNDATION = "delta k n", "delta e_star d_r width", "delta k d_r width"

elastic_force = Dispatch(
    "normal_law",
    {
        ElasticLaw.HERTZ: (hertz, _HERTZ),
        ElasticLaw.JOHNSON: (johnson, _CONFORMAL),
        ElasticLaw.LIU: (liu, _CONFORMAL),
        ElasticLaw.ELASTIC_FOUNDATION: (foundation_on_circles, _FOUNDATION),
    },
    _ARGUMENTS, np.nan,
)  # fmt: skip
"""Elastic force [N]. HERTZ is the power law K delta^n; ELASTIC_FOUNDATION its closed form on
unworn circles with k = (K_f / h) R [Pa] (the joint integrates the worn surfaces itself)."""

elastic_stiffness = Dispatch(
    "normal_law",
    {
        ElasticLaw.HERTZ: (hertz_stiffness, _HERTZ),
        ElasticLaw.JOHNSON: (johnson_stiffness, _CONFORMAL),
        ElasticLaw.LIU: (liu_stiffness, _CONFORMAL),
        ElasticLaw.ELASTIC_FOUNDATION: (foundation_stiffness, _FOUNDATION),
    },
    _ARGUMENTS, np.nan,
)  # fmt: skip
"""Contact stiffness dF/d(delta) [N/m] at delta [m]."""

elastic_energy = Dispatch(
    "normal_law",
    {
        ElasticLaw.HERTZ: (hertz_energy, _HERTZ),
        ElasticLaw.JOHNSON: (johnson_energy, _CONFORMAL),
        ElasticLaw.LIU: (liu_energy, _CONFORMAL),
        ElasticLaw.ELASTIC_FOUNDATION: (foundation_energy, _FOUNDATION),
    },
    _ARGUMENTS, np.nan,
)  # fmt: skip
"""Elastic energy [J] stored at penetration delta [m], the integral of the force."""


# ----------------------------------------------------------------------- damping laws


@njit(cache=True, no_cfunc_wrapper=True)
def undamped(c_e: float) -> float:
    """Hysteresis factor chi = 0 of an elastic contact (no damping) [-]."""
    return 0.0


@njit(cache=True, no_cfunc_wrapper=True)
def lankarani_nikravesh(c_e: float) -> float:
    """Hysteresis factor chi = 3 (1 - c_e^2) / 4 of Lankarani and Nikravesh (1990) [-].

    F = f_e [1 + 3 (1 - c_e^2) / 4 * delta_dot / delta_dot_minus] (Flores 2009, Eq. 18).
    Derived for c_e close to 1: the restitution it produces exceeds c_e by about
    1.5 (1 - c_e)^2.
    """
    return 0.75 * (1.0 - c_e * c_e)


@njit(cache=True, no_cfunc_wrapper=True)
def hunt_crossley(c_e: float) -> float:
    """Hysteresis factor chi = 3 (1 - c_e) / 2 of Hunt and Crossley (1975) [-].

    Their relation c_e = 1 - 2/3 lambda delta_dot_minus solved for the damping per unit
    elastic force lambda [s/m], the form common in multibody codes; the restitution it
    produces exceeds c_e by about (1 - c_e)^2.
    """
    return 1.5 * (1.0 - c_e)


@njit(cache=True, no_cfunc_wrapper=True)
def flores2011(c_e: float) -> float:
    """Hysteresis factor chi = 8 (1 - c_e) / (5 c_e) of Flores et al. (2011) [-].

    Meant for any c_e in (0, 1]; near c_e = 1 the restitution it produces falls short of c_e
    by about (1 - c_e) / 15.
    """
    return 1.6 * (1.0 - c_e) / c_e


hysteresis_factor = Dispatch(
    "damping",
    {
        Damping.NONE: (undamped, "c_e"),
        Damping.LANKARANI_NIKRAVESH: (lankarani_nikravesh, "c_e"),
        Damping.HUNT_CROSSLEY: (hunt_crossley, "c_e"),
        Damping.FLORES2011: (flores2011, "c_e"),
    },
    "c_e", np.nan,
)  # fmt: skip
"""Hysteresis factor chi [-] of the damping law."""


@njit(cache=True, no_cfunc_wrapper=True)
def damped_by(elastic: float, delta_dot: float, delta_dot_minus: float, chi: float) -> float:
    """Normal force [N]: elastic (1 + chi delta_dot / delta_dot_minus), clamped at zero.

    A NaN (a law's error value) passes through the clamp.
    """
    if elastic <= 0.0 or delta_dot_minus <= 0.0:
        return 0.0 if elastic <= 0.0 else elastic
    force = elastic * (1.0 + chi * delta_dot / delta_dot_minus)
    return 0.0 if force <= 0.0 else force
