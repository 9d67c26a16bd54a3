"""Tangential (friction) force laws of a clearance joint contact.

| symbol | meaning | unit | paper |
|---|---|---|---|
| v_t | sliding speed of the journal's contact point past the bearing's, along t | m/s | Eq. 19 |
| f_n | normal force | N | Eq. 18 |
| c_f | friction coefficient while sliding (kinetic) | - | Eq. 19 |
| c_d | Ambrosio's dynamic correction coefficient, 0..1 | - | Eq. 19 |
| v0, v1 | Ambrosio's speeds: no friction up to v0, full friction from v1 | m/s | Eq. 19 |
| v_reg | regularisation speed of plain Coulomb friction | m/s | |
| mu_s, dv, v_tr | stick-slip: static coefficient, stick band, transition end | -, m/s, m/s | |
| f_t | friction force along t on the journal (the bearing gets -f_t) | N | Eq. 17 |

Every law returns f_t = -mu(abs(v_t)) f_n sign(v_t): it opposes sliding and vanishes at
v_t = 0. The dispatchers ``tangential_force(law, v_t, f_n, c_f, p0, p1, p2)`` and
``slip_speed(law, v_t, p0, p1, p2)`` read:

| law | p0 | p1 | p2 | sticking (no wear) when |
|---|---|---|---|---|
| COULOMB | v_reg | - | - | v_t = 0 |
| AMBROSIO | v0 | v1 | - | abs(v_t) <= v0 (c_d = 0) |
| STICK_SLIP | mu_s | dv | v_tr | abs(v_t) <= dv |

Stick-slip. Karnopp's model (1985) treats abs(v_t) < DV as zero speed and sets the
friction equal and opposite to the tangential load there, up to mu_s f_n. In a multibody
mechanism that load is not available to a contact law: it is the tangential projection of
everything else (applied forces, inertia, constraint reactions), which needs the solution of
the equations of motion (paper Eq. 7) without the friction, and with several sticking
contacts an implicit, complementarity problem. (Flores 2009, sec. 4, notes the same
drawback.) We therefore use the velocity-based variant: inside the band the friction rises
linearly to the static limit, f_t = -mu_s f_n v_t / dv, a stiff damper that brings any load
below mu_s f_n to balance at a creep speed under dv, so the balance Karnopp imposes is
reached by the dynamics itself; a load above mu_s f_n pushes the contact out of the band.
Outside the band the coefficient falls linearly from mu_s at dv to c_f at v_tr (a jump
when v_tr <= dv, as in Karnopp's model). It is the friction curve of MSC Adams contacts
(stiction and friction transition speeds) with straight segments in place of cubic steps.
The band's slope sets a time constant m dv / (mu_s f_n) (m the effective tangential mass),
which the step-size control must resolve: a narrower band is closer to true sticking, and
makes the step smaller.

References
----------
J.A.C. Ambrosio, "Impact of rigid and flexible multibody systems: deformation description
and contact models", Virtual Nonlinear Multibody Systems, NATO ASI, vol. II (2002) 15-33.
D. Karnopp, "Computer simulation of stick-slip friction in mechanical dynamic systems",
J. Dyn. Syst. Meas. Control 107 (1985) 100-103.
MSC Software, Adams/Solver reference, CONTACT statement: friction force.
"""

from enum import IntEnum

import numpy as np
from numba import njit

from .dispatch import Dispatch


class FrictionLaw(IntEnum):
    """Codes of the friction laws (``model.laws.friction.FRICTION``, whose records name them)."""

    COULOMB = 0
    AMBROSIO = 1
    STICK_SLIP = 2


@njit(cache=True, no_cfunc_wrapper=True)
def _sign(x):
    if x > 0.0:
        return 1.0
    if x < 0.0:
        return -1.0
    return 0.0


@njit(cache=True, no_cfunc_wrapper=True)
def _ramp(s, s0, s1):
    """0 for s <= s0, linear to 1 at s1, 1 beyond (a step at s0 when s1 <= s0)."""
    if s <= s0:
        return 0.0
    if s >= s1:
        return 1.0
    return (s - s0) / (s1 - s0)


