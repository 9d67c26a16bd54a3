"""Hydrodynamic forces and viscous power loss of a lubricated revolute joint (journal bearing).

| symbol | meaning | unit | paper |
|---|---|---|---|
| c | radial clearance R_B - R_J | m | Flores et al. |
| r, width | journal radius R_J and joint width L | m | Flores et al. |
| mu | dynamic viscosity of the lubricant | Pa s | Flores et al. |
| eps, eps_dot | eccentricity ratio e / c, 0 <= eps < 1, and its rate | -, 1/s | Flores et al. |
| gamma, gamma_dot | direction bearing -> journal centre, its rate | rad, rad/s | Flores et al. |
| w | omega_journal + omega_bearing (absolute angular speeds) | rad/s | Flores et al. |
| w_rel | omega_journal - omega_bearing | rad/s | |
| theta | film angle from the thickest film, counted like gamma | rad | Flores et al. |
| h | film thickness c (1 + eps cos theta) | m | Flores et al. |
| f_r, f_t | film force on the journal along e_r and e_t | N | Flores et al. |
| f_x, f_y | the same force in global coordinates | N | |

Frame and signs. Angles and angular speeds are counter-clockwise positive. e_r = (cos gamma,
sin gamma) points from the bearing centre to the journal centre, e_t = (-sin gamma, cos gamma)
is e_r turned by +90 deg. The film is thinnest at theta = pi, i.e. in the direction e_r. In the
frame turning with the line of centres the surfaces slide at R (omega - gamma_dot), so the
wedge is driven by w - 2 gamma_dot, and the squeeze by dh/dt = c eps_dot cos theta (Reynolds
equation, Flores et al. 2009). The pressure p acts on the journal towards its centre, so
f_r = R int p cos theta and f_t = R int p sin theta over the film area (theta, z).

The pi-film. Both models keep the full Reynolds pressure on the half of the film where the
wedge builds pressure, 0 < theta < pi for w - 2 gamma_dot >= 0 (the converging half in the
direction of the mean surface motion), and set it to zero on the other half, as Flores et al.
(2009) do after Pinkus and Sternlicht. For w - 2 gamma_dot < 0 the wedge's half is the mirror
image, pi < theta < 2 pi; the published formulas, read literally there, would integrate the
diverging half and pull the journal towards the wall. The mirror replaces w - 2 gamma_dot by
its absolute value in f_r and flips the sign of the squeeze term of f_t. That flip, taken as
a sign, would make f_t jump wherever w - 2 gamma_dot crosses 0 while eps_dot != 0, and an
orbiting journal that reaches gamma_dot = w / 2 sits on the jump (the integrator stalls).

So the squeeze term of f_t carries a smooth sign instead (our regularisation): s = cos beta,
beta = atan2(2 eps_dot, eps v), v = w - 2 gamma_dot. In the short bearing the pressure has the
sign of eps v sin theta - 2 eps_dot cos theta, i.e. it is positive on beta < theta < beta + pi:
beta measures how far the squeeze turns the loaded half away from the wedge's pi-film. Pure
wedge (eps_dot = 0) gives s = +-1, the pi-film exactly, and the steady closed forms hold
unchanged; where the wedge dominates s differs from +-1 only to second order in
2 eps_dot / (eps v). Pure squeeze (v = 0) gives s = 0 and f_t = 0, as the symmetry of a
journal moving straight at the wall demands, where the literal (0, pi) film would give the
4 eps eps_dot term and push it sideways. f_t is then continuous wherever eps_dot or v is
nonzero, and f_r (with |v|) everywhere. The long bearing uses the same s. A film cavitated
wherever p < 0 (Gumbel applied pointwise) is not what these formulas describe: it also
changes f_r.

Checked signs (tests/test_lubrication.py): eps_dot > 0 gives f_r < 0 (the approaching
journal is pushed back); with w > 0, gamma_dot = eps_dot = 0 the short-bearing force makes
the angle phi, tan phi = pi sqrt(1 - eps^2) / (4 eps), with -e_r on the side of +e_t, so a
load W carried by the film lies at gamma - phi: the line of centres leads the load in the
sense of rotation, as in the classic journal-bearing picture. The short-bearing formulas are
those of Flores et al. (2009); we re-derived them by integrating the short-bearing pressure
over 0 < theta < pi, and the tests do the same by quadrature.

Long bearing. We could not retrieve the published long-bearing equations with the search tools
at hand, so we derived them: d/dtheta (h^3 dp/dtheta) = 6 mu R^2 [(w - 2 gamma_dot) dh/dtheta
+ 2 c eps_dot cos theta] with p(0) = p(pi) = 0 (the long-bearing pi-film; for the wedge alone it
is the half-Sommerfeld film). Integrating f_r, f_t by parts and with the Sommerfeld integrals
over 0..pi, for B = 6 mu L R^3 / c^2:

    f_r = -B [2 eps^2 (w - 2 gamma_dot) / ((2 + eps^2)(1 - eps^2))
              + 2 eps_dot (pi/2 - 8 / (pi (2 + eps^2))) / (1 - eps^2)^(3/2)]
    f_t =  B [pi eps (w - 2 gamma_dot) / ((2 + eps^2) sqrt(1 - eps^2))
              + 4 eps eps_dot / ((2 + eps^2)(1 - eps^2))]

These have the structure we recall from Flores et al. (2009), (2 + eps^2) denominators and the
squeeze factor pi/2 - 8 / (pi (2 + eps^2)); the wedge terms are the classic half-Sommerfeld
load (tan phi = pi sqrt(1 - eps^2) / (2 eps)). The tests solve the boundary-value problem
numerically (scipy) and integrate its pressure; they agree to 1e-9.

Power loss. The viscous dissipation of the film is int [mu U^2 / h + h^3 / (12 mu) |grad p|^2]
dA, U = R w_rel. The Couette part over the whole circumference is 2 pi mu U^2 R L / (c sqrt(1 -
eps^2)) (Petroff's 2 pi mu U^2 R L / c at eps = 0). Multiplying the Reynolds equation by p and
integrating by parts (p = 0 at z = +-L/2 for the short bearing, at the ends of the pi-film for
the long one) turns the pressure part into c [eps (w - 2 gamma_dot) f_t / 2 - eps_dot f_r],
exact for either model's pi-film (s = +-1); no quadrature is needed (the tests check it
against scipy quadrature of the defining integral). Pure squeeze gives -f_r c eps_dot, the
power the journal does on the film. With |s| < 1 we keep the same expression; it stays a
positive semi-definite quadratic form in (|v|, eps_dot) for every |s| <= 1 (the cross term is
largest at s = +-1, where it is the integral of a square).

Torques. The shear stress on each surface, mu (U_J - U_B) / h plus or minus (h / 2) dp/dx,
gives the journal T_J = -T_c - e f_t / 2 and the bearing T_B = T_c - e f_t / 2, with the
Couette torque T_c = 2 pi mu R^3 L w_rel / (c sqrt(1 - eps^2)) (the classic journal and
bearing torques; Hamrock et al. 2004). With the film force at the two centres (a couple
e f_t) the film's moments sum to zero, and the power the bodies lose to the film,
-(f . de/dt + T_J omega_J + T_B omega_B), is exactly the Phi above, for every s. A film
evaluated at another eccentricity ratio than the journal's (the short and long bearings held
at film_breakdown, a mixed film at its mean gap) keeps this: T_c is the film's, at its own
eps, while e and the rates in the pressure part and the torques are the journal's own, so
the moments still balance and Phi is still what the bodies lose.

References
----------
P. Flores, J. Ambrosio, J.C.P. Claro, H.M. Lankarani, C.S. Koshy, "Lubricated revolute joints
in rigid multibody systems", Nonlinear Dyn. 56 (2009) 277-295 (cited as Flores et al. (2009);
not the wear paper, Flores (2009), of the other law modules).
O. Pinkus, B. Sternlicht, Theory of Hydrodynamic Lubrication, McGraw-Hill (1961).
B.J. Hamrock, S.R. Schmid, B.O. Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed.,
Marcel Dekker (2004) (Sommerfeld substitution, half-Sommerfeld long bearing, Petroff).
"""

