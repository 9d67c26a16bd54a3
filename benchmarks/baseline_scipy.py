"""Hand-written numpy + scipy baseline of the paper's four-bar with a worn clearance joint.

This module exists only for ``benchmarks/bench.py``: it is the side-by-side speed baseline,
the same simulation written the way a careful engineer would write it by hand with plain
numpy and ``scipy.integrate``. It does not import jointwear and shares no code with it; it
implements the same equations with the same parameters so that its answers can be compared.

The case (``examples/flores2009_fourbar.toml``; P. Flores, Mech. Mach. Theory 44 (2009)
1211-1222, section 6): crank, coupler and follower in Cartesian coordinates (x, y, phi) each,
ideal revolute joints ground-crank, crank-coupler and ground-follower, the crank driven at
1500 rpm from 90 deg, gravity -9.81 m/s^2 in y. The coupler-follower joint has clearance: the
bearing (hole, R_B = 10 mm) is on the coupler, the journal (pin, R_J = 9.8 mm) on the follower.

Equations:

- Equations of motion, the paper's Eq. (7) with Baumgarte stabilisation,
  [[M, Phi_q^T], [Phi_q, 0]] [q''; lambda] = [g; gamma - 2 alpha Phi' - beta^2 Phi],
  alpha = beta = 5 1/s, solved with ``np.linalg.solve``.
- Clearance joint: e = r_J - r_B, n = e / abs(e), t = n turned +90 deg. Penetration
  delta = abs(e) - (c + w_B(theta_B) + w_J(theta_J)), theta_B and theta_J the direction of n in
  the coupler's and the follower's body frames, w the worn depths interpolated periodically and
  linearly between the sector centres (Eq. 15 with the wear fed back, Eqs. 20-22).
- Normal force for delta > 0, Lankarani-Nikravesh (Eq. 18):
  F_N = K delta^1.5 [1 + 3 (1 - c_e^2) / 4 * delta' / delta'_-] >= 0,
  K = 4/3 E* sqrt(R_B R_J / (R_B - R_J)). delta'_- is the penetration rate recorded when the
  contact period began (at least 1 mm/s), and the current rate while no period is open.
- Friction, Ambrosio (Eq. 19): F_T = -c_f c_d F_N sign(v_T), c_d = 0 up to v0 = 1e-4 m/s,
  linear to 1 at v1 = 1e-2 m/s, where v_T = t . e' + omega_J R_J - omega_B R_B is the sliding
  speed of the journal's contact point past the bearing's.
- The force -F_N n + F_T t acts on the follower at r_J + R_J n, its opposite on the coupler
  at r_B + R_B n.
- Wear, Archard (Eqs. 13-14): the Hertz line-contact pressure (half-width
  b = sqrt(4 F_N R* / (pi L E*)), p_max = 2 F_N / (pi b L), elliptical) is averaged over the
  36 sectors of each surface that the patch covers, so that a step removes exactly
  k F_N ds, half from each surface; ds = abs(v_T) dt; no wear while sticking
  (abs(v_T) <= v0).

Contact periods: a period begins when the penetration passes the contact tolerance 1e-10 m.
That crossing is a terminal event: it is located with ``scipy.optimize.brentq`` on the
step's dense output, the integration is cut there and restarted (as ``solve_ivp`` does with a
terminal event), and the penetration rate at the crossing is recorded as the impact speed of
the period. The period ends at the first step end without penetration.

Why the solver objects are driven step by step instead of one ``solve_ivp`` call with the
wear as 72 more ODE states: the wear is wanted as jointwear defines it, the incremental
method of the paper (Eq. 14), from the contact at the middle of each accepted step times the
step's length, the worn profile changing between steps. ``RK45.step()`` / ``LSODA.step()``
and ``dense_output()`` are exactly what ``solve_ivp`` runs internally, so this loop is
``solve_ivp`` with a hook after every step. Carrying the wear as states would also have
changed the problem the integrators solve (72 more states in the error norm and, for LSODA,
in every finite-difference Jacobian once it switches to its stiff method), which is not a
fair baseline. The largest contact force is taken, like jointwear's, at the step ends and
midpoints.

Agreement with jointwear (default tolerances, 0.1 s and 1 s): wear profiles within 0.2 % of
the deepest sector. The largest contact force is within 1 % with LSODA but about 3 % above
jointwear's dopri5 with RK45: it peaks while the contact slides at a few mm/s, inside
Ambrosio's friction ramp, where the friction acts as a stiff damper and an explicit
Runge-Kutta result depends on its step-size controller at rtol = 1e-6. Both converge to the
same value (about 84.45 kN in the first crank turn) as the tolerances are tightened.

Usage: ``simulate_baseline(t_end=0.1, rtol=1e-6, atol=1e-8, method="RK45", max_step=1e-3)``,
or run this file (``python benchmarks/baseline_scipy.py 0.1 RK45``).
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass

import numpy as np
from scipy.integrate import LSODA, RK45
from scipy.optimize import brentq

# The four-bar (paper Table 1; SPEC section 5). Bodies 0 crank, 1 coupler, 2 follower; the
# ground is -1. Each bar's x axis runs from its first joint to its second, centre of mass at
# mid-length.
MASS = np.array([3.120, 2.028, 3.588])  # [kg]
INERTIA = np.array([0.042, 0.012, 0.064])  # [kg m^2]
GRAVITY = np.array([0.0, -9.81])  # [m/s^2]
CRANK_SPEED = 1500.0 * 2.0 * math.pi / 60.0  # [rad/s], 50 pi
CRANK_START = math.pi / 2.0  # [rad]
GROUND_CRANK_PIVOT = (0.0, 0.0)  # [m], global
GROUND_FOLLOWER_PIVOT = (0.150, 0.0)  # [m], global

# Revolute joints: (body i, point on i, body j, point on j), points in body coordinates [m].
GROUND_CRANK = (-1, GROUND_CRANK_PIVOT, 0, (-0.200, 0.0))
CRANK_COUPLER = (0, (0.200, 0.0), 1, (-0.130, 0.0))
GROUND_FOLLOWER = (-1, GROUND_FOLLOWER_PIVOT, 2, (-0.230, 0.0))
COUPLER_FOLLOWER = (1, (0.130, 0.0), 2, (0.230, 0.0))  # bearing centre, journal centre
IDEAL_JOINTS = (GROUND_CRANK, CRANK_COUPLER, GROUND_FOLLOWER)

# Initial pose guess (the model file's), refined by the position analysis.
POSE_GUESS = np.array([
    0.0, 0.2, math.radians(90.0),
    0.1278, 0.4239, math.radians(10.58),
    0.2028, 0.2239, math.radians(76.73),
])  # fmt: skip

# Clearance joint (paper Table 2) and jointwear's default settings (docs/model-format.md).
R_B = 10.0e-3  # bearing radius [m], on the coupler
R_J = 9.8e-3  # journal radius [m], on the follower
CLEARANCE = R_B - R_J  # [m]
WIDTH = 20.0e-3  # [m]
RESTITUTION = 0.9
FRICTION = 0.1
YOUNG = 207e9  # [Pa], both surfaces
POISSON = 0.3  # both surfaces
WEAR_K = 8e-14  # Archard [1/Pa]
SECTORS = 36
JOURNAL_SHARE = 0.5  # of the worn volume
V0 = 1e-4  # [m/s] no friction (sticking) up to here
V1 = 1e-2  # [m/s] full friction from here
MIN_IMPACT_SPEED = 1e-3  # [m/s]
CONTACT_TOLERANCE = 1e-10  # [m]
EXPONENT = 1.5
E_STAR = 1.0 / (2.0 * (1.0 - POISSON**2) / YOUNG)  # contact modulus [Pa]
R_STAR = R_B * R_J / (R_B - R_J)  # relative radius [m]
STIFFNESS = 4.0 / 3.0 * E_STAR * math.sqrt(R_STAR)  # K [N/m^1.5]
HYSTERESIS = 0.75 * (1.0 - RESTITUTION**2)

BAUMGARTE_ALPHA = 5.0  # [1/s]
BAUMGARTE_BETA = 5.0  # [1/s]
SECTOR_ANGLE = 2.0 * math.pi / SECTORS

N_COORD = 9
MASS_DIAGONAL = np.repeat(MASS, 3)
MASS_DIAGONAL[2::3] = INERTIA
WEIGHT = np.zeros(N_COORD)
WEIGHT[0::3] = MASS * GRAVITY[0]
WEIGHT[1::3] = MASS * GRAVITY[1]


def rotation(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def point(q: np.ndarray, body: int, local: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Global position of a body point, and its offset A s from the centre of mass [m]."""
    if body < 0:
        return np.array(local), np.zeros(2)
    offset = rotation(q[3 * body + 2]) @ np.asarray(local)
    return q[3 * body : 3 * body + 2] + offset, offset


