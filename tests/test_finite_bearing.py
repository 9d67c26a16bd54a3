"""The finite journal bearing: Reynolds solver, impedance table and kernel.

Independent answers: published steady tables (Raimondi and Boyd 1958, as transcribed in the
sources named in ``references.py``), the short-bearing closed forms (Ocvirk for the wedge, the
cavitated half film for the squeeze), the long bearing with the Reynolds condition solved
here with scipy, the dissipation integral of the solved field, symmetry and homogeneity.
"""

import math

import numpy as np
import pytest
from references import RAIMONDI_BOYD, RAIMONDI_BOYD_EPS, RAIMONDI_BOYD_TABLE_LD1
from scipy.integrate import quad
from scipy.optimize import brentq

from jointwear.film import impedance
from jointwear.film.impedance import build_table, impedance_table
from jointwear.film.reynolds import film_force, film_grid, solve_film
from jointwear.kernels.laws.impedance import film_impedance, finite_bearing_forces
from jointwear.kernels.laws.lubrication import short_bearing_forces
from jointwear.model import ModelError

# 3 %: the issue's bound; the sources' rounding is up to 1.5 % (0.0116) and the solver's
# discretisation error below 1 % (test_grid_convergence).
PUBLISHED = 0.03

MU, R, C, W = 0.05, 0.01, 2e-5, 100.0  # Pa s, m, m, rad/s


def sommerfeld(w_r: float, w_t: float, eps: float) -> tuple[float, float]:
    """S and phi [deg] of a steady journal from W at psi = -90 deg: S = 2 / (pi eps |W|)."""
    return 2.0 / (math.pi * eps * math.hypot(w_r, w_t)), math.degrees(math.atan2(w_t, -w_r))


@pytest.fixture(scope="module")
def table():
    return build_table(1.0)  # the default table of L / D = 1 (about 2.5 s)


# ------------------------------------------------------------------ published steady tables


@pytest.mark.parametrize("ratio", sorted(RAIMONDI_BOYD))
def test_solver_against_raimondi_boyd(ratio):
    published_s, published_phi = RAIMONDI_BOYD[ratio]
    for eps, s_pub, phi_pub in zip(RAIMONDI_BOYD_EPS, published_s, published_phi, strict=True):
        s, phi = sommerfeld(*film_force(eps, -0.5 * math.pi, ratio), eps)
        assert s == pytest.approx(s_pub, rel=PUBLISHED), (ratio, eps)
        assert phi == pytest.approx(phi_pub, rel=PUBLISHED), (ratio, eps)


def test_solver_against_raimondi_boyd_table():
    for eps, s_pub in RAIMONDI_BOYD_TABLE_LD1.items():
        s, _ = sommerfeld(*film_force(eps, -0.5 * math.pi, 1.0), eps)
        assert s == pytest.approx(s_pub, rel=PUBLISHED), eps


def test_kernel_steady_journal_against_raimondi_boyd(table):
    """Physical units through ``finite_bearing_forces``: S = (R/c)^2 mu N / (F / (L D))."""
    width = 2.0 * R  # L / D = 1
    published_s, published_phi = RAIMONDI_BOYD[1.0]
    for eps, s_pub, phi_pub in zip(RAIMONDI_BOYD_EPS, published_s, published_phi, strict=True):
        f_r, f_t = finite_bearing_forces(table, eps, 0.0, 0.0, W, MU, R, width, C)
        assert f_r < 0.0 < f_t  # the short bearing's signs (lubrication.py)
        load = math.hypot(f_r, f_t) / (width * 2.0 * R)
        s = (R / C) ** 2 * MU * W / (2.0 * math.pi) / load
        assert s == pytest.approx(s_pub, rel=PUBLISHED), eps
        assert math.degrees(math.atan2(f_t, -f_r)) == pytest.approx(phi_pub, rel=PUBLISHED)


# ------------------------------------------------------------------ limits


def _short_squeeze_integral(eps: float) -> float:
    """int_{-pi/2}^{pi/2} cos^2 a / (1 - eps cos a)^3 da in closed form.

    With f(l) = int da / (l - eps cos a) = 2 arccos(-eps / l) / sqrt(l^2 - eps^2) over the
    half film, cos^2 / u^3 = (u^-3 - 2 u^-2 + u^-1) / eps^2 for u = 1 - eps cos a, and
    int u^-n = (-1)^(n-1) f^(n-1)(1) / (n-1)!.
    """
    q = 1.0 - eps * eps
    g, g1, g2 = math.acos(-eps), -eps / math.sqrt(q), eps / math.sqrt(q) + eps / q**1.5
    s, s1, s2 = q**-0.5, -(q**-1.5), -(q**-1.5) + 3.0 * q**-2.5
    f0 = 2.0 * g * s
    f1 = 2.0 * (g1 * s + g * s1)
    f2 = 2.0 * (g2 * s + 2.0 * g1 * s1 + g * s2)
    return (0.5 * f2 + 2.0 * f1 + f0) / eps**2