import math
from enum import IntEnum

import numpy as np
from numba import njit

from .dispatch import Dispatch
from .impedance import finite_bearing_forces


class FilmModel(IntEnum):
    """Codes of the lubrication laws (``model.laws.lubrication.LUBRICATION``).

    NONE is a dry joint (no film: the element never asks for one); the films approximate the
    Reynolds equation for a short (L/D small) or a long (L/D large) bearing, or solve it for
    the joint's L/D (``impedance``).
    """

    NONE = 0
    SHORT_BEARING = 1
    LONG_BEARING = 2
    FINITE_BEARING = 3


@njit(cache=True, no_cfunc_wrapper=True)
def squeeze_side(eps: float, eps_dot: float, v: float) -> float:
    """Smooth sign s = cos beta in [-1, 1] of the squeeze term of f_t [-].

    beta = atan2(2 eps_dot, eps v): the positive short-bearing pressure lies on
    beta < theta < beta + pi; v = w - 2 gamma_dot [rad/s]. s = +-1 for the pi-film and its
    mirror (eps_dot = 0), 0 for pure squeeze (v = 0) (module docstring).
    """
    wedge = eps * v
    size = math.hypot(wedge, 2.0 * eps_dot)
    return wedge / size if size > 0.0 else 1.0


@njit(cache=True, no_cfunc_wrapper=True)
def short_bearing_forces(
    eps: float,
    eps_dot: float,
    gamma_dot: float,
    w: float,
    mu: float,
    r: float,
    width: float,
    c: float,
) -> tuple[float, float]:
    """Film force (f_r, f_t) [N] on the journal of a short bearing, pi-film.

    With A = mu R L^3 / (2 c^2) and v = w - 2 gamma_dot:
    f_r = -A [2 eps^2 |v| / (1 - eps^2)^2 + pi (1 + 2 eps^2) eps_dot / (1 - eps^2)^(5/2)],
    f_t = A [pi eps v / (2 (1 - eps^2)^(3/2)) + s 4 eps eps_dot / (1 - eps^2)^2],
    s = ``squeeze_side(eps, eps_dot, v)`` (module docstring); 0 <= eps < 1.

    References
    ----------
    Flores et al. (2009), after Pinkus and Sternlicht (1961).
    """
    a = mu * r * width**3 / (2.0 * c * c)
    v = w - 2.0 * gamma_dot
    side = squeeze_side(eps, eps_dot, v)
    q = 1.0 - eps * eps
    f_r = -a * (
        2.0 * eps * eps * abs(v) / (q * q) + math.pi * (1.0 + 2.0 * eps * eps) * eps_dot / q**2.5
    )
    f_t = a * (math.pi * eps * v / (2.0 * q**1.5) + side * 4.0 * eps * eps_dot / (q * q))
    return f_r, f_t


