"""The uncertainty band of a long-life wear run: the same run at coarser ``max_change`` bounds.

A joint whose motion switches between regimes (the paper's four-bar passes through bursts of
chaotic impacts) makes a single life run uncertain: which regime an update lands in depends
on the jump in the profiles, so two runs that differ only in ``max_change`` reach the same
clearance growth some per cent apart, and no single run says by how much. The band measures
it. Beside the run at ``max_change`` (the *value*), the same life run is made at each bound
of ``band`` (coarser ones: ``BAND``, twice and four times the default), each in
``band/<bound>/`` of the run's folder, a life folder of its own. For every quantity the
half-width of the band is the largest difference between a companion and the value, and the
band is the value plus or minus it:

    low, high = value -/+ max_i |x_i - value|

This is the error estimate of step doubling: for a first-order method (the extrapolation's
error grows with the bound), the run at twice the bound is off by about twice the finer
run's error, so their difference estimates that error; where chaos rather than the bound
dominates, the companions are further samples of the scatter, on either side of the value,
hence the symmetric band. On the paper's four-bar over a million turns
(``benchmarks/bench_studies.py --band --direct``) it holds the 50 %-growth turn of the direct
simulation of every turn, which ``[min, max]`` of the runs does not, and that of direct
simulations with another integrator or a tighter tolerance. Late in that life the joint
settles into one of two wear regimes, and which one differs even between those direct
simulations: there the band holds the growth of some of them only (docs/benchmarks.md,
"Long-life wear against the direct simulation").

A band whose runs all ran away (``runaway``) measures nothing: they stopped at the same
blow-up, and their agreement says nothing of when the joint would have reached a milestone.
``summary.json`` then says so (``all_ran_away``), and the command line prints that instead of
the band.

``life.csv`` keeps the value's run; ``life_band.csv`` tabulates the band against cycles
(``band_table``), and ``summary.json`` gives it per joint (``band_summary``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence

import numpy as np
import pandas as pd

from ...engine.status import RUNAWAY
from ...joints import ClearanceKind, joints_by_kind
from ...model import Model
from ...results.cycles import cycles_at
from .records import GROWTH_MARK, HOUR_S, depth_keys, hours

BAND = ("0.5%", "1%")  # the companions of the default max_change "0.25%": twice, four times it
FOLDER = "band"  # the companions' life folders, band/<bound>/


def folder_name(bound: str | float) -> str:
    """The folder of the companion run at ``bound``: ``band/1pct``, ``band/2um``."""
    text = str(bound).replace("%", "pct").replace("/", "_")
    return "".join(c for c in text if c.isalnum() or c in "._-") or "bound"


def banded(model: Model) -> Iterator[tuple[ClearanceKind, object, list[str]]]:
    """(kind, joint, keys) of every clearance joint: the life.csv figures the band is of.

    The clearance growth, and the deepest cell of each mapped surface.
    """
    for kind, _, joint in joints_by_kind(model):
        yield kind, joint, ["clearance_growth_m", *depth_keys(kind, joint)]


def band_columns(model: Model) -> list[str]:
    """The columns of life_band.csv, in order."""
    columns = ["cycles", "hours", "runs"]
    for _, joint, keys in banded(model):
        for key in keys:
            stem = key.removesuffix("_m")
            columns += [f"{joint.name}.{key}", f"{joint.name}.{stem}_low_m"]
            columns += [f"{joint.name}.{stem}_high_m"]
    return columns


def _at(table: pd.DataFrame, column: str, cycles: int) -> float | None:
    """``column`` of a life table at ``cycles`` (linear between rows); None outside them."""
    value = float(_curve(table, column, np.array([float(cycles)]))[0])
    return value if math.isfinite(value) else None


def _curve(table: pd.DataFrame, column: str, at: np.ndarray) -> np.ndarray:
    """``column`` of a life table at cycles ``at``, linear between rows; NaN outside them."""
    x, y = table["cycles"].to_numpy(float), table[column].to_numpy(float)
    values = np.interp(at, x, y)
    values[(at < x[0]) | (at > x[-1])] = math.nan
    return values


def band_table(
    model: Model, value: pd.DataFrame, companions: Sequence[pd.DataFrame], period: float
) -> pd.DataFrame:
    """life_band.csv: the value's curves and the band around them, against cycles.

    On every cycle count of any run within the value's rows (and its hours, cycles of
    ``period`` [s]); ``runs`` counts the runs that reached it (the value's included). Where
    no companion did, low and high are the value.
    """
    tables = [t for t in companions if len(t)]
    cycles = np.unique(np.concatenate([t["cycles"].to_numpy(float) for t in [value, *tables]]))
    cycles = cycles[(cycles >= value["cycles"].iloc[0]) & (cycles <= value["cycles"].iloc[-1])]
    reached = [np.isfinite(_curve(t, "cycles", cycles)) for t in tables]
    data: dict[str, np.ndarray] = {"cycles": cycles, "runs": 1 + np.sum(reached, axis=0)}
    for _, joint, keys in banded(model):
        for key in keys:
            column = f"{joint.name}.{key}"
            centre = _curve(value, column, cycles)
            apart = [np.abs(_curve(t, column, cycles) - centre) for t in tables]
            half = np.nanmax(np.vstack([np.zeros_like(centre), *apart]), axis=0)
            stem = key.removesuffix("_m")
            data[column] = centre
            data[f"{joint.name}.{stem}_low_m"] = centre - half
            data[f"{joint.name}.{stem}_high_m"] = centre + half
    table = pd.DataFrame(data)
    table["cycles"] = table["cycles"].round().astype("int64")
    table["hours"] = table["cycles"] * period / HOUR_S
    return table[band_columns(model)]


def spread(value: float | None, others: Sequence[float | None]) -> dict[str, float | None]:
    """``{value, low, high}``: ``value`` -/+ its largest difference from ``others``.

    An ``other`` of None (never reached) leaves ``high`` None: beyond the cycles run; a
    ``value`` of None leaves all three None but ``low`` (the earliest of the others).
    """
    known = [x for x in others if x is not None]
    if value is None:
        return {"value": None, "low": min(known) if known else None, "high": None}
    half = max((abs(x - value) for x in known), default=0.0)
    high = None if len(known) < len(others) else value + half
    return {"value": value, "low": value - half, "high": high}


def band_summary(
    model: Model,
    value: pd.DataFrame,
    companions: dict[str, pd.DataFrame],
    runs: list[dict],
    cycles: int,
    period: float,
) -> tuple[dict, dict[str, dict]]:
    """The band's entries of summary.json: at the top, and per clearance joint.

    Parameters
    ----------
    model
        The model as run.
    value
        life.csv of the run at ``max_change``.
    companions
        life.csv of every companion that ended with a table, by bound.
    runs
        ``{max_change, folder, status, cycles_reached, wall_s, runaway_cycle}`` of every run
        of the band, the value's first.
    cycles
        The cycles asked for. A companion that stopped before them (at the clearance limit)
        without reaching 50 % growth says nothing of when it would have (its last update
        jumped past the mark and the limit), or ran away before it, says nothing of when it
        would have: it is left out of that figure; one that ran them all without reaching it
        leaves ``high`` None.
    period
        The cycle [s]: the cycles to 50 % growth are also given in hours.

    Returns
    -------
    tuple
        ``band`` (how it was made, the runs, ``at_cycles``: the cycle count at which the
        end-of-run figures are compared, the fewest any run reached, ``ran_away``: the
        ``max_change`` of the runs that ran away, and ``all_ran_away``) and, per joint,
        ``{value, low, high}`` of the cycles (and hours) to 50 % clearance growth and of the
        clearance growth and the deepest cells at ``at_cycles``.
    """
    tables = [t for t in companions.values() if len(t)]
    ends = [int(t["cycles"].iloc[-1]) for t in [value, *tables] if len(t)]
    at = min(ends) if ends else 0
    ran_away = [r["max_change"] for r in runs if r["status"] == RUNAWAY]
    top = {
        "rule": "value -/+ the largest difference between a companion run and the value",
        "max_change": [r["max_change"] for r in runs],
        "runs": runs,
        "at_cycles": at,
        "ran_away": ran_away,
        "all_ran_away": len(ran_away) == len(runs),
    }
    joints: dict[str, dict] = {}
    if not len(value):
        return top, joints
    for kind, joint, keys in banded(model):
        mark = GROWTH_MARK * kind.gap(joint)
        column = f"{joint.name}.clearance_growth_m"
        crossings = [(cycles_at(t["cycles"], t[column], mark), t) for t in tables]
        known = [at for at, t in crossings if at is not None or t["cycles"].iloc[-1] >= cycles]
        half = spread(cycles_at(value["cycles"], value[column], mark), known)
        entry = {
            "cycles_to_clearance_growth_50pct": half,
            "hours_to_clearance_growth_50pct": {e: hours(x, period) for e, x in half.items()},
        }
        for key in keys:
            column = f"{joint.name}.{key}"
            entry[key] = spread(_at(value, column, at), [_at(t, column, at) for t in tables])
        joints[joint.name] = entry
    return top, joints
