"""How a run, a sweep case or a life run ended: one vocabulary, in lowercase.

These are the ``status`` values of ``summary.json``, ``case.json``, ``sweep.csv`` and a life
run's ``summary.json``. A run's status is the name of the kernels' ``Status`` code in lowercase
(``status_name``: ``success``, ``non_finite``, ``singular``, ``max_steps``, ``interrupted``,
``constraint_drift``, ``energy_drift``, ``lock_up``);
a sweep case adds ``error`` and ``not_run``, a life run ``failed``, ``worn_through``,
``clearance_limit`` and ``runaway``. Everything but ``success`` means the work did not get to
its end; a study counts a life run stopped at a joint's limit as complete (``COMPLETE``).
"""

from ..kernels.codes import Status

__all__ = [
    "CLEARANCE_LIMIT",
    "COMPLETE",
    "ERROR",
    "FAILED",
    "INTERRUPTED",
    "NOT_RUN",
    "RUNAWAY",
    "SETTLED",
    "SUCCESS",
    "WORN_THROUGH",
    "Status",
    "status_message",
    "status_name",
]


def status_name(status: Status) -> str:
    """The name of a run status in files and messages: ``Status.MAX_STEPS`` -> ``max_steps``."""
    return status.name.lower()


# A run (``simulate``), and so also a sweep case or a life run
SUCCESS = status_name(Status.SUCCESS)  # reached its end
INTERRUPTED = status_name(Status.INTERRUPTED)  # Ctrl-C or SIGTERM; what was done is kept
# A sweep case
ERROR = "error"  # the case raised (an invalid model, a crash); its error column says what
NOT_RUN = "not_run"  # the sweep stopped before the case ran
# A life run
FAILED = "failed"  # one of its simulated runs did not succeed
WORN_THROUGH = "worn_through"  # a journal would be worn through its radius
CLEARANCE_LIMIT = "clearance_limit"  # a clearance would grow past max_growth
RUNAWAY = "runaway"  # a joint's force or wear jumped, or it left its contact law's range
# A study's case whose results are whole: a run that reached its end, or a life run that
# stopped at a limit of its joint. A study keeps it, counts it and does not run it again.
COMPLETE = (SUCCESS, CLEARANCE_LIMIT, WORN_THROUGH)
# A case that would end alike if run again: complete, or a life run that ran away (whose
# results, up to the run-away, no study counts). A study does not run it again.
SETTLED = (*COMPLETE, RUNAWAY)

_MESSAGES = {
    Status.RUNNING: "stopped between chunks",
    Status.SUCCESS: "reached the end time",
    Status.NON_FINITE: "the state became non-finite (NaN or inf) at the minimum step; check "
    "forces and stiffness, or try tighter tolerances or a smaller solver.max_step",
    Status.SINGULAR: "the constraint equations could not be solved: with formulation "
    "'baumgarte' the Jacobian became singular (a dead-centre position or redundant "
    "constraints, which 'augmented_lagrangian' passes); with 'augmented_lagrangian' its "
    "iterations did not settle (masses and inertias of very different sizes, or "
    "solver.penalty too low); check the geometry and the drivers",
    Status.MAX_STEPS: "solver.max_steps was reached; raise it or loosen the tolerances",
    Status.INTERRUPTED: "interrupted by the user; the results hold what was computed so far",
    Status.CONSTRAINT_DRIFT: "the joint constraints drifted past "
    "solver.max_constraint_violation (the motion may have left its assembly branch, as at a "
    "dead-centre or flat position, or the drivers contradict the joints); with formulation "
    "'baumgarte' try 'augmented_lagrangian', or tighter tolerances",
    Status.LOCK_UP: "the mechanism locks up: the drivers move it where no pose meets its "
    "joints; check the link lengths and the drivers' ranges",
    Status.ENERGY_DRIFT: "the energy of this conservative mechanism changed by more than "
    "solver.max_energy_error of its scale (summary.json, 'energy'): the motion has probably "
    "left its assembly branch at a singular position; with formulation 'baumgarte' try "
    "'augmented_lagrangian', or tighter tolerances",
}


def status_message(status: Status) -> str:
    """What a run status means, and what to try."""
    return _MESSAGES[status]
