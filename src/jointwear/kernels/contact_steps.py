"""What the step loop does for clearance joints between steps: contact periods and wear.

- **Contact periods** (SPEC sec. 3): a period begins when the penetration passes the contact
  tolerance (the loop locates that instant on the dense output and restarts the integrator
  there); ``begin_periods`` then records the penetration rate as the impact speed used by the
  damping until the period ends, at the first step end without penetration.
- **Wear** (SPEC sec. 4, paper Eq. 14): ``accumulate_step`` adds the wear of an accepted step
  to both surfaces' sectors, from the contact at the step's midpoint (dense output) times its
  length (midpoint rule), and no wear while the contact sticks. The same midpoint feeds the
  totals of ``LoopState.contact_totals`` (``T_*`` columns). Wear snapshots are taken at the
  requested times by splitting the step's wear at them.

Reye's law uses the effective friction coefficient abs(f_t) / f_n of the contact, so that
the worn volume follows the friction energy actually dissipated (paper Eq. 8).
"""

from numba import njit

from .codes import Counter, WearLaw
from .friction import is_sliding
from .joint_contact import (
    C_DDOT,
    C_DELTA,
    C_ELASTIC,
    C_FN,
    C_FT,
    C_THETA_B,
    C_THETA_J,
    C_VT,
    L_FRICTION,
    L_PEAK,
    L_WEAR,
    P_ESTAR,
    P_F0,
    P_F1,
    P_F2,
    P_MIN_SPEED,
    P_RB,
    P_RJ,
    P_RSTAR,
    P_SHARE,
    P_TOL,
    P_WEAR,
    P_WIDTH,
    evaluate_contact,
)
from .wear import accumulate_wear, hertz_line_contact, wear_coefficient

# Columns of LoopState.contact_totals.
T_CONTACT_TIME = 0  # time with a positive normal force [s]
T_MAX_FN = 1  # largest normal force [N]
T_MAX_DELTA = 2  # largest penetration [m]
T_IMPACTS = 3  # contact periods begun (free flight to contact)
T_DAMPING_ENERGY = 4  # energy dissipated by the damping of the normal force [J]
T_FRICTION_ENERGY = 5  # energy dissipated by friction [J]
T_WORN_VOLUME = 6  # volume removed from both surfaces [m^3]
T_SLIDING = 7  # sliding distance while in contact and sliding [m]
N_TOTALS = 8

# Columns of LoopState.impact_info.
I_SPEED = 0  # penetration rate at onset [m/s]
I_THETA_B = 1  # contact angle in the bearing's frame [rad]
I_THETA_J = 2  # contact angle in the journal's frame [rad]
I_DELTA = 3  # penetration where the onset was located [m]
N_IMPACT_INFO = 4


@njit(cache=True)
def penetration_excess(sys, wk, k, y):
    """Penetration of clearance joint k beyond the contact tolerance at state y [m]."""
    n = sys.inv_mass.shape[0]
    evaluate_contact(y[:n], y[n:], sys, wk, k)
    return wk.contact[k, C_DELTA] - sys.clearance_param[k, P_TOL]


@njit(cache=True)
def begin_periods(sys, ls, wk, t, y):
    """Open or close contact periods at the step end (t [s], y); log each onset.

    Also keeps the largest normal force and penetration seen at step ends.
    """
    for k in range(sys.clearance_body.shape[0]):
        excess = penetration_excess(sys, wk, k, y)
        _track_peaks(ls.contact_totals[k], wk.contact[k])
        if wk.contact_on[k]:
            if excess + sys.clearance_param[k, P_TOL] <= 0.0:
                wk.contact_on[k] = 0
            continue
        if excess <= 0.0:
            continue
        c = wk.contact[k]
        wk.contact_on[k] = 1
        wk.impact_speed[k] = max(c[C_DDOT], sys.clearance_param[k, P_MIN_SPEED])
        ls.contact_totals[k, T_IMPACTS] += 1.0
        slot = ls.counters[Counter.IMPACTS]
        if slot < ls.impact_time.shape[0]:
            ls.impact_time[slot] = t
            ls.impact_joint[slot] = k
            ls.impact_info[slot, I_SPEED] = c[C_DDOT]
            ls.impact_info[slot, I_THETA_B] = c[C_THETA_B]
            ls.impact_info[slot, I_THETA_J] = c[C_THETA_J]
            ls.impact_info[slot, I_DELTA] = c[C_DELTA]
            ls.counters[Counter.IMPACTS] = slot + 1


