"""The revolute clearance joint (a journal in a bearing) as a contact element.

Table (``JournalTable``, one row per joint, SI): bodies and laws in ``ints`` (``I_*``),
centres and parameters in ``params`` (``P_*``). Restart state (``JournalState``): whether a
contact period is under way, its impact speed, and both surfaces' worn profiles. Logs
(``JournalLog``): per-joint totals (``T_*``) and the wear snapshots. Scratch
(``JournalScratch``): the last evaluation of each joint (``C_*``).

Penetration (paper Eq. 15, SPEC secs. 3-4): delta = abs(e) - (c + w_B(theta_B) + w_J(theta_J)),
the wear depths w read from the sector profiles in each body's frame (``wear.depth_at``). The
force law is applied for any delta > 0, so the force is continuous; the contact tolerance only
decides when a contact period begins. A mixed film (a roughness) adds the asperities' load to
the normal force from four roughnesses before the surfaces touch (``_film``). Until the loop
has recorded the onset of a period, the damping uses the current penetration rate as the
impact speed, floored at ``min_impact_speed``.
The rate of penetration is n . de/dt: the slope of the worn profile (wear depths of the order
of 1e-8 m against a clearance of 1e-4 m) is neglected in it.

Wear (SPEC sec. 4, paper Eq. 14): ``accumulate`` adds the wear of an accepted step to both
surfaces' sectors from the contact at the step's midpoint times its length (midpoint rule),
and none while the contact sticks. Reye's law uses the effective friction coefficient
abs(f_t) / f_n, so that the worn volume follows the friction energy dissipated (paper Eq. 8).
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from ..kinematics import angular_velocity
from ..laws.asperity import asperity_energy, asperity_load, film_eccentricity
from ..laws.dispatch import if_used
from ..laws.foundation import foundation_load, foundation_points, spread_foundation_wear
from ..laws.lubrication import couette_torque, film_power_loss, film_torques
from ..laws.lubrication import film_force_components as films
from ..laws.normal import ElasticLaw
from ..laws.user import (
    KindLaws,
    UserLaws,
    damped,
    elastic_force,
    film_force_components,
    kind_laws,
    slip_speed,
    tangential_force,
    wear_coefficient,
)
from ..laws.user import elastic_energy as law_energy
from ..laws.wear import accumulate_wear, depth_at, hertz_line_contact
from .journal_geometry import (
    apply_at_centres,
    apply_contact,
    contact_velocities,
    eccentricity,
    surface_angles,
)
from .point_loads import apply_torque

# Columns of JournalTable.ints.
I_BEARING = 0  # bearing body (-1: ground)
I_JOURNAL = 1  # journal body
I_NORMAL = 2  # elastic law code (its record: model.laws.NORMAL)
I_FRICTION = 3  # friction law code (model.laws.FRICTION)
I_WEAR = 4  # wear law code (model.laws.WEAR)
I_SPREAD = 5  # wear distribution: SPREAD_HERTZ, SPREAD_PEAK or SPREAD_FOUNDATION
I_FEEDBACK = 6  # 1: the worn profile feeds back into the penetration
I_SECTORS = 7  # sectors of each surface
I_DAMPING = 8  # damping law code (model.laws.DAMPING)
I_LUBRICATION = 9  # lubrication code (model.laws.LUBRICATION), 0: dry
N_INTS = 10

# Wear distributions (I_SPREAD): Hertz's ellipse over the sectors it covers, its peak into
# one sector (the paper's), or the elastic foundation's pressure on the worn surfaces.
SPREAD_HERTZ = 0
SPREAD_PEAK = 1
SPREAD_FOUNDATION = 2

# Per law-code column, its family (``model.laws`` key) and the laws compiled only for the
# models that use them (``laws.lawset``): the films and the elastic foundation.
LAW_COLUMNS = {
    "normal_law": (I_NORMAL, (ElasticLaw.ELASTIC_FOUNDATION,)),
    "damping": (I_DAMPING, ()),
    "friction_law": (I_FRICTION, ()),
    "wear_law": (I_WEAR, ()),
    "wear_distribution": (I_SPREAD, (SPREAD_FOUNDATION,)),
    "lubrication": (I_LUBRICATION, tuple(films.laws)),
}

# Columns of JournalTable.params (SI).
P_SB_X = 0  # bearing centre in the bearing body's frame [m]
P_SB_Y = 1
P_SJ_X = 2  # journal centre in the journal body's frame [m]
P_SJ_Y = 3
P_RB = 4  # bearing radius [m]
P_RJ = 5  # journal radius [m]
P_C = 6  # radial clearance [m]
P_K = 7  # elastic law's stiffness: K [N/m^n] (hertz), (K_f / h) R [Pa] (elastic foundation)
P_EXP = 8  # exponent n [-] (hertz)
P_CE = 9  # damping law parameter: restitution coefficient [-]
P_CF = 10  # friction coefficient [-]
P_F0 = 11  # friction law parameters p0, p1, p2 (laws.friction)
P_F1 = 12
P_F2 = 13
P_WEAR = 14  # wear law parameter: Archard k [1/Pa], or Reye's shear strength [Pa]
P_SHARE = 15  # journal's share of the worn volume [-]
P_WIDTH = 16  # joint width [m]
P_RSTAR = 17  # relative radius R* [m]
P_ESTAR = 18  # contact modulus E* [Pa]
P_MIN_SPEED = 19  # floor of the impact speed [m/s]
P_TOL = 20  # contact tolerance [m]
P_VISCOSITY = 21  # lubricant's dynamic viscosity [Pa s]
P_BREAKDOWN = 22  # eccentricity ratio where the film hands over to solid contact [-]
P_DEPTH_LIMIT = 23  # the elastic law's range: penetration / c [-] (its record's)
P_PATCH_LIMIT = 24  # the Hertz patch's range: b / R_J [-]; 0: no law here uses the patch
P_ROUGHNESS = 25  # combined RMS roughness sigma [m]; 0: no asperity contact (film_breakdown)
P_ASPERITY = 26  # Greenwood-Tripp pressure scale K E' [Pa]
N_PARAMS = 27

# Columns of JournalScratch.contact (the last evaluation).
C_EX = 0  # eccentricity [m]
C_EY = 1
C_DELTA = 2  # penetration [m]
C_DDOT = 3  # penetration rate [m/s]
C_VT = 4  # sliding speed [m/s]
C_FN = 5  # normal force [N]
C_FT = 6  # friction force [N]
C_THETA_B = 7  # direction of n in the bearing's frame [rad]
C_THETA_J = 8  # direction of n in the journal's frame [rad]
C_ELASTIC = 9  # undamped (elastic) part of the normal force [N]
C_FX = 10  # contact force on the journal, global [N]
C_FY = 11
C_EPS = 12  # eccentricity ratio e / c_local [-]
C_FILM_MIN = 13  # minimum film thickness c_local - e, 0 in solid contact [m]
C_FILM_X = 14  # film force on the journal, global [N]
C_FILM_Y = 15
C_FILM_POWER = 16  # power dissipated in the film [W]
C_FILM_TJ = 17  # film's shear torque on the journal [N m]
C_FILM_TB = 18  # film's shear torque on the bearing [N m]
C_ASPERITY = 19  # load the asperities carry (in C_FN) [N]
C_SQUEEZE_X = 20  # squeeze velocity V = de/dt - (w / 2) z x e, global [m/s]
C_SQUEEZE_Y = 21
N_CONTACT = 22
OUTPUTS = (
    C_FX,
    C_FY,
    C_EX,
    C_EY,
    C_DELTA,
    C_FN,
    C_FT,
    C_VT,
    C_THETA_B,
    C_THETA_J,
    C_DDOT,
    C_ELASTIC,
)
OUTPUT_NAMES = (
    *("fx", "fy", "ex", "ey", "delta", "fn", "ft", "vt", "theta_bearing", "theta_journal"),
    *("delta_dot", "fn_elastic"),
)  # the time-series columns of OUTPUTS, in order
FILM_OUTPUTS = (
    *(C_EPS, C_FILM_MIN, C_FILM_X, C_FILM_Y, C_FILM_TJ, C_FILM_POWER),
    *(C_ASPERITY, C_SQUEEZE_X, C_SQUEEZE_Y),
)  # lubricated
FILM_OUTPUT_NAMES = (
    *("eps", "film_min", "film_fx", "film_fy", "film_torque", "film_power"),
    *("asperity_fn", "squeeze_vx", "squeeze_vy"),
)

# Columns of JournalLog.totals.
T_CONTACT_TIME = 0  # time with a positive normal force [s]
T_MAX_FN = 1  # largest normal force [N]
T_MAX_DELTA = 2  # largest penetration [m]
T_IMPACTS = 3  # contact periods begun (free flight to contact)
T_DAMPING_ENERGY = 4  # energy dissipated by the damping of the normal force [J]
T_FRICTION_ENERGY = 5  # energy dissipated by friction [J]
T_WORN_VOLUME = 6  # volume removed from both surfaces [m^3]
T_SLIDING = 7  # sliding distance while in contact and sliding [m]
T_FILM_ENERGY = 8  # energy dissipated in the lubricant film [J]
T_PATCH_TIME = 9  # time the Hertz half-width exceeded P_PATCH_LIMIT R_J [s]
T_PATCH_MAX = 10  # largest Hertz half-width / R_J [-]
T_DEPTH_TIME = 11  # time the penetration exceeded the law's range [s]
T_DEPTH_MAX = 12  # largest penetration / c [-]
T_FILM_TIME = 13  # time the eccentricity ratio exceeded the film's range [s]
T_FILM_MAX = 14  # largest eccentricity ratio [-]
T_SOLID_IMPULSE = 15  # integral of the solid (asperity and bulk) normal force [N s]
T_FILM_IMPULSE = 16  # integral of the film force's magnitude [N s]
T_LOAD_SLIDING = 17  # integral of the whole load x R_J |w_rel| [N m]
T_SPIN = 18  # integral of |w_rel|, the relative angle turned [rad]
T_FILM_FRICTION = 19  # the film's friction: its dissipation less the radial squeeze's [J]
T_FILM_CLOSURE = 20  # largest c - h, nominal clearance less the film's thickness [m]
N_TOTALS = 21

# Columns of an onset's entry in the impact log.
IMPACT_SPEED = 0  # penetration rate at onset [m/s]
IMPACT_THETA_B = 1  # contact angle in the bearing's frame [rad]
IMPACT_THETA_J = 2  # contact angle in the journal's frame [rad]
IMPACT_DELTA = 3  # penetration where the onset was located [m]
N_IMPACT_INFO = 4

DEGREES_OF_FREEDOM = 2  # a clearance joint frees the two components of the eccentricity
SLOTS = 1  # contact slots per joint: the journal touches its bearing at one place


class JournalTable(NamedTuple):
    """The clearance joints of a mechanism (fixed for a run)."""

    ints: np.ndarray  # (nc, N_INTS) int64
    params: np.ndarray  # (nc, N_PARAMS)
    lookups: np.ndarray  # (nc, size): each row's finite-bearing impedance table (film.impedance)
    laws: KindLaws  # the rows' laws: the codes compiled, and those registered from Python


class JournalState(NamedTuple):
    """What a restart needs: contact periods and worn profiles."""

    contact_on: np.ndarray  # (nc,) int64, 1 while a contact period lasts
    impact_speed: np.ndarray  # (nc,) penetration rate at the period's onset [m/s]
    wear: np.ndarray  # (nc, 2, max sectors) wear depth of bearing (0), journal (1) [m]


class JournalLog(NamedTuple):
    """What a run accumulates: totals and wear snapshots."""

    totals: np.ndarray  # (nc, N_TOTALS)
    snapshots: np.ndarray  # (snapshots, nc, 2, max sectors) wear at the snapshot times [m]


class JournalScratch(NamedTuple):
    """The last evaluation of each joint."""

    contact: np.ndarray  # (nc, N_CONTACT)


def make_tables(
    ints: np.ndarray,
    params: np.ndarray,
    snapshots: int,
    user: UserLaws | None = None,
    lookups: np.ndarray | None = None,
) -> tuple[JournalTable, JournalState, JournalLog, JournalScratch]:
    """Allocate a run's arrays for the joints of ``ints`` and ``params``, unworn (Python).

    ``user``: the rows' user laws (``laws.user``); None: no row has one. ``lookups``: each
    row's impedance table, flat (``film.impedance``); None: no row has a finite bearing.
    """
    nc = ints.shape[0]
    lookups = np.zeros((nc, 0)) if lookups is None else lookups
    sectors = int(ints[:, I_SECTORS].max(initial=1))
    return (
        JournalTable(
            ints=ints.astype(np.int64),
            params=params.astype(np.float64),
            lookups=np.ascontiguousarray(lookups, dtype=np.float64),
            laws=kind_laws(ints, LAW_COLUMNS, user),
        ),
        JournalState(
            contact_on=np.zeros(nc, dtype=np.int64),
            impact_speed=np.zeros(nc),
            wear=np.zeros((nc, 2, sectors)),
        ),
        JournalLog(
            totals=np.zeros((nc, N_TOTALS)), snapshots=np.zeros((snapshots, nc, 2, sectors))
        ),
        JournalScratch(contact=np.zeros((nc, N_CONTACT))),
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _profiles(law, state, k):
    """Joint k's worn profiles (bearing, journal) [m]; empty without wear feedback."""
    sectors = law[I_SECTORS] if law[I_FEEDBACK] else 0
    return state.wear[k, 0, :sectors], state.wear[k, 1, :sectors]


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _depth(theta, depths):
    """Wear depth of a profile in direction theta [rad]; 0 for an empty profile [m]."""
    if depths.shape[0] == 0:
        return 0.0
    return depth_at(theta, depths)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def evaluate(table, state, scratch, k, q, qd):
    """Geometry and forces of joint k at state (q, q'), into scratch.contact[k]."""
    law = table.ints[k]
    p = table.params[k]
    out = scratch.contact[k]
    for i in range(N_CONTACT):
        out[i] = 0.0
    ib = law[I_BEARING]
    ij = law[I_JOURNAL]
    ex, ey, dex, dey = eccentricity(q, qd, ib, p[P_SB_X], p[P_SB_Y], ij, p[P_SJ_X], p[P_SJ_Y])
    out[C_EX] = ex
    out[C_EY] = ey
    e = math.hypot(ex, ey)
    nx, ny = _line_of_centres(ex, ey, dex, dey)
    theta_b, theta_j = surface_angles(q, ib, ij, nx, ny)
    wear_b, wear_j = _profiles(law, state, k)
    gap = p[P_C] + _depth(theta_b, wear_b) + _depth(theta_j, wear_j)
    delta = e - gap
    elastic = 0.0
    foundation = law[I_NORMAL] == ElasticLaw.ELASTIC_FOUNDATION
    if foundation and e > p[P_C]:  # the worn surfaces touch where they interfere most
        elastic, delta = _on_foundation(table, k, e, delta, theta_b, wear_b, theta_j, wear_j)
    delta_dot, v_t = contact_velocities(qd, ib, ij, nx, ny, dex, dey, p[P_RB], p[P_RJ])
    out[C_DELTA] = delta
    out[C_DDOT] = delta_dot
    out[C_VT] = v_t
    out[C_THETA_B] = theta_b
    out[C_THETA_J] = theta_j
    if law[I_LUBRICATION]:
        w_j, w_b = angular_velocity(qd, ij), angular_velocity(qd, ib)
        gamma_dot = (nx * dey - ny * dex) / e if e > 0.0 else 0.0
        out[C_SQUEEZE_X] = dex + 0.5 * (w_j + w_b) * ey
        out[C_SQUEEZE_Y] = dey - 0.5 * (w_j + w_b) * ex
        speeds = (delta_dot, gamma_dot, w_j + w_b, w_j - w_b)
        _film_if_used(table, k, out, e, gap, delta, nx, ny, *speeds)
    asperity = out[C_ASPERITY]  # > 0 only in a mixed film: the asperities touch
    if delta <= 0.0 and asperity == 0.0:
        return
    f_n = asperity
    if delta > 0.0:
        impact_speed = max(delta_dot, p[P_MIN_SPEED])  # until the loop records the onset
        if state.contact_on[k]:
            impact_speed = state.impact_speed[k]
        if not foundation:
            elastic = elastic_force(
                table.laws, k, law[I_NORMAL], delta, p[P_K], p[P_EXP], p[P_ESTAR], p[P_C],
                p[P_WIDTH],
            )  # fmt: skip
        f_n += damped(table.laws, k, elastic, delta_dot, impact_speed, law[I_DAMPING], p[P_CE])
    f_t = tangential_force(
        table.laws, k, law[I_FRICTION], v_t, f_n, p[P_CF], p[P_F0], p[P_F1], p[P_F2]
    )
    out[C_FN] = f_n
    out[C_FT] = f_t
    out[C_ELASTIC] = elastic + asperity
    out[C_FX] = -f_n * nx - f_t * ny
    out[C_FY] = -f_n * ny + f_t * nx


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _foundation(table, k, e, delta, theta_b, wear_b, theta_j, wear_j):
    """(elastic force [N], penetration [m]) of joint k on its elastic foundation, worn.

    The worn surfaces touch where they interfere most: the penetration is the larger of the
    nominal one ``delta`` and that peak.
    """
    p = table.params[k]
    elastic, _, peak = foundation_load(
        e, p[P_C], theta_b, wear_b, theta_j, wear_j, p[P_RB], p[P_WIDTH],
        p[P_K] / p[P_RB], foundation_points(0.5 * math.pi, table.ints[k, I_SECTORS]),
    )  # fmt: skip
    return elastic, max(delta, peak)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_foundation(table, k, e, delta, theta_b, wear_b, theta_j, wear_j):
    return 0.0, delta


