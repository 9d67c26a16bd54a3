"""Normal contact force laws of a clearance joint, and the stiffness of its contact.

| symbol | meaning | unit | paper |
|---|---|---|---|
| delta | penetration, e - c_local | m | Eq. 15 |
| delta_dot | penetration rate (> 0 while approaching) | m/s | Eq. 18 |
| delta_dot_minus | penetration rate at contact onset (> 0) | m/s | Eq. 18 |
| k | generalised contact stiffness K | N/m^n | Eq. 18 |
| n | exponent of the penetration (1.5 for metals) | - | Eq. 18 |
| c_e | coefficient of restitution, 0 < c_e <= 1 | - | Table 2 |
| f_n | normal force, never negative (a contact never pulls) | N | Eq. 17 |
| e_b, nu_b; e_j, nu_j | Young's modulus, Poisson's ratio of bearing, journal | Pa, - | Table 2 |
| r_b, r_j | bearing and journal radii, r_b > r_j | m | Fig. 2 |

The damped laws share one form, F = K delta^n (1 + chi delta_dot / delta_dot_minus),
clamped at zero: they differ only in the hysteresis factor chi(c_e). ``delta_dot_minus``
must be positive; the caller floors it (SPEC sec. 3). A non-positive value means no
recorded approach speed, and these laws then fall back to the undamped Hertz force.

References
----------
H.M. Lankarani, P.E. Nikravesh, "A contact force model with hysteresis damping for impact
analysis of multibody systems", J. Mech. Des. 112 (1990) 369-376.
K.H. Hunt, F.R.E. Crossley, "Coefficient of restitution interpreted as damping in
vibroimpact", J. Appl. Mech. 42 (1975) 440-445.
P. Flores, M. Machado, M.T. Silva, J.M. Martins, "On the continuous contact force models
for soft materials in multibody dynamics", Multibody Syst. Dyn. 25 (2011) 357-375.
K.L. Johnson, Contact Mechanics, Cambridge University Press (1985), ch. 4.
"""

import math
from enum import IntEnum

from numba import njit

from .registry import Key, Law, pack_in_order


@njit(cache=True)
def hertz(delta: float, k: float, n: float) -> float:
    """Undamped Hertz force K delta^n [N] (zero without penetration).

    References
    ----------
    Flores (2009), Eq. 18 with D = 0.
    """
    if delta <= 0.0:
        return 0.0
    return k * delta**n


@njit(cache=True)
def _damped(delta, delta_dot, delta_dot_minus, k, n, chi):
    """K delta^n (1 + chi delta_dot / delta_dot_minus), clamped at zero [N]."""
    elastic = hertz(delta, k, n)
    if elastic == 0.0 or delta_dot_minus <= 0.0:
        return elastic
    return max(0.0, elastic * (1.0 + chi * delta_dot / delta_dot_minus))


@njit(cache=True)
def lankarani_nikravesh(
    delta: float, delta_dot: float, delta_dot_minus: float, k: float, n: float, c_e: float
) -> float:
    """Hertz force with Lankarani-Nikravesh hysteresis damping [N].

    F = K delta^n [1 + 3 (1 - c_e^2) / 4 * delta_dot / delta_dot_minus], F >= 0. Derived
    for c_e close to 1: the restitution it produces exceeds c_e by about 1.5 (1 - c_e)^2.

    References
    ----------
    Lankarani and Nikravesh (1990); Flores (2009), Eq. 18.
    """
    return _damped(delta, delta_dot, delta_dot_minus, k, n, 0.75 * (1.0 - c_e * c_e))


@njit(cache=True)
def hunt_crossley(
    delta: float, delta_dot: float, delta_dot_minus: float, k: float, n: float, c_e: float
) -> float:
    """Hertz force with Hunt-Crossley damping, chi = 3 (1 - c_e) / 2 [N].

    F = K delta^n [1 + 3 (1 - c_e) / 2 * delta_dot / delta_dot_minus], F >= 0. This is
    Hunt and Crossley's relation c_e = 1 - 2/3 lambda delta_dot_minus solved for their
    damping per unit elastic force lambda [s/m], the form common in multibody codes; the
    restitution it produces exceeds c_e by about (1 - c_e)^2.

    References
    ----------
    Hunt and Crossley (1975).
    """
    return _damped(delta, delta_dot, delta_dot_minus, k, n, 1.5 * (1.0 - c_e))


