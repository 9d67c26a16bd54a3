"""One row of the time-series output from a state.

Row layout (``system.column_names`` gives the names): time; per body x, y, phi, vx, vy,
omega, ax, ay, alpha; per driver the generalised force it applies (-lambda of its row);
per ideal joint the reaction force (fx, fy) on its second body; per clearance joint the
contact force (fx, fy) on the journal, the eccentricity (ex, ey), the penetration, the normal
and the friction force; kinetic and potential energy; with clearance joints, the elastic
energy of their contacts; the 2-norm of the position constraints.
"""

from numba import njit

from .dynamics import constraint_norm, rhs
from .forces import potential_energy
from .joint_contact import C_DELTA, C_EX, C_EY, C_FN, C_FT, C_FX, C_FY, contact_energy

CLEARANCE_OUTPUTS = (C_FX, C_FY, C_EX, C_EY, C_DELTA, C_FN, C_FT)  # system.CLEARANCE_COLUMNS


@njit(cache=True)
def kinetic_energy(qd, sys):
    """Kinetic energy 1/2 q'^T M q' [J]."""
    energy = 0.0
    for c in range(qd.shape[0]):
        energy += 0.5 * qd[c] * qd[c] / sys.inv_mass[c]
    return energy


@njit(cache=True)
def _reaction(wk, sys, jt, b, k):
    """Component k of the force that joint jt's two constraint rows apply to body b [N]."""
    r0 = sys.joint_row[jt]
    force = 0.0
    for r in range(r0, r0 + 2):
        force -= wk.cq[r, 3 * b + k] * wk.lam[r]
    return force


@njit(cache=True)
def write_row(t, y, sys, wk, ydot, row):
    """Fill one output row for state y at time t [s]. Returns False if the solve failed."""
    ok = rhs(t, y, sys, wk, ydot)
    n = sys.inv_mass.shape[0]
    nb = n // 3
    row[0] = t
    c = 1
    for b in range(nb):
        for k in range(3):
            row[c + k] = y[3 * b + k]
            row[c + 3 + k] = y[n + 3 * b + k]
            row[c + 6 + k] = ydot[n + 3 * b + k]
        c += 9
    for d in range(sys.driver_kind.shape[0]):
        row[c] = -wk.lam[sys.driver_row[d]]
        c += 1
    for jt in range(sys.joint_kind.shape[0]):
        j = sys.joint_body[jt, 1]
        for k in range(2):
            if j >= 0:
                row[c + k] = _reaction(wk, sys, jt, j, k)
            else:  # action and reaction: the force on the ground is minus that on body i
                row[c + k] = -_reaction(wk, sys, jt, sys.joint_body[jt, 0], k)
        c += 2
    nc = sys.clearance_body.shape[0]
    for k in range(nc):
        for i in range(len(CLEARANCE_OUTPUTS)):
            row[c + i] = wk.contact[k, CLEARANCE_OUTPUTS[i]]
        c += len(CLEARANCE_OUTPUTS)
    row[c] = kinetic_energy(y[n:], sys)
    row[c + 1] = potential_energy(y[:n], sys)
    c += 2
    if nc > 0:
        row[c] = contact_energy(sys, wk)
        c += 1
    row[c] = constraint_norm(wk)
    return ok
