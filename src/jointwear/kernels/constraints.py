"""Kinematic constraints Phi(q, t) = 0 of ideal joints and drivers, their Jacobian and gamma.

| symbol | meaning | unit |
|---|---|---|
| phi | constraint values Phi | m or rad |
| cq | Jacobian Phi_q, by row: x, y, phi of its first body, then of its second (rows x 6) | 1, m |
| gamma | right side of the acceleration equation Phi_q q'' = gamma (paper Eq. 3) | m/s^2, rad/s^2 |
| phi_t | partial time derivative of Phi (drivers) | m/s, rad/s |

Rows: revolute 2 (Phi = r_i + A_i s_i - r_j - A_j s_j), translational 2 (relative angle, and
the second point on the first body's line), point on a line 1 (that line alone: a pin in a
slot), driver 1. A joint of a kind not listed here sets its rows to NaN. The formulas
follow Nikravesh (1988), ch. 4 and 6; the paper's Eq. (1)-(3).
"""

import math

from numba import njit

from .codes import DriverKind, JointKind
from .functions import value
from .kinematics import angle, angular_velocity, point_position, point_velocity, rotate


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _add(cq, r, side, b, k, value):
    """Add value at row r, coordinate k (0 x, 1 y, 2 phi) of its side-0 or side-1 body b."""
    if b >= 0:
        cq[r, 3 * side + k] += value


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _revolute(q, qd, i, j, s, r, phi, cq, gamma):
    aix, aiy = rotate(q, i, s[0, 0], s[0, 1])
    ajx, ajy = rotate(q, j, s[1, 0], s[1, 1])
    pix, piy = point_position(q, i, s[0, 0], s[0, 1])
    pjx, pjy = point_position(q, j, s[1, 0], s[1, 1])
    phi[r] = pix - pjx
    phi[r + 1] = piy - pjy
    _add(cq, r, 0, i, 0, 1.0)
    _add(cq, r, 0, i, 2, -aiy)
    _add(cq, r, 1, j, 0, -1.0)
    _add(cq, r, 1, j, 2, ajy)
    _add(cq, r + 1, 0, i, 1, 1.0)
    _add(cq, r + 1, 0, i, 2, aix)
    _add(cq, r + 1, 1, j, 1, -1.0)
    _add(cq, r + 1, 1, j, 2, -ajx)
    wi2 = angular_velocity(qd, i) ** 2
    wj2 = angular_velocity(qd, j) ** 2
    gamma[r] = aix * wi2 - ajx * wj2
    gamma[r + 1] = aiy * wi2 - ajy * wj2


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def line_projection(q, qd, i, j, s, vx, vy, r, phi, cq, gamma):
    """Row r: f = (A_i v) . (r_Pj - r_Pi), the second point projected on a body-i direction v.

    Used for the translational joint (v normal to the axis, f = 0) and for distance drivers
    (v along the axis, f = slide). Fills phi[r], cq[r] and gamma[r] (no time dependence).
    """
    nx, ny = rotate(q, i, vx, vy)
    aix, aiy = rotate(q, i, s[0, 0], s[0, 1])
    ajx, ajy = rotate(q, j, s[1, 0], s[1, 1])
    pix, piy = point_position(q, i, s[0, 0], s[0, 1])
    pjx, pjy = point_position(q, j, s[1, 0], s[1, 1])
    dx = pjx - pix
    dy = pjy - piy
    phi[r] = nx * dx + ny * dy
    _add(cq, r, 0, i, 0, -nx)
    _add(cq, r, 0, i, 1, -ny)
    _add(cq, r, 0, i, 2, -ny * dx + nx * dy - (nx * -aiy + ny * aix))
    _add(cq, r, 1, j, 0, nx)
    _add(cq, r, 1, j, 1, ny)
    _add(cq, r, 1, j, 2, nx * -ajy + ny * ajx)
    wi = angular_velocity(qd, i)
    wj = angular_velocity(qd, j)
    vix, viy = point_velocity(q, qd, i, s[0, 0], s[0, 1])
    vjx, vjy = point_velocity(q, qd, j, s[1, 0], s[1, 1])
    ddx = vjx - vix
    ddy = vjy - viy
    rest = -(nx * dx + ny * dy) * wi * wi
    rest += 2.0 * wi * (-ny * ddx + nx * ddy)
    rest += nx * (aix * wi * wi - ajx * wj * wj) + ny * (aiy * wi * wi - ajy * wj * wj)
    gamma[r] = -rest


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def evaluate_constraints(t, q, qd, mech, phi, cq, gamma, phi_t):
    """Fill Phi, Phi_q, gamma and Phi_t for all joints and drivers of the mechanism."""
    for r in range(cq.shape[0]):
        phi_t[r] = 0.0
        for c in range(cq.shape[1]):
            cq[r, c] = 0.0
    for jt in range(mech.joint_kind.shape[0]):
        i = mech.joint_body[jt, 0]
        j = mech.joint_body[jt, 1]
        s = mech.joint_point[jt]
        r = mech.joint_row[jt]
        kind = mech.joint_kind[jt]
        ax = mech.joint_axis[jt, 0]
        ay = mech.joint_axis[jt, 1]
        if kind == JointKind.REVOLUTE:
            _revolute(q, qd, i, j, s, r, phi, cq, gamma)
        elif kind == JointKind.TRANSLATIONAL:  # relative angle, then the point on the line
            phi[r] = angle(q, j) - angle(q, i) - mech.joint_angle0[jt]
            _add(cq, r, 0, i, 2, -1.0)
            _add(cq, r, 1, j, 2, 1.0)
            gamma[r] = 0.0
            line_projection(q, qd, i, j, s, -ay, ax, r + 1, phi, cq, gamma)
        elif kind == JointKind.POINT_ON_LINE:
            line_projection(q, qd, i, j, s, -ay, ax, r, phi, cq, gamma)
        else:  # an unknown kind: the run stops non-finite rather than run as another
            phi[r] = math.nan
            gamma[r] = math.nan
    for d in range(mech.driver_kind.shape[0]):
        r = mech.driver_row[d]
        fn = mech.driver_function[d]
        f, fd, fdd = value(mech, fn, t, q, qd)
        if mech.driver_kind[d] == DriverKind.ANGLE:
            i = mech.driver_body[d, 0]
            j = mech.driver_body[d, 1]
            phi[r] = angle(q, j) - angle(q, i) - f
            _add(cq, r, 0, i, 2, -1.0)
            _add(cq, r, 1, j, 2, 1.0)
            gamma[r] = fdd
        else:
            jt = mech.driver_joint[d]
            line_projection(
                q,
                qd,
                mech.joint_body[jt, 0],
                mech.joint_body[jt, 1],
                mech.joint_point[jt],
                mech.joint_axis[jt, 0],
                mech.joint_axis[jt, 1],
                r,
                phi,
                cq,
                gamma,
            )
            phi[r] -= f
            gamma[r] += fdd
        phi_t[r] = -fd
