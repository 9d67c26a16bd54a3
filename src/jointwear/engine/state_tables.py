"""Tables of the mechanism's state that a run may leave: what to tell when it stops there.

A table without a period is NaN outside its points (``kernels.functions``): when its argument
is a state quantity, only the run finds out, and it stops as non-finite. ``left_tables``
names each such table with its points' range and the argument's value at the last finite
state, so the message says which table the motion ran out of.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from ..kernels.codes import ArgumentKind
from ..model import Model
from ..model.arguments import resolve
from ..model.functions import TableFunction


def left_tables(model: Model, y: NDArray[np.float64], certain: bool = True) -> str:
    """The state tables without a period, their ranges, and their arguments at state y [SI].

    ``certain``: the run stopped as non-finite; else (singular: a NaN load makes the
    constraints' solve fail as well) the tables are named as a possible cause.
    """
    n = y.shape[0] // 2
    q, qd = y[:n], y[n:]
    found = []
    for i, force in enumerate(model.forces):
        for key, function in force.functions.items():
            if not isinstance(function, TableFunction) or function.period is not None:
                continue
            argument = resolve(function.argument, model.drivers, model.bodies, model.joints)
            if argument.kind in (ArgumentKind.TIME, ArgumentKind.DRIVER):
                continue  # checked before the run
            value = _state_value(model, argument, q, qd)
            found.append(
                f"forces[{i}].{key} is a table of {function.argument} from {function.x[0]:.6g} "
                f"to {function.x[-1]:.6g} (SI) without a period, and {function.argument} was "
                f"{value:.6g} at the last finite state"
            )
    if not found:
        return ""
    lead = "; " if certain else "; or a table of the state was left: "
    return (
        f"{lead}{'; '.join(found)}: a run stops where it leaves a table's points; give points "
        "that cover the motion"
    )


def _state_value(model: Model, argument, q: NDArray, qd: NDArray) -> float:
    """A body's angle or angular speed, or a joint's slide or slide speed, at (q, qd) [SI]."""
    index = {body.name: b for b, body in enumerate(model.bodies)}
    if argument.kind in (ArgumentKind.ANGLE, ArgumentKind.ANGULAR_SPEED):
        b = 3 * index[argument.name] + 2
        return float(q[b] if argument.kind == ArgumentKind.ANGLE else qd[b])
    joint = model.joint(argument.name)
    ends = []
    for body, point in zip(joint.bodies, joint.points, strict=True):
        local = model.point(body, point)
        if body == "ground":
            ends.append((np.array(local), np.zeros(2), 0.0, 0.0))
            continue
        b = 3 * index[body]
        c, s = math.cos(q[b + 2]), math.sin(q[b + 2])
        arm = np.array([c * local[0] - s * local[1], s * local[0] + c * local[1]])
        w = qd[b + 2]
        velocity = qd[b : b + 2] + w * np.array([-arm[1], arm[0]])
        ends.append((q[b : b + 2] + arm, velocity, q[b + 2], w))
    (p1, v1, phi1, w1), (p2, v2, _, _) = ends
    c, s = math.cos(phi1), math.sin(phi1)
    u = np.array([c * joint.axis[0] - s * joint.axis[1], s * joint.axis[0] + c * joint.axis[1]])
    d = p2 - p1
    if argument.kind == ArgumentKind.SLIDE:
        return float(d @ u)
    return float((v2 - v1) @ u + w1 * (d[1] * u[0] - d[0] * u[1]))