@pytest.mark.parametrize("eps", [0.2, 0.5, 0.8, 0.95])
def test_short_bearing_limit(eps):
    """L / D -> 0: Ocvirk's wedge (the pi-film is the Reynolds film) and the half-film squeeze.

    W_r = -8 (L/D)^2 eps / q^2, W_t = 2 pi (L/D)^2 / q^(3/2) (``short_bearing_forces`` in W's
    units) for the wedge; W_r = -4 (L/D)^2 I(eps), W_t = 0 for the squeeze towards the wall.
    The finite film approaches them like (L/D)^2: at L/D = 0.025 within 1.2 %, and at least
    3 times closer than at L/D = 0.05 where the error is above the grid's (eps >= 0.8).
    """
    q = 1.0 - eps * eps

    def errors(ratio):
        w_r, w_t = film_force(eps, -0.5 * math.pi, ratio)
        s_r, s_t = film_force(eps, 0.0, ratio)
        wedge = (-8.0 * ratio**2 * eps / q**2, 2.0 * math.pi * ratio**2 / q**1.5)
        squeeze = -4.0 * ratio**2 * _short_squeeze_integral(eps)
        assert abs(s_t) < 1e-12 * abs(s_r)
        return np.array([w_r / wedge[0] - 1.0, w_t / wedge[1] - 1.0, s_r / squeeze - 1.0])

    near, nearer = errors(0.05), errors(0.025)
    assert np.abs(nearer).max() < 0.012
    if eps >= 0.8:
        assert (np.abs(nearer) < np.abs(near) / 3.0).all()


def test_squeeze_integral_closed_form():
    for eps in (0.1, 0.5, 0.9):

        def integrand(a, eps=eps):
            return math.cos(a) ** 2 / (1.0 - eps * math.cos(a)) ** 3

        numeric = quad(integrand, -0.5 * math.pi, 0.5 * math.pi, epsabs=0.0, epsrel=1e-12)[0]
        assert _short_squeeze_integral(eps) == pytest.approx(numeric, rel=1e-9)


def _long_bearing(eps: float) -> tuple[float, float]:
    """W of the long bearing with the Reynolds condition (p = 0 at a = -pi, p = p' = 0 at a2).

    H^3 P' = 12 (H - H*) / eps; H* = H(a2) and P(a2) = 0 fix a2 (scipy's brentq and quad);
    W = -int P n da.
    """

    def h(a):
        return 1.0 - eps * math.cos(a)

    def rise(a, end):
        return quad(lambda t: (h(t) - h(end)) / h(t) ** 3, -math.pi, a, epsrel=1e-12, limit=200)[0]

    end = brentq(lambda a2: rise(a2, a2), 1e-6, math.pi - 1e-9, xtol=1e-14)

    def pressure(a):
        return 12.0 / eps * rise(a, end)

    w_r = -quad(lambda a: pressure(a) * math.cos(a), -math.pi, end, epsrel=1e-10, limit=200)[0]
    w_t = -quad(lambda a: pressure(a) * math.sin(a), -math.pi, end, epsrel=1e-10, limit=200)[0]
    return w_r, w_t


@pytest.mark.parametrize("eps", [0.2, 0.5, 0.8, 0.95])
def test_long_bearing_limit(eps):
    """L / D = 20: the mid-plane film is the long bearing with the Reynolds condition.

    The ends' influence decays into the film over a distance of order R (the film's angular
    scale), e^-20 of the way to the middle: the mid-plane row of cells gives the long
    bearing's W within the grid's error (0.3 %).
    """
    grid = film_grid(eps, 20.0)
    middle = solve_film(grid, 0.0, -1.0).pressure[:, 0]
    faces = grid.angle_faces
    w_r = -np.sum(middle * np.diff(np.sin(faces)))
    w_t = np.sum(middle * np.diff(np.cos(faces)))
    assert (w_r, w_t) == pytest.approx(_long_bearing(eps), rel=3e-3)


# ------------------------------------------------------------------ the solver itself


@pytest.mark.parametrize(
    ("eps", "psi", "ratio"),
    [(0.3, -1.2, 1.0), (0.8, -0.5 * math.pi, 0.5), (0.95, 0.4, 2.0), (0.999, -1.0, 1.0)],
)
def test_grid_convergence(eps, psi, ratio):
    """Twice the cells each way change W by less than 1 %, the accuracy claimed (docs)."""
    coarse = np.array(film_force(eps, psi, ratio))
    fine = np.array(film_force(eps, psi, ratio, n_angle=192, n_axial=32))
    assert np.linalg.norm(coarse - fine) < 0.01 * np.linalg.norm(fine)


