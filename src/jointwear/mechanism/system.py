"""From a validated ``Model`` to the arrays the kernels run on.

``build_system`` turns names into indices and tables: the kernels never see a name or a unit.
The ``System`` is immutable for a run: the mechanism's tables, each contact element kind's
table, and the user events.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..joints import BY_NAME, KINDS
from ..kernels.codes import JOINT_ROWS, DriverKind, EventDirection
from ..kernels.loop import UserEvents
from ..model import Model
from ..model.clearance import contact_problems
from ..model.errors import ModelError
from ..model.sections import Load
from .functions import MAX_COEFFICIENTS, FunctionRows
from .pattern import build_pattern

GROUND = -1
BODY_COLUMNS = ("x", "y", "phi", "vx", "vy", "omega", "ax", "ay", "alpha")
# A load's columns (kernels.forces.write_loads): a point force's components, a torque, a
# spring-damper's force along its line, a rotational spring-damper's torque.
LOAD_QUANTITIES = {
    "point_force": ("fx", "fy"),
    "torque": ("torque",),
    "spring_damper": ("force",),
    "rotational_spring_damper": ("torque",),
    "joint_force": ("force",),
    "joint_pressure": ("pressure", "force"),
}
PROJECTION_TOLERANCE = 1e-13  # constraint norm the projections reach, of the mechanism's size


class Mechanism(NamedTuple):
    """The constrained mechanism as the kernels read it (SI). Body index -1 is the ground."""

    mass: NDArray[np.float64]  # (nb,) [kg]
    inv_mass: NDArray[np.float64]  # (3 nb,) diagonal of M^-1 [1/kg, 1/(kg m^2)]
    gravity: NDArray[np.float64]  # (2,) [m/s^2]
    joint_kind: NDArray[np.int64]  # (nj,) JointKind
    joint_body: NDArray[np.int64]  # (nj, 2)
    joint_point: NDArray[np.float64]  # (nj, 2, 2) local points [m]
    joint_axis: NDArray[np.float64]  # (nj, 2) unit axis in the first body's frame
    joint_angle0: NDArray[np.float64]  # (nj,) relative angle held by translational joints [rad]
    joint_row: NDArray[np.int64]  # (nj,) first constraint row
    joint_rows: NDArray[np.int64]  # (nj,) its number of rows (JOINT_ROWS)
    driver_kind: NDArray[np.int64]  # (nd,) DriverKind
    driver_body: NDArray[np.int64]  # (nd, 2) angle drivers: (relative_to, body)
    driver_joint: NDArray[np.int64]  # (nd,) distance drivers: translational joint index
    driver_function: NDArray[np.int64]  # (nd,) row of the function table
    driver_row: NDArray[np.int64]  # (nd,) constraint row
    function_kind: NDArray[np.int64]  # (nf,) FunctionKind
    function_param: NDArray[np.float64]  # (nf, 8)
    function_argument: NDArray[np.int64]  # (nf, 3) ArgumentKind, its driver, body or bodies
    function_geometry: NDArray[np.float64]  # (nf, 6) a slide's two points and axis [m, -]
    function_data: NDArray[np.float64]  # tables' breakpoints and coefficients, series' terms
    force_kind: NDArray[np.int64]  # (nl,) ForceKind
    force_body: NDArray[np.int64]  # (nl, 2)
    force_point: NDArray[np.float64]  # (nl, 2, 2) [m]
    force_function: NDArray[np.int64]  # (nl, 2) function rows of (fx, fy), (value, -)
    # (nl, 3): springs' stiffness, damping, free length or angle; joint loads' scale (1 or
    # the area [m^2]) and axis (first body's frame)
    force_param: NDArray[np.float64]
    baumgarte_alpha: float  # [1/s]
    baumgarte_beta: float  # [1/s]
    penalty: float  # augmented Lagrangian penalty, relative to each row's effective mass [-]
    projection_tolerance: float  # 2-norm of Phi (and Phi') the projections reach [m, rad]
    redundant: bool  # whether output rows need the least-norm multipliers (set by simulate)
    # The sparse Jacobian and the envelopes of the matrices factorised (pattern.Pattern)
    row_coord: NDArray[np.int64]
    row_order: NDArray[np.int64]
    row_first: NDArray[np.int64]
    row_ptr: NDArray[np.int64]
    row_pairs: NDArray[np.int64]
    coord_order: NDArray[np.int64]
    coord_first: NDArray[np.int64]
    coord_ptr: NDArray[np.int64]
    coord_diagonal: NDArray[np.int64]
    row_entry_pairs: NDArray[np.int64]
    open_tree: bool  # the joints close no loop (the augmented Lagrangian solves directly)


class ElementRows(NamedTuple):
    """The rows of one kind's contact elements (``kernels.elements.<kind>``: I_*, P_*)."""

    ints: NDArray[np.int64]  # (n, N_INTS)
    params: NDArray[np.float64]  # (n, N_PARAMS) [SI]
    lookups: NDArray[np.float64]  # (n, longest) each row's ``lookup``, zero-padded; (n, 0): none


