"""Independent reference answers for jointwear's physics tests.

Everything here is written from first principles with numpy and scipy only; nothing imports
jointwear. The answers are:

- closed-form position, velocity and acceleration analysis of a four-bar linkage (circle
  intersection for the position, the differentiated vector loop solved analytically for the
  rates);
- the body states of the paper's four-bar along a constant-speed crank motion, with the column
  names jointwear uses for its results;
- the crank torque of the ideal four-bar by the power balance (ideal joints do no work), and the
  same torque plus all joint reactions by Newton-Euler equations written body by body;
- the period of a compound pendulum at any amplitude (complete elliptic integral);
- kinetic and gravitational potential energy of a mechanism from a results table;
- Raimondi and Boyd's steady full journal bearing: Sommerfeld numbers and attitude angles.

References
----------
P. Flores, "Modeling and simulation of wear in revolute clearance joints in multibody systems",
Mechanism and Machine Theory 44 (2009) 1211-1222, section 6 and Table 1 (the four-bar data).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike, NDArray
from scipy.special import ellipk

GRAVITY = 9.81
"""Magnitude of the gravitational acceleration used by the examples [m/s^2]."""

CRANK_SPEED = 50.0 * np.pi
"""The paper's constant crank speed, 1500 rpm [rad/s]."""

CRANK_ANGLE_0 = 0.5 * np.pi
"""Crank angle at t = 0 in the paper's four-bar example [rad]."""


@dataclass(frozen=True)
class FourBar:
    """Geometry and inertia of a planar four-bar linkage (crank 2, coupler 3, follower 4).

    The crank turns about ``crank_pivot``, the follower about ``follower_pivot``; each moving
    bar is uniform in the sense that its centre of mass is at mid-length, with ``inertias``
    about that centre. Defaults are the paper's Table 1 and the pivots of SPEC section 5.

    Attributes
    ----------
    crank, coupler, follower : float
        Link lengths between joint centres [m].
    crank_pivot, follower_pivot : tuple of float
        Ground pivots in global coordinates [m].
    masses : tuple of float
        Masses of crank, coupler, follower [kg].
    inertias : tuple of float
        Moments of inertia about the centres of mass of crank, coupler, follower [kg m^2].
    gravity : tuple of float
        Gravitational acceleration vector [m/s^2].
    branch : int
        +1 puts the coupler-follower joint to the left of the line from the crank tip to the
        follower pivot (the open branch of the paper's example), -1 to the right.
    """

    crank: float = 0.400
    coupler: float = 0.260
    follower: float = 0.460
    crank_pivot: tuple[float, float] = (0.0, 0.0)
    follower_pivot: tuple[float, float] = (0.150, 0.0)
    masses: tuple[float, float, float] = (3.120, 2.028, 3.588)
    inertias: tuple[float, float, float] = (0.042, 0.012, 0.064)
    gravity: tuple[float, float] = (0.0, -GRAVITY)
    branch: int = 1


PAPER_FOURBAR = FourBar()
"""The four-bar of Flores (2009), Table 1, placed as SPEC section 5 says."""

BODY_NAMES = ("crank", "coupler", "follower")
"""Body names of ``examples/flores2009_fourbar.toml``, in the order 2, 3, 4."""

JOINT_NAMES = ("ground_crank", "crank_coupler", "coupler_follower", "ground_follower")
"""Joint names of ``examples/flores2009_fourbar.toml``; each lists the bodies as
(ground, crank), (crank, coupler), (coupler, follower), (ground, follower)."""


def _wrap(angle: NDArray[np.float64]) -> NDArray[np.float64]:
    """Map angles into [-pi, pi) [rad]."""
    return (angle + np.pi) % (2.0 * np.pi) - np.pi


