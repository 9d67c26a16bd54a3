"""Clearance-joint geometry kernels against direct rigid-body computations in numpy."""

import numpy as np
import pytest

from jointwear.kernels.elements.journal_geometry import (
    apply_contact,
    contact_velocities,
    eccentricity,
    surface_angles,
)

R_B, R_J = 0.010, 0.0098  # paper Table 2 [m]
SB = np.array([0.13, 0.0])  # bearing centre on body 0 [m]
SJ = np.array([0.23, 0.01])  # journal centre on body 1 [m]


def rot(phi):
    return np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])


def material_point(q, b, local):
    """World position of a body-fixed point given in body coordinates."""
    return q[3 * b : 3 * b + 2] + rot(q[3 * b + 2]) @ local


def random_state(rng):
    q = rng.normal(size=6)
    # Put the journal centre within about the clearance of the bearing centre.
    bearing = material_point(q, 0, SB)
    journal_cm_offset = rot(q[5]) @ SJ
    q[3:5] = bearing - journal_cm_offset + rng.normal(scale=2e-4, size=2)
    qd = rng.normal(scale=[1, 1, 50, 1, 1, 50])
    return q, qd


@pytest.mark.parametrize("seed", range(5))
def test_eccentricity_and_angles(seed):
    q, qd = random_state(np.random.default_rng(seed))
    ex, ey, dex, dey = eccentricity(q, qd, 0, *SB, 1, *SJ)
    e = material_point(q, 1, SJ) - material_point(q, 0, SB)
    np.testing.assert_allclose([ex, ey], e, rtol=0, atol=1e-15)
    eps = 1e-6  # central difference of exact rigid motion: error ~ eps^2 * |d3e/dt3|
    rate = (
        (material_point(q + eps * qd, 1, SJ) - material_point(q + eps * qd, 0, SB))
        - (material_point(q - eps * qd, 1, SJ) - material_point(q - eps * qd, 0, SB))
    ) / (2 * eps)
    np.testing.assert_allclose([dex, dey], rate, rtol=1e-7, atol=1e-9)
    n = e / np.linalg.norm(e)
    theta_b, theta_j = surface_angles(q, 0, 1, *n)
    # n seen from each body frame: rotate back by the body angle.
    for theta, phi in ((theta_b, q[2]), (theta_j, q[5])):
        np.testing.assert_allclose([np.cos(theta), np.sin(theta)], rot(-phi) @ n, atol=1e-14)
        assert 0.0 <= theta < 2 * np.pi


@pytest.mark.parametrize("seed", range(5))
def test_contact_velocities_are_those_of_the_material_points(seed):
    q, qd = random_state(np.random.default_rng(seed))
    ex, ey, dex, dey = eccentricity(q, qd, 0, *SB, 1, *SJ)
    n = np.array([ex, ey]) / np.hypot(ex, ey)
    t = np.array([-n[1], n[0]])
    # The journal's and the bearing's material points now at P_J and P_B, in body coordinates.
    pj = material_point(q, 1, SJ) + R_J * n
    pb = material_point(q, 0, SB) + R_B * n
    local_j = rot(-q[5]) @ (pj - q[3:5])
    local_b = rot(-q[2]) @ (pb - q[0:2])
    eps = 1e-6
    vj = material_point(q + eps * qd, 1, local_j) - material_point(q - eps * qd, 1, local_j)
    vb = material_point(q + eps * qd, 0, local_b) - material_point(q - eps * qd, 0, local_b)
    relative = (vj - vb) / (2 * eps)
    delta_dot, v_t = contact_velocities(qd, 0, 1, *n, dex, dey, R_B, R_J)
    assert delta_dot == pytest.approx(n @ [dex, dey], abs=1e-12)
    assert v_t == pytest.approx(t @ relative, rel=1e-7, abs=1e-9)


@pytest.mark.parametrize("seed", range(5))
def test_contact_force_pair_power_and_balance(seed):
    rng = np.random.default_rng(seed)
    q, qd = random_state(rng)
    ex, ey, _, _ = eccentricity(q, qd, 0, *SB, 1, *SJ)
    n = np.array([ex, ey]) / np.hypot(ex, ey)
    t = np.array([-n[1], n[0]])
    f_n, f_t = 1.0e4, -3.0e3
    g = np.zeros(6)
    apply_contact(q, g, 0, *SB, 1, *SJ, *n, R_B, R_J, f_n, f_t)
    # Action and reaction: no net force.
    np.testing.assert_allclose(g[0:2] + g[3:5], 0.0, atol=1e-9)
    # Power of the generalised forces = power of the two point forces on their material points.
    force_j = -f_n * n + f_t * t
    pj = material_point(q, 1, SJ) + R_J * n
    pb = material_point(q, 0, SB) + R_B * n
    w = qd[[2, 5]]
    v_pj = qd[3:5] + w[1] * np.array([-(pj - q[3:5])[1], (pj - q[3:5])[0]])
    v_pb = qd[0:2] + w[0] * np.array([-(pb - q[0:2])[1], (pb - q[0:2])[0]])
    expected = force_j @ v_pj - force_j @ v_pb
    assert g @ qd == pytest.approx(expected, rel=1e-12, abs=1e-8)