@njit(cache=True, no_cfunc_wrapper=True)
def long_bearing_forces(
    eps: float,
    eps_dot: float,
    gamma_dot: float,
    w: float,
    mu: float,
    r: float,
    width: float,
    c: float,
) -> tuple[float, float]:
    """Film force (f_r, f_t) [N] on the journal of a long bearing, pi-film (p = 0 at its ends).

    With B = 6 mu L R^3 / c^2 and v = w - 2 gamma_dot:
    f_r = -B [2 eps^2 |v| / ((2 + eps^2)(1 - eps^2))
              + 2 eps_dot (pi/2 - 8 / (pi (2 + eps^2))) / (1 - eps^2)^(3/2)],
    f_t = B [pi eps v / ((2 + eps^2) sqrt(1 - eps^2)) + s 4 eps eps_dot / ((2 + eps^2)(1 - eps^2))],
    s = ``squeeze_side(eps, eps_dot, v)``,
    derived from the long-bearing Reynolds equation (module docstring); 0 <= eps < 1.

    References
    ----------
    Flores et al. (2009); Hamrock, Schmid and Jacobson (2004), half-Sommerfeld solution.
    """
    b = 6.0 * mu * width * r**3 / (c * c)
    v = w - 2.0 * gamma_dot
    side = squeeze_side(eps, eps_dot, v)
    q = 1.0 - eps * eps
    s = 2.0 + eps * eps
    f_r = -b * (
        2.0 * eps * eps * abs(v) / (s * q)
        + 2.0 * eps_dot * (0.5 * math.pi - 8.0 / (math.pi * s)) / q**1.5
    )
    f_t = b * (math.pi * eps * v / (s * math.sqrt(q)) + side * 4.0 * eps * eps_dot / (s * q))
    return f_r, f_t