def _on_foundation(table, k, e, delta, theta_b, wear_b, theta_j, wear_j):
    """``_foundation`` where a row's normal law is the elastic foundation (compiled only then)."""


if_used(_on_foundation, "normal_law", (ElasticLaw.ELASTIC_FOUNDATION,), _foundation,
        _no_foundation)  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _line_of_centres(ex, ey, dex, dey):
    """Unit vector from the bearing's centre to the journal's [-].

    A journal exactly at the centre leaves along its velocity (e', [m/s]), or along +x at rest.
    """
    e = math.hypot(ex, ey)
    if e > 0.0:
        return ex / e, ey / e
    speed = math.hypot(dex, dey)
    if speed > 0.0:
        return dex / speed, dey / speed
    return 1.0, 0.0


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _film(table, k, out, e, gap, delta, nx, ny, delta_dot, gamma_dot, w, w_rel):
    """Film force, shear torques and power of a lubricated joint k into out (C_EPS, C_FILM_*).

    e, gap [m]: eccentricity and local clearance; (nx, ny): line of centres; delta_dot [m/s]:
    its rate of approach; w, w_rel [rad/s]: sum and difference of the journal's and bearing's
    angular speeds.

    Mixed (a roughness sigma > 0): the asperities carry ``asperity_load`` (into C_ASPERITY)
    where the gap h = -delta closes below 4 sigma, and the film sees the rough surfaces' mean
    gap (``mean_gap``), which stays positive, so film and asperities share the load and no
    setting decides the hand-over. Where the mean planes overlap (h < 0) the bulk contact
    law takes the further load (``evaluate``), and the asperities' load and the film's mean
    gap keep their values at h = 0 (docs/theory.md, section 6).

    Without roughness (the short and long bearings): up to the eccentricity ratio eps_b
    (``P_BREAKDOWN``) the film carries the journal alone. Beyond it the film is that at eps_b
    with the current rates (the formulas grow without bound towards eps = 1), and once the
    surfaces touch it fades out as the penetration grows from 0 to (1 - eps_b) c, by the
    smooth step 1 - 3 x^2 + 2 x^3, while the solid contact takes over: the force is
    continuous throughout, and the surfaces wear only while they touch.
    """
    law = table.ints[k]
    p = table.params[k]
    out[C_EPS] = e / gap
    out[C_FILM_MIN] = max(0.0, -delta)
    roughness = p[P_ROUGHNESS]
    weight = 1.0
    if roughness > 0.0:
        apart = max(-delta, 0.0)  # the mean planes' gap; the bulk law takes any overlap
        out[C_ASPERITY] = asperity_load(apart, roughness, p[P_ASPERITY], p[P_RSTAR], p[P_WIDTH])
        eps = film_eccentricity(delta, gap, roughness)
    else:
        breakdown = p[P_BREAKDOWN]
        if delta > 0.0:
            x = min(1.0, delta / ((1.0 - breakdown) * gap))
            weight = 1.0 - x * x * (3.0 - 2.0 * x)
        if weight == 0.0:
            return
        eps = min(e / gap, breakdown)
    args = (eps, delta_dot / gap, gamma_dot, w)
    fluid = (p[P_VISCOSITY], p[P_RJ], p[P_WIDTH], gap)
    code = law[I_LUBRICATION]
    f_r, f_t = film_force_components(table.laws, k, code, table.lookups[k], *args, *fluid)
    out[C_FILM_X] = weight * (f_r * nx - f_t * ny)
    out[C_FILM_Y] = weight * (f_r * ny + f_t * nx)
    couette = couette_torque(eps, w_rel, *fluid)
    motion = (e / gap, delta_dot / gap, gamma_dot, w, w_rel, gap)  # the journal's own
    out[C_FILM_POWER] = weight * film_power_loss(f_r, f_t, couette, *motion)
    t_journal, t_bearing = film_torques(f_t, couette, e)
    out[C_FILM_TJ] = weight * t_journal
    out[C_FILM_TB] = weight * t_bearing


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_film(table, k, out, e, gap, delta, nx, ny, delta_dot, gamma_dot, w, w_rel):
    return None


