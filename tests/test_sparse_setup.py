"""The sparse set-up against dense LAPACK: rank, dependent rows, minimum-norm solves (issue 32).

Random mechanisms (``random_mechanism``): bodies at random poses, revolute and translational
joints between random pairs of bodies and the ground placed where they hold (so the start is
assembled), some angle drivers, some joints doubled (redundant), and with ``collinear`` the
joints' points drawn from five points on the x axis (loops at dead centre: singular). The
references are computed here from numpy's SVD and lstsq of the whole dense Jacobian, as the
set-up did before issue 32 for every size.
"""

import itertools
import math
import signal
import threading
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from mechanisms import bar, chain, parallelogram, pin

import jointwear as jw
from jointwear.mechanism import jacobian as jacobian_module
from jointwear.mechanism.assembly import assemble
from jointwear.mechanism.background import off_main_thread
from jointwear.mechanism.blocks import row_blocks
from jointwear.mechanism.jacobian import evaluate
from jointwear.mechanism.least_norm import sparse_least_norm
from jointwear.mechanism.rank import block_dependence, dependence
from jointwear.mechanism.system import build_system, initial_guess
from jointwear.model import parse_model

RANK_TOLERANCE, INVOLVED = 1e-9, 1e-6  # the set-up's rule, restated for the reference


def random_mechanism(seed: int, collinear: float = 0.0) -> dict:
    """A random assembled mechanism of 1 to 6 bodies (module docstring)."""
    rng = np.random.default_rng(seed)
    bodies = int(rng.integers(1, 7))
    names = [f"b{k}" for k in range(bodies)]
    poses = [(*rng.uniform(-2.0, 2.0, 2), rng.uniform(-3.0, 3.0)) for _ in range(bodies)]
    points: list[dict] = [{} for _ in range(bodies)]
    ground: dict = {}

    def point_at(body: int, where: np.ndarray) -> str:
        """A new point of ``body`` (-1: the ground) at the global position ``where``."""
        if body < 0:
            ground[f"g{len(ground)}"] = [float(v) for v in where]
            return f"g{len(ground) - 1}"
        x, y, angle = poses[body]
        c, s = math.cos(angle), math.sin(angle)
        dx, dy = where[0] - x, where[1] - y
        points[body][f"p{len(points[body])}"] = [c * dx + s * dy, -s * dx + c * dy]
        return f"p{len(points[body]) - 1}"

    def spot() -> np.ndarray:
        if rng.random() < collinear:
            return np.array([float(rng.integers(-2, 3)), 0.0])
        return rng.uniform(-2.0, 2.0, 2)

    joints = []
    for k in range(int(rng.integers(0, 2 * bodies + 2))):
        a, b = (int(v) for v in rng.choice(np.arange(-1, bodies), size=2, replace=False))
        pair = ["ground" if a < 0 else names[a], "ground" if b < 0 else names[b]]
        where = spot()
        if rng.random() < 0.7:
            joint = pin(f"j{k}", pair, (point_at(a, where), point_at(b, where)))
        else:  # the second point on the first's line, along the axis
            theta = rng.uniform(-3.0, 3.0)
            along = where + rng.uniform(-1.0, 1.0) * np.array([math.cos(theta), math.sin(theta)])
            frame = 0.0 if a < 0 else poses[a][2]
            joint = {"name": f"j{k}", "type": "translational", "bodies": pair,
                     "points": [point_at(a, where), point_at(b, along)],
                     "axis": [math.cos(theta - frame), math.sin(theta - frame)]}  # fmt: skip
        joints.append(joint)
        if rng.random() < 0.2:
            joints.append({**joint, "name": f"j{k}_again"})
    drivers = []
    for k in range(int(rng.integers(0, 3))):
        body, other = int(rng.integers(bodies)), int(rng.integers(-1, bodies))
        drivers.append({"name": f"d{k}", "type": "angle", "body": names[body],
                        "relative_to": "ground" if other in (-1, body) else names[other],
                        "function": {"type": "constant_speed", "speed": 1.0}})  # fmt: skip
    tables = [
        {"name": names[k], "mass": 1.0, "inertia": 0.1, "position": [float(x), float(y)],
         "angle": float(angle), "points": points[k] or {"c": [0.0, 0.0]}}
        for k, (x, y, angle) in enumerate(poses)
    ]  # fmt: skip
    return {
        "ground": {"points": ground or {"o": [0.0, 0.0]}},
        "bodies": tables,
        "joints": joints,
        "drivers": drivers,
    }


