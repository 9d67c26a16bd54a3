"""The constraint Jacobian Phi_q at a state, as the kernels store it: by row, sparse.

Row r holds ``ENTRIES`` values in the columns ``coord[r]``: the x, y, phi of its first body,
then of its second, -1 for the ground (``pattern.py``). Products with it cost the number of
rows. The set-up's solves and rank take it dense up to ``DENSE_COLUMNS`` coordinates, where
LAPACK costs less than building a sparse factorisation (and computes what earlier versions
did); above, as a scipy CSR matrix (``least_norm``, ``rank``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..kernels.constraints import evaluate_constraints
from ..kernels.structs import to_struct
from .pattern import ENTRIES
from .system import System, constraint_count

DENSE_COLUMNS = 120  # coordinates (40 bodies) up to which the Jacobian is taken dense


class Jacobian(NamedTuple):
    """Phi_q of ``rows`` constraint equations in ``columns`` coordinates."""

    entries: NDArray[np.float64]  # (rows, ENTRIES) [1 or m]
    coord: NDArray[np.int64]  # (rows, ENTRIES) column of each entry, -1 for none
    columns: int

    @property
    def rows(self) -> int:
        """Number of constraint equations."""
        return self.entries.shape[0]

    @property
    def small(self) -> bool:
        """Whether the set-up takes it dense (at most ``DENSE_COLUMNS`` coordinates)."""
        return self.columns <= DENSE_COLUMNS

    def top(self, rows: int) -> Jacobian:
        """The Jacobian of the first ``rows`` equations."""
        return Jacobian(self.entries[:rows], self.coord[:rows], self.columns)

    def dot(self, x: NDArray[np.float64]) -> NDArray[np.float64]:
        """Phi_q x for a coordinate vector x (as a dense product when ``small``)."""
        if self.small:
            return self.dense() @ x
        return np.where(self.coord >= 0, self.entries * x[self.coord], 0.0).sum(axis=1)

    def dense(self) -> NDArray[np.float64]:
        """Phi_q as a (rows, columns) array."""
        matrix = np.zeros((self.rows, self.columns))
        rows, slots = np.nonzero(self.coord >= 0)
        matrix[rows, self.coord[rows, slots]] = self.entries[rows, slots]
        return matrix

    def csr(self) -> object:
        """Phi_q as a scipy CSR array (duplicate entries summed)."""
        from scipy.sparse import csr_array

        rows, slots = np.nonzero(self.coord >= 0)
        values = (self.entries[rows, slots], (rows, self.coord[rows, slots]))
        return csr_array(values, shape=(self.rows, self.columns))


def evaluate(
    system: System, q: NDArray, qd: NDArray, t: float = 0.0
) -> tuple[NDArray, Jacobian, NDArray]:
    """Phi, the Jacobian Phi_q and Phi_t at (q, q') and time t [s]."""
    mech = system.mechanism
    m = constraint_count(mech)
    phi, gamma, phi_t = np.zeros(m), np.zeros(m), np.zeros(m)
    entries = np.zeros((m, ENTRIES))
    # as a struct, the one specialization the step loop compiles too (kernels/structs.py)
    evaluate_constraints(t, q, qd, to_struct(mech), phi, entries, gamma, phi_t)
    return phi, Jacobian(entries, mech.row_coord, q.shape[0]), phi_t