class System(NamedTuple):
    """A model as arrays: the mechanism, the contact elements' rows, the user events."""

    mechanism: Mechanism
    elements: dict[str, ElementRows]  # per kind (``joints.KINDS``), its joints in file order
    events: UserEvents


def constraint_count(mechanism: Mechanism) -> int:
    """Number of constraint equations (each joint's ``JOINT_ROWS``, 1 per driver)."""
    return joint_row_count(mechanism) + mechanism.driver_kind.shape[0]


def joint_row_count(mechanism: Mechanism) -> int:
    """Number of the ideal joints' constraint equations (they come before the drivers')."""
    return int(mechanism.joint_rows.sum())


def freed_degrees_of_freedom(model: Model) -> int:
    """Degrees of freedom the clearance joints add to the ideal mechanism's."""
    return sum(kind.module.DEGREES_OF_FREEDOM * len(kind.joints(model)) for kind in KINDS)


def column_names(model: Model) -> list[str]:
    """Names of the time-series columns, in the order ``kernels.outputs.write_row`` fills."""
    before, after = _columns_around_loads(model)
    return [*before, *load_columns(model), *after]


def load_columns(model: Model) -> dict[str, str]:
    """Each time-series column of the model's loads but gravity, in file order: its quantity.

    Each load's columns are ``load_<name>_<quantity>`` (``LOAD_QUANTITIES``); a load with
    no name is named after what it acts on (``<body>_<point>`` for a point force, ``<body>``
    for a torque, ``<body 1>_<body 2>`` for a spring-damper). A name another load or column
    has already takes ``_2``, ``_3``, ...; named loads choose first.
    """
    before, after = _columns_around_loads(model)
    taken = set(before) | set(after)
    loads = [load for load in model.forces if load.type != "gravity"]
    stems: dict[int, str] = {}
    for named in (True, False):
        for i, load in enumerate(loads):
            if (load.name is not None) != named:
                continue
            base = stem = f"load_{load.name or _load_name(load)}"
            count = 1
            while stem in stems.values() or any(
                f"{stem}_{quantity}" in taken for quantity in LOAD_QUANTITIES[load.type]
            ):
                count += 1
                stem = f"{base}_{count}"
            stems[i] = stem
    return {
        f"{stems[i]}_{quantity}": quantity
        for i, load in enumerate(loads)
        for quantity in LOAD_QUANTITIES[load.type]
    }


def _load_name(load: Load) -> str:
    """A load's name from what it acts on, for a load the model leaves unnamed."""
    if load.type == "point_force":
        return f"{load.body}_{load.point}"
    if load.type == "torque":
        return load.body
    if load.type in ("joint_force", "joint_pressure"):
        return load.joint
    return "_".join(load.bodies)


def _columns_around_loads(model: Model) -> tuple[list[str], list[str]]:
    """The time-series columns before the loads' and after them."""
    before = ["time"]
    for body in model.bodies:
        before += [f"{c}_{body.name}" for c in BODY_COLUMNS]
    for driver in model.drivers:
        before.append(f"{'torque' if driver.type == 'angle' else 'force'}_{driver.name}")
    after = []
    for joint in (j for j in model.joints if j.clearance is None):
        after += [f"{joint.name}_fx", f"{joint.name}_fy"]
    for kind in KINDS:
        for joint in kind.joints(model):
            after += [f"{joint.name}_{c}" for c in kind.columns(joint)]
    after += ["energy_kinetic", "energy_potential"]
    if model.has_clearance:
        after.append("energy_contact")
    return before, [*after, "constraint_violation"]


