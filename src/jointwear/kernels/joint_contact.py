"""Contact of every clearance joint at one state: penetration, forces, and their moments.

The mechanism's clearance joints are rows of ``sys.clearance_*``; the run's contact state
(``wk.contact_on``, ``wk.impact_speed``, ``wk.wear``) is kept up to date by the loop between
steps (``kernels.contact_steps``). ``evaluate_contact`` leaves its results in the row
``wk.contact[k]``, indexed by the ``C_*`` constants, for the outputs and the wear.

Penetration (paper Eq. 15, SPEC secs. 3-4): delta = abs(e) - (c + w_B(theta_B) + w_J(theta_J)),
the wear depths w read from the sector profiles in each body's frame (``wear.depth_at``). The
force law is applied for any delta > 0, so the force is continuous; the contact tolerance only
decides when a contact period begins (``kernels.contact_steps``). Until the loop has
recorded the onset of a period, the damping uses the current penetration rate as the
impact speed, floored at ``min_impact_speed``. The rate of penetration is n . de/dt: the
slope of the worn profile (wear depths are of the order of 1e-8 m against a clearance of
1e-4 m) is neglected in it.
"""

import math

from numba import njit

from .clearance import apply_contact, contact_velocities, eccentricity, surface_angles
from .contact import hertz, normal_force
from .friction import tangential_force
from .wear import depth_at

# Columns of sys.clearance_param (SI).
P_RB = 0  # bearing radius [m]
P_RJ = 1  # journal radius [m]
P_C = 2  # radial clearance [m]
P_K = 3  # contact stiffness K [N/m^n]
P_EXP = 4  # exponent n [-]
P_CE = 5  # restitution coefficient [-]
P_CF = 6  # friction coefficient [-]
P_F0 = 7  # friction law parameters p0, p1, p2 (kernels.friction)
P_F1 = 8
P_F2 = 9
P_WEAR = 10  # Archard k [1/Pa], or Reye's shear strength [Pa]
P_SHARE = 11  # journal's share of the worn volume [-]
P_WIDTH = 12  # joint width [m]
P_RSTAR = 13  # relative radius R* [m]
P_ESTAR = 14  # contact modulus E* [Pa]
P_MIN_SPEED = 15  # floor of the impact speed [m/s]
P_TOL = 16  # contact tolerance [m]
N_PARAM = 17

# Columns of sys.clearance_law.
L_NORMAL = 0  # NormalLaw
L_FRICTION = 1  # FrictionLaw
L_WEAR = 2  # WearLaw
L_PEAK = 3  # 1: paper-style wear (peak pressure into one sector), 0: Hertz spread
L_FEEDBACK = 4  # 1: worn profile feeds back into the penetration
N_LAW = 5

# Columns of wk.contact (results of the last evaluation).
C_EX = 0  # eccentricity [m]
C_EY = 1
C_DELTA = 2  # penetration [m]
C_DDOT = 3  # penetration rate [m/s]
C_VT = 4  # sliding speed [m/s]
C_FN = 5  # normal force [N]
C_FT = 6  # friction force [N]
C_THETA_B = 7  # direction of n in the bearing's frame [rad]
C_THETA_J = 8  # direction of n in the journal's frame [rad]
C_ELASTIC = 9  # undamped part K delta^n of the normal force [N]
C_FX = 10  # contact force on the journal, global [N]
C_FY = 11
N_CONTACT = 12


@njit(cache=True, inline="always")
def evaluate_contact(q, qd, sys, wk, k):
    """Geometry and forces of clearance joint k at state (q, q'), into wk.contact[k]."""
    p = sys.clearance_param[k]
    law = sys.clearance_law[k]
    sb = sys.clearance_point[k, 0]
    sj = sys.clearance_point[k, 1]
    ib = sys.clearance_body[k, 0]
    ij = sys.clearance_body[k, 1]
    out = wk.contact[k]
    out[:] = 0.0
    ex, ey, dex, dey = eccentricity(q, qd, ib, sb[0], sb[1], ij, sj[0], sj[1])
    out[C_EX] = ex
    out[C_EY] = ey
    e = math.hypot(ex, ey)
    if e == 0.0:  # journal exactly centred: no direction, no contact
        out[C_DELTA] = -p[P_C]
        return
    nx, ny = ex / e, ey / e
    theta_b, theta_j = surface_angles(q, ib, ij, nx, ny)
    gap = p[P_C]
    if law[L_FEEDBACK]:
        sectors = sys.clearance_sectors[k]
        gap += depth_at(theta_b, wk.wear[k, 0, :sectors])
        gap += depth_at(theta_j, wk.wear[k, 1, :sectors])
    delta = e - gap
    delta_dot, v_t = contact_velocities(qd, ib, ij, nx, ny, dex, dey, p[P_RB], p[P_RJ])
    out[C_DELTA] = delta
    out[C_DDOT] = delta_dot
    out[C_VT] = v_t
    out[C_THETA_B] = theta_b
    out[C_THETA_J] = theta_j
    if delta <= 0.0:
        return
    impact_speed = wk.impact_speed[k] if wk.contact_on[k] else max(delta_dot, p[P_MIN_SPEED])
    f_n = normal_force(law[L_NORMAL], delta, delta_dot, impact_speed, p[P_K], p[P_EXP], p[P_CE])
    f_t = tangential_force(law[L_FRICTION], v_t, f_n, p[P_CF], p[P_F0], p[P_F1], p[P_F2])
    out[C_FN] = f_n
    out[C_FT] = f_t
    out[C_ELASTIC] = hertz(delta, p[P_K], p[P_EXP])
    out[C_FX] = -f_n * nx - f_t * ny
    out[C_FY] = -f_n * ny + f_t * nx


@njit(cache=True, inline="always")
def contact_forces(q, qd, sys, wk, g):
    """Evaluate every clearance joint and add its contact forces to g [N, N, N m]."""
    for k in range(sys.clearance_body.shape[0]):
        evaluate_contact(q, qd, sys, wk, k)
        c = wk.contact[k]
        if c[C_FN] == 0.0 and c[C_FT] == 0.0:
            continue
        e = math.hypot(c[C_EX], c[C_EY])
        sb = sys.clearance_point[k, 0]
        sj = sys.clearance_point[k, 1]
        p = sys.clearance_param[k]
        apply_contact(
            q, g,
            sys.clearance_body[k, 0], sb[0], sb[1],
            sys.clearance_body[k, 1], sj[0], sj[1],
            c[C_EX] / e, c[C_EY] / e, p[P_RB], p[P_RJ], c[C_FN], c[C_FT],
        )  # fmt: skip


@njit(cache=True)
def contact_energy(sys, wk):
    """Elastic energy K delta^(n+1) / (n+1) stored in the contacts of the last evaluation [J]."""
    energy = 0.0
    for k in range(sys.clearance_body.shape[0]):
        delta = wk.contact[k, C_DELTA]
        if delta > 0.0:
            n = sys.clearance_param[k, P_EXP]
            energy += sys.clearance_param[k, P_K] * delta ** (n + 1.0) / (n + 1.0)
    return energy
