"""The sections of a model file: ground, bodies, joints, drivers, forces, solver, events.

Each is a ``Table`` whose quantities are converted to SI floats as it is validated; the
``Model`` (``schema``) holds them and checks the names they refer to (``references``).
"""

import math
from typing import Annotated, ClassVar, Literal, Union

from annotated_types import Ge, Gt, Le
from pydantic import Field, Strict, ValidationInfo, field_validator, model_validator

from ..joints import KINDS
from ..kernels.codes import DriverKind, ForceKind, Formulation, Method
from ..units import (
    Acceleration2,
    Angle,
    AngularSpeed,
    Area,
    Damping,
    Inertia,
    Length,
    Mass,
    RotationalDamping,
    RotationalStiffness,
    Stiffness,
    Time,
    Vector2,
    Velocity2,
    to_si,
)
from .functions import AngleFunction, DistanceFunction, ForceValue, PressureValue, TorqueValue
from .tables import Name, Number, Table, one_of

INTEGRATORS: dict[str, Method] = {"dopri5": Method.DOPRI5, "abm": Method.ABM}
FORMULATIONS: dict[str, Formulation] = {
    "baumgarte": Formulation.BAUMGARTE,
    "augmented_lagrangian": Formulation.AUGMENTED_LAGRANGIAN,
}
MAX_OUTPUT_ROWS = 5e7  # about 16 GB of time series for a small mechanism
MAX_WEAR_SNAPSHOTS = 10_000  # each holds every sector of every clearance joint


# Ground, bodies, joints, drivers -----------------------------------------------------------


class Ground(Table):
    """Fixed points of the ground, named by ``"ground"`` in joints.

    Attributes
    ----------
    points
        Name -> (x, y) [m], global coordinates.
    """

    points: dict[Name, Vector2] = Field(default_factory=dict)


class Body(Table):
    """A moving rigid body; `position`, `angle` and velocities are initial guesses.

    Attributes
    ----------
    name
        Its name (letters, digits and _, starting with a letter; not ``"ground"``).
    mass
        Mass [kg].
    inertia
        Moment of inertia about the centre of mass [kg m^2].
    position
        (x, y) of the centre of mass [m], global; the assembly refines it.
    angle
        Angle of the body's x axis from the global x axis [rad].
    velocity
        (vx, vy) of the centre of mass [m/s].
    angular_velocity
        Angular velocity [rad/s], counter-clockwise positive.
    points
        Name -> (x, y) [m] in the body's frame (origin at the centre of mass).
    """

    name: Name
    # Bounds far outside any machine part, inside what 1/m and m v^2 keep finite.
    mass: Annotated[Mass, Ge(1e-20), Le(1e20)]
    inertia: Annotated[Inertia, Ge(1e-30), Le(1e30)]
    position: Vector2
    angle: Angle
    velocity: Velocity2 = (0.0, 0.0)
    angular_velocity: AngularSpeed = 0.0
    points: dict[Name, Vector2] = Field(default_factory=dict)


class AngleDriver(Table):
    """Prescribes the angle of `body` relative to `relative_to` [rad].

    Attributes
    ----------
    name
        The driver's name (its reaction torque is the column ``torque_<name>``).
    body
        The driven body.
    relative_to
        The body its angle is measured from (``"ground"``: the global x axis).
    function
        The angle [rad] as a function of time [s]: a ``ConstantSpeed`` (speed [rad/s],
        ``initial`` [rad]), a ``Polynomial`` or a ``Harmonic``.
    """

    kind: ClassVar = DriverKind.ANGLE
    type: Literal["angle"] = "angle"
    name: Name
    body: str
    relative_to: str = "ground"
    function: AngleFunction


