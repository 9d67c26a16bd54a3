"""Film forces of a finite-length journal bearing from a table of its impedance.

| symbol | meaning | unit | paper |
|---|---|---|---|
| c | radial clearance R_B - R_J | m | Childs et al. (1977) |
| r, width | journal radius R and joint width L | m | |
| mu | dynamic viscosity of the lubricant | Pa s | |
| eps, eps_dot | eccentricity ratio e / c, 0 <= eps < 1, and its rate | -, 1/s | |
| gamma_dot | rate of the direction bearing -> journal centre | rad/s | |
| w | omega_journal + omega_bearing (absolute angular speeds) | rad/s | |
| V = (v_r, v_t) | squeeze velocity de/dt - (w / 2) z x e, in (e_r, e_t) | m/s | Childs et al. |
| psi | angle of V from e_r | rad | |
| q | 1 - eps^2 | - | |
| s | -ln(1 - eps), the table's eccentricity coordinate | - | |
| chi | atan2(sqrt(q) v_t, v_r), the table's direction | rad | |
| theta | chi = theta + beta sin theta, the nodes' coordinate | rad | |
| G | q^(3/2) K(cos chi, sin chi / sqrt(q)), the tabulated force | - | |
| f_r, f_t | film force on the journal along e_r and e_t | N | |

The film force is F = mu L R^3 / c^3 K(V) with K homogeneous of degree 1 in V, solved
ahead of the run by ``jointwear.film`` (the Reynolds equation with the Reynolds cavitation
condition) and tabulated over (s, chi). The coordinates keep the table smooth and bounded up
to eps -> 1: near the thinnest film the pressure peak's width scales like sqrt(1 - eps), so
the squeeze part of K grows like q^(-3/2) and the wedge part like q^(-1) (the film behaves
locally like a long bearing); chi weighs v_t by sqrt(q), which keeps the hand-over between
the two at an angle of order one in chi instead of a width of order sqrt(1 - eps) in psi,
and q^(3/2) scales both to order one. With |V~| = hypot(v_r, sqrt(q) v_t),
F = mu L R^3 / c^3 |V~| G(s, chi) / q^(3/2). Where the journal leaves the wall (chi -> pi)
G falls by orders of magnitude within a few degrees of chi as the pressure moves out of the
thin film; the nodes, uniform in theta, are (1 - beta) times as far apart there.

Interpolation. Cubic convolution (Catmull-Rom) in s and in theta, periodic in theta: C1 in
both, and in (eps, psi). The table holds one ghost row at each end of s, the quadratic
extrapolation of the three nearest, so the end tangents are the one-sided second-order
differences. Beyond the last node (1 - eps below 1e-4) G follows
G_N + 2 G'_N (1 - exp(-(s - s_N) / 2)), matching the value and slope at s_N and bounded: the
film there is locally a long bearing whose side leakage, over a peak of width of order
sqrt(1 - eps) = exp(-s / 2), is the leading correction (the tests check it at 1 - eps = 1e-5).

Table layout (one float64 array per L / D; ``jointwear.film.impedance`` builds it):

    [0] LAYOUT (the layout's version), [1] n_s, [2] n_theta, [3] s_max, [4] L / D,
    [5] beta, then G_r at (s_k, theta_j), k = -1 .. n_s (ghost rows included),
    j = 0 .. n_theta - 1, row-major (n_s + 2 rows of n_theta), then G_t the same way;
    s_k = k s_max / (n_s - 1), theta_j = -pi + 2 pi j / n_theta.

References
----------
D. Childs, H. Moes, H. van Leeuwen, "Journal bearing impedance descriptions for rotordynamic
applications", J. Lubr. Technol. 99 (1977) 198-210.
R.G. Keys, "Cubic convolution interpolation for digital image processing", IEEE Trans.
Acoust. Speech Signal Process. 29 (1981) 1153-1160.
"""

import math

import numpy as np
from numba import njit

LAYOUT = 1.0  # the version of the layout below
HEADER = 6  # floats before the values
AT_LAYOUT, AT_N_S, AT_N_CHI, AT_S_MAX, AT_RATIO, AT_STRETCH = 0, 1, 2, 3, 4, 5


@njit(cache=True, no_cfunc_wrapper=True)
def _weights(t: float) -> tuple[float, float, float, float]:
    """Catmull-Rom weights of the nodes -1, 0, 1, 2 at 0 <= t <= 1."""
    t2 = t * t
    t3 = t2 * t
    return (
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    )


@njit(cache=True, no_cfunc_wrapper=True)
def _slopes(t: float) -> tuple[float, float, float, float]:
    """d/dt of ``_weights``."""
    t2 = t * t
    return (
        0.5 * (-3.0 * t2 + 4.0 * t - 1.0),
        0.5 * (9.0 * t2 - 10.0 * t),
        0.5 * (-9.0 * t2 + 8.0 * t + 1.0),
        0.5 * (3.0 * t2 - 2.0 * t),
    )