_FILM = "eps eps_dot gamma_dot w mu r width c"  # the films' arguments

film_force_components = Dispatch(
    "lubrication",
    {
        FilmModel.SHORT_BEARING: (short_bearing_forces, _FILM),
        FilmModel.LONG_BEARING: (long_bearing_forces, _FILM),
        FilmModel.FINITE_BEARING: (finite_bearing_forces, "table " + _FILM),
    },
    "table " + _FILM, (np.nan, np.nan),
)  # fmt: skip
"""Film force (f_r, f_t) [N] on the journal. ``table``: the finite bearing's impedance table
for the joint's L/D (``film.impedance``), read by that law only. A dry joint has no film."""


@njit(cache=True, no_cfunc_wrapper=True)
def couette_torque(eps: float, w_rel: float, mu: float, r: float, width: float, c: float) -> float:
    """Couette shear torque T_c = 2 pi mu R^3 L w_rel / (c sqrt(1 - eps^2)) [N m].

    The shear of a full film at eccentricity ratio eps [-]; w_rel = omega_journal -
    omega_bearing [rad/s]; T_c w_rel is its power, 2 pi mu (R w_rel)^2 R L / (c sqrt(1 -
    eps^2)) (Petroff's at eps = 0).
    """
    return 2.0 * math.pi * mu * r**3 * width * w_rel / (c * math.sqrt(1.0 - eps * eps))


@njit(cache=True, no_cfunc_wrapper=True)
def film_power_loss(
    f_r: float,
    f_t: float,
    couette: float,
    eps: float,
    eps_dot: float,
    gamma_dot: float,
    w: float,
    w_rel: float,
    c: float,
) -> float:
    """Power dissipated in the film [W] of film force (f_r, f_t) [N], never negative.

    Phi = T_c w_rel + c [eps (w - 2 gamma_dot) f_t / 2 - eps_dot f_r]: the Couette shear
    (``couette_torque`` T_c [N m], at the film's own eccentricity ratio) plus the pressure
    flow, int h^3 / (12 mu) |grad p|^2 dA = -F . V for any film whose pressure vanishes where
    it cavitates (module docstring). eps, eps_dot [-, 1/s]: the journal's own eccentricity
    ratio and rate, e / c, so that Phi is what the bodies lose; w_rel = omega_journal -
    omega_bearing [rad/s].
    """
    return couette * w_rel + c * (0.5 * eps * (w - 2.0 * gamma_dot) * f_t - eps_dot * f_r)


@njit(cache=True, no_cfunc_wrapper=True)
def film_torques(f_t: float, couette: float, e: float) -> tuple[float, float]:
    """Shear torques of the film (on the journal, on the bearing) [N m].

    T_J = -T_c - e f_t / 2, T_B = T_c - e f_t / 2 with the Couette torque T_c [N m]
    (``couette_torque``), the film force's tangential part f_t [N] and the journal's
    eccentricity e [m]: with the force pair at the two centres, whose moment is e f_t, the
    film's moments sum to zero (module docstring).
    """
    offset = 0.5 * e * f_t
    return -couette - offset, couette - offset
