"""Model dicts of planar linkages made of uniform bars, for ``jointwear.model.parse_model``.

Every bar is a uniform slender body of mass m and length l: centre of mass at its middle,
inertia m l^2 / 12 about it, body x axis along the bar, points ``a`` (-l/2, 0) and ``b``
(l/2, 0) at its ends. Poses and velocities are given exactly (consistent with the joints), so
assembly keeps them.
"""

import math

G = 9.81  # [m/s^2]
GRAVITY = {"type": "gravity", "acceleration": [0.0, -G]}

# Where each crank of a parallelogram sits, as a fraction of the ground link's length: on the
# ground from the origin along +x, and on the coupler from its left end.
CRANK_SITES = {"left": 0.0, "right": 1.0, "middle": 0.5}


def bar(name, mass, length, start, angle, omega=0.0, start_velocity=(0.0, 0.0)) -> dict:
    """A uniform bar with end ``a`` at ``start`` and moving at ``start_velocity``."""
    c, s = math.cos(angle), math.sin(angle)
    half = 0.5 * length
    return {
        "name": name,
        "mass": mass,
        "inertia": mass * length**2 / 12.0,
        "position": [start[0] + half * c, start[1] + half * s],
        "angle": angle,
        "velocity": [start_velocity[0] - half * omega * s, start_velocity[1] + half * omega * c],
        "angular_velocity": omega,
        "points": {"a": [-half, 0.0], "b": [half, 0.0]},
    }


def pin(name: str, bodies: tuple[str, str], points: tuple[str, str]) -> dict:
    """An ideal revolute joint."""
    return {"name": name, "type": "revolute", "bodies": list(bodies), "points": list(points)}


def parallelogram(cranks, ground_length, crank_length, crank_mass, coupler_mass, angle, omega,
                  solver: dict) -> dict:  # fmt: skip
    """Parallel cranks between the ground and a coupler as long as the ground link, gravity.

    One crank per name in ``cranks`` (keys of ``CRANK_SITES``), all at ``angle`` turning at
    ``omega``; the coupler starts level and translating. Bodies ``crank_<site>`` and
    ``coupler``; joints ``ground_<site>`` (ground, crank: its columns are the force on the
    crank) and ``<site>_coupler`` (crank, coupler: the force on the coupler).
    """
    c, s = math.cos(angle), math.sin(angle)
    tip = (crank_length * c, crank_length * s)
    tip_velocity = (-crank_length * omega * s, crank_length * omega * c)
    ground = {site: [CRANK_SITES[site] * ground_length, 0.0] for site in cranks}
    bodies = [
        bar(f"crank_{site}", crank_mass, crank_length, ground[site], angle, omega)
        for site in cranks
    ]
    coupler = bar("coupler", coupler_mass, ground_length, tip, 0.0, 0.0, tip_velocity)
    for site in cranks:
        coupler["points"][site] = [(CRANK_SITES[site] - 0.5) * ground_length, 0.0]
    joints = [pin(f"ground_{site}", ("ground", f"crank_{site}"), (site, "a")) for site in cranks]
    joints += [pin(f"{site}_coupler", (f"crank_{site}", "coupler"), ("b", site)) for site in cranks]
    return {
        "ground": {"points": ground},
        "bodies": [*bodies, coupler],
        "joints": joints,
        "forces": [GRAVITY],
        "solver": solver,
    }


def chain(n: int, length: float, mass: float, angle: float, solver: dict) -> dict:
    """``n`` bars ``bar1`` ... ``bar<n>`` pinned end to end, the first to the ground at the
    origin (joints ``j1`` ... ``j<n>``); straight at ``angle``, at rest, under gravity."""
    c, s = math.cos(angle), math.sin(angle)
    bodies = [
        bar(f"bar{k + 1}", mass, length, (k * length * c, k * length * s), angle) for k in range(n)
    ]
    joints = [pin("j1", ("ground", "bar1"), ("origin", "a"))]
    joints += [pin(f"j{k + 1}", (f"bar{k}", f"bar{k + 1}"), ("b", "a")) for k in range(1, n)]
    return {
        "ground": {"points": {"origin": [0.0, 0.0]}},
        "bodies": bodies,
        "joints": joints,
        "forces": [GRAVITY],
        "solver": solver,
    }


def rotor(*torques: object, inertia: float = 0.01, omega: float = 0.0, solver: dict) -> dict:
    """A disc on a pin at its centre, without gravity, under torques (model-file values)."""
    return {
        "name": "rotor",
        "ground": {"points": {"o": [0.0, 0.0]}},
        "bodies": [{"name": "disc", "mass": 1.0, "inertia": inertia, "position": [0.0, 0.0],
                    "angle": 0.0, "angular_velocity": omega, "points": {"c": [0.0, 0.0]}}],
        "joints": [pin("pin", ("ground", "disc"), ("o", "c"))],
        "forces": [{"type": "torque", "name": f"torque{i}", "body": "disc", "torque": torque}
                   for i, torque in enumerate(torques)],
        "solver": solver,
    }  # fmt: skip