def constraints(t: float, q: np.ndarray, qd: np.ndarray, joints, driven: bool = True):
    """Phi, Phi_q, gamma (Phi_q q'' = gamma) and Phi_t of the revolute joints and the driver."""
    rows = 2 * len(joints) + (1 if driven else 0)
    phi = np.zeros(rows)
    jac = np.zeros((rows, N_COORD))
    gamma = np.zeros(rows)
    phi_t = np.zeros(rows)
    for r, (i, s_i, j, s_j) in enumerate(joints):
        rows_r = slice(2 * r, 2 * r + 2)
        p_i, a_i = point(q, i, s_i)
        p_j, a_j = point(q, j, s_j)
        phi[rows_r] = p_i - p_j
        for body, a, sign in ((i, a_i, 1.0), (j, a_j, -1.0)):
            if body < 0:
                continue
            jac[2 * r, 3 * body] = jac[2 * r + 1, 3 * body + 1] = sign
            jac[rows_r, 3 * body + 2] = sign * np.array([-a[1], a[0]])  # d(A s)/d phi
            gamma[rows_r] += sign * a * qd[3 * body + 2] ** 2
    if driven:  # crank angle = CRANK_START + CRANK_SPEED t
        phi[-1] = q[2] - CRANK_START - CRANK_SPEED * t
        jac[-1, 2] = 1.0
        phi_t[-1] = -CRANK_SPEED
    return phi, jac, gamma, phi_t