@njit(cache=True)
def flores2011(
    delta: float, delta_dot: float, delta_dot_minus: float, k: float, n: float, c_e: float
) -> float:
    """Hertz force with the damping of Flores et al. (2011), chi = 8 (1 - c_e) / (5 c_e) [N].

    F = K delta^n [1 + 8 (1 - c_e) / (5 c_e) * delta_dot / delta_dot_minus], F >= 0. Meant
    for any c_e in (0, 1]; near c_e = 1 the restitution it produces falls short of c_e
    by about (1 - c_e) / 15.

    References
    ----------
    Flores, Machado, Silva and Martins (2011).
    """
    return _damped(delta, delta_dot, delta_dot_minus, k, n, 1.6 * (1.0 - c_e) / c_e)


RESTITUTION = Key(
    "restitution_coefficient", "", None, positive=True, high=1.0,
    help="coefficient of restitution c_e, 0 < c_e <= 1",
)  # fmt: skip
NORMAL_LAWS = (
    Law(
        "hertz", 0, (), lambda values: (1.0,),
        "K delta^n, no damping (Flores 2009, Eq. 18, D = 0)",
    ),
    Law(
        "lankarani_nikravesh", 1, (RESTITUTION,), pack_in_order(RESTITUTION),
        "K delta^n [1 + 3 (1 - c_e^2)/4 delta_dot/delta_dot_minus] (Lankarani, Nikravesh 1990)",
    ),
    Law(
        "hunt_crossley", 2, (RESTITUTION,), pack_in_order(RESTITUTION),
        "K delta^n [1 + 3 (1 - c_e)/2 delta_dot/delta_dot_minus] (Hunt, Crossley 1975)",
    ),
    Law(
        "flores2011", 3, (RESTITUTION,), pack_in_order(RESTITUTION),
        "K delta^n [1 + 8 (1 - c_e)/(5 c_e) delta_dot/delta_dot_minus] (Flores et al. 2011)",
    ),
)  # fmt: skip
NormalLaw = IntEnum("NormalLaw", {law.name.upper(): law.code for law in NORMAL_LAWS})


@njit(cache=True)
def normal_force(
    law: int,
    delta: float,
    delta_dot: float,
    delta_dot_minus: float,
    k: float,
    n: float,
    c_e: float,
) -> float:
    """Normal force [N] by the law with code ``law`` (``NORMAL_LAWS``); c_e packed by it."""
    if law == NormalLaw.LANKARANI_NIKRAVESH:
        return lankarani_nikravesh(delta, delta_dot, delta_dot_minus, k, n, c_e)
    if law == NormalLaw.HUNT_CROSSLEY:
        return hunt_crossley(delta, delta_dot, delta_dot_minus, k, n, c_e)
    if law == NormalLaw.FLORES2011:
        return flores2011(delta, delta_dot, delta_dot_minus, k, n, c_e)
    return hertz(delta, k, n)


@njit(cache=True)
def effective_modulus(e_b: float, nu_b: float, e_j: float, nu_j: float) -> float:
    """Contact modulus E* [Pa], 1/E* = (1 - nu_b^2)/E_b + (1 - nu_j^2)/E_j (Johnson 1985)."""
    return 1.0 / ((1.0 - nu_b * nu_b) / e_b + (1.0 - nu_j * nu_j) / e_j)


@njit(cache=True)
def effective_radius(r_b: float, r_j: float) -> float:
    """Relative radius R* = R_B R_J / (R_B - R_J) [m] of a cylinder inside a cylinder."""
    return r_b * r_j / (r_b - r_j)


@njit(cache=True)
def internal_cylinder_stiffness(
    r_b: float, r_j: float, e_b: float, nu_b: float, e_j: float, nu_j: float
) -> float:
    """Stiffness K [N/m^1.5] of a journal in a bearing, for use with n = 1.5.

    K = 4 / (3 (h_B + h_J)) sqrt(R_B R_J / (R_B - R_J)), h = (1 - nu^2) / E, which is
    4/3 E* sqrt(R*) (SPEC sec. 3).

    References
    ----------
    Lankarani and Nikravesh (1990), with the relative radius of internal contact as in
    P. Flores, J. Ambrosio, J.C.P. Claro, H.M. Lankarani, Kinematics and Dynamics of
    Multibody Systems with Imperfect Joints, Springer (2008); SPEC sec. 3.
    """
    e_star = effective_modulus(e_b, nu_b, e_j, nu_j)
    return 4.0 / 3.0 * e_star * math.sqrt(effective_radius(r_b, r_j))
