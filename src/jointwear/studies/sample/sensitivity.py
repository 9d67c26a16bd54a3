"""How much each input of a sampled study moves each output, with intervals.

Two measures, one row per (output, input):

- **Sobol' indices** from a Saltelli design (``method = "saltelli"``), through SALib: ``S1``,
  the share of the output's variance the input causes alone, and ``ST``, alone and with the
  others; their intervals by SALib's bootstrap. ``ST - S1`` large: the input acts through
  its interplay with others. Estimators after Saltelli et al. (2010) (first order) and
  Jansen (1999) (total), as SALib computes them.
- **Rank correlations** otherwise (any design), in [-1, 1], whether the output rises or
  falls with the input, for any monotone relation:

  - Spearman's ``rho``, the correlation of the ranks, with its interval by the Fisher
    transform and the variance ``(1 + rho^2 / 2) / (n - 3)`` of D.G. Bonett and T.A.
    Wright, "Sample size requirements for estimating Pearson, Kendall and Spearman
    correlations", Psychometrika 65 (2000) 23-28;
  - the partial rank correlation ``prcc``, the same with the other inputs' (linear, on
    ranks) share taken out of both: S. Marino, I.B. Hogue, C.J. Ray and D.E. Kirschner,
    "A methodology for performing global uncertainty and sensitivity analysis in systems
    biology", J. Theor. Biol. 254 (2008) 178-196. Drawn inputs are correlated by chance
    (by 0.28 between two of the tolerance example's 16 at 128 cases), and rho credits an
    input with the effect of another it happens to follow; prcc does not. Its interval by
    the Fisher transform with ``n - 3 - (inputs - 1)`` degrees of freedom; it needs more
    cases than inputs plus 3.

An input drawn from a list of texts (an integrator's name) has no order: it gets no rank
correlation, only Sobol' indices.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from ..sweep.cases import short_keys
from .statistics import CONFIDENCE

SOBOL_COLUMNS = ["output", "input", "S1", "S1_low", "S1_high", "ST", "ST_low", "ST_high"]
TABLE_WORDS = {"joints", "clearance", "bodies", "drivers", "forces", "function"}  # in labels
PERFECT = 1 - 1e-12  # a correlation this close to +-1 is perfect (1 but for rounding)
RANK_COLUMNS = ["output", "input", "n", "rho", "rho_low", "rho_high", "prcc", "prcc_low",
                "prcc_high"]  # fmt: skip


def input_labels(inputs: Sequence[str]) -> dict[str, str]:
    """Each input's path without the words every such path has (``joints``, ``clearance``).

    ``joints.crank_coupler.clearance.journal_radius`` -> "crank_coupler journal_radius";
    the shortest distinct trailing parts where that would confuse two inputs.
    """
    labels = {path: " ".join(p for p in path.split(".") if p not in TABLE_WORDS) or path
              for path in inputs}  # fmt: skip
    if len(set(labels.values())) < len(labels):
        return short_keys(list(inputs))
    return labels


def _with_effect(rows: pd.DataFrame) -> pd.DataFrame:
    """The rows with ``effect``: how strongly the input moves the output, to rank inputs by.

    ``|ST|``, or ``|prcc|`` (``|rho|`` where the output had too few cases for it); 0 for none.
    """
    rank = rows["prcc"].abs().fillna(rows["rho"].abs()) if "prcc" in rows else None
    found = rows["ST"].abs() if "ST" in rows else rank
    return rows.assign(effect=found.fillna(0.0))


def sobol_indices(
    table: pd.DataFrame,
    inputs: Sequence[str],
    outputs: Sequence[str],
    *,
    confidence: float = CONFIDENCE,
    seed: int = 0,
) -> pd.DataFrame:
    """First-order and total Sobol' indices of every output, from a Saltelli design's table.

    ``table`` holds the design's rows in order (``design.unit_points`` with ``saltelli``).
    An output missing in any case (a failed run) gets no indices: the estimators need every
    row of the design.
    """
    from SALib.analyze import sobol

    problem = {"num_vars": len(inputs), "names": list(inputs),
               "bounds": [[0.0, 1.0]] * len(inputs)}  # fmt: skip
    rows = []
    for output in outputs:
        y = pd.to_numeric(table[output], errors="coerce").to_numpy(dtype=float)
        if not np.all(np.isfinite(y)) or np.ptp(y) == 0:
            continue
        found = sobol.analyze(
            problem, y, calc_second_order=False, conf_level=confidence, seed=seed,
            num_resamples=1000,
        )  # fmt: skip
        for i, name in enumerate(inputs):
            s1, s1_half, st, st_half = (found[k][i] for k in ("S1", "S1_conf", "ST", "ST_conf"))
            rows.append([output, name, s1, s1 - s1_half, s1 + s1_half, st, st - st_half,
                         st + st_half])  # fmt: skip
    return _with_effect(pd.DataFrame(rows, columns=SOBOL_COLUMNS))


def rank_correlations(
    table: pd.DataFrame,
    inputs: Sequence[str],
    outputs: Sequence[str],
    *,
    confidence: float = CONFIDENCE,
) -> pd.DataFrame:
    """Spearman's rho and the partial rank correlation of every output with every input.

    Numeric inputs that vary only. The cases without a finite output are left out of that
    output's correlations. ``prcc`` is NaN where the cases are too few for it (``n`` at most
    the inputs plus 3).
    """
    from scipy.stats import norm, rankdata

    z = norm.ppf(0.5 + confidence / 2)
    numeric = [
        name
        for name in inputs
        if pd.api.types.is_numeric_dtype(table[name]) and table[name].nunique() > 1
    ]
    rows = []
    for output in outputs:
        y = pd.to_numeric(table[output], errors="coerce").to_numpy(dtype=float)
        finite = np.isfinite(y)
        n = int(finite.sum())
        if n < 4 or np.ptp(y[finite]) == 0 or not numeric:
            continue
        ranks = rankdata(
            np.column_stack([table[numeric].to_numpy(dtype=float)[finite], y[finite]]), axis=0
        )
        correlation = np.corrcoef(ranks, rowvar=False)
        rho = correlation[-1, :-1]
        partial = _partial(correlation) if n > len(numeric) + 3 else np.full(len(numeric), np.nan)
        rho_interval = _fisher(rho, z * np.sqrt((1 + rho**2 / 2) / (n - 3)))
        prcc_interval = _fisher(partial, z / np.sqrt(max(n - 3 - (len(numeric) - 1), 1)))
        for j, name in enumerate(numeric):
            rows.append([output, name, n, rho[j], *rho_interval[j], partial[j],
                         *prcc_interval[j]])  # fmt: skip
    return _with_effect(pd.DataFrame(rows, columns=RANK_COLUMNS))


def _partial(correlation: np.ndarray) -> np.ndarray:
    """The partial correlation of the last variable with each other one, given all the rest.

    From the inverse P of the correlation matrix: -P[i, -1] / sqrt(P[i, i] P[-1, -1]).
    NaN where the inputs' ranks are linearly dependent (the matrix is singular).
    """
    try:
        inverse = np.linalg.inv(correlation)
    except np.linalg.LinAlgError:
        return np.full(len(correlation) - 1, np.nan)
    diagonal = np.diag(inverse)
    return np.clip(-inverse[:-1, -1] / np.sqrt(diagonal[:-1] * diagonal[-1]), -1.0, 1.0)


def _fisher(values: np.ndarray, half: np.ndarray | float) -> np.ndarray:
    """Intervals (low, high) of correlations by the Fisher transform: tanh(atanh r -+ half).

    None (NaN) at |r| = 1, where the transform has no spread to give: a perfect rank order,
    which a few cases show by chance as readily as a law does.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        centre = np.where(np.abs(values) < PERFECT, np.arctanh(values), np.nan)
    return np.column_stack([np.tanh(centre - half), np.tanh(centre + half)])
