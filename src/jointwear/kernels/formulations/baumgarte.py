"""The paper's Eq. (7): Lagrange multipliers with Baumgarte stabilisation.

[[M, Phi_q^T], [Phi_q, 0]] [q''; lam] = [g; c], c = gamma - 2 alpha Phi' - beta^2 Phi, is
solved by its Schur complement, M being diagonal: (Phi_q M^-1 Phi_q^T) lam = Phi_q M^-1 g - c.
Baumgarte (1972); Nikravesh (1988) sec. 13. The Schur complement loses rank with Phi_q, at
dead-centre positions and with redundant constraints: the solve then reports a singular
system. The state is never projected: the Baumgarte terms hold the drift.
"""

from typing import NamedTuple

import numpy as np
from numba import njit

from ..jacobian import norm
from . import shared_arrays
from .schur import schur_multipliers


class BaumgarteScratch(NamedTuple):
    """Arrays of one evaluation (m constraint rows, n coordinates)."""

    g: np.ndarray  # (n,) generalised applied forces [N, N m]
    phi: np.ndarray  # (m,) Phi [m, rad]
    cq: np.ndarray  # (m, 6) Jacobian entries (jacobian.py)
    gamma: np.ndarray  # (m,) right side of Phi_q q'' = gamma
    phi_t: np.ndarray  # (m,) partial time derivative of Phi
    lam: np.ndarray  # (m,) Lagrange multipliers [N, N m]
    force: np.ndarray  # (n,) Phi_q^T lam after an evaluation; scratch within one
    x_rows: np.ndarray  # (m,) a row vector in envelope order
    schur: np.ndarray  # Phi_q M^-1 Phi_q^T in envelope storage


def make_scratch(n: int, m: int, mech: NamedTuple) -> BaumgarteScratch:
    """Allocate the scratch of n coordinates and m rows of ``system.Mechanism`` (Python)."""
    return BaumgarteScratch(
        **shared_arrays(n, m),
        schur=np.zeros(mech.row_ptr[-1]),
    )


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def solve(wk, t, y, mech):
    """Lam from the Schur complement; False if it is singular."""
    n = mech.inv_mass.shape[0]
    return schur_multipliers(wk, mech, y[n:], mech.baumgarte_alpha, mech.baumgarte_beta)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def project(wk, t, y, mech):
    """The 2-norm of Phi at the step's end, from its last evaluation there [m, rad]."""
    return norm(wk.phi)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def row_multipliers(wk, mech):
    """Lam as solved: unique, the constraints being independent."""
