"""The cases of a sampled study: points of the unit cube, through the inputs' distributions.

``method`` picks the points:

- ``random``: independent uniform points (numpy's generator);
- ``lhs``: a Latin hypercube, one point in each of ``n`` equal slices of every input
  (``scipy.stats.qmc.LatinHypercube``);
- ``sobol``: a scrambled Sobol' sequence (``scipy.stats.qmc.Sobol``), most even for ``n`` a
  power of two;
- ``saltelli``: the design of Saltelli et al. (2010) for first-order and total Sobol'
  indices, through SALib: ``n (d + 2)`` cases for ``d`` inputs, in blocks of ``d + 2``: a
  point A, A with each input in turn taken from B, and B. The A and B points are
  independent draws; the statistics are of them (``base`` rows) and the indices of all.

Correlated inputs (any method but ``saltelli``, whose indices assume independent inputs) go
through a Gaussian copula: the points' normal scores are mixed by the Cholesky factor of the
asked correlation matrix, so ``rho`` is the correlation of the inputs' normal scores; each
input keeps its own distribution.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence

import numpy as np
from numpy.typing import NDArray

from ...model import ModelError

METHODS = ("random", "lhs", "sobol", "saltelli")
BASE = "base"  # a study table's column: the case is an independent draw (unit_points)


def unit_points(
    inputs: int,
    n: int,
    method: str,
    seed: int,
    correlation: NDArray[np.float64] | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    """Points of the unit cube, one row per case, and which rows are independent draws.

    Parameters
    ----------
    inputs
        Inputs (columns).
    n
        Cases; for ``saltelli`` the base points, giving ``n (inputs + 2)`` cases.
    method
        One of ``METHODS``.
    seed
        Seed of the random generator: the same seed gives the same points.
    correlation
        The inputs' correlation matrix of normal scores, or None for independent inputs.
    """
    from scipy.stats import qmc

    rng = np.random.default_rng(seed)
    with warnings.catch_warnings():  # balance: Sobol' points for n not a power of two
        warnings.simplefilter("ignore", UserWarning)
        if method == "random":
            points = rng.random((n, inputs))
        elif method == "lhs":
            points = qmc.LatinHypercube(inputs, rng=rng).random(n)
        elif method == "sobol":
            points = qmc.Sobol(inputs, rng=rng).random(n)
        else:
            return _saltelli(inputs, n, seed)
    if correlation is not None:
        points = _correlated(points, correlation)
    return points, np.ones(len(points), dtype=bool)


def _saltelli(inputs: int, n: int, seed: int) -> tuple[NDArray[np.float64], NDArray[np.bool_]]:
    from SALib.sample import sobol

    problem = {"num_vars": inputs, "names": [f"x{i}" for i in range(inputs)],
               "bounds": [[0.0, 1.0]] * inputs}  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        points = sobol.sample(problem, n, calc_second_order=False, seed=seed)
    block = np.arange(len(points)) % (inputs + 2)
    return points, (block == 0) | (block == inputs + 1)


def _correlated(points: NDArray[np.float64], correlation: NDArray[np.float64]) -> NDArray:
    """Points whose normal scores are correlated by ``correlation`` (a Gaussian copula)."""
    from scipy.stats import norm

    scores = norm.ppf(np.clip(points, 1e-12, 1 - 1e-12))
    return norm.cdf(scores @ np.linalg.cholesky(correlation).T)


def correlation_matrix(
    paths: Sequence[str], pairs: Mapping[tuple[str, str], float]
) -> NDArray[np.float64] | None:
    """The correlation matrix of ``paths`` with ``pairs`` off the diagonal; None if no pairs.

    Raises
    ------
    ModelError
        If a pair names a path that is not drawn, repeats, or is not in (-1, 1), or if the
        matrix is not positive definite (correlations that contradict each other).
    """
    if not pairs:
        return None
    matrix = np.eye(len(paths))
    problems = []
    for (first, second), rho in pairs.items():
        where = f"--correlate {first},{second}"
        unknown = [path for path in (first, second) if path not in paths]
        if unknown:
            problems.append(f"{where}: {unknown[0]} has no distribution (--dist)")
        elif first == second:
            problems.append(f"{where}: a path with itself; name two paths")
        elif not (isinstance(rho, int | float) and -1 < rho < 1):
            problems.append(f"{where}: got {rho!r}; expected a number between -1 and 1")
        else:
            i, j = paths.index(first), paths.index(second)
            if matrix[i, j] != 0:
                problems.append(f"{where}: given twice; give each pair once")
            matrix[i, j] = matrix[j, i] = rho
    if problems:
        raise ModelError(problems)
    if np.linalg.eigvalsh(matrix)[0] <= 0:
        contradiction = "their matrix is not positive definite; weaken some"
        raise ModelError([f"--correlate: the correlations contradict each other ({contradiction})"])
    return matrix
