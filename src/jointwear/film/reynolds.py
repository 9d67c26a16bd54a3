"""The Reynolds equation of a finite journal bearing with the Reynolds cavitation condition.

The film between a journal (radius R, width L) and its bearing (radial clearance c) is
unwrapped: the film angle a is measured from e_r, the direction from the bearing centre to the
journal centre, counter-clockwise; zeta = 2 z / L runs across the width. With the
eccentricity ratio eps the film is h = c (1 - eps cos a), H = h / c, thinnest at a = 0.

Rigid, isoviscous, incompressible: with the mean surface speed w_bar = (omega_J + omega_B) / 2
and the journal centre moving at de/dt, the Reynolds equation is that of a pure squeeze by the
effective velocity V = de/dt - w_bar z x e = e_dot e_r + e (gamma_dot - w_bar) e_t (Childs,
Moes and van Leeuwen 1977): dh/dt = -V . n(a), n(a) = cos a e_r + sin a e_t. With
p = mu R^2 / c^3 P (V in P, not factored out) and D = 2 R:

    d/da (H^3 dP/da) + (D/L)^2 d/dzeta (H^3 dP/dzeta) = -12 (V_r cos a + V_t sin a),

P = 0 at the edges zeta = +-1 and along the thickest film a = pi, and the Reynolds
(Swift-Stieber) condition P >= 0, posed as the linear complementarity problem P >= 0,
A P - b >= 0, P . (A P - b) = 0, A the finite-volume -div(H^3 grad) and b the integrated
right-hand side: the film is cavitated (P = 0) where the full film would pull. The force on
the journal, F = -int p n dA with dA = R da dz, is F = mu L R^3 / c^3 K(V),
K = -(1/2) int int P n da dzeta. P is homogeneous of degree 1 in V (the cone P >= 0 is
invariant under positive scaling), so K is too, and one table over eps and the direction of
V is enough.

The line P = 0 at the thickest film is where the lubricant enters at ambient pressure, as in
Raimondi and Boyd's (1958) full bearing, whose tables it reproduces, and in the classic long
bearing with the Reynolds condition (p = 0 at the thickest film, p = dp/da = 0 where the film
ruptures), to which it tends as L / D grows. A periodic film without it (``supply=False``)
has no inlet: the Reynolds condition conserves no mass where the film re-forms, nothing holds
the pressure of the whole film down, and as L / D grows it tends to the full Sommerfeld film
lifted until its least pressure is 0 (attitude angle -> 90 deg): 14 % above Raimondi and
Boyd's angle at L / D = 2. The price of the inlet: the thickest film is undefined at eps = 0,
where the force then depends on the direction of V relative to e_r.

Discretisation. Cell-centred finite volumes on the half width 0 <= zeta <= 1 (the film is
symmetric in zeta), around the film from a = -pi to pi. The cells in a follow the density
1 / sqrt(H) + 1/2: their size near the thinnest film scales like sqrt(1 - eps), the width of
the pressure peak, and the number of cells across the thin film grows only like
ln(1 / (1 - eps)), so the grid stays fine enough up to eps = 0.9999. The faces in zeta are
sin(pi j / (2 m)), fine at the edge, where the pressure falls to zero over a distance that
shrinks like sqrt(1 - eps) D / L. The conductance between two cells in a is the exact one of
a one-dimensional flow, 1 / int H^-3 da between their centres, and the source and the force
integrate cos a and sin a exactly over each cell, so the flow balance holds on the coarse
cells of the thick film too. The complementarity problem is solved by the primal-dual
active-set method (Hintermueller, Ito and Kunisch 2003), which ends in finitely many steps for
this M-matrix; each step is a direct solve, banded Cholesky (LAPACK through scipy) along the
ring cut open at the inlet.

References
----------
D. Childs, H. Moes, H. van Leeuwen, "Journal bearing impedance descriptions for rotordynamic
applications", J. Lubr. Technol. 99 (1977) 198-210.
M. Hintermueller, K. Ito, K. Kunisch, "The primal-dual active set strategy as a semismooth
Newton method", SIAM J. Optim. 13 (2003) 865-888.
A.A. Raimondi, J. Boyd, "A solution for the finite journal bearing and its application to
analysis and design", ASLE Trans. 1 (1958) 159-209.
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

N_ANGLE = 96  # cells around the film (even: the faces are symmetric about a = 0)
N_AXIAL = 16  # cells across the half width
MAX_STEPS = 60  # active-set steps; the M-matrix bound is the number of cells, far more
_GAUSS = np.polynomial.legendre.leggauss(6)
_FAR_DENSITY = 0.5  # the constant part of the cell density: cells for the thick film too


@dataclass(frozen=True)
class FilmGrid:
    """The discretised film of one bearing at one eccentricity ratio.

    The cells are indexed (i, j): i around the film (a), j across the half width (zeta).
    A, the finite-volume -div(H^3 grad), is kept as its conductances: (A P)_ij = diagonal_ij
    P_ij - sum over the neighbours of the conductance times their P.

    Attributes
    ----------
    eps, width_over_diameter
        The eccentricity ratio and L / D [-].
    angle_faces, axial_faces
        Cell faces in a (n_angle + 1, from -pi to pi) [rad] and in zeta (n_axial + 1, 0 to 1).
    diagonal
        A_ii per cell, shape (n_angle, n_axial).
    axial
        Conductance between cells (i, j) and (i, j + 1), shape (n_angle, n_axial - 1).
    angular
        Conductance between cells (i, j) and (i + 1, j), the last row to the first (the film
        is periodic), shape (n_angle, n_axial); zero across a supply line.
    source_r, source_t
        The right-hand side b of V = e_r and of V = e_t: 12 int (cos a, sin a) da dzeta per
        cell. b = V_r source_r + V_t source_t, and K = -(sum source_r P, sum source_t P) / 12.
    """

    eps: float
    width_over_diameter: float
    angle_faces: NDArray[np.float64]
    axial_faces: NDArray[np.float64]
    diagonal: NDArray[np.float64]
    axial: NDArray[np.float64]
    angular: NDArray[np.float64]
    source_r: NDArray[np.float64]
    source_t: NDArray[np.float64]

    @property
    def shape(self) -> tuple[int, int]:
        """(n_angle, n_axial), the shape of a pressure field."""
        return self.diagonal.shape

    def apply(self, pressure: NDArray[np.float64]) -> NDArray[np.float64]:
        """A P for a field of shape ``shape``."""
        out = self.diagonal * pressure
        out[:, :-1] -= self.axial * pressure[:, 1:]
        out[:, 1:] -= self.axial * pressure[:, :-1]
        coupled = self.angular * pressure  # row i's term in the equation of row i + 1
        out[:-1] -= self.angular[:-1] * pressure[1:]
        out[-1] -= self.angular[-1] * pressure[0]
        out[1:] -= coupled[:-1]
        out[0] -= coupled[-1]
        return out


@dataclass(frozen=True)
class FilmSolution:
    """A solved film: the pressure and the force.

    Attributes
    ----------
    pressure
        P per cell, shape ``grid.shape`` (p = mu R^2 / c^3 P [Pa] with V in m/s).
    force
        (K_r, K_t): F = mu L R^3 / c^3 (K_r e_r + K_t e_t) [N] with V in m/s.
    steps
        Active-set steps taken (linear solves).
    cavitated
        The cells where P = 0 (the active set), shape ``grid.shape``.
    """

    pressure: NDArray[np.float64]
    force: tuple[float, float]
    steps: int
    cavitated: NDArray[np.bool_]


def film_grid(
    eps: float,
    width_over_diameter: float,
    n_angle: int = N_ANGLE,
    n_axial: int = N_AXIAL,
    supply: bool = True,
) -> FilmGrid:
    """Discretise the film of a bearing with L / D ``width_over_diameter`` at ``eps``.

    Parameters
    ----------
    eps
        Eccentricity ratio, 0 <= eps < 1 [-].
    width_over_diameter
        L / D > 0 [-].
    n_angle, n_axial
        Cells around the film (even, >= 8) and across the half width (>= 2).
    supply
        Hold P = 0 along the thickest film, a = pi, the lubricant's inlet at ambient pressure
        (Raimondi and Boyd's full bearing; module docstring); False: a periodic film.
    """
    if not 0.0 <= eps < 1.0:
        raise ValueError(f"eps must be in [0, 1), got {eps}")
    if n_angle % 2 or n_angle < 8 or n_axial < 2:
        raise ValueError(f"n_angle must be even and >= 8, n_axial >= 2; got {n_angle}, {n_axial}")
    faces = _angle_faces(eps, n_angle)
    zeta = np.sin(0.5 * np.pi * np.arange(n_axial + 1) / n_axial)
    zeta[-1] = 1.0
    centres = 0.5 * (faces[:-1] + faces[1:])
    zeta_c = 0.5 * (zeta[:-1] + zeta[1:])
    dzeta = np.diff(zeta)

    def inverse_h3(a):
        return (1.0 - eps * np.cos(a)) ** -3

    # around: the one-dimensional conductance between neighbouring centres (periodic)
    upper = np.append(centres[1:], centres[0] + 2.0 * np.pi)
    angular = np.outer(1.0 / _integral(inverse_h3, centres, upper), dzeta)
    # across: (D / L)^2 H^3 integrated over the cell's angle, over the centres' distance
    h3 = _integral(lambda a: (1.0 - eps * np.cos(a)) ** 3, faces[:-1], faces[1:])
    gaps = np.append(np.diff(zeta_c), 1.0 - zeta_c[-1])  # the last one to the edge P = 0
    across = np.outer(h3, 1.0 / gaps) / width_over_diameter**2
    diagonal = np.zeros_like(across)
    diagonal[:, -1] = across[:, -1]  # to the edge zeta = 1, where P = 0
    diagonal[:, :-1] += across[:, :-1]
    diagonal[:, 1:] += across[:, :-1]
    diagonal += angular + np.roll(angular, 1, axis=0)
    if supply:  # the face at a = pi joins its two cells to P = 0 instead of each other
        half_gap = dzeta / _integral(inverse_h3, faces[:1], centres[:1])[0]
        diagonal[[0, -1]] += half_gap - angular[-1]
        angular[-1] = 0.0

    source_r = 12.0 * np.outer(np.diff(np.sin(faces)), dzeta)
    source_t = 12.0 * np.outer(-np.diff(np.cos(faces)), dzeta)
    return FilmGrid(
        eps,
        width_over_diameter,
        faces,
        zeta,
        diagonal,
        across[:, :-1],
        angular,
        source_r,
        source_t,
    )


def solve_film(
    grid: FilmGrid,
    v_r: float,
    v_t: float,
    start: NDArray[np.bool_] | None = None,
) -> FilmSolution:
    """Solve the film for the effective squeeze velocity V = (v_r, v_t) [m/s].

    Parameters
    ----------
    grid
        The film (:func:`film_grid`).
    v_r, v_t
        V along e_r and e_t; P and the force scale with it.
    start
        A guess of the cavitated cells (``FilmSolution.cavitated`` of a nearby direction or
        eccentricity); none: start from the full film.

    Raises
    ------
    RuntimeError
        If the active set has not settled after ``MAX_STEPS`` steps (not seen: the method ends
        in finitely many steps for an M-matrix).
    """
    b = v_r * grid.source_r + v_t * grid.source_t
    active = np.zeros(grid.shape, bool) if start is None else start.copy()
    for step in range(1, MAX_STEPS + 1):
        pressure = _solve_free(grid, b, ~active)
        residual = grid.apply(pressure) - b
        # the semismooth Newton step on min(P, (A P - b) / A_ii) = 0: P = 0 where P is smaller
        new = pressure * grid.diagonal < residual
        if np.array_equal(new, active):
            force = (
                -np.sum(grid.source_r * pressure) / 12.0,
                -np.sum(grid.source_t * pressure) / 12.0,
            )
            return FilmSolution(pressure, force, step, active)
        active = new
    raise RuntimeError(f"the cavitation region did not settle in {MAX_STEPS} steps")


def film_force(
    eps: float,
    psi: float,
    width_over_diameter: float,
    n_angle: int = N_ANGLE,
    n_axial: int = N_AXIAL,
    supply: bool = True,
) -> tuple[float, float]:
    """The dimensionless film force W = (W_r, W_t) of a unit V at the angle ``psi`` [rad].

    F = mu L R^3 |V| / c^3 (W_r e_r + W_t e_t) [N]; psi is the angle of V from e_r.
    """
    grid = film_grid(eps, width_over_diameter, n_angle, n_axial, supply)
    return solve_film(grid, np.cos(psi), np.sin(psi)).force


def _solve_free(grid: FilmGrid, b: NDArray[np.float64], free: NDArray[np.bool_]) -> NDArray:
    """P with P = 0 off ``free`` and (A P)_ij = b_ij on it.

    The cavitated cells become identity rows, which keeps the matrix symmetric positive
    definite. Cut open where no flow crosses from one row of cells to the next (the supply
    line, or a row that is all cavitated), and without its rows that are all cavitated, the
    ring is a band of half-width n_axial (LAPACK's banded Cholesky); a ring with no such place
    goes to SuperLU.
    """
    from scipy.linalg import solveh_banded  # scipy loads where a film is solved

    n_a, n_z = grid.shape
    diagonal = np.where(free, grid.diagonal, 1.0)
    axial = grid.axial * (free[:, :-1] & free[:, 1:])
    angular = grid.angular * free
    angular[:-1] *= free[1:]
    angular[-1] *= free[0]
    rhs = np.where(free, b, 0.0)
    cuts = np.flatnonzero(~angular.any(axis=1))  # no flow from row k to row k + 1
    if cuts.size:
        ring = np.roll(np.arange(n_a), -(cuts[0] + 1))  # the ring, cut open there
        order = ring[free[ring].any(axis=1)]  # without the rows that are all cavitated
        pressure = np.zeros((n_a, n_z))
        if order.size:
            band = np.zeros((n_z + 1, order.size * n_z))
            band[n_z] = diagonal[order].ravel()
            upper = np.zeros((order.size, n_z))
            upper[:, 1:] = -axial[order]
            band[n_z - 1] = upper.ravel()
            # a row's flow to the next row in the ring; 0 where that one was left out
            band[0, n_z:] = -angular[order][:-1].ravel()
            solved = solveh_banded(band, rhs[order].ravel(), check_finite=False)
            pressure[order] = solved.reshape(order.size, n_z)
        return pressure
    from scipy import sparse
    from scipy.sparse.linalg import splu

    index = np.arange(n_a * n_z).reshape(n_a, n_z)
    rows = np.concatenate([index[:, :-1].ravel(), index.ravel()])
    cols = np.concatenate([index[:, 1:].ravel(), np.roll(index, -1, axis=0).ravel()])
    values = -np.concatenate([axial.ravel(), angular.ravel()])
    off = sparse.coo_matrix((values, (rows, cols)), shape=(index.size, index.size))
    matrix = (off + off.T + sparse.diags(diagonal.ravel())).tocsc()
    return splu(matrix).solve(rhs.ravel()).reshape(n_a, n_z)


def _angle_faces(eps: float, n_angle: int) -> NDArray[np.float64]:
    """Faces in a with the cell density 1 / sqrt(H) + 1/2, symmetric about a = 0."""
    half = n_angle // 2
    total = _density_integral(eps, np.array([np.pi]))[0]
    targets = total * np.arange(1, half) / half
    low, high = np.zeros(half - 1), np.full(half - 1, np.pi)
    for _ in range(60):  # bisection to 1e-18 of pi: the integral is monotonic
        mid = 0.5 * (low + high)
        below = _density_integral(eps, mid) < targets
        low, high = np.where(below, mid, low), np.where(below, high, mid)
    positive = np.concatenate([[0.0], 0.5 * (low + high), [np.pi]])
    return np.concatenate([-positive[:0:-1], positive])


def _density_integral(eps: float, a: NDArray[np.float64]) -> NDArray[np.float64]:
    """int_0^a (1 / sqrt(1 - eps cos t) + 1/2) dt for 0 <= a <= pi.

    With t = pi - 2 u, 1 - eps cos t = (1 + eps)(1 - m sin^2 u), m = 2 eps / (1 + eps): the
    first part is 2 / sqrt(1 + eps) (F(pi/2 | m) - F(pi/2 - a/2 | m)).
    """
    from scipy.special import ellipkinc

    m = 2.0 * eps / (1.0 + eps)
    elliptic = ellipkinc(0.5 * np.pi, m) - ellipkinc(0.5 * np.pi - 0.5 * a, m)
    return 2.0 / np.sqrt(1.0 + eps) * elliptic + _FAR_DENSITY * a


def _integral(f, lower: NDArray[np.float64], upper: NDArray[np.float64]) -> NDArray[np.float64]:
    """int_lower^upper f by 6-point Gauss-Legendre per interval (vectorised)."""
    nodes, weights = _GAUSS
    half = 0.5 * (upper - lower)
    points = 0.5 * (upper + lower)[:, None] + half[:, None] * nodes[None, :]
    return half * (f(points) @ weights)