def _size(model: Model) -> float:
    """The mechanism's size [m]: its largest point or position coordinate, at least 1 mm."""
    points = [abs(v) for b in model.bodies for p in b.points.values() for v in p]
    points += [abs(v) for p in model.ground.points.values() for v in p]
    points += [abs(v) for b in model.bodies for v in b.position]
    return max([1e-3, *points])


def _table(rows: list, shape: tuple[int, ...], dtype: type) -> NDArray:
    return np.array(rows, dtype=dtype).reshape((len(rows), *shape))


class _Poses:
    """The bodies' kernel indices and initial poses, and points in body and global frames."""

    def __init__(self, model: Model) -> None:
        self.index = {b.name: i for i, b in enumerate(model.bodies)} | {"ground": GROUND}
        self.pose = {b.name: (b.position[0], b.position[1], b.angle) for b in model.bodies}
        self.pose["ground"] = (0.0, 0.0, 0.0)
        self.points = {b.name: b.points for b in model.bodies} | {"ground": model.ground.points}

    def local(self, body: str, point: str) -> tuple[float, float]:
        """Point ``point`` of ``body`` [m] in its frame (``Model.point``, by name at once)."""
        return self.points[body][point]

    def angle(self, body: str) -> float:
        """Initial angle of ``body`` [rad]."""
        return self.pose[body][2]

    def global_point(self, body: str, point: str) -> NDArray[np.float64]:
        """Initial global position of ``point`` of ``body`` [m]."""
        x, y, phi = self.pose[body]
        c, s = np.cos(phi), np.sin(phi)
        px, py = self.local(body, point)
        if body == "ground":
            return np.array([px, py])
        return np.array([x + c * px - s * py, y + s * px + c * py])


def _joint_tables(
    model: Model, poses: _Poses, ideal: bool
) -> tuple[dict[str, list], dict[str, int], dict[str, list]]:
    """The ideal joints' table, each ideal joint's index in it, each kind's element rows.

    Constraint rows from 0; with ``ideal`` every joint is ideal, and no kind has rows.
    """
    joints = {"kind": [], "body": [], "point": [], "axis": [], "angle0": [], "row": [], "rows": []}
    kernel_index: dict[str, int] = {}
    elements: dict[str, list] = {kind.name: [] for kind in KINDS}
    row = 0
    for joint in model.joints:
        b1, b2 = joint.bodies
        angle0 = poses.angle(b2) - poses.angle(b1)
        if joint.clearance is not None and not ideal:
            kind = BY_NAME[joint.type]
            bodies = (poses.index[b1], poses.index[b2])
            elements[kind.name].append(
                (*kind.row(joint, model, bodies, angle0), kind.lookup(joint))
            )
            continue
        axis = np.array(getattr(joint, "axis", (1.0, 0.0)), dtype=float)
        kernel_index[joint.name] = len(joints["kind"])
        joints["kind"].append(int(joint.kind))
        joints["body"].append([poses.index[b1], poses.index[b2]])
        joints["point"].append([poses.local(b1, joint.points[0]), poses.local(b2, joint.points[1])])
        joints["axis"].append(axis / np.linalg.norm(axis))
        joints["angle0"].append(angle0)
        joints["row"].append(row)
        joints["rows"].append(JOINT_ROWS[joint.kind])
        row += JOINT_ROWS[joint.kind]
    return joints, kernel_index, elements


def _driver_table(
    model: Model, poses: _Poses, functions: FunctionRows, kernel_index: dict[str, int], row: int
) -> dict[str, list]:
    """The drivers' table, their constraint rows from ``row`` on."""
    drivers = {"kind": [], "body": [], "joint": [], "function": [], "row": []}
    for d, driver in enumerate(model.drivers):
        if driver.type == "angle":
            i, j = driver.relative_to, driver.body
            initial = poses.angle(j) - poses.angle(i)
            drivers["kind"].append(int(DriverKind.ANGLE))
            drivers["body"].append([poses.index[i], poses.index[j]])
            drivers["joint"].append(-1)
        else:
            joint = model.joint(driver.joint)
            b1, b2 = joint.bodies
            axis = np.array(joint.axis, dtype=float)
            c, s = np.cos(poses.angle(b1)), np.sin(poses.angle(b1))
            axis_global = np.array([c * axis[0] - s * axis[1], s * axis[0] + c * axis[1]])
            slide = poses.global_point(b2, joint.points[1]) - poses.global_point(
                b1, joint.points[0]
            )
            initial = float(slide @ axis_global / np.linalg.norm(axis))
            drivers["kind"].append(int(DriverKind.DISTANCE))
            drivers["body"].append([GROUND, GROUND])
            drivers["joint"].append(kernel_index[driver.joint])
        drivers["function"].append(
            functions.add(driver.function, f"drivers[{d}].function", initial)
        )
        drivers["row"].append(row)
        row += 1
    return drivers