class DistanceDriver(Table):
    """Prescribes the slide of translational joint `joint` [m].

    Attributes
    ----------
    name
        The driver's name (its reaction force is the column ``force_<name>``).
    joint
        The ideal translational or pin-in-slot joint whose slide it sets.
    function
        The slide [m] as a function of time [s]: a ``ConstantSpeed`` (speed [m/s],
        ``initial`` [m]), a ``Polynomial`` or a ``Harmonic``.
    """

    kind: ClassVar = DriverKind.DISTANCE
    type: Literal["distance"] = "distance"
    name: Name
    joint: str
    function: DistanceFunction


# Forces, solver, events ---------------------------------------------------------------------


MAX_GRAVITY = 1e7  # [m/s^2] a million g


class LoadTable(Table):
    """An applied load: whether it does work from outside, and its functions by key."""

    does_work: ClassVar[bool] = False
    FUNCTION_KEYS: ClassVar[tuple[str, ...]] = ()  # its keys whose values may be functions

    @property
    def functions(self) -> dict[str, object]:
        """Its values that may be functions (a constant, or a function table), by key path."""
        found = {}
        for key in self.FUNCTION_KEYS:
            value = getattr(self, key)
            if isinstance(value, tuple):
                found |= {f"{key}[{i}]": item for i, item in enumerate(value)}
            else:
                found[key] = value
        return found


class Gravity(LoadTable):
    """Uniform gravitational acceleration on every body.

    Attributes
    ----------
    acceleration
        (ax, ay) [m/s^2], global, e.g. ``(0.0, "-9.81 m/s^2")``.
    name
        An optional name.
    """

    type: Literal["gravity"] = "gravity"
    name: Name | None = None
    acceleration: Acceleration2

    @model_validator(mode="after")
    def _plausible(self) -> "Gravity":
        size = math.hypot(*self.acceleration)
        if size > MAX_GRAVITY:
            raise ValueError(
                f"acceleration: {size:.3g} m/s^2 is beyond any field a machine runs in (at "
                f"most {MAX_GRAVITY:g} m/s^2, a million g); check its units"
            )
        return self


