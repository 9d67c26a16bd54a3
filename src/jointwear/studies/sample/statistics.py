"""The statistics of a sampled study's outputs, each with a bootstrap confidence interval.

Per output: the cases described (``cases``), those it has a finite value in (``n``: fewer
where a life run's milestone was not reached, and the statistics are of those that reached
it), the mean, the standard deviation
(``ddof = 1``) and the 5th, 50th and 95th percentiles (numpy's linear interpolation between
order statistics). Each comes with the interval that holds it at ``confidence`` by the
percentile bootstrap (``scipy.stats.bootstrap``): what another draw of as many cases might
have given. A narrow interval says ``n`` was enough for that figure; P5 and P95 need many
more cases than the mean.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

STATISTICS = {  # name: statistic of a sample along an axis
    "mean": lambda x, axis: np.mean(x, axis=axis),
    "std": lambda x, axis: np.std(x, axis=axis, ddof=1),
    "p5": lambda x, axis: np.quantile(x, 0.05, axis=axis),
    "p50": lambda x, axis: np.quantile(x, 0.50, axis=axis),
    "p95": lambda x, axis: np.quantile(x, 0.95, axis=axis),
}
CONFIDENCE = 0.95
RESAMPLES = 2000  # bootstrap resamples: the interval's ends vary by ~1 % of its width
MIN_CASES = 5  # fewer values than this (that differ) get no interval: NaN


def statistics(
    table: pd.DataFrame,
    outputs: Sequence[str],
    *,
    confidence: float = CONFIDENCE,
    resamples: int = RESAMPLES,
    seed: int = 0,
) -> pd.DataFrame:
    """One row per output: ``cases``, ``n`` (with a value), each statistic and its interval.

    Parameters
    ----------
    table
        One row per independent case (for a Saltelli design, its base rows only).
    outputs
        The numeric columns to describe; the cases without a finite value are left out.
    confidence
        Of the intervals [-].
    resamples
        Bootstrap resamples.
    seed
        Of the resampling: the same seed gives the same intervals.
    """
    from scipy.stats import bootstrap

    rows = []
    for output in outputs:
        values = pd.to_numeric(table[output], errors="coerce").to_numpy(dtype=float)
        values = values[np.isfinite(values)]
        row: dict[str, object] = {"output": output, "cases": len(table), "n": len(values)}
        for name, statistic in STATISTICS.items():
            row[name] = float(statistic(values, None)) if len(values) > 1 else np.nan
            low = high = np.nan
            if len(values) >= MIN_CASES and np.ptp(values) > 0:
                interval = bootstrap(
                    (values,), statistic, confidence_level=confidence, n_resamples=resamples,
                    method="percentile", rng=np.random.default_rng(seed), vectorized=True,
                ).confidence_interval  # fmt: skip
                low, high = float(interval.low), float(interval.high)
            elif len(values) > 1 and np.ptp(values) == 0:  # every case alike: no spread
                low = high = row[name]
            row[f"{name}_low"], row[f"{name}_high"] = low, high
        rows.append(row)
    columns = ["output", "cases", "n"] + [
        f"{s}{end}" for s in STATISTICS for end in ("", "_low", "_high")
    ]
    return pd.DataFrame(rows, columns=columns)
