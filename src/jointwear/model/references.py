"""References between names in a model: unique names, and every name referred to exists."""

from collections.abc import Sequence

from ..joints import BY_NAME, KINDS
from .errors import unknown
from .sections import Body, Driver, Event, Ground, Joint, Load


def reference_problems(
    ground: Ground,
    bodies: Sequence[Body],
    joints: Sequence[Joint],
    drivers: Sequence[Driver],
    forces: Sequence[Load],
    events: Sequence[Event],
) -> list[str]:
    """Check the names of a model's sections: unique, and everything referred to exists.

    Parameters
    ----------
    ground, bodies, joints, drivers, forces, events
        The sections of a model, each valid on its own (called while the model is being
        validated).

    Returns
    -------
    list of str
        One line per problem, empty if the names are consistent.
    """
    problems: list[str] = []
    named = {"bodies": bodies, "joints": joints, "drivers": drivers, "forces": forces}
    for section, items in (named | {"events": events}).items():
        first: dict[str, int] = {}
        for i, item in enumerate(items):
            if item.name in first:
                problems.append(
                    f"{section}[{i}].name: duplicate name {item.name!r}; "
                    f"{section}[{first[item.name]}] has it already"
                )
            elif item.name is not None:
                first[item.name] = i

    points = {"ground": ground.points} | {body.name: body.points for body in bodies}
    moving = list(dict.fromkeys(body.name for body in bodies))
    found = set(moving)

    def body(path: str, name: str, allow_ground: bool = True) -> bool:
        if name in found or (allow_ground and name == "ground"):
            return True
        known = ["ground", *moving] if allow_ground else moving
        problems.append(f"{path}: {unknown('body', name, known, 'bodies')}")
        return False

    def point(path: str, body_name: str, name: str) -> None:
        known = list(points[body_name])
        if name not in known:
            problems.append(f"{path}: {unknown('point', name, known, f'points of {body_name!r}')}")

    def pair(path: str, table, with_points: bool) -> None:
        found = [body(f"{path}.bodies[{k}]", name) for k, name in enumerate(table.bodies)]
        if table.bodies[0] == table.bodies[1]:
            problems.append(f"{path}.bodies: both are {table.bodies[0]!r}; give two bodies")
        for k in range(2 if with_points and all(found) else 0):
            point(f"{path}.points[{k}]", table.bodies[k], table.points[k])

    for i, joint in enumerate(joints):
        pair(f"joints[{i}]", joint, with_points=True)
    kinds = {joint.name: joint.type for joint in joints}
    sliders = [j.name for j in joints if BY_NAME[j.type].slides and j.clearance is None]
    sliding = " or ".join(kind.name for kind in KINDS if kind.slides)
    for i, driver in enumerate(drivers):
        path = f"drivers[{i}]"
        if driver.type == "angle":
            body(f"{path}.body", driver.body, allow_ground=False)
            body(f"{path}.relative_to", driver.relative_to)
            if driver.body == driver.relative_to:
                problems.append(f"{path}.relative_to: is the driven body; give another body")
        elif driver.joint not in kinds:
            problems.append(
                f"{path}.joint: {unknown('joint', driver.joint, list(kinds), 'joints')}"
            )
        elif driver.joint not in sliders:
            kind = kinds[driver.joint]
            kind += " with clearance" if BY_NAME[kind].slides else ""
            problems.append(
                f"{path}.joint: {driver.joint!r} is {kind}; a distance driver needs an ideal "
                f"{sliding} joint ({', '.join(sliders) or 'there are none'})"
            )
    for i, force in enumerate(forces):
        path = f"forces[{i}]"
        if force.type == "point_force" and body(f"{path}.body", force.body, allow_ground=False):
            point(f"{path}.point", force.body, force.point)
        elif force.type == "torque":
            body(f"{path}.body", force.body, allow_ground=False)
        elif force.type in ("spring_damper", "rotational_spring_damper"):
            pair(path, force, with_points=force.type == "spring_damper")
        elif force.type in ("joint_force", "joint_pressure") and force.joint not in kinds:
            problems.append(f"{path}.joint: {unknown('joint', force.joint, list(kinds), 'joints')}")
        elif (
            force.type in ("joint_force", "joint_pressure")
            and not BY_NAME[kinds[force.joint]].slides
        ):
            along = [j.name for j in joints if BY_NAME[j.type].slides]
            problems.append(
                f"{path}.joint: {force.joint!r} is {kinds[force.joint]}; a {force.type} acts "
                f"along a {sliding} joint's axis ({', '.join(along) or 'there are none'})"
            )
    for i, event in enumerate(events):
        body(f"events[{i}].body", event.body, allow_ground=False)
    return problems
