"""The right-hand side: accelerations and multipliers of the constrained mechanism.

| symbol | meaning | unit |
|---|---|---|
| y | state (q, q') | m, rad, m/s, rad/s |
| M | diagonal mass matrix (m, m, J per body) | kg, kg m^2 |
| g | generalised applied forces, the contact elements' included | N, N m |
| lam | Lagrange multipliers (paper Eq. 5: g_c = -Phi_q^T lam) | N, N m |

M q'' = g - Phi_q^T lam, with lam from the formulation (``kernels.formulations``): the
paper's Baumgarte-stabilised Eq. (7), or the augmented Lagrangian with projections. The
formulation is chosen by the type of the scratch (``Problem.dyn``) when the loop compiles.
"""

from typing import NamedTuple

from numba import njit

from . import elements
from .codes import Formulation
from .constraints import evaluate_constraints
from .forces import applied_forces
from .formulations import augmented, baumgarte
from .jacobian import add_transpose_product, norm
from .structs import by_kind

_FORMULATIONS = {
    Formulation.BAUMGARTE: baumgarte,
    Formulation.AUGMENTED_LAGRANGIAN: augmented,
}


class Problem(NamedTuple):
    """What the right-hand side reads: the mechanism, its contact elements, and scratch."""

    mech: NamedTuple  # system.Mechanism
    elements: elements.Elements
    state: elements.ElementState  # updated by the loop between steps
    scratch: elements.ElementScratch
    dyn: NamedTuple  # the formulation's scratch


def make_dynamics_scratch(mech: NamedTuple, formulation: Formulation) -> NamedTuple:
    """Allocate the scratch of ``formulation`` for a ``system.Mechanism`` (Python)."""
    n = mech.inv_mass.shape[0]
    m = mech.row_coord.shape[0]
    return _FORMULATIONS[formulation].make_scratch(n, m, mech)


def _solve(wk, t, y, mech):
    """The formulation's multipliers into wk.lam; False if singular."""


def _project(wk, t, y, mech):
    """The formulation's end-of-step check and projection (``formulations``)."""


def _row_multipliers(wk, mech):
    """The formulation's reported multipliers (``formulations``)."""


_BY_KIND = {
    module.make_scratch.__annotations__["return"].__name__: module
    for module in _FORMULATIONS.values()
}
for _stub in (_solve, _project, _row_multipliers):
    by_kind(_stub, {kind: getattr(module, _stub.__name__[1:]) for kind, module in _BY_KIND.items()})


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def rhs(t, y, problem, ydot):
    """Write y' = (q', q'') into ydot; lambda is left in problem.dyn.lam. False if singular."""
    mech = problem.mech
    wk = problem.dyn
    n = mech.inv_mass.shape[0]
    q = y[:n]
    qd = y[n:]
    g = wk.g
    applied_forces(t, q, qd, mech, g)
    elements.add_forces(problem.elements, problem.state, problem.scratch, q, qd, g)
    evaluate_constraints(t, q, qd, mech, wk.phi, wk.cq, wk.gamma, wk.phi_t)
    if not _solve(wk, t, y, mech):
        return False
    force = wk.force
    force[:] = 0.0
    add_transpose_product(mech, wk.cq, wk.lam, force)
    inv_mass = mech.inv_mass
    for c in range(n):
        ydot[c] = qd[c]
        ydot[n + c] = inv_mass[c] * (g[c] - force[c])
    return True


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def project(t, y, problem):
    """After an accepted step ending at (t [s], y): the 2-norm of Phi it ended with [m, rad].

    The augmented Lagrangian formulation also moves y back onto the constraints; -1 if that
    failed.
    """
    return _project(problem.dyn, t, y, problem.mech)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def row_multipliers(problem):
    """After ``rhs`` for an output row: lam as reported (least-norm where not unique)."""
    _row_multipliers(problem.dyn, problem.mech)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def constraint_norm(dyn):
    """2-norm of Phi from the last evaluation [m, rad]."""
    return norm(dyn.phi)