def _cross(a: NDArray[np.float64], b: NDArray[np.float64]) -> NDArray[np.float64]:
    """Scalar (z) cross product of 2-vectors stored along the last axis."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def fourbar_kinematics(
    theta2: ArrayLike,
    omega2: ArrayLike = CRANK_SPEED,
    alpha2: ArrayLike = 0.0,
    fourbar: FourBar = PAPER_FOURBAR,
) -> dict[str, NDArray[np.float64]]:
    """Closed-form position, velocity and acceleration analysis of a four-bar linkage.

    Angles are those of the bars' axes from the global x axis, counter-clockwise: crank from
    its ground pivot to the crank-coupler joint A, coupler from A to the coupler-follower joint
    B, follower from its ground pivot to B. B is the intersection of the circle of radius
    ``coupler`` about A with the circle of radius ``follower`` about the follower pivot,
    on the side given by ``fourbar.branch``. The rates come from the time derivatives of the
    vector loop ``L2 e2 + L3 e3 - L4 e4 = O4 - O2``, dotted with e4 and e3 to decouple them.

    The returned coupler and follower angles are continuous: each is unwrapped against its
    neighbour (coupler against crank, follower against coupler), which is exact as long as
    neither relative angle reaches +-pi; for the paper's drag-link this holds at every crank
    angle (the crank tip stays between 0.25 m and 0.55 m from the follower pivot, and the
    coupler-follower dyad folds only at 0.20 m and stretches at 0.72 m).

    Parameters
    ----------
    theta2 : array_like
        Crank angle [rad] (continuous; any number of turns).
    omega2 : array_like, optional
        Crank angular velocity [rad/s]; default the paper's 50 pi.
    alpha2 : array_like, optional
        Crank angular acceleration [rad/s^2]; default 0.
    fourbar : FourBar, optional
        Geometry; default the paper's.

    Returns
    -------
    dict of ndarray
        ``theta2, theta3, theta4`` [rad], ``omega2, omega3, omega4`` [rad/s],
        ``alpha2, alpha3, alpha4`` [rad/s^2], broadcast to a common shape.

    Raises
    ------
    ValueError
        If the linkage cannot be assembled at some crank angle.
    """
    theta2, omega2, alpha2 = np.broadcast_arrays(
        *(np.asarray(v, dtype=np.float64) for v in (theta2, omega2, alpha2))
    )
    l2, l3, l4 = fourbar.crank, fourbar.coupler, fourbar.follower
    o2 = np.asarray(fourbar.crank_pivot, dtype=np.float64)
    o4 = np.asarray(fourbar.follower_pivot, dtype=np.float64)

    # Position: B on the intersection of two circles, centres A and O4.
    a_pt = o2 + l2 * np.stack([np.cos(theta2), np.sin(theta2)], axis=-1)
    d = o4 - a_pt
    r = np.hypot(d[..., 0], d[..., 1])
    along = (l3**2 - l4**2 + r**2) / (2.0 * r)  # distance from A to the chord [m]
    h2 = l3**2 - along**2
    if np.any(h2 < 0.0):
        raise ValueError("the four-bar cannot be assembled at some crank angles")
    h = np.sqrt(h2)
    u = d / r[..., None]
    u_left = np.stack([-u[..., 1], u[..., 0]], axis=-1)  # u turned by +90 degrees
    b_pt = a_pt + along[..., None] * u + fourbar.branch * h[..., None] * u_left

    ab = b_pt - a_pt
    o4b = b_pt - o4
    theta3 = theta2 + _wrap(np.arctan2(ab[..., 1], ab[..., 0]) - theta2)
    theta4 = theta3 + _wrap(np.arctan2(o4b[..., 1], o4b[..., 0]) - theta3)

    # Velocity: L2 w2 e2' + L3 w3 e3' - L4 w4 e4' = 0 with e' = (-sin, cos);
    # e_i' . e_j = sin(theta_j - theta_i).
    s34 = np.sin(theta4 - theta3)
    omega3 = -l2 * omega2 * np.sin(theta4 - theta2) / (l3 * s34)
    omega4 = -l2 * omega2 * np.sin(theta3 - theta2) / (l4 * s34)

    # Acceleration: sum_i s_i L_i (alpha_i e_i' - omega_i^2 e_i) = 0, s = (+1, +1, -1).
    c = np.cos
    alpha3 = (
        l2 * omega2**2 * c(theta2 - theta4)
        + l3 * omega3**2 * c(theta3 - theta4)
        - l4 * omega4**2
        - l2 * alpha2 * np.sin(theta4 - theta2)
    ) / (l3 * s34)
    alpha4 = (
        l2 * omega2**2 * c(theta2 - theta3)
        + l3 * omega3**2
        - l4 * omega4**2 * c(theta4 - theta3)
        - l2 * alpha2 * np.sin(theta3 - theta2)
    ) / (l4 * s34)

    return {
        "theta2": theta2,
        "theta3": theta3,
        "theta4": theta4,
        "omega2": omega2,
        "omega3": omega3,
        "omega4": omega4,
        "alpha2": alpha2,
        "alpha3": alpha3,
        "alpha4": alpha4,
    }


def fourbar_states(
    time: ArrayLike,
    theta2_0: float = CRANK_ANGLE_0,
    omega2: float = CRANK_SPEED,
    fourbar: FourBar = PAPER_FOURBAR,
) -> pd.DataFrame:
    """Body states of a four-bar whose crank turns at constant speed.

    Parameters
    ----------
    time : array_like
        Times [s].
    theta2_0 : float, optional
        Crank angle at t = 0 [rad]; default 90 degrees.
    omega2 : float, optional
        Constant crank speed [rad/s]; default 50 pi.
    fourbar : FourBar, optional
        Geometry and inertia; default the paper's.

    Returns
    -------
    pandas.DataFrame
        Columns ``time`` and, for each body b of ``BODY_NAMES``, ``x_b, y_b`` [m] (centre of
        mass), ``phi_b`` [rad], ``vx_b, vy_b`` [m/s], ``omega_b`` [rad/s], ``ax_b, ay_b``
        [m/s^2], ``alpha_b`` [rad/s^2], named as in jointwear's results.
    """
    time = np.asarray(time, dtype=np.float64)
    kin = fourbar_kinematics(theta2_0 + omega2 * time, omega2, 0.0, fourbar)
    o2 = np.asarray(fourbar.crank_pivot, dtype=np.float64)
    o4 = np.asarray(fourbar.follower_pivot, dtype=np.float64)

    def bar_terms(theta, omega, alpha, arm):
        """Position, velocity and acceleration of a point ``arm`` along a bar's axis."""
        e = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
        e_left = np.stack([-np.sin(theta), np.cos(theta)], axis=-1)
        pos = arm * e
        vel = arm * omega[..., None] * e_left
        acc = arm * (alpha[..., None] * e_left - (omega**2)[..., None] * e)
        return pos, vel, acc

    th2, th3, th4 = kin["theta2"], kin["theta3"], kin["theta4"]
    w2, w3, w4 = kin["omega2"], kin["omega3"], kin["omega4"]
    a2, a3, a4 = kin["alpha2"], kin["alpha3"], kin["alpha4"]
    l2, l3, l4 = fourbar.crank, fourbar.coupler, fourbar.follower

    p2, v2, acc2 = bar_terms(th2, w2, a2, 0.5 * l2)
    tip, vtip, atip = bar_terms(th2, w2, a2, l2)
    p3, v3, acc3 = bar_terms(th3, w3, a3, 0.5 * l3)
    p4, v4, acc4 = bar_terms(th4, w4, a4, 0.5 * l4)
    centres = {
        "crank": (o2 + p2, v2, acc2, th2, w2, a2),
        "coupler": (o2 + tip + p3, vtip + v3, atip + acc3, th3, w3, a3),
        "follower": (o4 + p4, v4, acc4, th4, w4, a4),
    }
    columns: dict[str, NDArray[np.float64]] = {"time": time}
    for name, (pos, vel, acc, phi, omega, alpha) in centres.items():
        columns[f"x_{name}"] = pos[..., 0]
        columns[f"y_{name}"] = pos[..., 1]
        columns[f"phi_{name}"] = phi
        columns[f"vx_{name}"] = vel[..., 0]
        columns[f"vy_{name}"] = vel[..., 1]
        columns[f"omega_{name}"] = omega
        columns[f"ax_{name}"] = acc[..., 0]
        columns[f"ay_{name}"] = acc[..., 1]
        columns[f"alpha_{name}"] = alpha
    return pd.DataFrame(columns)


