"""Accuracy of the Greenwood-Tripp fit and of the journal's asperity load (docs/theory.md).

Prints the table of docs/theory.md, section "Mixed lubrication": F_5/2 by quadrature against
the fit of Hu et al. (1994) that ``kernels.laws.asperity.f52`` uses; ``asperity_load`` (the
fit integrated over the parabolic gap in closed form) against the exact Gaussian load over
the same gap, (5 pi / 16) F_3 (F_3 by the parabolic cylinder function); and against
quadrature of the fitted pressure over the circles' exact gap, for a journal of radius
10 mm, clearance 100 um and roughness 1 um.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/asperity_fit.py
"""

from __future__ import annotations

import math

import numpy as np
from scipy import integrate, special

from jointwear.kernels.laws.asperity import asperity_load, f52

LAMBDAS = (-1.0, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5)
JOURNAL = 10e-3, 100e-6, 1e-6  # R_J, c, sigma [m]


def f_n_exact(n: float, lam: float) -> float:
    """F_n by the parabolic cylinder function: Gamma(n + 1) / sqrt(2 pi) e^(-lam^2/4) D_-(n+1)."""
    return (
        special.gamma(n + 1)
        / math.sqrt(2 * math.pi)
        * math.exp(-lam * lam / 4)
        * special.pbdv(-(n + 1), lam)[0]
    )


def f52_quadrature(lam: float) -> float:
    """F_5/2 by its defining integral."""
    return integrate.quad(
        lambda s: (s - lam) ** 2.5 * math.exp(-s * s / 2) / math.sqrt(2 * math.pi),
        lam,
        np.inf,
        epsabs=0,
        epsrel=1e-12,
    )[0]


def circle_load(lam: float, r_j: float, c: float, sigma: float) -> float:
    """Fitted asperity load [N] per unit k_gt E' L over the circles' exact gap, by quadrature.

    The gap along the bearing's radius at angle a from the line of centres is R_B - e cos a -
    sqrt(R_J^2 - e^2 sin^2 a); the pressure's component along the line of centres is summed
    over the bearing's surface, R_B da.
    """
    r_b, e = r_j + c, c - lam * sigma
    r_star = r_b * r_j / c
    edge = min(math.pi / 2, 3 * math.sqrt(2 * r_star * sigma * (20 + abs(lam))) / r_b)

    def pressure(a: float) -> float:
        gap = r_b - e * math.cos(a) - math.sqrt(r_j**2 - (e * math.sin(a)) ** 2)
        return f52(gap / sigma) * math.cos(a) * r_b

    return integrate.quad(pressure, -edge, edge, points=[0.0], epsabs=0, epsrel=1e-10, limit=200)[0]


def fit_load_error(lam: float) -> float:
    """Relative error of ``asperity_load`` against the Gaussian load over the parabolic gap."""
    r_star = 1.0
    fit = asperity_load(lam, 1.0, 1.0, r_star, 1.0) / math.sqrt(2 * r_star)
    return fit / (5 * math.pi / 16 * f_n_exact(3, lam)) - 1


def row(lam: float) -> str:
    """One row of the table: lam, F_5/2, the fit and its error, the loads' errors."""
    exact = f52_quadrature(lam)
    fit = f52(lam)
    r_j, c, sigma = JOURNAL
    load = asperity_load(lam * sigma, sigma, 1.0, (r_j + c) * r_j / c, 1.0)
    load_error = load / circle_load(lam, r_j, c, sigma) - 1
    return (
        f"| {lam:4.1f} | {exact:.4e} | {fit:.4e} | {100 * (fit / exact - 1):+6.1f} % "
        f"| {100 * fit_load_error(lam):+6.1f} % | {100 * load_error:+6.2f} % |"
    )


if __name__ == "__main__":
    print(
        "| lambda | F_5/2 (quadrature) | fit | fit error | fit's load error "
        "| load error (parabola) |"
    )
    print("|---|---|---|---|---|---|")
    for lam in LAMBDAS:
        print(row(lam))