def _load_table(
    model: Model, poses: _Poses, functions: FunctionRows
) -> tuple[dict[str, list], NDArray[np.float64]]:
    """The applied loads' table, and gravity [m/s^2]."""
    gravity = np.zeros(2)
    loads = {"kind": [], "body": [], "point": [], "function": [], "param": []}
    for i, force in enumerate(model.forces):
        if force.type == "gravity":
            gravity += np.asarray(force.acceleration, dtype=float)
            continue
        body_pair, point_pair = [GROUND, GROUND], [(0.0, 0.0), (0.0, 0.0)]
        param = [0.0, 0.0, 0.0]
        funcs = [functions.add(f, f"forces[{i}].{key}") for key, f in force.functions.items()]
        funcs += [-1] * (2 - len(funcs))
        if force.type == "point_force":
            body_pair[0] = poses.index[force.body]
            point_pair[0] = poses.local(force.body, force.point)
        elif force.type == "torque":
            body_pair[0] = poses.index[force.body]
        elif force.type in ("joint_force", "joint_pressure"):
            joint = model.joint(force.joint)
            body_pair = [poses.index[b] for b in joint.bodies]
            point_pair = [
                poses.local(b, p) for b, p in zip(joint.bodies, joint.points, strict=True)
            ]
            param = [getattr(force, "area", 1.0), *joint.axis]
        elif force.type == "spring_damper":
            body_pair = [poses.index[b] for b in force.bodies]
            point_pair = [
                poses.local(b, p) for b, p in zip(force.bodies, force.points, strict=True)
            ]
            param = [force.stiffness, force.damping, force.free_length]
        else:
            body_pair = [poses.index[b] for b in force.bodies]
            param = [force.stiffness, force.damping, force.free_angle]
        loads["kind"].append(int(force.kind))
        loads["body"].append(body_pair)
        loads["point"].append(point_pair)
        loads["function"].append(funcs)
        loads["param"].append(param)
    return loads, gravity


def _row_bodies(joints: dict[str, list], drivers: dict[str, list], rows: int) -> NDArray[np.int64]:
    """The two bodies of every constraint row (the Jacobian's pattern)."""
    row_bodies = np.zeros((rows, 2), dtype=np.int64)
    for first, count, pair in zip(joints["row"], joints["rows"], joints["body"], strict=True):
        row_bodies[first : first + count] = pair
    for r, kind, pair, jt in zip(
        drivers["row"], drivers["kind"], drivers["body"], drivers["joint"], strict=True
    ):
        row_bodies[r] = pair if kind == DriverKind.ANGLE else joints["body"][jt]
    return row_bodies


def _user_events(model: Model, poses: _Poses) -> UserEvents:
    coordinate = {"x": 0, "y": 1, "phi": 2}
    return UserEvents(
        body=_table([poses.index[e.body] for e in model.events], (), np.int64),
        coordinate=_table([coordinate[e.coordinate] for e in model.events], (), np.int64),
        value=_table([e.value for e in model.events], (), np.float64),
        direction=_table(
            [int(EventDirection[e.direction.upper()]) for e in model.events], (), np.int64
        ),
    )