def _film_if_used(table, k, out, e, gap, delta, nx, ny, delta_dot, gamma_dot, w, w_rel):
    """``_film`` where a row is lubricated (compiled only then)."""


LUBRICATED = LAW_COLUMNS["lubrication"][1]  # the codes of the laws with a film
if_used(_film_if_used, "lubrication", LUBRICATED, _film, _no_film)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def add_forces(table, state, scratch, q, qd, g):
    """Evaluate every joint and add its contact and film forces to g [N, N, N m]."""
    for k in range(table.ints.shape[0]):
        evaluate(table, state, scratch, k, q, qd)
        c = scratch.contact[k]
        p = table.params[k]
        if table.ints[k, I_LUBRICATION]:
            apply_at_centres(
                q, g, table.ints[k, I_BEARING], p[P_SB_X], p[P_SB_Y],
                table.ints[k, I_JOURNAL], p[P_SJ_X], p[P_SJ_Y], c[C_FILM_X], c[C_FILM_Y],
            )  # fmt: skip
            apply_torque(g, table.ints[k, I_JOURNAL], c[C_FILM_TJ])
            apply_torque(g, table.ints[k, I_BEARING], c[C_FILM_TB])
        if c[C_FN] == 0.0 and c[C_FT] == 0.0:
            continue
        e = math.hypot(c[C_EX], c[C_EY])
        apply_contact(
            q, g,
            table.ints[k, I_BEARING], p[P_SB_X], p[P_SB_Y],
            table.ints[k, I_JOURNAL], p[P_SJ_X], p[P_SJ_Y],
            c[C_EX] / e, c[C_EY] / e, p[P_RB], p[P_RJ], c[C_FN], c[C_FT],
        )  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def penetration_excess(table, state, scratch, k, q, qd):
    """Penetration of joint k beyond its contact tolerance at (q, q') [m]."""
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

    An opening period records its impact speed, and fills ``info`` (``IMPACT_*``) for the
    impact log. Also keeps the largest normal force and penetration seen at step ends.
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
    info[IMPACT_THETA_B] = c[C_THETA_B]
    info[IMPACT_THETA_J] = c[C_THETA_J]
    info[IMPACT_DELTA] = c[C_DELTA]
    return True


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spread_on_foundation(table, state, scratch, k, volume):
    """Spread the worn volume [m^3] of joint k by its foundation's pressure; the volume."""
    c = scratch.contact[k]
    p = table.params[k]
    law = table.ints[k]
    e = math.hypot(c[C_EX], c[C_EY])
    wear_b, wear_j = _profiles(law, state, k)
    points = foundation_points(0.5 * math.pi, law[I_SECTORS])
    args = (e, p[P_C], c[C_THETA_B], wear_b, c[C_THETA_J], wear_j, points)
    share = p[P_SHARE]
    bearing = state.wear[k, 0, : law[I_SECTORS]]
    journal = state.wear[k, 1, : law[I_SECTORS]]
    return spread_foundation_wear(
        bearing, c[C_THETA_B], p[P_RB], p[P_WIDTH], (1.0 - share) * volume, *args
    ) + spread_foundation_wear(journal, c[C_THETA_J], p[P_RJ], p[P_WIDTH], share * volume, *args)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_spread(table, state, scratch, k, volume):
    return 0.0


