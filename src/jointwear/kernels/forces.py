"""Applied loads as generalised forces g (paper Eq. 4), and their potential energy.

| symbol | meaning | unit |
|---|---|---|
| g | generalised force on (x, y, phi) of every body | N, N, N m |
| gravity | acceleration of gravity (g_x, g_y) | m/s^2 |
| k, c | spring stiffness and damping | N/m, N s/m (rotational: N m/rad, N m s/rad) |
| l0 | free length (rotational: free angle) | m (rad) |

A force F at body point s adds (F_x, F_y, (A s) x F) to that body's entries. A joint force
(or a joint pressure times its area) F acts along the joint's axis u (the first body's frame):
+F u on the second body at its point, -F u on the first body at the same global point, so
the pair has no moment.

``write_loads`` puts each load as it is applied in the output row (``system.load_columns``
names them): a point force's (F_x, F_y) [N]; a torque [N m]; a spring-damper's force on its
second point along the line from its first, positive pushing them apart [N]; a rotational
spring-damper's torque on its second body [N m]; a joint force's F [N], or a joint pressure's
pressure [Pa] and F [N]. Gravity has no columns.
"""

import math

from numba import njit

from .codes import ForceKind
from .functions import value
from .kinematics import (
    angle,
    angular_velocity,
    point_position,
    point_velocity,
    rotate,
)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _apply(q, g, b, sx, sy, fx, fy):
    """Add force (fx, fy) [N] acting at body point s [m] to g."""
    if b < 0:
        return
    ax, ay = rotate(q, b, sx, sy)
    g[3 * b] += fx
    g[3 * b + 1] += fy
    g[3 * b + 2] += ax * fy - ay * fx


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _apply_at(q, g, b, px, py, fx, fy):
    """Add force (fx, fy) [N] acting at global point p [m] to body b's entries of g."""
    if b < 0:
        return
    g[3 * b] += fx
    g[3 * b + 1] += fy
    g[3 * b + 2] += (px - q[3 * b]) * fy - (py - q[3 * b + 1]) * fx


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _function_value(mech, fn, t, q, qd):
    return value(mech, fn, t, q, qd)[0]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _joint_force(q, g, mech, e, force):
    """Apply ``force`` [N] along load e's joint axis: on body 2 at its point, minus on body 1."""
    b1 = mech.force_body[e, 0]
    b2 = mech.force_body[e, 1]
    s = mech.force_point[e]
    ux, uy = rotate(q, b1, mech.force_param[e, 1], mech.force_param[e, 2])
    px, py = point_position(q, b2, s[1, 0], s[1, 1])
    _apply_at(q, g, b2, px, py, force * ux, force * uy)
    _apply_at(q, g, b1, px, py, -force * ux, -force * uy)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spring_axis(q, mech, e):
    """Unit vector u from point 1 to point 2 of load e, and the length between them [m]."""
    s = mech.force_point[e]
    p1x, p1y = point_position(q, mech.force_body[e, 0], s[0, 0], s[0, 1])
    p2x, p2y = point_position(q, mech.force_body[e, 1], s[1, 0], s[1, 1])
    dx = p2x - p1x
    dy = p2y - p1y
    length = math.sqrt(dx * dx + dy * dy)
    if length == 0.0:  # coincident ends: no direction, so no force (exact for l0 = 0)
        return 0.0, 0.0, 0.0
    return dx / length, dy / length, length


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spring_rate(q, qd, mech, e, ux, uy):
    """Rate of change of the length between the two points of load e [m/s]."""
    s = mech.force_point[e]
    v1x, v1y = point_velocity(q, qd, mech.force_body[e, 0], s[0, 0], s[0, 1])
    v2x, v2y = point_velocity(q, qd, mech.force_body[e, 1], s[1, 0], s[1, 1])
    return ux * (v2x - v1x) + uy * (v2y - v1y)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spring_tension(q, qd, mech, e):
    """Tension [N] of spring-damper e (positive pulls its points together), and its axis u."""
    ux, uy, length = _spring_axis(q, mech, e)
    if length == 0.0:  # coincident ends: no direction, so no force
        return 0.0, ux, uy
    k, c, l0 = mech.force_param[e, 0], mech.force_param[e, 1], mech.force_param[e, 2]
    return k * (length - l0) + c * _spring_rate(q, qd, mech, e, ux, uy), ux, uy


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spring_torque(q, qd, mech, e):
    """Torque [N m] rotational spring-damper e puts on its first body (minus that on the second)."""
    k, c, a0 = mech.force_param[e, 0], mech.force_param[e, 1], mech.force_param[e, 2]
    b1 = mech.force_body[e, 0]
    b2 = mech.force_body[e, 1]
    rel = angle(q, b2) - angle(q, b1) - a0
    rate = angular_velocity(qd, b2) - angular_velocity(qd, b1)
    return k * rel + c * rate


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def applied_forces(t, q, qd, mech, g):
    """Fill g [N, N, N m] with gravity and every applied load at time t [s]."""
    nb = mech.mass.shape[0]
    for b in range(nb):
        g[3 * b] = mech.mass[b] * mech.gravity[0]
        g[3 * b + 1] = mech.mass[b] * mech.gravity[1]
        g[3 * b + 2] = 0.0
    for e in range(mech.force_kind.shape[0]):
        kind = mech.force_kind[e]
        b1 = mech.force_body[e, 0]
        b2 = mech.force_body[e, 1]
        if kind == ForceKind.POINT_FORCE:
            fx = _function_value(mech, mech.force_function[e, 0], t, q, qd)
            fy = _function_value(mech, mech.force_function[e, 1], t, q, qd)
            _apply(q, g, b1, mech.force_point[e, 0, 0], mech.force_point[e, 0, 1], fx, fy)
        elif kind == ForceKind.TORQUE:
            if b1 >= 0:
                g[3 * b1 + 2] += _function_value(mech, mech.force_function[e, 0], t, q, qd)
        elif kind == ForceKind.JOINT_FORCE or kind == ForceKind.JOINT_PRESSURE:
            force = mech.force_param[e, 0] * _function_value(
                mech, mech.force_function[e, 0], t, q, qd
            )
            _joint_force(q, g, mech, e, force)
        elif kind == ForceKind.SPRING_DAMPER:
            tension, ux, uy = _spring_tension(q, qd, mech, e)
            s = mech.force_point[e]
            _apply(q, g, b1, s[0, 0], s[0, 1], tension * ux, tension * uy)
            _apply(q, g, b2, s[1, 0], s[1, 1], -tension * ux, -tension * uy)
        elif kind == ForceKind.ROTATIONAL_SPRING_DAMPER:  # on phi_2 - phi_1
            torque = _spring_torque(q, qd, mech, e)
            if b1 >= 0:
                g[3 * b1 + 2] += torque
            if b2 >= 0:
                g[3 * b2 + 2] -= torque
        else:  # an unknown kind: the run stops non-finite rather than run as another
            g[0] = math.nan


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def write_loads(t, q, qd, mech, row, c):
    """Write every load but gravity, as applied at time t [s], from column c of row.

    Returns the column after the last written.
    """
    for e in range(mech.force_kind.shape[0]):
        kind = mech.force_kind[e]
        if kind == ForceKind.POINT_FORCE:
            row[c] = _function_value(mech, mech.force_function[e, 0], t, q, qd)
            row[c + 1] = _function_value(mech, mech.force_function[e, 1], t, q, qd)
            c += 2
        elif kind == ForceKind.TORQUE:
            row[c] = _function_value(mech, mech.force_function[e, 0], t, q, qd)
            c += 1
        elif kind == ForceKind.JOINT_FORCE:  # its scale is 1
            row[c] = mech.force_param[e, 0] * _function_value(
                mech, mech.force_function[e, 0], t, q, qd
            )
            c += 1
        elif kind == ForceKind.JOINT_PRESSURE:
            row[c] = _function_value(mech, mech.force_function[e, 0], t, q, qd)
            row[c + 1] = mech.force_param[e, 0] * row[c]
            c += 2
        elif kind == ForceKind.SPRING_DAMPER:
            row[c] = -_spring_tension(q, qd, mech, e)[0]
            c += 1
        elif kind == ForceKind.ROTATIONAL_SPRING_DAMPER:
            row[c] = -_spring_torque(q, qd, mech, e)
            c += 1
        else:  # an unknown kind: the run stops non-finite rather than run as another
            row[c] = math.nan
            c += 1
    return c


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def potential_energy(q, mech):
    """Gravitational and spring potential energy [J] (zero at the origin / free length)."""
    energy = 0.0
    for b in range(mech.mass.shape[0]):
        energy -= mech.mass[b] * (mech.gravity[0] * q[3 * b] + mech.gravity[1] * q[3 * b + 1])
    for e in range(mech.force_kind.shape[0]):
        kind = mech.force_kind[e]
        if kind == ForceKind.SPRING_DAMPER:
            length = _spring_axis(q, mech, e)[2]
            energy += 0.5 * mech.force_param[e, 0] * (length - mech.force_param[e, 2]) ** 2
        elif kind == ForceKind.ROTATIONAL_SPRING_DAMPER:
            rel = angle(q, mech.force_body[e, 1]) - angle(q, mech.force_body[e, 0])
            energy += 0.5 * mech.force_param[e, 0] * (rel - mech.force_param[e, 2]) ** 2
    return energy
