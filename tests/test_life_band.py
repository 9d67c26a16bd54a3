"""The uncertainty band of a life run (``studies.life.band``) against the direct simulation.

The paper's four-bar (examples/flores2009_fourbar.toml) at ten times the paper's wear
coefficient, so that its clearance grows by 50 % within about 76 crank turns and the direct
simulation of every turn takes some 10 s: a life run at max_change 2 % with its band of runs
at 4 % and 8 % (coarse bounds, so that the three runs take some 20 s) must hold the direct
run's 50 %-growth turn. Not its growth at the end: there the wear regime the joint settles
into differs even between direct simulations (``studies.life.band``), and between machines
whose compiled kernels round alike but not identically: measured 126 µm in a band of 104 to
149 µm on one, 133 µm against a band of 105 to 131 µm on another.
"""

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from jointwear.results.cycles import cycles_at
from jointwear.studies.life.band import band_columns, spread
from jointwear.studies.life.study import life

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
WEAR = ["joints.coupler_follower.clearance.wear_coefficient=8e-13"]  # 10 x the paper's
CYCLES = 85  # past the 50 % growth (about turn 76), short of the doubled clearance
C = 200e-6  # the radial clearance [m]
HOUR = 3600.0 / 0.04  # crank turns in an hour at 1500 rpm


def test_spread_is_the_value_plus_or_minus_the_largest_difference():
    assert spread(10.0, [12.0, 7.0]) == {"value": 10.0, "low": 7.0, "high": 13.0}
    assert spread(10.0, []) == {"value": 10.0, "low": 10.0, "high": 10.0}
    # A companion that never reached the mark: the band's top is beyond the run.
    assert spread(10.0, [12.0, None]) == {"value": 10.0, "low": 8.0, "high": None}


def test_the_band_holds_the_direct_simulation(tmp_path):
    res = life(FOURBAR, tmp_path / "life", cycles=CYCLES, overrides=WEAR, max_change="2%",
               band=("4%", "8%"))  # fmt: skip
    direct = life(FOURBAR, tmp_path / "direct", cycles=CYCLES, overrides=WEAR, extrapolate=False,
                  figures=False)  # fmt: skip
    assert res.status == direct.status == "success", (res.message, direct.message)
    growth = direct.table["coupler_follower.clearance_growth_m"]
    reference = cycles_at(direct.table["cycles"], growth, 0.5 * C)
    joint = res.summary["clearance_joints"]["coupler_follower"]
    band = joint["band"]
    half, grown = band["cycles_to_clearance_growth_50pct"], band["clearance_growth_m"]
    # The value is the run at max_change, low <= value <= high.
    assert half["value"] == joint["cycles_to_clearance_growth_50pct"]
    assert grown["value"] == joint["clearance_growth_m"]
    for entry in band.values():
        assert entry["low"] <= entry["value"] <= entry["high"], band
    # The band holds the direct run's 50 % growth, with no tolerance: that is the band's
    # claim. Measured: 50 % growth at turn 76.5 directly; the runs at 2, 4 and 8 % reach it
    # at 67.5, 81.1 and 78.9, so the band is 67.5 -/+ 13.6 = 53.9 to 81.1.
    assert half["low"] <= reference <= half["high"], (reference, half)
    hours = band["hours_to_clearance_growth_50pct"]
    assert hours == {k: pytest.approx(v / HOUR, rel=1e-12) for k, v in half.items()}
    assert joint["hours_to_clearance_growth_50pct"] == pytest.approx(half["value"] / HOUR)
    # Not a run-away: from one update to the next the joint's peak force and wear per turn
    # stay within 2.3 times the median of the three updates before (measured on these runs'
    # life.csv), well within the factor 10.
    assert "runaway" not in res.summary and not res.summary["band"]["ran_away"]
    assert res.summary["cycles_reached"] == direct.summary["cycles_reached"] == CYCLES
    # How the band was made, and where its runs are.
    made = res.summary["band"]
    assert made["max_change"] == ["2%", "4%", "8%"] and made["at_cycles"] == CYCLES
    assert [r["folder"] for r in made["runs"]] == [".", "band/4pct", "band/8pct"]
    for run in made["runs"]:
        assert (tmp_path / "life" / run["folder"] / "life.csv").is_file()
        assert run["status"] == "success" and run["cycles_reached"] == CYCLES
    # The files: summary.json as returned, life_band.csv, the figure.
    folder = tmp_path / "life"
    assert json.loads((folder / "summary.json").read_text())["band"] == made
    table = pd.read_csv(folder / "life_band.csv")
    assert table.columns.tolist() == band_columns_of(res)
    assert table["runs"].max() == 3 and table["cycles"].iloc[-1] == CYCLES
    np.testing.assert_allclose(table["hours"], table["cycles"] / HOUR, rtol=1e-11)  # 12 digits
    low, high = (table[f"coupler_follower.clearance_growth_{e}_m"] for e in ("low", "high"))
    assert (low <= table["coupler_follower.clearance_growth_m"]).all() and (low <= high).all()
    assert high.iloc[-1] == pytest.approx(grown["high"], rel=1e-9)
    assert (folder / "figures" / "life_wear.png").stat().st_size > 10_000
    # Without extrapolation there is no band: a direct run is its own reference.
    assert "band" not in direct.summary and not (tmp_path / "direct" / "life_band.csv").exists()


