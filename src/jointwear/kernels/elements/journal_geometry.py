"""Revolute clearance joint geometry and the forces of its contact on both bodies.

| symbol | meaning | unit | paper |
|---|---|---|---|
| e | eccentricity vector r_J - r_B of the journal centre from the bearing centre | m | Fig. 2 |
| n | unit normal e / abs(e), pointing from the bearing centre to the journal centre | - | |
| t | unit tangent, n turned +90 degrees | - | |
| delta | penetration e - c_local(n) | m | Eq. 15 |
| delta_dot | rate of penetration (n . de/dt) | m/s | Eq. 18 |
| v_t | sliding speed of the journal's contact point past the bearing's | m/s | Eq. 19 |
| theta_b, theta_j | direction of n in the bearing's and journal's body frames | rad | Fig. 4 |
| f_n, f_t | normal force (pushes the journal to the bearing centre), friction | N | Eq. 17 |

The contact points are P_J = r_J + R_J n on the journal and P_B = r_B + R_B n on the bearing
(SPEC sec. 3); the force on the journal, -f_n n + f_t t, acts at P_J and its opposite at P_B,
so both bodies also get moments.
"""

import math

from numba import njit

from ..kinematics import angle, angular_velocity, point_position, point_velocity
from .point_loads import apply_force_at


@njit(cache=True, no_cfunc_wrapper=True)
def eccentricity(q, qd, ib, sb_x, sb_y, ij, sj_x, sj_y):
    """Journal-centre offset from the bearing centre and its rate.

    Returns (ex, ey, dex, dey) [m, m, m/s, m/s] for the bearing centre at body point s_b of
    body ib and the journal centre at body point s_j of body ij (-1 is the ground).
    """
    bx, by = point_position(q, ib, sb_x, sb_y)
    jx, jy = point_position(q, ij, sj_x, sj_y)
    vbx, vby = point_velocity(q, qd, ib, sb_x, sb_y)
    vjx, vjy = point_velocity(q, qd, ij, sj_x, sj_y)
    return jx - bx, jy - by, vjx - vbx, vjy - vby


@njit(cache=True, no_cfunc_wrapper=True)
def surface_angles(q, ib, ij, nx, ny):
    """Direction of n in the bearing's and the journal's body frames, in [0, 2 pi) [rad]."""
    direction = math.atan2(ny, nx)
    two_pi = 2.0 * math.pi
    return (direction - angle(q, ib)) % two_pi, (direction - angle(q, ij)) % two_pi


@njit(cache=True, no_cfunc_wrapper=True)
def contact_velocities(qd, ib, ij, nx, ny, dex, dey, r_b, r_j):
    """Penetration rate along n, and sliding speed v_t of P_J relative to P_B along t [m/s].

    The material points at P_J and P_B move with their bodies: v_PJ - v_PB =
    de/dt + (omega_J R_J - omega_B R_B) t.
    """
    delta_dot = nx * dex + ny * dey
    tx, ty = -ny, nx
    spin = angular_velocity(qd, ij) * r_j - angular_velocity(qd, ib) * r_b
    return delta_dot, tx * dex + ty * dey + spin


@njit(cache=True, no_cfunc_wrapper=True)
def apply_contact(q, g, ib, sb_x, sb_y, ij, sj_x, sj_y, nx, ny, r_b, r_j, f_n, f_t):
    """Add the contact force pair to the generalised forces g [N, N, N m].

    The journal gets -f_n n + f_t t at P_J, the bearing its opposite at P_B.
    """
    tx, ty = -ny, nx
    fx = -f_n * nx + f_t * tx
    fy = -f_n * ny + f_t * ty
    apply_force_at(q, g, ij, sj_x, sj_y, r_j * nx, r_j * ny, fx, fy)
    apply_force_at(q, g, ib, sb_x, sb_y, r_b * nx, r_b * ny, -fx, -fy)


@njit(cache=True, no_cfunc_wrapper=True)
def apply_at_centres(q, g, ib, sb_x, sb_y, ij, sj_x, sj_y, fx, fy):
    """Add (fx, fy) [N] on the journal and minus it on the bearing, through their centres.

    A lubricant film's pressure is radial, so its resultant passes through both centres.
    """
    apply_force_at(q, g, ij, sj_x, sj_y, 0.0, 0.0, fx, fy)
    apply_force_at(q, g, ib, sb_x, sb_y, 0.0, 0.0, -fx, -fy)