def initial_state() -> np.ndarray:
    """Position and velocity analysis at t = 0 with every joint ideal (journal centred)."""
    joints = (*IDEAL_JOINTS, COUPLER_FOLLOWER)
    q = POSE_GUESS.copy()
    zero = np.zeros(N_COORD)
    for _ in range(50):
        phi, jac, _, _ = constraints(0.0, q, zero, joints)
        if np.abs(phi).max() < 1e-12:
            break
        q -= np.linalg.solve(jac, phi)
    else:
        raise RuntimeError("position analysis did not converge")
    _, jac, _, phi_t = constraints(0.0, q, zero, joints)
    qd = np.linalg.solve(jac, -phi_t)
    return np.concatenate([q, qd])


@dataclass
class Contact:
    """The clearance joint at one state."""

    delta: float  # penetration [m]
    delta_dot: float  # penetration rate [m/s]
    v_t: float  # sliding speed [m/s]
    f_n: float  # normal force [N]
    f_t: float  # friction force along t, on the journal [N]
    normal: tuple[float, float]  # n
    theta_b: float  # direction of n in the coupler's frame [rad]
    theta_j: float  # direction of n in the follower's frame [rad]


class ClearanceJoint:
    """The coupler-follower joint: contact state, forces and worn profiles."""

    def __init__(self) -> None:
        self.wear_bearing = np.zeros(SECTORS)  # [m], sectors fixed in the coupler
        self.wear_journal = np.zeros(SECTORS)  # [m], sectors fixed in the follower
        self.in_contact = False
        self.impact_speed = 0.0  # [m/s], of the open contact period
        self.impacts = 0
        self.max_force = 0.0  # [N]

    def evaluate(self, y: np.ndarray) -> Contact:
        q, qd = y[:N_COORD], y[N_COORD:]
        ib, sb, ij, sj = COUPLER_FOLLOWER
        cb, sb_ = math.cos(q[3 * ib + 2]), math.sin(q[3 * ib + 2])
        cj, sj_ = math.cos(q[3 * ij + 2]), math.sin(q[3 * ij + 2])
        ab = (cb * sb[0] - sb_ * sb[1], sb_ * sb[0] + cb * sb[1])  # A_B s_B
        aj = (cj * sj[0] - sj_ * sj[1], sj_ * sj[0] + cj * sj[1])  # A_J s_J
        wb, wj = qd[3 * ib + 2], qd[3 * ij + 2]
        ex = q[3 * ij] + aj[0] - q[3 * ib] - ab[0]
        ey = q[3 * ij + 1] + aj[1] - q[3 * ib + 1] - ab[1]
        dex = qd[3 * ij] - wj * aj[1] - qd[3 * ib] + wb * ab[1]
        dey = qd[3 * ij + 1] + wj * aj[0] - qd[3 * ib + 1] - wb * ab[0]
        e = math.hypot(ex, ey)
        if e == 0.0:
            return Contact(-CLEARANCE, 0.0, 0.0, 0.0, 0.0, (1.0, 0.0), 0.0, 0.0)
        nx, ny = ex / e, ey / e
        direction = math.atan2(ny, nx)
        theta_b = (direction - q[3 * ib + 2]) % (2.0 * math.pi)
        theta_j = (direction - q[3 * ij + 2]) % (2.0 * math.pi)
        gap = CLEARANCE + worn_depth(self.wear_bearing, theta_b)
        gap += worn_depth(self.wear_journal, theta_j)
        delta = e - gap
        delta_dot = nx * dex + ny * dey
        v_t = -ny * dex + nx * dey + wj * R_J - wb * R_B
        f_n = f_t = 0.0
        if delta > 0.0:
            speed = self.impact_speed if self.in_contact else max(delta_dot, MIN_IMPACT_SPEED)
            elastic = STIFFNESS * delta**EXPONENT
            f_n = max(0.0, elastic * (1.0 + HYSTERESIS * delta_dot / speed))
            slide = abs(v_t)
            c_d = min(1.0, max(0.0, (slide - V0) / (V1 - V0)))
            f_t = -FRICTION * c_d * f_n * math.copysign(1.0, v_t) if slide > 0.0 else 0.0
        return Contact(delta, delta_dot, v_t, f_n, f_t, (nx, ny), theta_b, theta_j)

    def forces(self, y: np.ndarray, g: np.ndarray) -> None:
        """Add the contact forces at state y to the generalised forces g."""
        c = self.evaluate(y)
        if c.f_n == 0.0 and c.f_t == 0.0:
            return
        q = y[:N_COORD]
        n = np.array(c.normal)
        t = np.array([-n[1], n[0]])
        force = -c.f_n * n + c.f_t * t  # on the journal
        ib, sb, ij, sj = COUPLER_FOLLOWER
        for body, local, radius, f in ((ij, sj, R_J, force), (ib, sb, R_B, -force)):
            _, offset = point(q, body, local)
            arm = offset + radius * n  # contact point minus the centre of mass
            g[3 * body : 3 * body + 2] += f
            g[3 * body + 2] += arm[0] * f[1] - arm[1] * f[0]

    def begin_period(self, c: Contact) -> None:
        self.in_contact = True
        self.impact_speed = max(c.delta_dot, MIN_IMPACT_SPEED)
        self.impacts += 1

    def wear(self, c: Contact, dt: float) -> None:
        """Archard wear of sliding for dt [s] under contact c, into both surfaces' sectors."""
        if c.f_n <= 0.0 or abs(c.v_t) <= V0:  # no contact, or sticking
            return
        ds = abs(c.v_t) * dt
        b = math.sqrt(4.0 * c.f_n * R_STAR / (math.pi * WIDTH * E_STAR))
        p_max = 2.0 * c.f_n / (math.pi * b * WIDTH)
        depth = WEAR_K * p_max * ds  # Archard depth under the peak pressure
        spread(self.wear_bearing, c.theta_b, b / R_B, (1.0 - JOURNAL_SHARE) * depth)
        spread(self.wear_journal, c.theta_j, b / R_J, JOURNAL_SHARE * depth)