@njit(cache=True, no_cfunc_wrapper=True)
def ambrosio(v_t: float, f_n: float, c_f: float, v0: float, v1: float) -> float:
    """Coulomb friction with Ambrosio's dynamic correction [N].

    f_t = -c_f c_d f_n sign(v_t) with c_d = 0 for abs(v_t) <= v0,
    c_d = (abs(v_t) - v0) / (v1 - v0) for v0 < abs(v_t) < v1 and c_d = 1 from v1 on.

    References
    ----------
    Ambrosio (2002); Flores (2009), Eq. 19.
    """
    return -c_f * _ramp(abs(v_t), v0, v1) * f_n * _sign(v_t)


@njit(cache=True, no_cfunc_wrapper=True)
def coulomb(v_t: float, f_n: float, c_f: float, v_reg: float) -> float:
    """Coulomb friction regularised linearly over abs(v_t) < v_reg [N].

    f_t = -c_f f_n v_t / v_reg inside the band and -c_f f_n sign(v_t) outside (plain sign
    for v_reg <= 0). The linear band, not tanh, gives the exact Coulomb force from v_reg on,
    so v_reg means what it says, and it is continuous, which an adaptive step needs.

    References
    ----------
    Flores (2009), Eq. 19 with c_d = 1.
    """
    s = abs(v_t)
    if s < v_reg:
        return -c_f * f_n * v_t / v_reg
    return -c_f * f_n * _sign(v_t)


@njit(cache=True, no_cfunc_wrapper=True)
def stick_slip(v_t: float, f_n: float, c_f: float, mu_s: float, dv: float, v_tr: float) -> float:
    """Velocity-based Karnopp-type stick-slip friction [N] (module docstring).

    mu = mu_s abs(v_t) / dv for abs(v_t) <= dv (sticking); then linear from mu_s at dv to
    c_f at v_tr; c_f beyond. f_t = -mu f_n sign(v_t).

    References
    ----------
    Karnopp (1985), velocity-based variant.
    """
    s = abs(v_t)
    if s == 0.0:
        return 0.0
    if s <= dv:  # so dv > 0
        return -mu_s * f_n * v_t / dv
    mu = mu_s + (c_f - mu_s) * _ramp(s, dv, v_tr)
    return -mu * f_n * _sign(v_t)


@njit(cache=True, no_cfunc_wrapper=True)
def coulomb_sliding(v_t: float) -> float:
    """Sliding speed [m/s] of Coulomb friction: abs(v_t), sticking only at v_t = 0."""
    return abs(v_t)


@njit(cache=True, no_cfunc_wrapper=True)
def ambrosio_sliding(v_t: float, v0: float) -> float:
    """Sliding speed [m/s] under Ambrosio's law: abs(v_t), 0 up to v0 (where c_d = 0)."""
    s = abs(v_t)
    return s if s > v0 else 0.0


@njit(cache=True, no_cfunc_wrapper=True)
def stick_slip_sliding(v_t: float, dv: float) -> float:
    """Sliding speed [m/s] under stick-slip friction: abs(v_t), 0 inside the stick band dv."""
    s = abs(v_t)
    return s if s > dv else 0.0


# The dispatchers: per code, the law's function and the arguments it takes (``dispatch``).
tangential_force = Dispatch(
    "friction_law",
    {
        FrictionLaw.COULOMB: (coulomb, "v_t f_n c_f p0"),
        FrictionLaw.AMBROSIO: (ambrosio, "v_t f_n c_f p0 p1"),
        FrictionLaw.STICK_SLIP: (stick_slip, "v_t f_n c_f p0 p1 p2"),
    },
    "v_t f_n c_f p0 p1 p2", np.nan,
)  # fmt: skip
"""Friction force f_t [N]; p0, p1, p2 as in the module docstring's table."""

slip_speed = Dispatch(
    "friction_law",
    {
        FrictionLaw.COULOMB: (coulomb_sliding, "v_t"),
        FrictionLaw.AMBROSIO: (ambrosio_sliding, "v_t p0"),
        FrictionLaw.STICK_SLIP: (stick_slip_sliding, "v_t p1"),
    },
    "v_t p0 p1 p2", np.nan,
)  # fmt: skip
"""Speed [m/s] at which the contact slides, and so wears: abs(v_t), or 0 while it sticks
(abs(v_t) <= v0 for AMBROSIO, abs(v_t) <= dv for STICK_SLIP, v_t = 0 for COULOMB)."""
