"""Preparing a run: the model's arrays, the assembled start, and where a driven mechanism locks.

``simulate`` and ``jointwear check`` both start here, so what ``check`` accepts is what a run
starts from.
"""

from __future__ import annotations

from typing import NamedTuple

from ..mechanism.assembly import Assembly, assemble, redundant_equations
from ..mechanism.lockup import LockUp, find_lock_up, lock_up_span
from ..mechanism.system import System, build_system, start_problems
from ..model import Model, ModelError


class Prepared(NamedTuple):
    """A model ready to run."""

    system: System  # the arrays that run; rows with redundant constraints are marked
    ideal: System  # the same with every clearance joint ideal (the assembly's mechanism)
    assembly: Assembly  # the initial pose and velocities, every clearance joint centred
    redundant: int  # constraint equations that depend on others
    lock: LockUp | None  # where the ideal mechanism locks up within a driver cycle, if it does


def prepare(model: Model, *, check_lock_up: bool = True) -> Prepared:
    """Build ``model``'s arrays, assemble its start and look for a lock-up.

    Raises
    ------
    ModelError
        If the mechanism cannot be assembled, or a clearance joint cannot start from the
        assembled pose (``ClearanceKind.start_problems``).
    """
    system = build_system(model)
    ideal = build_system(model, ideal=True)
    assembly = assemble(model, ideal)
    # of the system that runs, without the clearance joints' rows
    redundant = redundant_equations(system, assembly.y0) if assembly.redundant else 0
    if redundant:  # rows report the least-norm multipliers (kernels.formulations)
        system = system._replace(mechanism=system.mechanism._replace(redundant=True))
    problems = start_problems(model, assembly.y0)
    if problems:
        raise ModelError(problems)
    lock = find_lock_up(model, ideal, assembly, lock_up_span(model)) if check_lock_up else None
    return Prepared(system, ideal, assembly, redundant, lock)