def _spread_if_used(table, state, scratch, k, volume):
    """``_spread_on_foundation`` where a row spreads wear so (compiled only then)."""


if_used(_spread_if_used, "wear_distribution", (SPREAD_FOUNDATION,), _spread_on_foundation,
        _no_spread)  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _wear_surfaces(table, state, scratch, k, ds):
    """Add the wear of sliding distance ds [m] under the last evaluation of joint k.

    Returns the volume removed from both surfaces [m^3].
    """
    c = scratch.contact[k]
    p = table.params[k]
    law = table.ints[k]
    f_n = c[C_FN]
    coef = wear_coefficient(table.laws, k, law[I_WEAR], abs(c[C_FT]) / f_n, p[P_WEAR])
    sectors = law[I_SECTORS]
    share = p[P_SHARE]
    bearing = state.wear[k, 0, :sectors]
    journal = state.wear[k, 1, :sectors]
    if law[I_SPREAD] == SPREAD_FOUNDATION:
        return _spread_if_used(table, state, scratch, k, coef * f_n * ds)
    b, _ = hertz_line_contact(f_n, p[P_RSTAR], p[P_ESTAR], p[P_WIDTH])
    peak = law[I_SPREAD] == SPREAD_PEAK
    volume = accumulate_wear(
        bearing, c[C_THETA_B], p[P_RB], p[P_WIDTH], f_n, b, ds, coef, 1.0 - share, peak
    )
    return volume + accumulate_wear(
        journal, c[C_THETA_J], p[P_RJ], p[P_WIDTH], f_n, b, ds, coef, share, peak
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _track_ranges(law, p, c, totals, h):
    """Time and extent of the step [s] beyond the laws' ranges, into totals (T_*_TIME, _MAX).

    The limits are the chosen laws' (``P_DEPTH_LIMIT``, ``P_PATCH_LIMIT``, ``P_BREAKDOWN``):
    the Hertz patch is checked where a law uses Hertz's line contact, the film's
    eccentricity where the joint is lubricated.
    """
    if c[C_FN] > 0.0:
        if p[P_PATCH_LIMIT] > 0.0:
            b, _ = hertz_line_contact(c[C_FN], p[P_RSTAR], p[P_ESTAR], p[P_WIDTH])
            _beyond(totals, T_PATCH_TIME, T_PATCH_MAX, b / p[P_RJ], p[P_PATCH_LIMIT], h)
        _beyond(totals, T_DEPTH_TIME, T_DEPTH_MAX, c[C_DELTA] / p[P_C], p[P_DEPTH_LIMIT], h)
    if law[I_LUBRICATION]:
        _beyond(totals, T_FILM_TIME, T_FILM_MAX, c[C_EPS], p[P_BREAKDOWN], h)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _track_film(table, k, c, totals, qd, h):
    """The film's energy and the integrals its summary needs, over a step of h [s]."""
    totals[T_FILM_ENERGY] += c[C_FILM_POWER] * h
    totals[T_FILM_IMPULSE] += math.hypot(c[C_FILM_X], c[C_FILM_Y]) * h
    w_j = angular_velocity(qd, table.ints[k, I_JOURNAL])
    w_b = angular_velocity(qd, table.ints[k, I_BEARING])
    spin = abs(w_j - w_b)
    load = math.hypot(c[C_FX] + c[C_FILM_X], c[C_FY] + c[C_FILM_Y])
    totals[T_LOAD_SLIDING] += load * table.params[k, P_RJ] * spin * h
    totals[T_SPIN] += spin * h
    e = math.hypot(c[C_EX], c[C_EY])
    radial = (c[C_FILM_X] * c[C_EX] + c[C_FILM_Y] * c[C_EY]) / e if e > 0.0 else 0.0
    totals[T_FILM_FRICTION] += (c[C_FILM_POWER] + radial * c[C_DDOT]) * h
    totals[T_FILM_CLOSURE] = max(totals[T_FILM_CLOSURE], table.params[k, P_C] + c[C_DELTA])


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_track_film(table, k, c, totals, qd, h):
    return None


def _track_film_if_used(table, k, c, totals, qd, h):
    """``_track_film`` where a row is lubricated (compiled only then)."""


if_used(_track_film_if_used, "lubrication", LUBRICATED, _track_film, _no_track_film)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def _beyond(totals, time_slot, max_slot, value, limit, h):
    totals[max_slot] = max(totals[max_slot], value)
    if value > limit:
        totals[time_slot] += h


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def accumulate(table, state, scratch, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear and totals of the step [t_old, t_new] [s] from its midpoint state.

    The wear snapshots due in the step (``snap_times[first:]`` up to t_new) are taken with
    the step's wear split at them.
    """
    h = t_new - t_old
    for k in range(table.ints.shape[0]):
        evaluate(table, state, scratch, k, q_mid, qd_mid)
        c = scratch.contact[k]
        totals = log.totals[k]
        sliding_speed = 0.0  # of a contact that wears
        # Also while F_N is clamped at 0 with the surfaces still overlapping: the elastic
        # energy they release then is lost, (0 - f_e) delta_dot > 0.
        totals[T_DAMPING_ENERGY] += (c[C_FN] - c[C_ELASTIC]) * c[C_DDOT] * h
        if c[C_FN] > 0.0:
            totals[T_CONTACT_TIME] += h
            _track_peaks(totals, c)
            totals[T_FRICTION_ENERGY] -= c[C_FT] * c[C_VT] * h
            p = table.params[k]
            sliding_speed = slip_speed(
                table.laws, k, table.ints[k, I_FRICTION], c[C_VT], p[P_F0], p[P_F1], p[P_F2]
            )
            totals[T_SLIDING] += sliding_speed * h
        totals[T_SOLID_IMPULSE] += c[C_FN] * h
        if table.ints[k, I_LUBRICATION]:
            _track_film_if_used(table, k, c, totals, qd_mid, h)
        _track_ranges(table.ints[k], table.params[k], c, totals, h)
        t_from = t_old
        s = first
        while s < snap_times.shape[0] and snap_times[s] <= t_new:  # split the wear there
            t_snap = max(snap_times[s], t_from)
            if sliding_speed > 0.0:
                ds = sliding_speed * (t_snap - t_from)
                totals[T_WORN_VOLUME] += _wear_surfaces(table, state, scratch, k, ds)
            for surface in range(2):
                for i in range(state.wear.shape[2]):
                    log.snapshots[s, k, surface, i] = state.wear[k, surface, i]
            t_from = t_snap
            s += 1
        if sliding_speed > 0.0:
            ds = sliding_speed * (t_new - t_from)
            totals[T_WORN_VOLUME] += _wear_surfaces(table, state, scratch, k, ds)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def write_outputs(table, scratch, row, c):
    """Write each joint's ``OUTPUTS`` from its last evaluation into row from column c.

    A lubricated joint also writes its ``FILM_OUTPUTS``. Returns the next free column.
    """
    for k in range(table.ints.shape[0]):
        for i in range(len(OUTPUTS)):
            row[c + i] = scratch.contact[k, OUTPUTS[i]]
        c += len(OUTPUTS)
        if table.ints[k, I_LUBRICATION]:
            for i in range(len(FILM_OUTPUTS)):
                row[c + i] = scratch.contact[k, FILM_OUTPUTS[i]]
            c += len(FILM_OUTPUTS)
    return c


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def elastic_energy(table, scratch):
    """Elastic energy stored in the last evaluated contacts [J]."""
    energy = 0.0
    for k in range(table.ints.shape[0]):
        p = table.params[k]
        delta = scratch.contact[k, C_DELTA]
        energy += law_energy(
            table.laws, k, table.ints[k, I_NORMAL], delta, p[P_K], p[P_EXP], p[P_ESTAR],
            p[P_C], p[P_WIDTH],
        )  # fmt: skip
        if p[P_ROUGHNESS] > 0.0:
            energy += _asperities_if_used(table, k, delta)
    return energy


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _asperities(table, k, delta):
    """Energy [J] of joint k's asperities at penetration delta [m].

    Their load is held at W(0) through any overlap of the mean planes.
    """
    p = table.params[k]
    rough = (p[P_ROUGHNESS], p[P_ASPERITY], p[P_RSTAR], p[P_WIDTH])
    return asperity_energy(max(-delta, 0.0), *rough) + asperity_load(0.0, *rough) * max(delta, 0.0)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_asperities(table, k, delta):
    return 0.0


def _asperities_if_used(table, k, delta):
    """``_asperities`` where a row is lubricated (compiled only then)."""


if_used(_asperities_if_used, "lubrication", LUBRICATED, _asperities, _no_asperities)