def worn_depth(depths: np.ndarray, theta: float) -> float:
    """Depth [m] in direction theta [rad], linear between sector centres, periodic."""
    x = theta / SECTOR_ANGLE - 0.5  # in sector widths from the first centre
    below = math.floor(x)
    frac = x - below
    return (1.0 - frac) * depths[below % SECTORS] + frac * depths[(below + 1) % SECTORS]


def spread(depths: np.ndarray, theta: float, half_angle: float, peak: float) -> None:
    """Add peak sqrt(1 - ((x - theta) / half_angle)^2), averaged per sector, to depths."""
    first = math.floor((theta - half_angle) / SECTOR_ANGLE)
    last = math.floor((theta + half_angle) / SECTOR_ANGLE)
    edges = np.arange(first, last + 2) * SECTOR_ANGLE
    u = np.clip((edges - theta) / half_angle, -1.0, 1.0)
    area = 0.5 * (u * np.sqrt(1.0 - u * u) + np.arcsin(u))  # integral of sqrt(1 - u^2)
    sectors = np.arange(first, last + 1) % SECTORS
    np.add.at(depths, sectors, peak * half_angle / SECTOR_ANGLE * np.diff(area))


def make_rhs(joint: ClearanceJoint, counter: list[int]):
    """The right-hand side y' = (q', q'') of Eq. (7) with Baumgarte stabilisation."""
    n = N_COORD
    m = 2 * len(IDEAL_JOINTS) + 1
    kkt = np.zeros((n + m, n + m))
    kkt[:n, :n] = np.diag(MASS_DIAGONAL)
    a2 = 2.0 * BAUMGARTE_ALPHA
    b2 = BAUMGARTE_BETA**2

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        counter[0] += 1
        q, qd = y[:n], y[n:]
        g = WEIGHT.copy()
        joint.forces(y, g)
        phi, jac, gamma, phi_t = constraints(t, q, qd, IDEAL_JOINTS)
        kkt[:n, n:] = jac.T
        kkt[n:, :n] = jac
        right = np.concatenate([g, gamma - a2 * (jac @ qd + phi_t) - b2 * phi])
        qdd = np.linalg.solve(kkt, right)[:n]
        return np.concatenate([qd, qdd])

    return rhs