def test_symmetry_and_homogeneity():
    grid = film_grid(0.7, 1.0)
    for psi in (0.3, 1.4, 2.5):
        w_r, w_t = solve_film(grid, math.cos(psi), math.sin(psi)).force
        m_r, m_t = solve_film(grid, math.cos(psi), -math.sin(psi)).force
        assert (m_r, m_t) == pytest.approx((w_r, -w_t), rel=1e-10, abs=1e-12)
        scaled = solve_film(grid, 3.5 * math.cos(psi), 3.5 * math.sin(psi)).force
        assert scaled == pytest.approx((3.5 * w_r, 3.5 * w_t), rel=1e-10)


def test_complementarity():
    grid = film_grid(0.9, 1.0)
    solution = solve_film(grid, 0.4, -1.0)
    pressure = solution.pressure
    residual = grid.apply(pressure) - (0.4 * grid.source_r - grid.source_t)
    scale = np.abs(residual).max()
    assert pressure.min() >= 0.0
    assert residual.min() > -1e-10 * scale
    assert np.abs(pressure * residual).max() < 1e-10 * scale * pressure.max()
    assert solution.cavitated.any() and not solution.cavitated.all()


@pytest.mark.parametrize(("eps", "psi"), [(0.5, -0.5 * math.pi), (0.8, -0.7), (0.6, 2.0)])
def test_pressure_power_is_minus_force_dot_velocity(eps, psi):
    """int h^3 / (12 mu) |grad p|^2 dA = -F . V, for any film with the Reynolds condition.

    In W's units: (1/24) int int H^3 (P_a^2 + (D/L)^2 P_zeta^2) da dzeta = -W . V / |V|,
    the left side by finite differences of the solved field and the trapezoidal rule on a
    fine grid (second order; 0.5 % at 384 x 64 cells).
    This is what makes the power loss and the torques of ``lubrication.py``, written in
    (f_r, f_t), hold for the finite bearing: c [eps (w - 2 gamma_dot) f_t / 2 - eps_dot f_r]
    is -F . V with V = (c eps_dot, c eps (gamma_dot - w / 2)).
    """
    ratio = 1.0
    grid = film_grid(eps, ratio, n_angle=384, n_axial=64)
    solution = solve_film(grid, math.cos(psi), math.sin(psi))
    a = 0.5 * (grid.angle_faces[1:] + grid.angle_faces[:-1])
    zeta = 0.5 * (grid.axial_faces[1:] + grid.axial_faces[:-1])
    # the whole width by symmetry, with the boundary values P = 0 at zeta = +-1 and at
    # a = +-pi (the inlet)
    a = np.concatenate([[-math.pi], a, [math.pi]])
    zeta = np.concatenate([[-1.0], -zeta[::-1], zeta, [1.0]])
    p = np.pad(np.hstack([solution.pressure[:, ::-1], solution.pressure]), 1)
    p_a, p_z = np.gradient(p, a, zeta)
    h3 = (1.0 - eps * np.cos(a)) ** 3
    density = h3[:, None] * (p_a**2 + p_z**2 / ratio**2)
    dissipation = np.trapezoid(np.trapezoid(density, zeta, axis=1), a) / 24.0
    work = -(solution.force[0] * math.cos(psi) + solution.force[1] * math.sin(psi))
    assert work > 0.0
    assert dissipation == pytest.approx(work, rel=0.005)


# ------------------------------------------------------------------ table and kernel


def test_kernel_against_direct_solves(table):
    """Off-node points: within 0.5 % of |W| towards the wall, 1 % away from it (5 % beyond
    eps = 0.999, where that force falls by orders of magnitude over a few degrees of chi)."""
    rng = np.random.default_rng(7)
    for _ in range(40):
        eps = -math.expm1(-rng.uniform(0.0, math.log(1e4)))
        psi = rng.uniform(-math.pi, math.pi)
        direct = np.array(film_force(eps, psi, 1.0))
        kernel = np.array(film_impedance(table, eps, psi))
        bound = 0.005 if math.cos(psi) >= 0.0 else 0.01 if eps < 0.999 else 0.05
        assert np.linalg.norm(kernel - direct) < bound * np.linalg.norm(direct), (eps, psi)


