"""Generalised forces of the loads a contact element puts on its bodies (shared by the kinds).

g holds, per moving body b, (F_x, F_y, M) at entries 3 b, 3 b + 1, 3 b + 2 [N, N, N m];
the ground (b < 0) takes nothing.
"""

from numba import njit

from ..kinematics import point_position


@njit(cache=True, no_cfunc_wrapper=True)
def apply_force_at(q, g, b, s_x, s_y, off_x, off_y, fx, fy):
    """Add force (fx, fy) [N] acting at body point s plus the global offset off [m] of body b."""
    if b < 0:
        return
    px, py = point_position(q, b, s_x, s_y)
    arm_x = px + off_x - q[3 * b]
    arm_y = py + off_y - q[3 * b + 1]
    g[3 * b] += fx
    g[3 * b + 1] += fy
    g[3 * b + 2] += arm_x * fy - arm_y * fx


@njit(cache=True, no_cfunc_wrapper=True)
def apply_torque(g, b, torque):
    """Add a torque [N m] to body b."""
    if b >= 0:
        g[3 * b + 2] += torque