def simulate_baseline(
    t_end: float = 1.0,
    rtol: float = 1e-6,
    atol: float = 1e-8,
    method: str = "RK45",
    max_step: float = 1e-3,
) -> dict:
    """Simulate the four-bar with its worn clearance joint from t = 0 to t_end [s].

    Returns wall_s (the integration only), rhs_evaluations, steps, impacts,
    max_contact_force_n, and wear_journal, wear_bearing: the 36 sector depths [m], sector i
    centred at (i + 0.5) * 10 deg in that surface's body frame.
    """
    solvers = {"RK45": RK45, "LSODA": LSODA}
    if method not in solvers:
        raise ValueError(f"method must be one of {sorted(solvers)}, not {method!r}")
    joint = ClearanceJoint()
    counter = [0]
    rhs = make_rhs(joint, counter)
    y0 = initial_state()

    def start(t0: float, y: np.ndarray):
        return solvers[method](rhs, t0, y, t_end, rtol=rtol, atol=atol, max_step=max_step)

    started = time.perf_counter()
    solver = start(0.0, y0)
    steps = 0
    while solver.status == "running":
        t_old, y_old = solver.t, solver.y.copy()
        message = solver.step()
        if solver.status == "failed":
            raise RuntimeError(f"{method} failed at t = {t_old:.6g} s: {message}")
        steps += 1
        t_new, y_new = solver.t, solver.y
        dense = solver.dense_output()

        def state(t, t_old=t_old, y_old=y_old, t_new=t_new, y_new=y_new, dense=dense):
            if t == t_old:  # the step's ends exactly (LSODA's interpolant is not at t_old)
                return y_old
            return y_new if t == t_new else dense(t)

        end = joint.evaluate(y_new)
        t_cut = t_new
        if not joint.in_contact and end.delta > CONTACT_TOLERANCE:  # terminal event: onset
            t_cut = brentq(
                lambda t, state=state: joint.evaluate(state(t)).delta - CONTACT_TOLERANCE,
                t_old, t_new, xtol=1e-15, rtol=4.0 * np.finfo(float).eps,
            )  # fmt: skip
        middle = joint.evaluate(state(0.5 * (t_old + t_cut)))
        joint.max_force = max(joint.max_force, middle.f_n)
        joint.wear(middle, t_cut - t_old)  # the wear of the step, midpoint rule
        if t_cut < t_new:  # restart at the onset, as solve_ivp after a terminal event
            y_cut = state(t_cut)
            onset = joint.evaluate(y_cut)
            joint.max_force = max(joint.max_force, onset.f_n)
            joint.begin_period(onset)
            solver = start(t_cut, y_cut)
            continue
        joint.max_force = max(joint.max_force, end.f_n)
        if joint.in_contact and end.delta <= 0.0:
            joint.in_contact = False
    wall = time.perf_counter() - started
    return {
        "wall_s": wall,
        "rhs_evaluations": counter[0],
        "steps": steps,
        "impacts": joint.impacts,
        "max_contact_force_n": joint.max_force,
        "wear_journal": joint.wear_journal.copy(),
        "wear_bearing": joint.wear_bearing.copy(),
    }


if __name__ == "__main__":
    t_end = float(sys.argv[1]) if len(sys.argv) > 1 else 0.1
    method = sys.argv[2] if len(sys.argv) > 2 else "RK45"
    result = simulate_baseline(t_end=t_end, method=method)
    for key in ("wall_s", "rhs_evaluations", "steps", "impacts", "max_contact_force_n"):
        print(f"{key}: {result[key]}")
    for surface in ("journal", "bearing"):
        depths = result[f"wear_{surface}"]
        peak = int(np.argmax(depths))
        print(f"{surface}: max {depths[peak]:.6g} m at {(peak + 0.5) * 10:.0f} deg")