def fourbar_torque_power(states: pd.DataFrame, fourbar: FourBar = PAPER_FOURBAR) -> NDArray:
    """Crank torque of an ideal four-bar by the power balance.

    Ideal joints do no work, so the driver's power equals the rate of change of kinetic plus
    gravitational potential energy: ``T omega2 = sum_i (m_i a_i . v_i + J_i alpha_i omega_i
    - m_i g . v_i)``.

    Parameters
    ----------
    states : pandas.DataFrame
        Body states as returned by :func:`fourbar_states` (or a results table with the same
        columns).
    fourbar : FourBar, optional
        Masses, inertias and gravity; default the paper's.

    Returns
    -------
    ndarray
        Moment the driver applies to the crank, counter-clockwise positive [N m].
    """
    gx, gy = fourbar.gravity
    power = np.zeros(len(states))
    for name, m, j in zip(BODY_NAMES, fourbar.masses, fourbar.inertias, strict=True):
        vx, vy = states[f"vx_{name}"].to_numpy(), states[f"vy_{name}"].to_numpy()
        ax, ay = states[f"ax_{name}"].to_numpy(), states[f"ay_{name}"].to_numpy()
        omega, alpha = states[f"omega_{name}"].to_numpy(), states[f"alpha_{name}"].to_numpy()
        power += m * (ax * vx + ay * vy) + j * alpha * omega - m * (gx * vx + gy * vy)
    return power / states["omega_crank"].to_numpy()