@njit(cache=True, no_cfunc_wrapper=True)
def _node_angle(values: np.ndarray, chi: float) -> float:
    """The node coordinate theta in [-pi, pi] of chi: theta + beta sin theta = chi (Newton)."""
    beta = values[AT_STRETCH]
    theta = chi
    for _ in range(8):
        theta -= (theta + beta * math.sin(theta) - chi) / (1.0 + beta * math.cos(theta))
        theta = min(max(theta, -math.pi), math.pi)
    return theta


@njit(cache=True, no_cfunc_wrapper=True)
def _interpolate(values: np.ndarray, s: float, theta: float) -> tuple[float, float, float, float]:
    """G_r, G_t and their s-derivatives at 0 <= s <= s_max, theta in [-pi, pi]."""
    n_s = int(values[AT_N_S])
    n_chi = int(values[AT_N_CHI])
    h_s = values[AT_S_MAX] / (n_s - 1)
    u = s / h_s
    k = min(max(math.floor(u), 0), n_s - 2)
    x = (theta + math.pi) * n_chi / (2.0 * math.pi)
    j = math.floor(x)
    wc = _weights(x - j)
    ws = _weights(u - k)
    ds = _slopes(u - k)
    block = (n_s + 2) * n_chi
    g_r = g_t = dg_r = dg_t = 0.0
    for a in range(4):
        row = HEADER + (k + a) * n_chi  # the ghost row first: node k - 1 + a is row k + a
        line_r = line_t = 0.0
        for b in range(4):
            col = row + (j - 1 + b) % n_chi
            line_r += wc[b] * values[col]
            line_t += wc[b] * values[col + block]
        g_r += ws[a] * line_r
        g_t += ws[a] * line_t
        dg_r += ds[a] * line_r / h_s
        dg_t += ds[a] * line_t / h_s
    return g_r, g_t, dg_r, dg_t


@njit(cache=True, no_cfunc_wrapper=True)
def _table(values: np.ndarray, s: float, chi: float) -> tuple[float, float]:
    """G(s, chi) at s >= 0, continued beyond s_max (module docstring)."""
    s_max = values[AT_S_MAX]
    theta = _node_angle(values, chi)
    if s <= s_max:
        g_r, g_t, _, _ = _interpolate(values, s, theta)
        return g_r, g_t
    g_r, g_t, dg_r, dg_t = _interpolate(values, s_max, theta)
    rise = 2.0 * (1.0 - math.exp(-0.5 * (s - s_max)))
    return g_r + rise * dg_r, g_t + rise * dg_t


@njit(cache=True, no_cfunc_wrapper=True)
def _impedance(values: np.ndarray, eps: float, v_r: float, v_t: float) -> tuple[float, float]:
    """K(V) for V = (v_r, v_t) [m/s], 0 <= eps < 1: F = mu L R^3 / c^3 K [N]."""
    q = 1.0 - eps * eps
    root = math.sqrt(q)
    scaled_t = root * v_t
    size = math.hypot(v_r, scaled_t)  # |V~|
    if size == 0.0:
        return 0.0, 0.0
    g_r, g_t = _table(values, -math.log1p(-eps), math.atan2(scaled_t, v_r))
    scale = size / (q * root)
    return scale * g_r, scale * g_t


@njit(cache=True, no_cfunc_wrapper=True)
def film_impedance(values: np.ndarray, eps: float, psi: float) -> tuple[float, float]:
    """Dimensionless film force (W_r, W_t) [-] of a unit V at the angle psi [rad] from e_r.

    F = mu L R^3 |V| / c^3 (W_r e_r + W_t e_t) [N]; 0 <= eps < 1; ``values``: the table of
    the bearing's L / D (module docstring).
    """
    return _impedance(values, eps, math.cos(psi), math.sin(psi))


@njit(cache=True, no_cfunc_wrapper=True)
def finite_bearing_forces(
    values: np.ndarray,
    eps: float,
    eps_dot: float,
    gamma_dot: float,
    w: float,
    mu: float,
    r: float,
    width: float,
    c: float,
) -> tuple[float, float]:
    """Film force (f_r, f_t) [N] on the journal of a finite bearing, Reynolds cavitation.

    The arguments mean what they mean in ``lubrication.short_bearing_forces`` (w = omega_J
    + omega_B [rad/s], so the mean surface speed is w / 2); ``values`` is the table of the
    joint's L / D = width / (2 r). F = mu L R^3 / c^3 K(V) with V = (c eps_dot, c eps
    (gamma_dot - w / 2)) [m/s] (module docstring); 0 <= eps < 1.
    """
    k_r, k_t = _impedance(values, eps, c * eps_dot, c * eps * (gamma_dot - 0.5 * w))
    scale = mu * width * r**3 / c**3
    return scale * k_r, scale * k_t