def test_kernel_symmetry_homogeneity_and_zero(table):
    for eps, psi in [(0.3, 0.7), (0.9, 2.2), (0.99, 1.5)]:
        w_r, w_t = film_impedance(table, eps, psi)
        assert film_impedance(table, eps, -psi) == pytest.approx((w_r, -w_t), rel=1e-12)
    forces = finite_bearing_forces(table, 0.6, 3.0, 40.0, 200.0, MU, R, 2 * R, C)
    doubled = finite_bearing_forces(table, 0.6, 6.0, 80.0, 400.0, MU, R, 2 * R, C)
    assert doubled == pytest.approx(tuple(2.0 * f for f in forces), rel=1e-12)
    assert finite_bearing_forces(table, 0.6, 0.0, 50.0, 100.0, MU, R, 2 * R, C) == (0.0, 0.0)


def test_kernel_beyond_the_table(table):
    """1 - eps = 1e-5, past the last node (1e-4): the continuation within 1 % of a solve."""
    for psi in (0.0, -0.25 * math.pi, -0.5 * math.pi):
        direct = np.array(film_force(1.0 - 1e-5, psi, 1.0))
        kernel = np.array(film_impedance(table, 1.0 - 1e-5, psi))
        assert np.linalg.norm(kernel - direct) < 0.01 * np.linalg.norm(direct), psi


def test_table_film_never_delivers_power(table):
    """-K . V >= 0 at every node: the film only dissipates (test_pressure_power_...)."""
    n_s, n_theta, beta = int(table[1]), int(table[2]), table[5]
    g = table[6:].reshape(2, n_s + 2, n_theta)[:, 1:-1]
    theta = -math.pi + 2.0 * math.pi * np.arange(n_theta) / n_theta
    chi = theta + beta * np.sin(theta)
    eps = -np.expm1(-np.linspace(0.0, table[3], n_s))
    v_t = np.sin(chi)[None, :] / np.sqrt(1.0 - eps**2)[:, None]
    assert (g[0] * np.cos(chi)[None, :] + g[1] * v_t <= 1e-12).all()


def test_kernel_drops_in_beside_the_short_bearing():
    """A table of L / D = 0.02 at its nodes gives ``short_bearing_forces``, same arguments.

    States without squeeze (eps_dot = 0), where the short bearing's pi-film is the Reynolds
    film: w - 2 gamma_dot of either sign (psi = -90 or +90 deg, nodes of the unstretched
    table), eps on the nodes; 1 % (the short bearing's own error at L / D = 0.02 and
    eps <= 0.9, test_short_bearing_limit).
    """
    small = build_table(0.02, n_s=7, n_chi=8, s_max=math.log(10.0), stretch=0.0)
    width = 0.04 * R
    for s in np.linspace(0.0, math.log(10.0), 7)[1:]:
        eps = -math.expm1(-s)
        for gamma_dot, w in [(0.0, W), (30.0, W), (80.0, W), (-20.0, -W)]:
            args = (eps, 0.0, gamma_dot, w, MU, R, width, C)
            assert finite_bearing_forces(small, *args) == pytest.approx(
                short_bearing_forces(*args), rel=0.01
            ), (eps, gamma_dot, w)


# ------------------------------------------------------------------ the cache


def test_cache_loads_rebuilds_and_survives(tmp_path, monkeypatch, table):
    built = []

    def counted(ratio):
        built.append(ratio)
        return table.copy()

    monkeypatch.setenv("JOINTWEAR_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(impedance, "build_table", counted)
    impedance._cached_table.cache_clear()
    first = impedance_table(1.0)
    assert built == [1.0] and np.array_equal(first, table)
    assert impedance.cache_file(1.0).parent == tmp_path
    first[:] = 0.0  # a caller's copy: the cache keeps its own
    assert np.array_equal(impedance_table(1.0), table) and built == [1.0]  # memory
    impedance._cached_table.cache_clear()
    assert np.array_equal(impedance_table(1.0), table) and built == [1.0]  # disk
    impedance.cache_file(1.0).write_bytes(b"not a table")
    impedance._cached_table.cache_clear()
    assert np.array_equal(impedance_table(1.0), table) and built == [1.0, 1.0]  # rebuilt
    impedance._cached_table.cache_clear()
    assert np.array_equal(impedance_table(1.0), table) and built == [1.0, 1.0]  # rewritten
    blocked = tmp_path / "a file"
    blocked.write_text("")
    monkeypatch.setenv("JOINTWEAR_CACHE_DIR", str(blocked / "cache"))
    impedance._cached_table.cache_clear()
    assert np.array_equal(impedance_table(1.0), table)  # no folder to write: fine
    impedance._cached_table.cache_clear()


def test_cache_folder_defaults(monkeypatch, tmp_path):
    monkeypatch.delenv("JOINTWEAR_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert impedance.cache_folder() == tmp_path / "jointwear"
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path))
    assert impedance.cache_folder() == tmp_path / ".cache" / "jointwear"


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, 20.5, "wide", None])
def test_bad_width_over_diameter(bad):
    with pytest.raises(ModelError, match="width / diameter"):
        impedance_table(bad)