def start_jacobian(data: dict):
    """Phi_q of the model ``data`` at its initial pose."""
    model = parse_model(data)
    y = initial_guess(model)
    n = y.shape[0] // 2
    return evaluate(build_system(model, ideal=True), y[:n], y[n:])[1]


def reference(matrix: np.ndarray) -> tuple[int, list[bool]]:
    """Rank and the rows in the left null space, from the SVD of the whole matrix."""
    u, sv, _ = np.linalg.svd(matrix)
    tolerance = RANK_TOLERANCE * max(1.0, sv[0] if sv.size else 1.0)
    null = np.concatenate([sv, np.zeros(matrix.shape[0] - sv.size)]) <= tolerance
    return int((sv > tolerance).sum()), (np.abs(u[:, null]).sum(axis=1) > INVOLVED).tolist()


# ----- rank and dependent rows ---------------------------------------------------------------


def test_block_rank_is_the_whole_svds_on_random_mechanisms():
    deficient = full = 0
    for seed in range(400):
        cq = start_jacobian(random_mechanism(seed, collinear=0.3 if seed % 2 else 0.0))
        if cq.rows == 0:
            continue
        found = block_dependence(cq)
        assert (found.rank, found.involved.tolist()) == reference(cq.dense()), seed
        deficient += found.rank < cq.rows
        full += found.rank == cq.rows
    assert deficient > 200 and full > 50, (deficient, full)  # both kinds well sampled


@pytest.mark.parametrize(
    ("name", "cranks", "angle", "rank"),
    [
        ("parallelogram", ("left", "right"), 0.25 * math.pi, 8),
        ("flat parallelogram (singular)", ("left", "right"), 0.0, 7),
        ("double parallelogram (redundant)", ("left", "right", "middle"), 0.25 * math.pi, 11),
    ],
)
def test_block_rank_of_the_parallelograms(name, cranks, angle, rank):
    # Ranks known exactly: 8 independent equations for one degree of freedom in 9
    # coordinates; at the flat position one more degree (the anti-parallelogram's branch);
    # the third crank's two equations add one more constraint only.
    cq = start_jacobian(parallelogram(cranks, 1.0, 0.3, 1.0, 2.0, angle, 0.0, {}))
    found = block_dependence(cq)
    assert found.rank == rank == reference(cq.dense())[0]
    assert found.involved.tolist() == reference(cq.dense())[1]


def test_a_long_chain_with_loops_and_a_doubled_pin():
    # 60 bars (180 coordinates: the sparse set-up's size) pinned end to end in a straight
    # line; bars 10 and 30 also pinned to the ground where their ends are, closing two
    # straight loops, each at dead centre (one dependence each); pin 45 doubled (two more):
    # rank 122 of 126 equations, the loops' pins and the doubled pin's involved, not the rest.
    data = chain(60, 0.1, 0.1, -0.5, {})
    for k in (10, 30):
        end = [0.1 * k * math.cos(-0.5), 0.1 * k * math.sin(-0.5)]
        data["ground"]["points"][f"at{k}"] = end
        data["joints"].append(pin(f"ground{k}", ("ground", f"bar{k}"), (f"at{k}", "b")))
    data["joints"].append({**data["joints"][44], "name": "j45_again"})
    cq = start_jacobian(data)
    assert cq.rows == 126 and not cq.small
    found = dependence(cq)
    assert found.rank == 122 == reference(cq.dense())[0]
    assert found.involved.tolist() == reference(cq.dense())[1]
    labels = [*(j["name"] for j in data["joints"] for _ in range(2))]
    involved = {labels[i] for i in np.flatnonzero(found.involved)}
    assert {"j1", "j30", "ground10", "ground30", "j45", "j45_again"} <= involved
    assert not involved & {"j31", "j44", "j46", "j60"}


def cycles_of(ends: list[tuple[int, int]]) -> list[set[int]]:
    """The edge sets of every simple cycle of a small multigraph (by depth-first search)."""
    found = []
    for start in {a for edge in ends for a in edge}:
        paths = [(start, [start], [])]
        while paths:
            node, visited, edges = paths.pop()
            for e, (a, b) in enumerate(ends):
                if node not in (a, b) or e in edges:
                    continue
                other = b if node == a else a
                if other == start and edges:
                    found.append({*edges, e})
                elif other not in visited:
                    paths.append((other, [*visited, other], [*edges, e]))
    return found


