"""How much each input of a sampled study moves each output, with intervals.

Two measures, one row per (output, input):

- **Sobol' indices** from a Saltelli design (``method = "saltelli"``), through SALib: ``S1``,
  the share of the output's variance the input causes alone, and ``ST``, alone and with the
  others; their intervals by SALib's bootstrap. ``ST - S1`` large: the input acts through
  its interplay with others. Estimators after Saltelli et al. (2010) (first order) and
  Jansen (1999) (total), as SALib computes them.
- **Spearman's rank correlation** otherwise (any design): ``rho`` in [-1, 1], whether the
  output rises or falls with the input, for any monotone relation; its interval by the
  Fisher transform with the variance ``(1 + rho^2 / 2) / (n - 3)`` of D.G. Bonett and
  T.A. Wright, "Sample size requirements for estimating Pearson, Kendall and Spearman
  correlations", Psychometrika 65 (2000) 23-28.

An input drawn from a list of texts (an integrator's name) has no order: it gets no rank
correlation, only Sobol' indices.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from .statistics import CONFIDENCE

SOBOL_COLUMNS = ["output", "input", "S1", "S1_low", "S1_high", "ST", "ST_low", "ST_high"]
RANK_COLUMNS = ["output", "input", "n", "rho", "rho_low", "rho_high"]
EDGE = 1e-15  # a rank correlation of exactly +-1 is taken this far inside, for its interval


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
    return pd.DataFrame(rows, columns=SOBOL_COLUMNS)


def rank_correlations(
    table: pd.DataFrame,
    inputs: Sequence[str],
    outputs: Sequence[str],
    *,
    confidence: float = CONFIDENCE,
) -> pd.DataFrame:
    """Spearman's rho of every output with every numeric input, with its interval.

    The cases without a finite output are left out of that output's correlations.
    """
    from scipy.stats import norm, spearmanr

    z = norm.ppf(0.5 + confidence / 2)
    numeric = [name for name in inputs if pd.api.types.is_numeric_dtype(table[name])]
    rows = []
    for output in outputs:
        y = pd.to_numeric(table[output], errors="coerce").to_numpy(dtype=float)
        finite = np.isfinite(y)
        n = int(finite.sum())
        if n < 4 or np.ptp(y[finite]) == 0:
            continue
        for name in numeric:
            x = table[name].to_numpy(dtype=float)[finite]
            if np.ptp(x) == 0:
                continue
            rho = float(spearmanr(x, y[finite]).statistic)
            half = z * np.sqrt((1 + rho**2 / 2) / (n - 3))
            centre = np.arctanh(np.clip(rho, -1 + EDGE, 1 - EDGE))  # |rho| = 1: an edge
            rows.append([output, name, n, rho, np.tanh(centre - half), np.tanh(centre + half)])
    return pd.DataFrame(rows, columns=RANK_COLUMNS)
