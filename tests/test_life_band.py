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
    low, high = (table[f"coupler_follower.clearance_growth_{e}_m"] for e in ("low", "high"))
    assert (low <= table["coupler_follower.clearance_growth_m"]).all() and (low <= high).all()
    assert high.iloc[-1] == pytest.approx(grown["high"], rel=1e-9)
    assert (folder / "figures" / "life_wear.png").stat().st_size > 10_000
    # Without extrapolation there is no band: a direct run is its own reference.
    assert "band" not in direct.summary and not (tmp_path / "direct" / "life_band.csv").exists()


def band_columns_of(res) -> list[str]:
    from jointwear.model import load_model

    return band_columns(load_model(FOURBAR, WEAR))