def band_columns_of(res) -> list[str]:
    from jointwear.model import load_model

    return band_columns(load_model(FOURBAR, WEAR))


def test_the_band_s_runs_beside_each_other_give_the_numbers_in_series(tmp_path):
    settings = {"cycles": 40, "overrides": WEAR, "max_change": "2%", "band": ("4%", "8%"),
                "figures": False}  # fmt: skip
    reports = []
    series = life(FOURBAR, tmp_path / "series", **settings, workers=1)
    beside = life(FOURBAR, tmp_path / "beside", **settings, workers=3,
                  progress=lambda done, total: reports.append((done, total)))  # fmt: skip
    assert series.status == beside.status == "success"
    # The companions ran in other processes (the runners record each in case.json).
    assert (tmp_path / "beside" / "band" / "4pct" / "case.json").is_file()
    assert not (tmp_path / "series" / "band" / "4pct" / "case.json").exists()
    # The same runs: the same numbers, to the last bit, but for the wall times.
    for name in ("life.csv", "profiles.csv", "life_band.csv", "band/4pct/life.csv",
                 "band/8pct/life.csv", "band/8pct/profiles.csv"):  # fmt: skip
        alone, together = (pd.read_csv(tmp_path / run / name) for run in ("series", "beside"))
        kept = [c for c in alone.columns if c != "wall_s"]
        pd.testing.assert_frame_equal(alone[kept], together[kept], check_exact=True)
    assert without_walls(series.summary) == without_walls(beside.summary)
    # Progress over the three runs' cycles, never backwards.
    assert reports[-1] == (120, 120)
    assert [d for d, _ in reports] == sorted(d for d, _ in reports)
    # The companions on a Dask cluster (a worker in this process, over a real connection).
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=1, processes=False, protocol="tcp://",
        host="127.0.0.1", dashboard_address=None,
    ) as cluster:  # fmt: skip
        dask = life(FOURBAR, tmp_path / "dask", **settings, scheduler=cluster.scheduler_address)
    assert (tmp_path / "dask" / "band" / "8pct" / "case.json").is_file()
    assert without_walls(dask.summary) == without_walls(series.summary)


def without_walls(entry: object) -> object:
    """A summary without its wall times (``wall_s``, ``elapsed_s``), at every level."""
    if isinstance(entry, dict):
        return {k: without_walls(v) for k, v in entry.items() if k not in ("wall_s", "elapsed_s")}
    if isinstance(entry, list):
        return [without_walls(v) for v in entry]
    return entry
