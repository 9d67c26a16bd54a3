"""Planar rigid-body kinematics in Cartesian coordinates.

| symbol | meaning | unit |
|---|---|---|
| q | (x, y, phi) of every moving body, stacked | m, m, rad |
| qd | time derivative of q | m/s, m/s, rad/s |
| b | body index; -1 is the ground (fixed, global frame) | - |
| s | point in body coordinates (global for the ground) | m |

A(phi) s is the point's offset from the centre of mass in global axes (Nikravesh 1988,
ch. 4); its derivative with respect to phi is perp(A s) with perp(v) = (-v_y, v_x).
"""

import math

from numba import njit


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def rotate(q, b, sx, sy):
    """Return A(phi_b) s [m]; the ground's points are already global."""
    if b < 0:
        return sx, sy
    c = math.cos(q[3 * b + 2])
    s = math.sin(q[3 * b + 2])
    return c * sx - s * sy, s * sx + c * sy


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def point_position(q, b, sx, sy):
    """Global position r_b + A_b s of a body point [m]."""
    ax, ay = rotate(q, b, sx, sy)
    if b < 0:
        return ax, ay
    return q[3 * b] + ax, q[3 * b + 1] + ay


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def point_velocity(q, qd, b, sx, sy):
    """Global velocity of a body point [m/s]: r_b' + omega_b perp(A_b s)."""
    if b < 0:
        return 0.0, 0.0
    ax, ay = rotate(q, b, sx, sy)
    w = qd[3 * b + 2]
    return qd[3 * b] - w * ay, qd[3 * b + 1] + w * ax


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def angle(q, b):
    """Body angle [rad]; 0 for the ground."""
    return 0.0 if b < 0 else q[3 * b + 2]


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def angular_velocity(qd, b):
    """Body angular velocity [rad/s]; 0 for the ground."""
    return 0.0 if b < 0 else qd[3 * b + 2]