def fourbar_newton_euler(
    states: pd.DataFrame, fourbar: FourBar = PAPER_FOURBAR
) -> dict[str, NDArray[np.float64]]:
    """Crank torque and joint reactions of an ideal four-bar by Newton-Euler, body by body.

    Unknowns per instant: the forces F12 (ground on crank at O2), F23 (crank on coupler at A),
    F34 (coupler on follower at B), F14 (ground on follower at O4), and the driver torque T on
    the crank; nine linear equations (force and moment balance of the three bars) give them.

    Parameters
    ----------
    states : pandas.DataFrame
        Body states as returned by :func:`fourbar_states`.
    fourbar : FourBar, optional
        Geometry, masses, inertias and gravity; default the paper's.

    Returns
    -------
    dict of ndarray
        ``torque`` [N m] (moment of the driver on the crank, counter-clockwise positive) and,
        for each joint name j of ``JOINT_NAMES``, ``j_fx`` and ``j_fy`` [N]: the force the
        joint applies to its second listed body.
    """
    n = len(states)
    g = np.asarray(fourbar.gravity, dtype=np.float64)
    o2 = np.broadcast_to(np.asarray(fourbar.crank_pivot, dtype=np.float64), (n, 2))
    o4 = np.broadcast_to(np.asarray(fourbar.follower_pivot, dtype=np.float64), (n, 2))
    th2 = states["phi_crank"].to_numpy()
    th4 = states["phi_follower"].to_numpy()
    a_pt = o2 + fourbar.crank * np.stack([np.cos(th2), np.sin(th2)], axis=-1)
    b_pt = o4 + fourbar.follower * np.stack([np.cos(th4), np.sin(th4)], axis=-1)

    def col(prefix, name):
        return states[f"{prefix}_{name}"].to_numpy()

    centre = {b: np.stack([col("x", b), col("y", b)], axis=-1) for b in BODY_NAMES}
    acc = {b: np.stack([col("ax", b), col("ay", b)], axis=-1) for b in BODY_NAMES}
    alpha = {b: col("alpha", b) for b in BODY_NAMES}
    mass = dict(zip(BODY_NAMES, fourbar.masses, strict=True))
    inertia = dict(zip(BODY_NAMES, fourbar.inertias, strict=True))

    # Unknown vector z = [F12x, F12y, F23x, F23y, F34x, F34y, F14x, F14y, T].
    # Rows: crank (fx, fy, moment), coupler (fx, fy, moment), follower (fx, fy, moment).
    mat = np.zeros((n, 9, 9))
    rhs = np.zeros((n, 9))

    def moment_row(row, arm, col0, sign):
        """Add the moment of force (z[col0], z[col0+1]) applied at ``arm`` to a row."""
        mat[:, row, col0] += -sign * arm[:, 1]
        mat[:, row, col0 + 1] += sign * arm[:, 0]

    # crank: F12 - F23 + m g = m a ; T + r(O2) x F12 - r(A) x F23 = J alpha
    mat[:, 0, 0], mat[:, 0, 2] = 1.0, -1.0
    mat[:, 1, 1], mat[:, 1, 3] = 1.0, -1.0
    moment_row(2, o2 - centre["crank"], 0, 1.0)
    moment_row(2, a_pt - centre["crank"], 2, -1.0)
    mat[:, 2, 8] = 1.0
    # coupler: F23 - F34 + m g = m a ; r(A) x F23 - r(B) x F34 = J alpha
    mat[:, 3, 2], mat[:, 3, 4] = 1.0, -1.0
    mat[:, 4, 3], mat[:, 4, 5] = 1.0, -1.0
    moment_row(5, a_pt - centre["coupler"], 2, 1.0)
    moment_row(5, b_pt - centre["coupler"], 4, -1.0)
    # follower: F34 + F14 + m g = m a ; r(B) x F34 + r(O4) x F14 = J alpha
    mat[:, 6, 4], mat[:, 6, 6] = 1.0, 1.0
    mat[:, 7, 5], mat[:, 7, 7] = 1.0, 1.0
    moment_row(8, b_pt - centre["follower"], 4, 1.0)
    moment_row(8, o4 - centre["follower"], 6, 1.0)
    for k, body in enumerate(BODY_NAMES):
        rhs[:, 3 * k : 3 * k + 2] = mass[body] * (acc[body] - g)
        rhs[:, 3 * k + 2] = inertia[body] * alpha[body]

    z = np.linalg.solve(mat, rhs[..., None])[..., 0]
    out = {"torque": z[:, 8]}
    for k, joint in enumerate(JOINT_NAMES):
        out[f"{joint}_fx"] = z[:, 2 * k]
        out[f"{joint}_fy"] = z[:, 2 * k + 1]
    return out


