"""The pin-in-slot clearance joint (a pin in a straight slot with round ends) as a contact element.

| symbol | meaning | unit |
|---|---|---|
| C, u, v | point on the slot's centre line, unit axis, u turned +90 deg (slot body) | m, - |
| l | half the length between the end centres C +- l u (l >= 0) | m |
| R_s, R_p | slot half-width (the radius of its ends), pin radius | m |
| c | gap R_s - R_p | m |
| P | pin centre (pin body) | m |
| x, y | P along u and along v from C | m |
| Q | the point of the segment C +- l u closest to P, C + clamp(x, -l, l) u | m |
| d, n | distance abs(P - Q), unit normal (P - Q) / d | m, - |
| t | n turned +90 deg | - |
| delta, delta_dot | penetration and its rate | m, m/s |
| v_t | sliding speed of the pin's contact point past the slot's, along t | m/s |
| f_n, f_t | normal force (pushes the pin back towards Q), friction along t on the pin | N |
| phi | direction of n on an end, from its outward axis s u towards s v (s = +-1) | rad |

Geometry. The slot's wall lies at distance R_s from the segment between the end centres (a
stadium), so the pin touches it where d exceeds c:

    delta = d - (c + w_slot + w_pin),  delta_dot = n . (v_P - v_Q),
    v_t = t . (v_P - v_Q) + omega_pin R_p - omega_slot R_s,

w the wear depths of both surfaces where n meets them, v_Q the velocity of the slot body's
material point at Q. For abs(x) < l, Q = C + x u and n = +-v: the pin on a side (a circle on a
line). Otherwise Q is an end centre: the pin in an end (a circle in a circle, the revolute
clearance joint's contact with the bearing centred at Q; with l = 0 the joint is that joint
exactly). delta is continuous across abs(x) = l, and so is n. The rate is exact although Q
slides along a side with the pin: its motion there is along u, normal to n. A pin smaller
than the slot touches it at one place at most: one contact slot per joint. The pin gets
-f_n n + f_t t at P + R_p n, the slot its opposite at Q + R_s n (``journal_geometry``).
The slope of the worn profiles is neglected in delta_dot, as in the journal.

Stiffness: one K for the sides and the ends. With K_side != K_end the force would jump at
abs(x) = l by their ratio, and the contact would stop being conservative: a pin pressed
against a side and slid into an end would gain or lose (K_end / K_side - 1) times its stored
energy, and the step-size control would meet a discontinuity. The difference such a pair
stands for is itself an artefact of the point-contact formula K = 4/3 E* sqrt(R*): it gives
K_end / K_side = sqrt(R_s / c), about 10 for c = R_s / 100, whereas for a line contact
(a pin along its width) the approach depends on the radii only through a logarithm (Johnson
1985, secs. 4.2 and 5.3), so side and end differ by a factor of order one.

Wear (Archard or Reye through ``laws.wear.wear_coefficient``): a sliding contact removes
coef f_n ds, the pin taking ``P_SHARE`` of it. The volume goes as a uniform depth into one
cell of each surface, where the contact is (``laws.segments.add_wear``), so the cells add up
to the volume exactly whatever their number. Cells of ``PinSlotState.wear[k, surface]``:
the sides (``SIDE_PLUS_V``, ``SIDE_MINUS_V``): ``I_SEGMENTS`` segments along x over
[-l, l]; the ends (``END_PLUS_U``, ``END_MINUS_U``): ``I_END_SECTORS`` sectors of the half
circle, along the arc R_s phi over [-pi R_s / 2, pi R_s / 2]; the pin (``PIN``):
``I_PIN_SECTORS`` sectors of its circle in the pin body's frame, sector i covering the
directions [i, i + 1) 2 pi / N (the arc R_p (theta - pi) over [-pi R_p, pi R_p]). The depth
read back is linear between cell centres (periodic on the pin, ``laws.wear.depth_at``).
A side and the end it meets keep separate cells, so a worn gap may step where they meet.

Reference check. I. Skrinjar, J. Slavic, M. Boltezar, "A validated model for a pin-slot
clearance joint", Nonlinear Dyn. 88 (2017) 131-143: the paper's text could not be read
(only a fragment: the model is built on the revolute and the translational clearance
joints). Checked instead against the authors' open implementation (ladisk/DyS, files
``pin_slot_clearance_joint_linear.py`` and ``distance_PSCJ.py``): the same geometry (the
section chosen by the angle between P minus an end centre and the slot axis, which is
abs(x) > l; on a side, the distance from P to the side's line minus R_p; in an end, the
distance to the end centre against c). Differences: their code gives each section its own
contact law (flat and cylindrical); here one law and one K (above). It has no wear.

References
----------
K.L. Johnson, Contact Mechanics, Cambridge University Press (1985).
J.F. Archard, "Contact and rubbing of flat surfaces", J. Appl. Phys. 24 (1953) 981-988.
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from ..kinematics import point_position, rotate
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
from ..laws.wear import depth_at, hertz_line_contact
from .journal_geometry import apply_contact, contact_velocities, eccentricity, surface_angles

# Columns of PinSlotTable.ints.
I_SLOT = 0  # slot body (-1: ground)
I_PIN = 1  # pin body
I_NORMAL = 2  # elastic law code (its record: model.laws.NORMAL)
I_DAMPING = 3  # damping law code (model.laws.DAMPING)
I_FRICTION = 4  # friction law code (model.laws.FRICTION)
I_WEAR = 5  # wear law code (model.laws.WEAR)
I_FEEDBACK = 6  # 1: the worn depths feed back into the penetration
I_SEGMENTS = 7  # segments of each side
I_END_SECTORS = 8  # sectors of each end's half circle
I_PIN_SECTORS = 9  # sectors of the pin
N_INTS = 10

# Per law-code column, its family (``model.laws`` key) and the laws compiled only for the
# models that use them (``laws.lawset``): none of this kind's.
LAW_COLUMNS = {
    "normal_law": (I_NORMAL, ()),
    "damping": (I_DAMPING, ()),
    "friction_law": (I_FRICTION, ()),
    "wear_law": (I_WEAR, ()),
}

# Columns of PinSlotTable.params (SI).
P_C_X = 0  # point C on the slot's centre line, slot body's frame [m]
P_C_Y = 1
P_U_X = 2  # slot axis u, unit, slot body's frame
P_U_Y = 3
P_P_X = 4  # pin centre, pin body's frame [m]
P_P_Y = 5
P_L = 6  # half the length between the end centres [m]
P_RS = 7  # slot half-width R_s [m]
P_RP = 8  # pin radius R_p [m]
P_C = 9  # gap c = R_s - R_p [m]
P_K = 10  # elastic law's stiffness K [N/m^n], sides and ends
P_EXP = 11  # exponent n [-]
P_CE = 12  # damping law parameter: restitution coefficient [-]
P_CF = 13  # friction coefficient [-]
P_F0 = 14  # friction law parameters (laws.friction)
P_F1 = 15
P_F2 = 16
P_WEAR = 17  # wear law parameter: Archard k [1/Pa], or Reye's shear strength [Pa]
P_SHARE = 18  # pin's share of the worn volume [-]
P_WIDTH = 19  # width out of the plane [m]
P_ESTAR = 20  # contact modulus E* [Pa]
P_MIN_SPEED = 21  # floor of the impact speed [m/s]
P_TOL = 22  # contact tolerance [m]
P_DEPTH_LIMIT = 23  # the elastic law's range: penetration / c [-] (its record's)
P_PATCH_LIMIT = 24  # the Hertz patch's range: b / R_p [-]; 0: not checked
N_PARAMS = 25

# Worn surfaces, the first index of PinSlotState.wear; the slot's four are also the surface
# codes of the contact (C_SURFACE, IMPACT_SURFACE).
SIDE_PLUS_V = 0
SIDE_MINUS_V = 1
END_PLUS_U = 2
END_MINUS_U = 3
PIN = 4
SURFACES = ("side_plus_v", "side_minus_v", "end_plus_u", "end_minus_u", "pin")

# Columns of PinSlotScratch.contact[k] (the last evaluation).
C_ALONG = 0  # x: the pin centre along u from C [m]
C_ACROSS = 1  # y: the pin centre along v from C [m]
C_DELTA = 2  # penetration [m]
C_DDOT = 3  # penetration rate [m/s]
C_VT = 4  # sliding speed [m/s]
C_FN = 5  # normal force [N]
C_FT = 6  # friction force [N]
C_ELASTIC = 7  # undamped (elastic) part of the normal force [N]
C_NX = 8  # normal n, global
C_NY = 9
C_FX = 10  # contact force on the pin, global [N]
C_FY = 11
C_SURFACE = 12  # surface touched: SIDE_PLUS_V .. END_MINUS_U
C_WHERE = 13  # x on a side [m], phi on an end [rad]
C_Q = 14  # clamp(x, -l, l): Q along u from C [m]
C_THETA_PIN = 15  # direction of n in the pin's frame, [0, 2 pi) [rad]
N_CONTACT = 16

# Columns of PinSlotLog.totals: 0-7 as in every kind.
T_CONTACT_TIME = 0  # time with a positive normal force [s]
T_MAX_FN = 1  # largest normal force [N]
T_MAX_DELTA = 2  # largest penetration [m]
T_IMPACTS = 3  # contact periods begun
T_DAMPING_ENERGY = 4  # energy dissipated by the damping, (f_n - f_e) delta_dot [J]
T_FRICTION_ENERGY = 5  # energy dissipated by friction [J]
T_WORN_VOLUME = 6  # volume removed from the slot and the pin [m^3]
T_SLIDING = 7  # sliding distance while in contact and sliding [m]
T_PATCH_TIME = 8  # time the Hertz half-width exceeded P_PATCH_LIMIT R_p [s]
T_PATCH_MAX = 9  # largest Hertz half-width / R_p [-]
T_DEPTH_TIME = 10  # time the penetration exceeded P_DEPTH_LIMIT c [s]
T_DEPTH_MAX = 11  # largest penetration / c [-]
N_TOTALS = 12

# Columns of an onset's entry in the impact log.
IMPACT_SPEED = 0  # penetration rate at onset [m/s]
IMPACT_SURFACE = 1  # surface touched (SIDE_PLUS_V .. END_MINUS_U)
IMPACT_WHERE = 2  # x on a side [m], phi on an end [rad]
IMPACT_DELTA = 3  # penetration where the onset was located [m]
N_IMPACT_INFO = 4

# Time-series columns per joint (without the joint's name), in write_outputs' order.
OUTPUT_NAMES = (
    "along", "across", "fx", "fy", "fn", "vt", "friction_power", "damping_power",
)  # fmt: skip
DEGREES_OF_FREEDOM = 1  # the pin centre across the slot (the ideal joint frees it along)
SLOTS = 1  # contact slots per joint


class PinSlotTable(NamedTuple):
    """The pin-in-slot clearance joints of a mechanism (fixed for a run)."""

    ints: np.ndarray  # (np, N_INTS) int64
    params: np.ndarray  # (np, N_PARAMS)
    laws: KindLaws  # the rows' laws: the codes compiled, and those registered from Python


class PinSlotState(NamedTuple):
    """What a restart needs: contact periods and worn surfaces."""

    contact_on: np.ndarray  # (np,) int64, 1 while a contact period lasts
    impact_speed: np.ndarray  # (np,) penetration rate at the period's onset [m/s]
    wear: np.ndarray  # (np, 5, max cells) wear depth of each of SURFACES [m]


class PinSlotLog(NamedTuple):
    """What a run accumulates: totals and wear snapshots."""

    totals: np.ndarray  # (np, N_TOTALS)
    snapshots: np.ndarray  # (snapshots, np, 5, max cells) [m]


class PinSlotScratch(NamedTuple):
    """The last evaluation of each joint."""

    contact: np.ndarray  # (np, N_CONTACT)


def make_tables(
    ints: np.ndarray,
    params: np.ndarray,
    snapshots: int,
    user: UserLaws | None = None,
) -> tuple[PinSlotTable, PinSlotState, PinSlotLog, PinSlotScratch]:
    """Allocate a run's arrays for the joints of ``ints`` and ``params``, unworn (Python).

    ``user``: the rows' user laws (``laws.user``); None: no row has one.
    """
    n = ints.shape[0]
    ints = ints.astype(np.int64).reshape(n, N_INTS)
    counts = ints[:, [I_SEGMENTS, I_END_SECTORS, I_PIN_SECTORS]]
    cells = int(counts.max(initial=1))
    surfaces = len(SURFACES)
    return (
        PinSlotTable(
            ints=ints,
            params=params.astype(np.float64).reshape(n, N_PARAMS),
            laws=kind_laws(ints, LAW_COLUMNS, user),
        ),
        PinSlotState(
            contact_on=np.zeros(n, dtype=np.int64),
            impact_speed=np.zeros(n),
            wear=np.zeros((n, surfaces, cells)),
        ),
        PinSlotLog(
            totals=np.zeros((n, N_TOTALS)), snapshots=np.zeros((snapshots, n, surfaces, cells))
        ),
        PinSlotScratch(contact=np.zeros((n, N_CONTACT))),
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _cells(law, surface):
    """Number of wear cells of a surface."""
    if surface <= SIDE_MINUS_V:
        return law[I_SEGMENTS]
    if surface == PIN:
        return law[I_PIN_SECTORS]
    return law[I_END_SECTORS]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _length(p, surface):
    """Length of a surface along its cells [m]."""
    if surface <= SIDE_MINUS_V:
        return 2.0 * p[P_L]
    if surface == PIN:
        return 2.0 * math.pi * p[P_RP]
    return math.pi * p[P_RS]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _position(p, surface, where):
    """Position along a surface's cells from its middle [m] of x, phi or theta (``where``)."""
    if surface <= SIDE_MINUS_V:
        return where
    if surface == PIN:
        return p[P_RP] * (where - math.pi)
    return p[P_RS] * where


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _depth(state, law, p, k, surface, where):
    """Wear depth of a surface at x, phi or theta (``where``) [m]; 0 without feedback."""
    if not law[I_FEEDBACK]:
        return 0.0
    cells = state.wear[k, surface, : _cells(law, surface)]
    if surface == PIN:
        return depth_at(where, cells)
    return depth_along(_position(p, surface, where), cells, _length(p, surface))


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def evaluate(table, state, scratch, k, q, qd):
    """Geometry and forces of joint k at state (q, q'), into scratch.contact[k]."""
    law = table.ints[k]
    p = table.params[k]
    out = scratch.contact[k]
    for i in range(N_CONTACT):
        out[i] = 0.0
    i_slot, i_pin = law[I_SLOT], law[I_PIN]
    cx, cy = point_position(q, i_slot, p[P_C_X], p[P_C_Y])
    ux, uy = rotate(q, i_slot, p[P_U_X], p[P_U_Y])
    px, py = point_position(q, i_pin, p[P_P_X], p[P_P_Y])
    x = ux * (px - cx) + uy * (py - cy)
    y = -uy * (px - cx) + ux * (py - cy)
    side = abs(x) < p[P_L]
    if side:  # s: the side's or the end's sign; (ax, ay) its outward direction
        s = 1.0 if y >= 0.0 else -1.0
        along, surface, ax, ay = x, SIDE_PLUS_V if s > 0.0 else SIDE_MINUS_V, -s * uy, s * ux
    else:
        s = 1.0 if x >= 0.0 else -1.0
        along, surface, ax, ay = s * p[P_L], END_PLUS_U if s > 0.0 else END_MINUS_U, s * ux, s * uy
    qx, qy = p[P_C_X] + along * p[P_U_X], p[P_C_Y] + along * p[P_U_Y]
    ex, ey, dex, dey = eccentricity(q, qd, i_slot, qx, qy, i_pin, p[P_P_X], p[P_P_Y])
    d = math.hypot(ex, ey)
    nx, ny = (ex / d, ey / d) if d > 0.0 else (ax, ay)
    # phi on an end: n from the outward axis s u towards s v; x on a side
    where = x if side else math.atan2(s * (ux * ny - uy * nx), s * (ux * nx + uy * ny))
    _, theta_pin = surface_angles(q, i_slot, i_pin, nx, ny)
    wear = _depth(state, law, p, k, surface, where) + _depth(state, law, p, k, PIN, theta_pin)
    delta = d - (p[P_C] + wear)
    delta_dot, v_t = contact_velocities(qd, i_slot, i_pin, nx, ny, dex, dey, p[P_RS], p[P_RP])
    out[C_ALONG], out[C_ACROSS] = x, y
    out[C_DELTA], out[C_DDOT], out[C_VT] = delta, delta_dot, v_t
    out[C_NX], out[C_NY] = nx, ny
    out[C_SURFACE], out[C_WHERE], out[C_Q], out[C_THETA_PIN] = surface, where, along, theta_pin
    if delta <= 0.0:
        return
    impact_speed = max(delta_dot, p[P_MIN_SPEED])  # until the loop records the onset
    if state.contact_on[k]:
        impact_speed = state.impact_speed[k]
    elastic = elastic_force(
        table.laws, k, law[I_NORMAL], delta, p[P_K], p[P_EXP], p[P_ESTAR], p[P_C], p[P_WIDTH]
    )
    f_n = damped(table.laws, k, elastic, delta_dot, impact_speed, law[I_DAMPING], p[P_CE])
    f_t = tangential_force(
        table.laws, k, law[I_FRICTION], v_t, f_n, p[P_CF], p[P_F0], p[P_F1], p[P_F2]
    )
    out[C_FN], out[C_FT], out[C_ELASTIC] = f_n, f_t, elastic
    out[C_FX] = -f_n * nx - f_t * ny
    out[C_FY] = -f_n * ny + f_t * nx


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def add_forces(table, state, scratch, q, qd, g):
    """Evaluate every joint and add its contact forces on pin and slot to g [N, N, N m]."""
    for k in range(table.ints.shape[0]):
        evaluate(table, state, scratch, k, q, qd)
        c = scratch.contact[k]
        if c[C_FN] == 0.0 and c[C_FT] == 0.0:
            continue
        p = table.params[k]
        apply_contact(
            q, g,
            table.ints[k, I_SLOT], p[P_C_X] + c[C_Q] * p[P_U_X], p[P_C_Y] + c[C_Q] * p[P_U_Y],
            table.ints[k, I_PIN], p[P_P_X], p[P_P_Y],
            c[C_NX], c[C_NY], p[P_RS], p[P_RP], c[C_FN], c[C_FT],
        )  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def penetration_excess(table, state, scratch, k, q, qd):
    """Penetration of joint k (its one slot) beyond its contact tolerance at (q, q') [m]."""
    evaluate(table, state, scratch, k, q, qd)
    return scratch.contact[k, C_DELTA] - table.params[k, P_TOL]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def tolerance(table, k):
    """Contact tolerance of joint k [m]: a period begins past it."""
    return table.params[k, P_TOL]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _track_peaks(totals, c):
    totals[T_MAX_FN] = max(totals[T_MAX_FN], c[C_FN])
    totals[T_MAX_DELTA] = max(totals[T_MAX_DELTA], c[C_DELTA])


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def begin_period(table, state, scratch, log, k, q, qd, info):
    """Open or close joint k's contact period at a step end; True when one opens.

    An opening period records its impact speed and fills ``info`` (``IMPACT_*``). Also keeps
    the largest normal force and penetration seen at step ends.
    """
    excess = penetration_excess(table, state, scratch, k, q, qd)
    c = scratch.contact[k]
    _track_peaks(log.totals[k], c)
    if state.contact_on[k]:
        if excess + table.params[k, P_TOL] <= 0.0:
            state.contact_on[k] = 0
        return False
    if excess <= 0.0:
        return False
    state.contact_on[k] = 1
    state.impact_speed[k] = max(c[C_DDOT], table.params[k, P_MIN_SPEED])
    log.totals[k, T_IMPACTS] += 1.0
    info[IMPACT_SPEED] = c[C_DDOT]
    info[IMPACT_SURFACE] = c[C_SURFACE]
    info[IMPACT_WHERE] = c[C_WHERE]
    info[IMPACT_DELTA] = c[C_DELTA]
    return True


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wear(table, state, scratch, k, ds):
    """Remove the wear of sliding distance ds [m] under joint k's last evaluation [m^3]."""
    c = scratch.contact[k]
    law = table.ints[k]
    p = table.params[k]
    coef = wear_coefficient(table.laws, k, law[I_WEAR], abs(c[C_FT]) / c[C_FN], p[P_WEAR])
    volume = coef * c[C_FN] * ds
    share = p[P_SHARE]
    slot = int(c[C_SURFACE])
    add_wear(
        state.wear[k, slot, : _cells(law, slot)], _position(p, slot, c[C_WHERE]),
        _length(p, slot), p[P_WIDTH], (1.0 - share) * volume,
    )  # fmt: skip
    add_wear(
        state.wear[k, PIN, : _cells(law, PIN)], _position(p, PIN, c[C_THETA_PIN]),
        _length(p, PIN), p[P_WIDTH], share * volume,
    )  # fmt: skip
    return volume


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _track_ranges(law, p, c, totals, h):
    """Time and extent of the step [s] beyond the laws' ranges, into totals (T_*_TIME, _MAX).

    The Hertz half-width of a pin on a side (R* = R_p) or in an end (R* = R_s R_p / c),
    against R_p; the penetration against c.
    """
    if c[C_FN] <= 0.0:
        return
    on_side = c[C_SURFACE] <= SIDE_MINUS_V
    r_star = p[P_RP] if on_side else p[P_RS] * p[P_RP] / p[P_C]  # R_s R_p / c in an end
    b, _ = hertz_line_contact(c[C_FN], r_star, p[P_ESTAR], p[P_WIDTH])
    ranges = (
        (T_PATCH_TIME, T_PATCH_MAX, b / p[P_RP], p[P_PATCH_LIMIT]),
        (T_DEPTH_TIME, T_DEPTH_MAX, c[C_DELTA] / p[P_C], p[P_DEPTH_LIMIT]),
    )
    for time_slot, max_slot, ratio, limit in ranges:
        totals[max_slot] = max(totals[max_slot], ratio)
        if limit > 0.0 and ratio > limit:
            totals[time_slot] += h


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def accumulate(table, state, scratch, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear and totals of the step [t_old, t_new] [s] from its midpoint state.

    The damping energy counts wherever the surfaces overlap, also while the normal force is
    clamped at zero (then f_n - f_e = -f_e). The wear snapshots due in the step
    (``snap_times[first:]`` up to t_new) are taken with the step's wear split at them.
    """
    h = t_new - t_old
    for k in range(table.ints.shape[0]):
        evaluate(table, state, scratch, k, q_mid, qd_mid)
        c = scratch.contact[k]
        p = table.params[k]
        totals = log.totals[k]
        totals[T_DAMPING_ENERGY] += (c[C_FN] - c[C_ELASTIC]) * c[C_DDOT] * h
        sliding_speed = 0.0  # of a contact that wears
        if c[C_FN] > 0.0:
            totals[T_CONTACT_TIME] += h
            _track_peaks(totals, c)
            totals[T_FRICTION_ENERGY] -= c[C_FT] * c[C_VT] * h
            sliding_speed = slip_speed(
                table.laws, k, table.ints[k, I_FRICTION], c[C_VT], p[P_F0], p[P_F1], p[P_F2]
            )
            totals[T_SLIDING] += sliding_speed * h
        _track_ranges(table.ints[k], p, c, totals, h)
        t_from = t_old
        s = first
        while s < snap_times.shape[0] and snap_times[s] <= t_new:  # split the wear there
            t_snap = max(snap_times[s], t_from)
            if sliding_speed > 0.0:
                totals[T_WORN_VOLUME] += _wear(
                    table, state, scratch, k, sliding_speed * (t_snap - t_from)
                )
            log.snapshots[s, k] = state.wear[k]
            t_from = t_snap
            s += 1
        if sliding_speed > 0.0:
            totals[T_WORN_VOLUME] += _wear(
                table, state, scratch, k, sliding_speed * (t_new - t_from)
            )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def write_outputs(table, scratch, row, c):
    """Write each joint's ``OUTPUT_NAMES`` columns from its last evaluation from column c.

    The powers are those ``accumulate`` integrates: friction -f_t v_t, damping
    (f_n - f_e) delta_dot. Returns the next free column.
    """
    for k in range(table.ints.shape[0]):
        e = scratch.contact[k]
        row[c] = e[C_ALONG]
        row[c + 1] = e[C_ACROSS]
        row[c + 2] = e[C_FX]
        row[c + 3] = e[C_FY]
        row[c + 4] = e[C_FN]
        row[c + 5] = e[C_VT]
        row[c + 6] = -e[C_FT] * e[C_VT]
        row[c + 7] = (e[C_FN] - e[C_ELASTIC]) * e[C_DDOT]
        c += len(OUTPUT_NAMES)
    return c


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def elastic_energy(table, scratch):
    """Elastic energy stored in the last evaluated contacts [J]."""
    energy = 0.0
    for k in range(table.ints.shape[0]):
        p = table.params[k]
        energy += law_energy(
            table.laws, k, table.ints[k, I_NORMAL], scratch.contact[k, C_DELTA], p[P_K],
            p[P_EXP], p[P_ESTAR], p[P_C], p[P_WIDTH],
        )  # fmt: skip
    return energy