@settings(max_examples=80, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), nodes=st.integers(2, 7), edges=st.integers(1, 10))
def test_blocks_are_the_edges_on_common_cycles(seed, nodes, edges):
    # Two edges share a block exactly when a simple cycle holds both (parallel edges are a
    # cycle of two); every other edge is a block of its own.
    rng = np.random.default_rng(seed)
    ends = [tuple(int(v) for v in rng.choice(nodes, size=2, replace=False)) for _ in range(edges)]
    label = row_blocks(np.array(ends, dtype=np.int64), nodes)
    cycles = cycles_of(ends)
    for e, f in itertools.combinations(range(edges), 2):
        together = any(e in cycle and f in cycle for cycle in cycles)
        assert (label[e] == label[f]) == together, (ends, e, f)


# ----- minimum-norm solutions -----------------------------------------------------------------


def test_sparse_least_norm_is_lapacks():
    worst = {"full": 0.0, "consistent": 0.0, "inconsistent": 0.0, "residual": 0.0}
    for seed in range(300):
        cq = start_jacobian(random_mechanism(seed, collinear=0.3 if seed % 2 else 0.0))
        if cq.rows == 0:
            continue
        matrix = cq.dense()
        rng = np.random.default_rng(seed)
        full = reference(matrix)[0] == cq.rows
        right_sides = {"full" if full else "consistent": matrix @ rng.normal(size=cq.columns)}
        if not full:
            right_sides["inconsistent"] = rng.normal(size=cq.rows)
        for kind, b in right_sides.items():
            expected = np.linalg.lstsq(matrix, b, rcond=None)[0]
            found = sparse_least_norm(cq, b)
            error = np.linalg.norm(found - expected)
            worst[kind] = max(worst[kind], error / np.linalg.norm(expected))
            least = np.linalg.norm(matrix @ expected - b)
            excess = (np.linalg.norm(matrix @ found - b) - least) / max(least, 1e-300)
            worst["residual"] = max(worst["residual"], excess if kind == "inconsistent" else 0.0)
    # Full row rank, or rows that depend on others with a right side they agree on: to
    # rounding in the normal equations (condition^2 eps, conditions up to ~1e2). Rows that
    # contradict each other: their share of b, amplified by 1/delta (least_norm.py), moves x
    # by 1e-3 of its size (7e-4 here) and the least residual by far less (4e-8 here).
    assert worst["full"] < 1e-12 and worst["consistent"] < 1e-12, worst
    assert worst["inconsistent"] < 1e-2 and worst["residual"] < 1e-6, worst


def test_sparse_least_norm_is_the_least_norm_solution():
    # The defining property, without lstsq: Phi_q x = b, and x orthogonal to the null space
    # of Phi_q (minimum norm), for a rank-deficient Jacobian (the straight chain with its
    # pin 45 doubled) and a right side it can meet.
    data = chain(60, 0.1, 0.1, -0.5, {})
    data["joints"].append({**data["joints"][44], "name": "j45_again"})
    cq = start_jacobian(data)
    matrix = cq.dense()
    b = matrix @ np.random.default_rng(1).normal(size=cq.columns)
    x = sparse_least_norm(cq, b)
    _, sv, vt = np.linalg.svd(matrix)
    null_space = vt[np.count_nonzero(sv > 1e-9 * sv[0]) :]
    assert null_space.shape[0] == 60  # 180 coordinates, rank 120
    assert np.abs(matrix @ x - b).max() < 1e-12 * np.abs(b).max()
    assert np.abs(null_space @ x).max() < 1e-12 * np.abs(x).max()


def perturbed_chain(bars: int, formulation: str) -> dict:
    """``bars`` bars on an arc, its far end pinned to the ground too (one loop), the guess off
    by up to 5 mm and 0.05 rad, at random velocities."""
    bend = 0.03  # [rad] between neighbouring bars: a curved chain, far from dead centre
    start, bodies = [0.0, 0.0], []
    for k in range(bars):
        angle = -0.5 + bend * k
        bodies.append(bar(f"bar{k + 1}", 0.1, 0.1, start, angle))
        start = [start[0] + 0.1 * math.cos(angle), start[1] + 0.1 * math.sin(angle)]
    data = chain(bars, 0.1, 0.1, -0.5, {"formulation": formulation})
    data["bodies"] = bodies
    data["ground"]["points"]["end"] = start
    data["joints"].append(pin("closing", ("ground", f"bar{bars}"), ("end", "b")))
    rng = np.random.default_rng(bars)
    for body in data["bodies"]:
        body["position"] = [v + rng.uniform(-5e-3, 5e-3) for v in body["position"]]
        body["angle"] += rng.uniform(-0.05, 0.05)
        body["velocity"] = rng.uniform(-1.0, 1.0, 2).tolist()
        body["angular_velocity"] = rng.uniform(-1.0, 1.0)
    return data


