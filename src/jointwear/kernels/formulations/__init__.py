"""How the right-hand side meets the joints' constraints: one module per formulation.

A formulation is its scratch (a named tuple whose class names it) and three functions that
``kernels.dynamics`` calls through its interface, chosen by the scratch's type when the loop
is compiled:

1. ``solve(wk, t, y, mech)``: with g, Phi, Phi_q, gamma and Phi_t evaluated at (t, y), fill
   wk.lam, the multipliers whose forces -Phi_q^T lam hold the constraints; False if singular.
2. ``project(wk, t, y, mech)``: after an accepted step ending at (t, y), return the 2-norm of
   Phi it ended with, and move y back onto the constraints if the formulation does; -1 if
   that failed.
3. ``row_multipliers(wk, mech)``: after ``solve`` for an output row, make lam the reported
   multipliers (the least-norm set where redundant constraints leave them open).
"""

import numpy as np

from ..jacobian import ENTRIES


def shared_arrays(n: int, m: int) -> dict[str, np.ndarray]:
    """The arrays every formulation's scratch has, for n coordinates and m rows (Python).

    g (n,) applied forces [N, N m]; phi, gamma, phi_t (m,) Phi and its acceleration terms;
    cq (m, 6) Jacobian entries (``jacobian.py``); lam (m,) multipliers [N, N m]; force (n,)
    Phi_q^T lam after an evaluation, scratch within one; x_rows (m,) a row vector.
    """
    return {
        "g": np.zeros(n),
        "phi": np.zeros(m),
        "cq": np.zeros((m, ENTRIES)),
        "gamma": np.zeros(m),
        "phi_t": np.zeros(m),
        "lam": np.zeros(m),
        "force": np.zeros(n),
        "x_rows": np.zeros(m),
    }
