"""Integer codes shared by the kernels and the Python API.

The kernels see a joint kind, a driver or a load only as one of these integers; ``model.py``
maps the model file's names onto them. Law codes live with their laws (``kernels.laws``).
"""

from enum import IntEnum


class JointKind(IntEnum):
    """Kinds of ideal kinematic joints (rows of the constraint table)."""

    REVOLUTE = 0  # the two points coincide
    TRANSLATIONAL = 1  # relative angle fixed, the second point on the first body's line
    POINT_ON_LINE = 2  # the second point on the first body's line


JOINT_ROWS = (2, 2, 1)  # constraint equations of each JointKind, in code order


class DriverKind(IntEnum):
    """What a driving constraint prescribes as a function of time."""

    ANGLE = 0  # phi_j - phi_i = f(t); i may be the ground
    DISTANCE = 1  # slide of a translational joint along its axis = f(t)


class FunctionKind(IntEnum):
    """Functions f(x) used by drivers and applied loads (``kernels.functions``)."""

    POLYNOMIAL = 0  # sum_k c_k x^k
    HARMONIC = 1  # offset + amplitude * sin(omega x + phase)
    SPLINE = 2  # a piecewise cubic on breakpoints, periodic or not (a table)
    FOURIER = 3  # mean + sum_k a_k cos(k omega x) + b_k sin(k omega x)


class ArgumentKind(IntEnum):
    """What a function's argument x is (``kernels.functions.argument``)."""

    TIME = 0  # t [s]
    DRIVER = 1  # the value a driver prescribes at t [rad or m]
    ANGLE = 2  # a body's angle [rad]
    ANGULAR_SPEED = 3  # a body's angular speed [rad/s]
    SLIDE = 4  # a joint's slide along its axis [m]
    SLIDE_SPEED = 5  # its rate [m/s]


class ForceKind(IntEnum):
    """Applied loads."""

    POINT_FORCE = 0
    TORQUE = 1
    SPRING_DAMPER = 2
    ROTATIONAL_SPRING_DAMPER = 3
    JOINT_FORCE = 4  # along a joint's axis between its two bodies
    JOINT_PRESSURE = 5  # a pressure times an area, along a joint's axis


class Method(IntEnum):
    """Integrators (``kernels.integrate``): an explicit Runge-Kutta tableau, or Adams."""

    DOPRI5 = 0
    ABM = 1


class Status(IntEnum):
    """Outcome of a chunk of integration (``loop.advance``) or of a whole run."""

    RUNNING = 0  # chunk ended at its stop time; the run goes on
    SUCCESS = 1  # the end time was reached
    NON_FINITE = 3  # codes stay stable: compiled kernels hold them as constants
    SINGULAR = 4
    MAX_STEPS = 5
    INTERRUPTED = 6
    CONSTRAINT_DRIFT = 7  # the constraints drifted past solver.max_constraint_violation
    ENERGY_DRIFT = 8  # a conservative mechanism's energy changed past solver.max_energy_error
    LOCK_UP = 9  # the drivers move the mechanism where no pose meets its joints (lockup.py)


class Formulation(IntEnum):
    """How the right-hand side meets the constraints (``kernels.dynamics``)."""

    BAUMGARTE = 0  # the paper's Eq. (7): Lagrange multipliers with Baumgarte stabilisation
    AUGMENTED_LAGRANGIAN = 1  # index-1 augmented Lagrangian with mass-orthogonal projections


class EventDirection(IntEnum):
    """Which sign changes of an event function count."""

    ANY = 0
    RISING = 1
    FALLING = 2


class Counter(IntEnum):
    """Slots of the run-statistics counter array carried in the loop state."""

    ACCEPTED = 0
    REJECTED = 1
    RHS_EVALS = 2
    MIN_STEP_HITS = 3
    OUTPUT_ROWS = 4
    EVENTS = 5
    IMPACTS = 6  # contact onsets logged in this chunk
    SNAPSHOTS = 7  # wear snapshots taken so far


N_COUNTERS = len(Counter)