@njit(cache=True)
def _track_peaks(totals, c):
    """Largest normal force and penetration so far, with the contact evaluation c."""
    totals[T_MAX_FN] = max(totals[T_MAX_FN], c[C_FN])
    totals[T_MAX_DELTA] = max(totals[T_MAX_DELTA], c[C_DELTA])


@njit(cache=True)
def _wear_surfaces(sys, wk, k, ds):
    """Add the wear of sliding distance ds [m] under the last evaluated contact of joint k.

    Returns the volume removed from both surfaces [m^3].
    """
    c = wk.contact[k]
    p = sys.clearance_param[k]
    f_n = c[C_FN]
    law = sys.clearance_law[k, L_WEAR]
    if law == WearLaw.REYE:  # mu: the friction acting, abs(f_t) / f_n (module docstring)
        coef = wear_coefficient(law, abs(c[C_FT]) / f_n, p[P_WEAR])
    else:
        coef = wear_coefficient(law, p[P_WEAR], 0.0)
    b, _ = hertz_line_contact(f_n, p[P_RSTAR], p[P_ESTAR], p[P_WIDTH])
    peak = sys.clearance_law[k, L_PEAK] == 1
    sectors = sys.clearance_sectors[k]
    share = p[P_SHARE]
    bearing = wk.wear[k, 0, :sectors]
    journal = wk.wear[k, 1, :sectors]
    volume = accumulate_wear(
        bearing, c[C_THETA_B], p[P_RB], p[P_WIDTH], f_n, b, ds, coef, 1.0 - share, peak
    )
    return volume + accumulate_wear(
        journal, c[C_THETA_J], p[P_RJ], p[P_WIDTH], f_n, b, ds, coef, share, peak
    )


@njit(cache=True)
def accumulate_step(sys, ctl, ls, wk, t_old, t_new, y_mid):
    """Wear, totals and snapshots of the step [t_old, t_new] [s] from its midpoint state."""
    n = sys.inv_mass.shape[0]
    h = t_new - t_old
    n_snap = ctl.snapshot_times.shape[0]
    first = ls.counters[Counter.SNAPSHOTS]
    for k in range(sys.clearance_body.shape[0]):
        evaluate_contact(y_mid[:n], y_mid[n:], sys, wk, k)
        c = wk.contact[k]
        totals = ls.contact_totals[k]
        sliding_speed = 0.0  # of a contact that wears
        if c[C_FN] > 0.0:
            totals[T_CONTACT_TIME] += h
            _track_peaks(totals, c)
            totals[T_DAMPING_ENERGY] += (c[C_FN] - c[C_ELASTIC]) * c[C_DDOT] * h
            totals[T_FRICTION_ENERGY] -= c[C_FT] * c[C_VT] * h
            p = sys.clearance_param[k]
            law = sys.clearance_law[k, L_FRICTION]
            if is_sliding(law, c[C_VT], p[P_F0], p[P_F1], p[P_F2]):
                sliding_speed = abs(c[C_VT])
                totals[T_SLIDING] += sliding_speed * h
        t_from = t_old
        s = first
        while s < n_snap and ctl.snapshot_times[s] <= t_new:  # split the step's wear there
            t_snap = max(ctl.snapshot_times[s], t_from)
            if sliding_speed > 0.0:
                ds = sliding_speed * (t_snap - t_from)
                totals[T_WORN_VOLUME] += _wear_surfaces(sys, wk, k, ds)
            ls.wear_snapshots[s, k] = wk.wear[k]
            t_from = t_snap
            s += 1
        if sliding_speed > 0.0:
            totals[T_WORN_VOLUME] += _wear_surfaces(sys, wk, k, sliding_speed * (t_new - t_from))
    while first < n_snap and ctl.snapshot_times[first] <= t_new:
        first += 1
    ls.counters[Counter.SNAPSHOTS] = first
