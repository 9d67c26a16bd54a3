"""The translational clearance joint (a slider in a guide) as a contact element.

| symbol | meaning | unit |
|---|---|---|
| G, u, v | guide point on its centreline, unit axis, u turned +90 deg (guide body) | m, - |
| S, u_s, v_s | slider centre, axis and normal (slider body; u_s = u when level) | m, - |
| a, b | half-length and half-height of the slider | m |
| h | half-height of the guide: its surfaces lie at v . (x - G) = +-h | m |
| l | half-length of the guide (infinite for an unbounded guide) | m |
| c | gap on each side, h - b | m |
| delta, delta_dot | penetration and its rate | m, m/s |
| f_n, f_t | normal force (pushes the slider back into the guide), friction along the axis | N |

Contacts (slots), after Flores, Ambrosio, Claro and Lankarani (2008): the slider's four corners
S + r u_s + sigma b v_s (r = +-a, sigma = +1 on the top, -1 on the bottom) against the guide
surface on their side, where the corner lies within the guide's length; and, for a finite
guide, its four edges G + e u + sigma h v (e = +-l) against the slider's face on their side,
where the edge lies within the slider's length. Each contact is a point P with an outward
normal nu of the slider (sigma v for a corner, sigma v_s for an edge):

    corner: delta = sigma v . (P - G) - h - (wear depths of both surfaces there)
    edge:   delta = b - sigma v_s . (P - S) - (wear depths of both surfaces there)
    delta_dot = nu . (v_slider(P) - v_guide(P)),  v_t = tau . (v_slider(P) - v_guide(P)),

with tau = nu turned by -90 deg (+-u for a corner, +-u_s for an edge), each velocity that of
the body's material point at P. The slider gets -f_n nu + f_t tau at P, the guide its
opposite. The worn depths come from the surfaces' segments (``laws.segments``); an unbounded
guide keeps no map of its wear (its share of the volume is still counted).

Wear: a sliding contact removes coef f_n ds from the two surfaces at P (the slider takes
``P_SHARE``), into the segment of each surface where P lies.

References
----------
P. Flores, J. Ambrosio, J.C.P. Claro, H.M. Lankarani, "Translational joints with clearance in
rigid multibody systems", J. Comput. Nonlinear Dyn. 3 (2008) 011007.
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from ..kinematics import angle, point_position
from ..laws.segments import add_wear, depth_along
from ..laws.user import (
    KindLaws,
    UserLaws,
    damped,
    elastic_force,
    kind_laws,
    slip_speed,
    tangential_force,
    wear_coefficient,
)
from ..laws.user import elastic_energy as law_energy
from ..laws.wear import hertz_line_contact
from .point_loads import apply_force_at

# Columns of SliderTable.ints.
I_GUIDE = 0  # guide body (-1: ground)
I_SLIDER = 1  # slider body
I_NORMAL = 2  # elastic law code (its record: model.laws.NORMAL)
I_DAMPING = 3  # damping law code (model.laws.DAMPING)
I_FRICTION = 4  # friction law code (model.laws.FRICTION)
I_WEAR = 5  # wear law code (model.laws.WEAR)
I_FEEDBACK = 6  # 1: the worn depths feed back into the penetrations
I_SEGMENTS = 7  # segments of each surface
I_ENDS = 8  # 1: a finite guide, whose edges touch the slider's faces
N_INTS = 9

# Per law-code column, its family (``model.laws`` key) and the laws compiled only for the
# models that use them (``laws.lawset``): none of this kind's.
LAW_COLUMNS = {
    "normal_law": (I_NORMAL, ()),
    "damping": (I_DAMPING, ()),
    "friction_law": (I_FRICTION, ()),
    "wear_law": (I_WEAR, ()),
}

# Columns of SliderTable.params (SI).
P_G_X = 0  # guide point on the centreline, guide body's frame [m]
P_G_Y = 1
P_U_X = 2  # guide axis, unit, guide body's frame
P_U_Y = 3
P_S_X = 4  # slider centre, slider body's frame [m]
P_S_Y = 5
P_US_X = 6  # slider axis, unit, slider body's frame
P_US_Y = 7
P_A = 8  # slider half-length [m]
P_B = 9  # slider half-height [m]
P_H = 10  # guide half-height [m]
P_L = 11  # guide half-length [m] (a finite guide; else unused)
P_K = 12  # elastic law's stiffness K [N/m^n]
P_EXP = 13  # exponent n [-]
P_CE = 14  # damping law parameter: restitution coefficient [-]
P_CF = 15  # friction coefficient [-]
P_F0 = 16  # friction law parameters (laws.friction)
P_F1 = 17
P_F2 = 18
P_WEAR = 19  # wear law parameter: Archard k [1/Pa], or Reye's shear strength [Pa]
P_SHARE = 20  # slider's share of the worn volume [-]
P_WIDTH = 21  # width out of the plane [m]
P_ESTAR = 22  # contact modulus E* [Pa]
P_MIN_SPEED = 23  # floor of the impact speed [m/s]
P_TOL = 24  # contact tolerance [m]
P_ANGLE0 = 25  # slider angle minus guide angle when level [rad]
P_RSTAR = 26  # corner radius, the contacts' R* [m]; 0: not given (the patch is not checked)
P_DEPTH_LIMIT = 27  # the elastic law's range: penetration / c [-] (its record's)
P_PATCH_LIMIT = 28  # the Hertz patch's range: b / R* [-]; 0: not checked
N_PARAMS = 29

# Contact slots of one joint: the corners, then the guide's edges; front is +axis, top +normal.
CONTACT_NAMES = (
    "front_top", "front_bottom", "rear_top", "rear_bottom",
    "edge_front_top", "edge_front_bottom", "edge_rear_top", "edge_rear_bottom",
)  # fmt: skip
SLOTS = 8
CORNERS = 4

# Worn surfaces, the first index of SliderState.wear.
GUIDE_TOP = 0
GUIDE_BOTTOM = 1
SLIDER_TOP = 2
SLIDER_BOTTOM = 3
SURFACES = ("guide_top", "guide_bottom", "slider_top", "slider_bottom")

# Columns of SliderScratch.contact[k, slot] (the last evaluation).
C_DELTA = 0  # penetration [m]
C_DDOT = 1  # penetration rate [m/s]
C_VT = 2  # sliding speed, slider past guide along tau [m/s]
C_FN = 3  # normal force [N]
C_FT = 4  # friction force [N]
C_ELASTIC = 5  # undamped part of the normal force [N]
C_X_GUIDE = 6  # position of P along the guide from G [m]
C_X_SLIDER = 7  # position of P along the slider from S [m]
C_PX = 8  # contact point, global [m]
C_PY = 9
C_NX = 10  # the slider's outward normal nu, global
C_NY = 11
N_CONTACT = 12

# Columns of SliderLog.totals.
T_CONTACT_TIME = 0  # time with any positive normal force [s]
T_MAX_FN = 1  # largest normal force of one contact [N]
T_MAX_DELTA = 2  # largest penetration [m]
T_IMPACTS = 3  # contact periods begun
T_DAMPING_ENERGY = 4  # energy dissipated by damping [J]
T_FRICTION_ENERGY = 5  # energy dissipated by friction [J]
T_WORN_VOLUME = 6  # volume removed from all surfaces [m^3]
T_SLIDING = 7  # sliding distance of the contacts while sliding [m]
T_DEPTH_TIME = 8  # time some contact's penetration exceeded P_DEPTH_LIMIT c [s]
T_DEPTH_MAX = 9  # largest penetration / c [-]
T_PATCH_TIME = 10  # time some contact's Hertz half-width exceeded P_PATCH_LIMIT R* [s]
T_PATCH_MAX = 11  # largest Hertz half-width / R* [-]
N_TOTALS = 12

# Columns of an onset's entry in the impact log.
IMPACT_SPEED = 0  # penetration rate at onset [m/s]
IMPACT_X_GUIDE = 1  # where along the guide [m]
IMPACT_CONTACT = 2  # contact slot within the joint (CONTACT_NAMES)
IMPACT_DELTA = 3  # penetration where the onset was located [m]
N_IMPACT_INFO = 4

# Time-series columns per joint: the slider's lateral offset and tilt, the force on it, and
# each contact's normal force (the edges' only for a finite guide).
OUTPUT_NAMES = ("lateral", "tilt", "fx", "fy", "friction_power", "damping_power")
DEGREES_OF_FREEDOM = 2  # the lateral offset and the tilt


class SliderTable(NamedTuple):
    """The translational clearance joints of a mechanism (fixed for a run)."""

    ints: np.ndarray  # (ns, N_INTS) int64
    params: np.ndarray  # (ns, N_PARAMS)
    laws: KindLaws  # the rows' laws: the codes compiled, and those registered from Python


class SliderState(NamedTuple):
    """What a restart needs: contact periods and worn surfaces."""

    contact_on: np.ndarray  # (ns * SLOTS,) int64, 1 while a contact period lasts
    impact_speed: np.ndarray  # (ns * SLOTS,) penetration rate at the period's onset [m/s]
    wear: np.ndarray  # (ns, 4, max segments) wear depth of each surface (SURFACES) [m]


class SliderLog(NamedTuple):
    """What a run accumulates: totals and wear snapshots."""

    totals: np.ndarray  # (ns, N_TOTALS)
    snapshots: np.ndarray  # (snapshots, ns, 4, max segments) [m]


class SliderScratch(NamedTuple):
    """The last evaluation of each contact and joint."""

    contact: np.ndarray  # (ns, SLOTS, N_CONTACT)
    pose: np.ndarray  # (ns, 2) the slider's lateral offset [m] and tilt [rad]
    sliding: np.ndarray  # (ns, SLOTS) sliding speed of each contact that wears [m/s]


def make_tables(
    ints: np.ndarray,
    params: np.ndarray,
    snapshots: int,
    user: UserLaws | None = None,
) -> tuple[SliderTable, SliderState, SliderLog, SliderScratch]:
    """Allocate a run's arrays for the joints of ``ints`` and ``params``, unworn (Python).

    ``user``: the rows' user laws (``laws.user``); None: no row has one.
    """
    ns = ints.shape[0]
    ints = ints.astype(np.int64).reshape(ns, N_INTS)
    segments = int(ints[:, I_SEGMENTS].max(initial=1))
    return (
        SliderTable(
            ints=ints,
            params=params.astype(np.float64).reshape(ns, N_PARAMS),
            laws=kind_laws(ints, LAW_COLUMNS, user),
        ),
        SliderState(
            contact_on=np.zeros(ns * SLOTS, dtype=np.int64),
            impact_speed=np.zeros(ns * SLOTS),
            wear=np.zeros((ns, 4, segments)),
        ),
        SliderLog(
            totals=np.zeros((ns, N_TOTALS)), snapshots=np.zeros((snapshots, ns, 4, segments))
        ),
        SliderScratch(
            contact=np.zeros((ns, SLOTS, N_CONTACT)),
            pose=np.zeros((ns, 2)),
            sliding=np.zeros((ns, SLOTS)),
        ),
    )


def output_names(finite_guide: bool) -> tuple[str, ...]:
    """The time-series columns of one joint, without its name (Python).

    ``OUTPUT_NAMES``, then each contact's normal force ``fn_<contact>`` and sliding speed
    ``vt_<contact>`` (slider past guide along the surface).
    """
    contacts = CONTACT_NAMES if finite_guide else CONTACT_NAMES[:CORNERS]
    return (
        *OUTPUT_NAMES,
        *(f"fn_{name}" for name in contacts),
        *(f"vt_{name}" for name in contacts),
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _frames(q, p, ig, isl):
    """Global G, u and S, u_s: (gx, gy, ux, uy, sx, sy, usx, usy) [m, -]."""
    gx, gy = point_position(q, ig, p[P_G_X], p[P_G_Y])
    sx, sy = point_position(q, isl, p[P_S_X], p[P_S_Y])
    phi_g, phi_s = angle(q, ig), angle(q, isl)
    cg, sg = math.cos(phi_g), math.sin(phi_g)
    cs, ss = math.cos(phi_s), math.sin(phi_s)
    ux, uy = cg * p[P_U_X] - sg * p[P_U_Y], sg * p[P_U_X] + cg * p[P_U_Y]
    usx, usy = cs * p[P_US_X] - ss * p[P_US_Y], ss * p[P_US_X] + cs * p[P_US_Y]
    return gx, gy, ux, uy, sx, sy, usx, usy


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _surface(state, law, k, surface):
    """Worn depths of one surface [m]; empty without wear feedback."""
    segments = law[I_SEGMENTS] if law[I_FEEDBACK] else 0
    return state.wear[k, surface, :segments]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _geometry(table, state, k, i, q, out):
    """Contact i of joint k at q: delta, P, nu and the positions along both surfaces, into out."""
    law = table.ints[k]
    p = table.params[k]
    gx, gy, ux, uy, sx, sy, usx, usy = _frames(q, p, law[I_GUIDE], law[I_SLIDER])
    top = i % 2 == 0
    sigma = 1.0 if top else -1.0
    front = 1.0 if (i % CORNERS) < 2 else -1.0
    if i < CORNERS:
        x_slider = front * p[P_A]
        px = sx + x_slider * usx - sigma * p[P_B] * usy
        py = sy + x_slider * usy + sigma * p[P_B] * usx
        x_guide = ux * (px - gx) + uy * (py - gy)
        delta = sigma * (-uy * (px - gx) + ux * (py - gy)) - p[P_H]
        out[C_NX], out[C_NY] = -sigma * uy, sigma * ux
        reachable = not law[I_ENDS] or abs(x_guide) <= p[P_L]
    else:
        x_guide = front * p[P_L]
        px = gx + x_guide * ux - sigma * p[P_H] * uy
        py = gy + x_guide * uy + sigma * p[P_H] * ux
        x_slider = usx * (px - sx) + usy * (py - sy)
        delta = p[P_B] - sigma * (-usy * (px - sx) + usx * (py - sy))
        out[C_NX], out[C_NY] = -sigma * usy, sigma * usx
        reachable = law[I_ENDS] == 1 and abs(x_slider) <= p[P_A]
    if law[I_ENDS]:
        guide = _surface(state, law, k, GUIDE_TOP if top else GUIDE_BOTTOM)
        delta -= depth_along(x_guide, guide, 2.0 * p[P_L])
    slider = _surface(state, law, k, SLIDER_TOP if top else SLIDER_BOTTOM)
    delta -= depth_along(x_slider, slider, 2.0 * p[P_A])
    out[C_DELTA] = delta if reachable else -(p[P_H] - p[P_B]) - p[P_TOL]
    out[C_PX], out[C_PY] = px, py
    out[C_X_GUIDE] = x_guide
    out[C_X_SLIDER] = x_slider


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _evaluate(table, state, scratch, k, i, q, qd):
    """Geometry and forces of contact i of joint k at (q, q'), into scratch.contact[k, i]."""
    out = scratch.contact[k, i]
    for j in range(N_CONTACT):
        out[j] = 0.0
    law = table.ints[k]
    p = table.params[k]
    _geometry(table, state, k, i, q, out)
    tau_x, tau_y = _tangent(out)
    px, py = out[C_PX], out[C_PY]
    slider_vx, slider_vy = _material_velocity(q, qd, law[I_SLIDER], px, py)
    guide_vx, guide_vy = _material_velocity(q, qd, law[I_GUIDE], px, py)
    dvx, dvy = slider_vx - guide_vx, slider_vy - guide_vy
    out[C_DDOT] = out[C_NX] * dvx + out[C_NY] * dvy
    out[C_VT] = tau_x * dvx + tau_y * dvy
    delta = out[C_DELTA]
    if delta <= 0.0:
        return
    slot = k * SLOTS + i
    impact_speed = max(out[C_DDOT], p[P_MIN_SPEED])
    if state.contact_on[slot]:
        impact_speed = state.impact_speed[slot]
    elastic = elastic_force(
        table.laws, k, law[I_NORMAL], delta, p[P_K], p[P_EXP], p[P_ESTAR], p[P_H], p[P_WIDTH]
    )
    f_n = damped(table.laws, k, elastic, out[C_DDOT], impact_speed, law[I_DAMPING], p[P_CE])
    out[C_FN] = f_n
    out[C_FT] = tangential_force(
        table.laws, k, law[I_FRICTION], out[C_VT], f_n, p[P_CF], p[P_F0], p[P_F1], p[P_F2]
    )
    out[C_ELASTIC] = elastic


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _material_velocity(q, qd, b, px, py):
    """Velocity [m/s] of body b's material point at the global position (px, py) [m]."""
    if b < 0:
        return 0.0, 0.0
    w = qd[3 * b + 2]
    return qd[3 * b] - w * (py - q[3 * b + 1]), qd[3 * b + 1] + w * (px - q[3 * b])


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _tangent(c):
    """tau: the contact's normal nu turned by -90 deg, along the surface slid on."""
    return c[C_NY], -c[C_NX]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _force_on_slider(c):
    """The contact's force on the slider, -f_n nu + f_t tau [N]."""
    tau_x, tau_y = _tangent(c)
    return -c[C_FN] * c[C_NX] + c[C_FT] * tau_x, -c[C_FN] * c[C_NY] + c[C_FT] * tau_y


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def add_forces(table, state, scratch, q, qd, g):
    """Evaluate every contact and add its forces on slider and guide to g [N, N, N m].

    Also keeps each slider's lateral offset and tilt (scratch.pose) for the outputs.
    """
    for k in range(table.ints.shape[0]):
        law = table.ints[k]
        p = table.params[k]
        gx, gy, ux, uy, sx, sy, _, _ = _frames(q, p, law[I_GUIDE], law[I_SLIDER])
        scratch.pose[k, 0] = -uy * (sx - gx) + ux * (sy - gy)
        scratch.pose[k, 1] = angle(q, law[I_SLIDER]) - angle(q, law[I_GUIDE]) - p[P_ANGLE0]
        for i in range(SLOTS):
            _evaluate(table, state, scratch, k, i, q, qd)
            c = scratch.contact[k, i]
            if c[C_FN] == 0.0 and c[C_FT] == 0.0:
                continue
            fx, fy = _force_on_slider(c)
            _apply_at_point(q, g, law[I_SLIDER], c[C_PX], c[C_PY], fx, fy)
            _apply_at_point(q, g, law[I_GUIDE], c[C_PX], c[C_PY], -fx, -fy)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _apply_at_point(q, g, b, px, py, fx, fy):
    """Add the force (fx, fy) [N] acting at the global position (px, py) [m] on body b."""
    if b >= 0:
        apply_force_at(q, g, b, 0.0, 0.0, px - q[3 * b], py - q[3 * b + 1], fx, fy)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def penetration_excess(table, state, scratch, slot, q, qd):
    """Penetration of a contact slot beyond its contact tolerance at (q, q') [m]."""
    k, i = slot // SLOTS, slot % SLOTS
    _evaluate(table, state, scratch, k, i, q, qd)
    return scratch.contact[k, i, C_DELTA] - table.params[k, P_TOL]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def tolerance(table, slot):
    """Contact tolerance of a slot [m]."""
    return table.params[slot // SLOTS, P_TOL]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def begin_period(table, state, scratch, log, slot, q, qd, info):
    """Open or close a slot's contact period at a step end; True when one opens (info filled)."""
    excess = penetration_excess(table, state, scratch, slot, q, qd)
    k, i = slot // SLOTS, slot % SLOTS
    c = scratch.contact[k, i]
    totals = log.totals[k]
    totals[T_MAX_FN] = max(totals[T_MAX_FN], c[C_FN])
    totals[T_MAX_DELTA] = max(totals[T_MAX_DELTA], c[C_DELTA])
    if state.contact_on[slot]:
        if excess + table.params[k, P_TOL] <= 0.0:
            state.contact_on[slot] = 0
        return False
    if excess <= 0.0:
        return False
    state.contact_on[slot] = 1
    state.impact_speed[slot] = max(c[C_DDOT], table.params[k, P_MIN_SPEED])
    totals[T_IMPACTS] += 1.0
    info[IMPACT_SPEED] = c[C_DDOT]
    info[IMPACT_X_GUIDE] = c[C_X_GUIDE]
    info[IMPACT_CONTACT] = i
    info[IMPACT_DELTA] = c[C_DELTA]
    return True


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wear(table, state, k, i, c, ds):
    """Remove the wear of sliding distance ds [m] under contact i; return the volume [m^3]."""
    law = table.ints[k]
    p = table.params[k]
    coef = wear_coefficient(table.laws, k, law[I_WEAR], abs(c[C_FT]) / c[C_FN], p[P_WEAR])
    volume = coef * c[C_FN] * ds
    segments = law[I_SEGMENTS]
    top = i % 2 == 0
    slider = state.wear[k, SLIDER_TOP if top else SLIDER_BOTTOM, :segments]
    add_wear(slider, c[C_X_SLIDER], 2.0 * p[P_A], p[P_WIDTH], p[P_SHARE] * volume)
    if law[I_ENDS]:
        guide = state.wear[k, GUIDE_TOP if top else GUIDE_BOTTOM, :segments]
        add_wear(guide, c[C_X_GUIDE], 2.0 * p[P_L], p[P_WIDTH], (1.0 - p[P_SHARE]) * volume)
    return volume


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def accumulate(table, state, scratch, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear and totals of the step [t_old, t_new] [s] from its midpoint state.

    The wear snapshots due in the step are taken with the step's wear split at them.
    """
    h = t_new - t_old
    for k in range(table.ints.shape[0]):
        totals = log.totals[k]
        touching = False
        speeds = scratch.sliding[k]
        for i in range(SLOTS):
            speeds[i] = 0.0
            _evaluate(table, state, scratch, k, i, q_mid, qd_mid)
            c = scratch.contact[k, i]
            # Also while F_N is clamped at 0 with the bodies still overlapping (see
            # write_outputs).
            totals[T_DAMPING_ENERGY] += (c[C_FN] - c[C_ELASTIC]) * c[C_DDOT] * h
            if c[C_FN] <= 0.0:
                continue
            touching = True
            totals[T_MAX_FN] = max(totals[T_MAX_FN], c[C_FN])
            totals[T_MAX_DELTA] = max(totals[T_MAX_DELTA], c[C_DELTA])
            totals[T_FRICTION_ENERGY] -= c[C_FT] * c[C_VT] * h
            p = table.params[k]
            speeds[i] = slip_speed(
                table.laws, k, table.ints[k, I_FRICTION], c[C_VT], p[P_F0], p[P_F1], p[P_F2]
            )
            totals[T_SLIDING] += speeds[i] * h
        if touching:
            totals[T_CONTACT_TIME] += h
            _track_ranges(table.params[k], scratch.contact[k], totals, h)
        t_from = t_old
        s = first
        while s < snap_times.shape[0] and snap_times[s] <= t_new:  # split the wear there
            t_snap = max(snap_times[s], t_from)
            totals[T_WORN_VOLUME] += _wear_all(table, state, scratch, k, speeds, t_snap - t_from)
            log.snapshots[s, k] = state.wear[k]
            t_from = t_snap
            s += 1
        totals[T_WORN_VOLUME] += _wear_all(table, state, scratch, k, speeds, t_new - t_from)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _track_ranges(p, contacts, totals, h):
    """The step's h [s] beyond the laws' ranges, and the largest ratios, into totals.

    Over the contacts with a positive normal force: penetration / c, and the Hertz half-width
    of a corner of radius R* pressed on a flat (a line contact) / R*, each counted once per
    step when some contact is beyond its limit.
    """
    depth = 0.0
    patch = 0.0
    for i in range(contacts.shape[0]):
        c = contacts[i]
        if c[C_FN] <= 0.0:
            continue
        depth = max(depth, c[C_DELTA] / (p[P_H] - p[P_B]))
        if p[P_RSTAR] > 0.0:
            b, _ = hertz_line_contact(c[C_FN], p[P_RSTAR], p[P_ESTAR], p[P_WIDTH])
            patch = max(patch, b / p[P_RSTAR])
    totals[T_DEPTH_MAX] = max(totals[T_DEPTH_MAX], depth)
    totals[T_PATCH_MAX] = max(totals[T_PATCH_MAX], patch)
    if depth > p[P_DEPTH_LIMIT]:
        totals[T_DEPTH_TIME] += h
    if p[P_PATCH_LIMIT] > 0.0 and patch > p[P_PATCH_LIMIT]:
        totals[T_PATCH_TIME] += h


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wear_all(table, state, scratch, k, speeds, dt):
    """The wear of every sliding contact of joint k over dt [s]; the volume [m^3]."""
    volume = 0.0
    for i in range(SLOTS):
        if speeds[i] > 0.0:
            volume += _wear(table, state, k, i, scratch.contact[k, i], speeds[i] * dt)
    return volume


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def write_outputs(table, scratch, row, c):
    """Write each joint's columns (``output_names``) from its last evaluation from column c.

    Returns the next free column.
    """
    n = len(OUTPUT_NAMES)
    for k in range(table.ints.shape[0]):
        row[c] = scratch.pose[k, 0]
        row[c + 1] = scratch.pose[k, 1]
        fx = 0.0
        fy = 0.0
        friction = 0.0
        damping = 0.0
        contacts = SLOTS if table.ints[k, I_ENDS] else CORNERS
        for i in range(contacts):
            contact = scratch.contact[k, i]
            f = _force_on_slider(contact)
            fx += f[0]
            fy += f[1]
            # The powers the loop integrates into its totals. The damped part's, (F_N - f_e)
            # delta_dot, also while F_N is clamped at 0 with the bodies still overlapping
            # (receding faster than the onset speed over the hysteresis factor): the elastic
            # energy released then is lost, f_e |delta_dot| (0 without overlap: f_e = F_N = 0).
            damping += (contact[C_FN] - contact[C_ELASTIC]) * contact[C_DDOT]
            if contact[C_FN] > 0.0:
                friction -= contact[C_FT] * contact[C_VT]
            row[c + n + i] = contact[C_FN]
            row[c + n + contacts + i] = contact[C_VT]
        row[c + 2] = fx
        row[c + 3] = fy
        row[c + 4] = friction
        row[c + 5] = damping
        c += n + 2 * contacts
    return c


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def elastic_energy(table, scratch):
    """Elastic energy stored in the last evaluated contacts [J]."""
    energy = 0.0
    for k in range(table.ints.shape[0]):
        p = table.params[k]
        for i in range(SLOTS):
            energy += law_energy(
                table.laws, k, table.ints[k, I_NORMAL], scratch.contact[k, i, C_DELTA], p[P_K],
                p[P_EXP], p[P_ESTAR], p[P_H], p[P_WIDTH],
            )  # fmt: skip
    return energy