def build_system(model: Model, *, ideal: bool = False) -> System:
    """Build the kernel arrays of ``model`` (validated, SI).

    Clearance joints become rows of their element kind's table; with ``ideal`` they are ideal
    joints instead (the assembly's "journal centred" mechanism, SPEC sec. 1). ModelError if a
    clearance joint's contact cannot be computed with its values (``contact_problems``).
    """
    problems = [] if ideal else contact_problems(model)
    if problems:
        raise ModelError(problems)
    poses = _Poses(model)
    functions = FunctionRows(model, poses.index, poses.local)
    joints, kernel_index, elements = _joint_tables(model, poses, ideal)
    first_driver_row = sum(joints["rows"])
    drivers = _driver_table(model, poses, functions, kernel_index, first_driver_row)
    loads, gravity = _load_table(model, poses, functions)
    row_bodies = _row_bodies(joints, drivers, first_driver_row + len(model.drivers))
    mass = np.array([b.mass for b in model.bodies], dtype=float)
    inertia = np.array([b.inertia for b in model.bodies], dtype=float)
    mechanism = Mechanism(
        mass=mass,
        inv_mass=1.0 / np.column_stack([mass, mass, inertia]).ravel(),
        gravity=gravity,
        joint_kind=_table(joints["kind"], (), np.int64),
        joint_body=_table(joints["body"], (2,), np.int64),
        joint_point=_table(joints["point"], (2, 2), np.float64),
        joint_axis=_table(joints["axis"], (2,), np.float64),
        joint_angle0=_table(joints["angle0"], (), np.float64),
        joint_row=_table(joints["row"], (), np.int64),
        joint_rows=_table(joints["rows"], (), np.int64),
        driver_kind=_table(drivers["kind"], (), np.int64),
        driver_body=_table(drivers["body"], (2,), np.int64),
        driver_joint=_table(drivers["joint"], (), np.int64),
        driver_function=_table(drivers["function"], (), np.int64),
        driver_row=_table(drivers["row"], (), np.int64),
        function_kind=_table(functions.kind, (), np.int64),
        function_param=_table(functions.param, (MAX_COEFFICIENTS,), np.float64),
        function_argument=_table(functions.argument, (3,), np.int64),
        function_geometry=_table(functions.geometry, (6,), np.float64),
        function_data=np.array(functions.data, dtype=np.float64),
        force_kind=_table(loads["kind"], (), np.int64),
        force_body=_table(loads["body"], (2,), np.int64),
        force_point=_table(loads["point"], (2, 2), np.float64),
        force_function=_table(loads["function"], (2,), np.int64),
        force_param=_table(loads["param"], (3,), np.float64),
        baumgarte_alpha=float(model.solver.baumgarte_alpha),
        baumgarte_beta=float(model.solver.baumgarte_beta),
        penalty=float(model.solver.penalty),
        projection_tolerance=PROJECTION_TOLERANCE * _size(model),
        redundant=False,
        **build_pattern(row_bodies, len(model.bodies))._asdict(),
    )
    problems = functions.range_problems(mechanism)
    if problems:
        raise ModelError(problems)
    return System(mechanism, _element_rows(elements), _user_events(model, poses))


def _element_rows(rows: dict[str, list]) -> dict[str, ElementRows]:
    """Each kind's rows as arrays (``KIND.row`` and ``KIND.lookup`` give one joint's)."""
    tables = {}
    for kind in KINDS:
        module = kind.module
        ints = [r[0] for r in rows[kind.name]]
        params = [r[1] for r in rows[kind.name]]
        lookups = [r[2] for r in rows[kind.name]]
        longest = max((len(lookup) for lookup in lookups), default=0)
        padded = np.zeros((len(lookups), longest))
        for i, lookup in enumerate(lookups):
            padded[i, : len(lookup)] = lookup
        tables[kind.name] = ElementRows(
            ints=_table(ints, (module.N_INTS,), np.int64),
            params=_table(params, (module.N_PARAMS,), np.float64),
            lookups=padded,
        )
    return tables


def start_problems(model: Model, y0: NDArray[np.float64]) -> list[str]:
    """One line per clearance joint that cannot start from the pose y0 (``KIND.start_problems``)."""
    index = {name: i for i, name in enumerate(model.body_names)}

    def place(body: str, point: tuple[float, float]) -> NDArray[np.float64]:
        """Global position [m] at y0 of ``point`` [m] in ``body``'s frame."""
        if body == "ground":
            return np.asarray(point, dtype=float)
        bx, by, phi = y0[3 * index[body] : 3 * index[body] + 3]
        c, s = np.cos(phi), np.sin(phi)
        return np.array([bx + c * point[0] - s * point[1], by + s * point[0] + c * point[1]])

    return [
        line
        for kind in KINDS
        for joint in kind.joints(model)
        for line in kind.start_problems(joint, model, place)
    ]


def initial_guess(model: Model) -> NDArray[np.float64]:
    """State guess (q, q') from the bodies' initial poses and velocities."""
    q = [v for b in model.bodies for v in (b.position[0], b.position[1], b.angle)]
    qd = [v for b in model.bodies for v in (b.velocity[0], b.velocity[1], b.angular_velocity)]
    return np.array(q + qd, dtype=float)
