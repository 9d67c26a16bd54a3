"""Lock-up: a driven mechanism that cannot follow its drivers through a cycle.

With as many drivers as degrees of freedom, the positions follow from the drivers alone.
``find_lock_up`` solves them (Newton-Raphson, as the assembly does) at small steps of time
over one driver cycle of the all-ideal mechanism, each from the last pose moved on by its
velocity. Where the best pose still misses the joints by a millionth of the mechanism's size
(a connecting rod shorter than its crank, a rocker driven past its limit), the mechanism
locks up; the time is located by bisection.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import Model
from ..model.functions import period
from .assembly import Assembly
from .jacobian import evaluate
from .least_norm import least_norm
from .system import System

SAMPLES_PER_CYCLE = 360  # poses solved per driver cycle (a degree of a crank's turn)
BISECTIONS = 30  # halvings of the step that locates the lock-up
NEWTON_ITERATIONS = 30  # slow only next to a singular position
SIZE_FLOOR = 1e-3  # [m] the smallest mechanism size taken
GAP = 1e-6  # a best pose missing the joints by this share of the mechanism's size: no pose
CONVERGED = 1e-6  # of GAP: close enough to go on from


@dataclass(frozen=True)
class LockUp:
    """Where a driven mechanism locks up."""

    time: float  # the last time at which a pose was found [s]
    where: str  # the drivers' values there, in words

    def message(self) -> str:
        """The lock-up in one line, with what to check."""
        return (
            f"the mechanism locks up at t = {self.time:.6g} s ({self.where}): no pose meets "
            "the joints beyond it as the drivers go on; check the link lengths and the "
            "drivers' ranges"
        )


def lock_up_span(model: Model) -> float:
    """Time to check [s]: one cycle of the slowest periodic driver, at most the run's end."""
    periods = [period(d.function, d.type, model.drivers) for d in model.drivers]
    cycles = [p for p in periods if p]  # None (never repeats) and 0 (constant) give no cycle
    return min(model.solver.t_end, max(cycles)) if cycles else model.solver.t_end


def find_lock_up(model: Model, system: System, assembly: Assembly, span: float) -> LockUp | None:
    """The first lock-up of the all-ideal ``system`` within ``span`` [s], or None.

    Only a mechanism the drivers move alone (no degree of freedom left) can lock up this way;
    for any other, None.
    """
    if assembly.dof != 0 or not model.drivers:
        return None
    n = assembly.y0.shape[0] // 2
    q = assembly.y0[:n].copy()
    gap = GAP * _size(model)
    dt = span / SAMPLES_PER_CYCLE
    t = 0.0
    while t < span:
        t_next = min(t + dt, span)
        moved = _pose(system, q, t, t_next, gap)
        if moved is None:
            good, bad = t, t_next
            for _ in range(BISECTIONS):
                middle = 0.5 * (good + bad)
                found = _pose(system, q, good, middle, gap)
                if found is None:
                    bad = middle
                else:
                    good, q = middle, found
            return LockUp(good, _drivers_at(model, q))
        q, t = moved, t_next
    return None


def _pose(system: System, q: NDArray, t: float, t_next: float, gap: float) -> NDArray | None:
    """The pose at ``t_next`` [s] near pose ``q`` at ``t``; None if none is within ``gap``.

    Gauss-Newton from ``q`` moved on by its velocity: it converges to a pose where one exists
    (also at a singular position, where a parallelogram goes flat), and to the least-squares
    best, a residual of the size of the missing length, where none does.
    """
    zero = np.zeros_like(q)
    _, cq, phi_t = evaluate(system, q, zero, t)
    guess = q - least_norm(cq, phi_t) * (t_next - t)
    residual = math.inf
    for _ in range(NEWTON_ITERATIONS):
        phi, cq, _ = evaluate(system, guess, zero, t_next)
        residual = float(np.max(np.abs(phi)))
        if not math.isfinite(residual):
            return None
        step = least_norm(cq, -phi)
        if not np.all(np.isfinite(step)):
            return None
        guess = guess + step
        if residual <= gap * CONVERGED:
            break
    return guess if residual <= gap else None


def _size(model: Model) -> float:
    """The mechanism's size [m]: the largest distance of a body or ground point from the origin."""
    points = [
        math.hypot(*p) for p in (*model.ground.points.values(), *(b.position for b in model.bodies))
    ]
    return max([*points, SIZE_FLOOR])


def _drivers_at(model: Model, q: NDArray) -> str:
    """The angle drivers' angles at pose ``q``, in words (the names of the others)."""
    index = {b.name: i for i, b in enumerate(model.bodies)}
    words = []
    for driver in model.drivers:
        if driver.type != "angle":
            words.append(f"driver '{driver.name}'")
            continue
        angle = q[3 * index[driver.body] + 2]
        if driver.relative_to != "ground":
            angle -= q[3 * index[driver.relative_to] + 2]
        words.append(f"driver '{driver.name}' at {math.degrees(angle) % 360.0:.4g} deg")
    return ", ".join(words)