def compound_pendulum_period(
    pivot_inertia: float,
    mass: float,
    distance: float,
    amplitude: float,
    gravity: float = GRAVITY,
) -> float:
    """Exact period of a compound pendulum swinging with a given amplitude.

    ``T = 4 sqrt(I_O / (m g d)) K(k^2)`` with ``k = sin(amplitude / 2)``. scipy's ``ellipk``
    takes the parameter m = k^2, not the modulus k.

    Parameters
    ----------
    pivot_inertia : float
        Moment of inertia about the pivot [kg m^2].
    mass : float
        Mass [kg].
    distance : float
        Distance from the pivot to the centre of mass [m].
    amplitude : float
        Largest angle from the downward vertical, 0 <= amplitude < pi [rad].
    gravity : float, optional
        Gravitational acceleration [m/s^2].

    Returns
    -------
    float
        Period [s].
    """
    omega0 = np.sqrt(mass * gravity * distance / pivot_inertia)
    return float(4.0 / omega0 * ellipk(np.sin(0.5 * amplitude) ** 2))


def mechanism_energy(
    table: pd.DataFrame,
    bodies: Mapping[str, tuple[float, float]],
    gravity: tuple[float, float] = (0.0, -GRAVITY),
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Kinetic and gravitational potential energy of rigid bodies from a results table.

    Parameters
    ----------
    table : pandas.DataFrame
        Columns ``x_b, y_b`` [m], ``vx_b, vy_b`` [m/s] and ``omega_b`` [rad/s] for every body b.
    bodies : mapping of str to (float, float)
        Body name -> (mass [kg], moment of inertia about the centre of mass [kg m^2]).
    gravity : tuple of float, optional
        Gravitational acceleration vector [m/s^2].

    Returns
    -------
    kinetic : ndarray
        ``sum 1/2 m v^2 + 1/2 J omega^2`` [J].
    potential : ndarray
        ``-sum m g . r``, zero with every centre of mass at the origin [J].
    """
    gx, gy = gravity
    kinetic = np.zeros(len(table))
    potential = np.zeros(len(table))
    for name, (m, j) in bodies.items():
        vx, vy = table[f"vx_{name}"].to_numpy(), table[f"vy_{name}"].to_numpy()
        kinetic += 0.5 * m * (vx**2 + vy**2) + 0.5 * j * table[f"omega_{name}"].to_numpy() ** 2
        potential -= m * (gx * table[f"x_{name}"].to_numpy() + gy * table[f"y_{name}"].to_numpy())
    return kinetic, potential


def fourbar_bodies(fourbar: FourBar = PAPER_FOURBAR) -> dict[str, tuple[float, float]]:
    """Body name -> (mass [kg], inertia [kg m^2]) of a four-bar, for :func:`mechanism_energy`."""
    return dict(zip(BODY_NAMES, zip(fourbar.masses, fourbar.inertias, strict=True), strict=True))


# Raimondi and Boyd (1958, ASLE Trans. 1: 159-209), full (360 deg) journal bearing: the
# Sommerfeld number S = (R/c)^2 mu N / P and the attitude angle phi [deg] at the eccentricity
# ratios RAIMONDI_BOYD_EPS, by L / D. Transcribed from their charts in a course tool found in
# the public code index (search verb ``find_string "1.33, 0.631"``, file id 69000706882; the
# tool names no source; S to 3 figures, phi read to 0.5 deg). Its L / D = 1 values agree with
# the three-figure table below; L / D = 2 is not among the charts textbooks reproduce from
# Raimondi and Boyd (infinite, 1, 1/2, 1/4), so its row is a chart reading of unchecked origin.
RAIMONDI_BOYD_EPS = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95)
RAIMONDI_BOYD = {
    0.5: (
        (4.32, 2.03, 1.21, 0.784, 0.508, 0.318, 0.184, 0.0912, 0.0309, 0.0116),
        (82, 75, 68.5, 61.53, 55, 48, 41, 33, 23.5, 17),
    ),
    1.0: (
        (1.33, 0.631, 0.388, 0.260, 0.178, 0.120, 0.0776, 0.0443, 0.0185, 0.00831),
        (79.5, 74.0, 68.0, 62.5, 56.5, 50.5, 44.0, 36.0, 26.0, 19.0),
    ),
    2.0: (
        (0.559, 0.271, 0.173, 0.122, 0.0893, 0.0654, 0.0463, 0.0297, 0.0143, 0.00707),
        (75, 71, 67, 62.5, 58, 52.5, 46.5, 39, 29, 21),
    ),
}
# L / D = 1, S at h0 / c = 1 - eps to the 3 figures of Raimondi and Boyd's table, from the
# MATLAB Answers page "design of journal bearing" (mathworks.com/matlabcentral/answers/707318),
# which lists them with the friction variable of the same table.
RAIMONDI_BOYD_TABLE_LD1 = {0.1: 1.33, 0.2: 0.631, 0.4: 0.264, 0.6: 0.121, 0.8: 0.0446, 0.9: 0.0188}
