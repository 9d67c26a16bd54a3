"""Initial conditions: position and velocity analysis with all joints ideal.

Newton-Raphson on Phi(q, t0) = 0 from the model's pose guess, each correction the
minimum-norm solution of Phi_q dq = -Phi (so coordinates the constraints leave free stay at
their guessed values); then the velocities closest to the guessed ones that satisfy
Phi_q q' = -Phi_t. Nikravesh (1988), ch. 4 and 5; paper sec. 6 ("initial conditions ... from a
kinematic analysis ... in which all the joints are assumed to be ideal"). The solves
(``least_norm``) and the rank (``rank``) cost time linear in the bodies of a large mechanism.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..joints import BY_NAME
from ..model import Model, ModelError
from .jacobian import evaluate
from .least_norm import least_norm
from .rank import Dependence, dependence
from .system import System, initial_guess, joint_row_count

MAX_ITERATIONS = 50
VELOCITY_RATE = 1.0  # velocity equations are met to the position tolerance per second [1/s]


@dataclass(frozen=True)
class Assembly:
    """Outcome of the initial position and velocity analysis."""

    y0: NDArray[np.float64]  # consistent (q, q') at t = 0
    iterations: int  # Newton iterations used
    residual: float  # max |Phi| at the solution [m or rad]
    dof: int  # degrees of freedom left by joints and drivers
    redundant: int  # constraint equations that depend on others (at the initial pose)
    dof_without_drivers: int  # degrees of freedom of the joints alone


def row_labels(model: Model) -> list[str]:
    """A readable label per constraint row, in kernel row order."""
    labels = [
        f"joint '{joint.name}' ({joint.type}, {row})"
        for joint in model.joints
        for row in BY_NAME[joint.type].ideal_rows
    ]
    labels += [f"driver '{d.name}'" for d in model.drivers]
    return labels


def _redundancy_message(found: Dependence, labels: list[str]) -> str:
    involved = [labels[i] for i in np.flatnonzero(found.involved)]
    return (
        f"constraints: the Jacobian has rank {found.rank} for {len(labels)} equations (redundant "
        f"or singular); the dependent equations involve {', '.join(involved)}; the Baumgarte "
        "formulation needs independent constraints: use solver.formulation = "
        "'augmented_lagrangian', remove a redundant joint or driver, or move the initial pose "
        "away from a singular (dead-centre) position"
    )


def redundant_equations(system: System, y0: NDArray[np.float64]) -> int:
    """Constraint equations of ``system`` that depend on others at the state y0."""
    n = y0.shape[0] // 2
    _, cq, _ = evaluate(system, y0[:n], y0[n:])
    return cq.rows - dependence(cq).rank


def _finite(matrix: np.ndarray) -> bool:
    return bool(np.all(np.isfinite(matrix)))


def assemble(model: Model, system: System, tolerance: float | None = None) -> Assembly:
    """Solve the initial position and velocity analysis.

    Raises
    ------
    ModelError
        If the constraints cannot be met from the guess (naming the worst ones), or their
        Jacobian is rank-deficient (redundant constraints or a singular pose).
    """
    tol = model.solver.assembly_tolerance if tolerance is None else tolerance
    labels = row_labels(model)
    y = initial_guess(model)
    n = y.shape[0] // 2
    q, qd = y[:n].copy(), y[n:].copy()
    phi, cq, phi_t = evaluate(system, q, qd)
    iterations = 0
    while not np.max(np.abs(phi), initial=0.0) <= tol:  # NaN included
        if iterations == MAX_ITERATIONS or not (np.all(np.isfinite(phi)) and _finite(cq.entries)):
            worst = np.argsort(-np.abs(phi))[:3]
            unmet = "; ".join(f"{labels[i]} off by {abs(phi[i]):.3g}" for i in worst)
            raise ModelError(
                [
                    f"assembly: the constraints cannot be met from the initial guess ({unmet}); "
                    "check the body points and lengths, and the initial positions and angles"
                ]
            )
        q += least_norm(cq, -phi)
        phi, cq, phi_t = evaluate(system, q, qd)
        iterations += 1
    not_finite = [labels[i] for i in np.flatnonzero(~np.isfinite(phi_t))]
    if not_finite:
        raise ModelError(
            [
                "assembly: the initial velocities are not finite numbers: the rate of "
                f"{', '.join(not_finite)} overflows; check the drivers' amplitudes and frequencies"
            ]
        )
    found = dependence(cq)
    rank = found.rank
    if rank < cq.rows and model.solver.formulation == "baumgarte":
        raise ModelError([_redundancy_message(found, labels)])
    qd -= least_norm(cq, cq.dot(qd) + phi_t)
    velocity_residual = np.abs(cq.dot(qd) + phi_t)
    if np.max(velocity_residual, initial=0.0) > tol * VELOCITY_RATE:
        worst = np.argsort(-velocity_residual)[:3]
        unmet = "; ".join(f"{labels[i]} off by {velocity_residual[i]:.3g}" for i in worst)
        raise ModelError(
            [
                "assembly: the constraints' velocity equations contradict each other "
                f"({unmet} per second): redundant drivers or joints that prescribe different "
                "motions; make them agree or remove one"
            ]
        )
    joint_rows = joint_row_count(system.mechanism)
    return Assembly(
        y0=np.concatenate([q, qd]),
        iterations=iterations,
        residual=float(np.max(np.abs(phi), initial=0.0)),
        dof=n - rank,
        redundant=cq.rows - rank,
        dof_without_drivers=n - dependence(cq.top(joint_rows)).rank,
    )