def test_sparse_assembly_is_the_dense_one(monkeypatch):
    # 60 bars closed into one loop through the ground, from a rough guess: the Newton
    # iterations and the velocity projection by sparse solves against the same done by
    # lstsq (the dense path, all sizes taken dense). Both meet the constraints to the
    # assembly tolerance; the poses agree to the rounding of the iterations.
    model = parse_model(perturbed_chain(60, "baumgarte"))
    sparse = assemble(model, build_system(model, ideal=True))
    monkeypatch.setattr(jacobian_module, "DENSE_COLUMNS", 10**6)
    dense = assemble(model, build_system(model, ideal=True))
    assert sparse.iterations == dense.iterations > 1
    assert (sparse.dof, sparse.redundant, sparse.dof_without_drivers) == (58, 0, 58)
    assert (dense.dof, dense.redundant, dense.dof_without_drivers) == (58, 0, 58)
    np.testing.assert_allclose(sparse.y0, dense.y0, rtol=0, atol=1e-12)


def test_sparse_assembly_meets_the_constraints_with_the_least_velocity_change():
    model = parse_model(perturbed_chain(60, "baumgarte"))
    system = build_system(model, ideal=True)
    start = assemble(model, system)
    n = start.y0.shape[0] // 2
    phi, cq, phi_t = evaluate(system, start.y0[:n], start.y0[n:])
    assert np.abs(phi).max() <= model.solver.assembly_tolerance
    matrix = cq.dense()
    assert np.abs(matrix @ start.y0[n:] + phi_t).max() < 1e-12
    # The velocities closest to the guess: the change lies in the row space of Phi_q.
    change = start.y0[n:] - initial_guess(model)[n:]
    _, sv, vt = np.linalg.svd(matrix)
    null_space = vt[np.count_nonzero(sv > 1e-9 * sv[0]) :]
    assert np.abs(null_space @ change).max() < 1e-12 * np.abs(change).max()


def test_a_large_redundant_mechanism_is_named_or_run():
    # The 60-bar loop with its 30th pin doubled: Baumgarte names the two pins; the augmented
    # Lagrangian counts two redundant equations.
    data = perturbed_chain(60, "baumgarte")
    data["joints"].append({**data["joints"][29], "name": "j30_again"})
    model = parse_model(data)
    with pytest.raises(jw.ModelError) as error:
        assemble(model, build_system(model, ideal=True))
    message = str(error.value)
    assert "rank 122 for 124 equations" in message
    assert "joint 'j30'" in message and "joint 'j30_again'" in message
    assert "joint 'j29'" not in message
    data["solver"]["formulation"] = "augmented_lagrangian"
    model = parse_model(data)
    start = assemble(model, build_system(model, ideal=True))
    assert (start.redundant, start.dof) == (2, 58)


# ----- signals ---------------------------------------------------------------------------------


class Stop(Exception):
    pass


def test_a_signal_is_answered_during_work_off_the_main_thread():
    # Work that would take 20 s (a wait that, like LAPACK, releases the GIL): a signal 0.2 s
    # in is answered at once, its handler's exception raised from the waiting main thread.
    release = threading.Event()

    def stop(signum, frame):
        raise Stop

    previous = signal.signal(signal.SIGUSR1, stop)
    main = threading.main_thread().ident
    timer = threading.Timer(0.2, signal.pthread_kill, (main, signal.SIGUSR1))
    start = time.perf_counter()
    try:
        timer.start()
        with pytest.raises(Stop):
            off_main_thread(lambda: release.wait(20.0))
        assert time.perf_counter() - start < 2.0
    finally:
        release.set()
        timer.cancel()
        signal.signal(signal.SIGUSR1, previous)


def test_work_off_the_main_thread_returns_or_raises_as_called():
    assert off_main_thread(lambda: 6 * 7) == 42
    with pytest.raises(ZeroDivisionError):
        off_main_thread(lambda: 1 / 0)
