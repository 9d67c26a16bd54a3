"""One row of the time-series output from a state.

Row layout (``system.column_names`` gives the names): time; per body x, y, phi, vx, vy,
omega, ax, ay, alpha; per driver the generalised force it applies (-lambda of its row);
per applied load but gravity its force or torque (``forces.write_loads``); per ideal joint
the reaction force (fx, fy) on its second body; per contact element its columns
(``elements.write_outputs``); kinetic and potential energy; with contact elements, the
elastic energy of their contacts; the 2-norm of the position constraints.
"""

from numba import njit

from . import elements
from .dynamics import constraint_norm, rhs, row_multipliers
from .forces import potential_energy, write_loads


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def kinetic_energy(qd, mech):
    """Kinetic energy 1/2 q'^T M q' [J]."""
    energy = 0.0
    for c in range(qd.shape[0]):
        energy += 0.5 * qd[c] * qd[c] / mech.inv_mass[c]
    return energy


@njit(
    cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always"
)
def _reaction(dyn, mech, jt, side, k):
    """Component k of the force joint jt's rows apply to its first (side 0) or second body [N]."""
    r0 = mech.joint_row[jt]
    force = 0.0
    for r in range(r0, r0 + mech.joint_rows[jt]):
        force -= dyn.cq[r, 3 * side + k] * dyn.lam[r]
    return force


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def write_row(t, y, problem, ydot, row):
    """Fill one output row for state y at time t [s]. Returns False if the solve failed."""
    ok = rhs(t, y, problem, ydot)
    if ok:
        row_multipliers(problem)
    fill_row(t, y, problem, ydot, row)
    return ok


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def fill_row(t, y, problem, ydot, row):
    """Fill one output row from the last evaluation ``rhs(t, y, problem, ydot)`` [s].

    The multipliers must be as ``row_multipliers`` reports them.
    """
    mech = problem.mech
    dyn = problem.dyn
    n = mech.inv_mass.shape[0]
    row[0] = t
    c = 1
    for b in range(n // 3):
        for k in range(3):
            row[c + k] = y[3 * b + k]
            row[c + 3 + k] = y[n + 3 * b + k]
            row[c + 6 + k] = ydot[n + 3 * b + k]
        c += 9
    for d in range(mech.driver_kind.shape[0]):
        row[c] = -dyn.lam[mech.driver_row[d]]
        c += 1
    c = write_loads(t, y[:n], y[n:], mech, row, c)
    for jt in range(mech.joint_kind.shape[0]):
        j = mech.joint_body[jt, 1]
        for k in range(2):
            if j >= 0:
                row[c + k] = _reaction(dyn, mech, jt, 1, k)
            else:  # action and reaction: the force on the ground is minus that on body i
                row[c + k] = -_reaction(dyn, mech, jt, 0, k)
        c += 2
    c = elements.write_outputs(problem.elements, problem.scratch, row, c)
    row[c] = kinetic_energy(y[n:], mech)
    row[c + 1] = potential_energy(y[:n], mech)
    c += 2
    if elements.slot_count(problem.elements) > 0:
        row[c] = elements.elastic_energy(problem.elements, problem.scratch)
        c += 1
    row[c] = constraint_norm(dyn)