class PointForce(LoadTable):
    """Force at a named point of a body.

    Attributes
    ----------
    body, point
        The body and one of its points.
    force
        (Fx, Fy) [N], global; each a constant or a function (a ``Polynomial`` or ``Harmonic``
        of time, a ``Table`` or ``Fourier`` series of its argument).
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.POINT_FORCE
    does_work: ClassVar[bool] = True
    FUNCTION_KEYS: ClassVar[tuple[str, ...]] = ("force",)
    type: Literal["point_force"] = "point_force"
    name: Name | None = None
    body: str
    point: str
    force: tuple[ForceValue, ForceValue]


class AppliedTorque(LoadTable):
    """Torque on a body, counter-clockwise positive.

    Attributes
    ----------
    body
        The body.
    torque
        [N m], a constant or a function (a ``Polynomial`` or ``Harmonic`` of time, a
        ``Table`` or ``Fourier`` series of its argument: a motor's torque-speed curve).
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.TORQUE
    does_work: ClassVar[bool] = True
    FUNCTION_KEYS: ClassVar[tuple[str, ...]] = ("torque",)
    type: Literal["torque"] = "torque"
    name: Name | None = None
    body: str
    torque: TorqueValue


class JointForce(LoadTable):
    """Force along a joint's axis between its two bodies (a joint that slides).

    Positive pushes the second body along the axis (the slide grows) and the first body back,
    both at the second body's joint point: a gas spring, a damper curve, an actuator.

    Attributes
    ----------
    joint
        A translational or pin-in-slot joint, ideal or with clearance.
    force
        [N], a constant or a function (e.g. a ``Table`` of ``"<joint>.slide"``).
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.JOINT_FORCE
    does_work: ClassVar[bool] = True
    FUNCTION_KEYS: ClassVar[tuple[str, ...]] = ("force",)
    type: Literal["joint_force"] = "joint_force"
    name: Name | None = None
    joint: str
    force: ForceValue


class JointPressure(LoadTable):
    """A pressure on an area, acting as a ``JointForce`` of pressure times area.

    The gas force on a piston (its crown's area), the oil force in a hydraulic cylinder.

    Attributes
    ----------
    joint
        A translational or pin-in-slot joint, ideal or with clearance.
    area
        [m^2], > 0.
    pressure
        [Pa], a constant or a function (e.g. a ``Table`` of the crank's driver over 720 deg).
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.JOINT_PRESSURE
    does_work: ClassVar[bool] = True
    FUNCTION_KEYS: ClassVar[tuple[str, ...]] = ("pressure",)
    type: Literal["joint_pressure"] = "joint_pressure"
    name: Name | None = None
    joint: str
    area: Annotated[Area, Gt(0)]
    pressure: PressureValue


class SpringDamper(LoadTable):
    """Translational spring-damper along the line between two points.

    Attributes
    ----------
    bodies, points
        The two bodies (``"ground"`` allowed) and a point of each.
    stiffness
        [N/m], >= 0.
    damping
        [N s/m], >= 0.
    free_length
        Length at which the spring carries no force [m].
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.SPRING_DAMPER
    type: Literal["spring_damper"] = "spring_damper"
    name: Name | None = None
    bodies: tuple[str, str]
    points: tuple[str, str]
    stiffness: Annotated[Stiffness, Ge(0)]
    damping: Annotated[Damping, Ge(0)] = 0.0
    free_length: Annotated[Length, Ge(0)]


class RotationalSpringDamper(LoadTable):
    """Rotational spring-damper on the relative angle phi_2 - phi_1.

    Attributes
    ----------
    bodies
        The two bodies (``"ground"`` allowed).
    stiffness
        [N m/rad], >= 0.
    damping
        [N m s/rad], >= 0.
    free_angle
        Relative angle at which the spring carries no torque [rad].
    name
        An optional name, for its result columns.
    """

    kind: ClassVar = ForceKind.ROTATIONAL_SPRING_DAMPER
    type: Literal["rotational_spring_damper"] = "rotational_spring_damper"
    name: Name | None = None
    bodies: tuple[str, str]
    stiffness: Annotated[RotationalStiffness, Ge(0)]
    damping: Annotated[RotationalDamping, Ge(0)] = 0.0
    free_angle: Angle = 0.0


Joint = Annotated[Union[tuple(kind.schema for kind in KINDS)], Field(discriminator="type")]  # noqa: UP007
Driver = Annotated[AngleDriver | DistanceDriver, Field(discriminator="type")]
Load = Annotated[
    Gravity
    | PointForce
    | AppliedTorque
    | JointForce
    | JointPressure
    | SpringDamper
    | RotationalSpringDamper,
    Field(discriminator="type"),
]
# Solver times: above the resolution of float times near 1 s, and below 30,000 years.
SolverTime = Annotated[Time, Ge(1e-15), Le(1e12)]


class Solver(Table):
    """Integration and output settings (docs/model-format.md, ``solver``).

    Attributes
    ----------
    integrator
        ``"abm"`` (Adams-Bashforth-Moulton) or ``"dopri5"`` (Dormand-Prince 5(4)).
    rtol, atol
        Relative [-] and absolute tolerances of the integrator.
    min_step, max_step, initial_step
        Step sizes [s].
    formulation
        ``"augmented_lagrangian"`` or ``"baumgarte"``: how constraints are met.
    penalty
        Augmented Lagrangian penalty [-], relative to each constraint's effective mass.
    baumgarte_alpha, baumgarte_beta
        Baumgarte's terms [1/s].
    max_constraint_violation
        2-norm of the position constraints [m and rad] that stops a run.
    max_energy_error
        Energy change of a conservative mechanism [-, of its energy scale] that stops a run.
    output_interval
        Time between output rows [s].
    wear_snapshot_interval
        Time between wear snapshots [s]; None: t_end / 5.
    t_end
        End time [s].
    max_steps
        Safety limit on steps.
    assembly_tolerance
        Tolerance of the position analysis [m].
    settle_cycles, settle_time
        Start-up left out of the steady-state figures, in cycles [-] or seconds [s]; give at
        most one (None: the default settling).
    """

    integrator: Annotated[str, one_of(INTEGRATORS, "integrator")] = "abm"
    rtol: Annotated[Number, Gt(0)] = 1e-6
    atol: Annotated[Number, Gt(0)] = 1e-8
    min_step: SolverTime = 1e-12
    max_step: SolverTime = 1e-3
    initial_step: SolverTime = 1e-6
    formulation: Annotated[str, one_of(FORMULATIONS, "formulation")] = "augmented_lagrangian"
    penalty: Annotated[Number, Ge(1), Le(1e9)] = 1e6
    baumgarte_alpha: Annotated[Number, Ge(0)] = 5.0
    baumgarte_beta: Annotated[Number, Ge(0)] = 5.0
    max_constraint_violation: Annotated[Number, Gt(0)] = 1e-3
    max_energy_error: Annotated[Number, Gt(0)] = 1e-3
    output_interval: SolverTime = 1e-4
    wear_snapshot_interval: SolverTime | None = None  # default: a fifth of t_end
    t_end: SolverTime = 1.0
    max_steps: Annotated[int, Strict(), Gt(0), Le(2**62)] = 10_000_000
    assembly_tolerance: Annotated[Length, Gt(0)] = 1e-10
    settle_cycles: Annotated[Number, Ge(0), Le(1e15)] | None = None  # default: see settling
    settle_time: Annotated[Time, Ge(0), Le(1e12)] | None = None

    @model_validator(mode="after")
    def _steps_in_order(self) -> "Solver":
        if not self.min_step <= self.initial_step <= self.max_step:
            raise ValueError(
                f"min_step {self.min_step:g}, initial_step {self.initial_step:g}, max_step "
                f"{self.max_step:g} [s] are out of order; need min_step <= initial_step <= max_step"
            )
        snapshots = self.t_end / (self.wear_snapshot_interval or self.t_end)
        if snapshots > MAX_WEAR_SNAPSHOTS:
            raise ValueError(
                f"t_end / wear_snapshot_interval asks for {snapshots:.3g} wear snapshots; at "
                f"most {MAX_WEAR_SNAPSHOTS} are allowed; raise wear_snapshot_interval"
            )
        if self.settle_cycles is not None and self.settle_time is not None:
            raise ValueError(
                "settle_cycles and settle_time both given; give one: the start-up left out "
                "of the steady-state figures, in driver cycles or in seconds"
            )
        if self.settle_time is not None and self.settle_time >= self.t_end:
            raise ValueError(
                f"settle_time {self.settle_time:g} s leaves nothing of the run (t_end "
                f"{self.t_end:g} s) for the steady state; need settle_time < t_end"
            )
        rows = self.t_end / self.output_interval
        if rows > MAX_OUTPUT_ROWS:
            raise ValueError(
                f"t_end / output_interval asks for {rows:.3g} output rows; at most "
                f"{MAX_OUTPUT_ROWS:.0e} are allowed; raise output_interval"
            )
        return self

    @property
    def method(self) -> Method:
        """Integrator code for the kernels."""
        return INTEGRATORS[self.integrator]


class Event(Table):
    """Crossing of a body's x or y [m] or phi [rad] through `value`.

    Attributes
    ----------
    name
        The event's name.
    body
        The body whose coordinate is watched.
    coordinate
        ``"x"``, ``"y"`` (its centre of mass [m]) or ``"phi"`` (its angle [rad]).
    value
        The level crossed [m or rad].
    direction
        ``"rising"``, ``"falling"`` or ``"any"``.
    """

    name: Name
    body: str
    coordinate: Literal["x", "y", "phi"]
    value: float
    direction: Literal["rising", "falling", "any"] = "any"

    @field_validator("value", mode="before")
    @classmethod
    def _value_units(cls, value: object, info: ValidationInfo) -> float:
        if "coordinate" not in info.data:
            return 0.0  # the coordinate is invalid and reported; its value cannot be judged
        return to_si(value, "[]" if info.data["coordinate"] == "phi" else "[length]")
