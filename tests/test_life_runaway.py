"""Run-aways in life runs (``studies.life.runaway``): the detector, and runs it stops.

- The detector against sequences whose answers are known by hand, and the watch of a life
  run against constructed updates and cycles.
- A steel pin in a bronze bush (examples/slider_crank_clearance.toml's rod-slider joint with
  a bronze bush, E 110 GPa and nu 0.34, dry friction 0.15, 90 % of the wear to the bush)
  worn a thousand times faster than issue 30's case (k = 1.3e-10 1/Pa), so that its
  clearance grows by some 5 µm a cycle: as it grows, the rod's small end strikes the pin
  harder, and its penetration, 0.072 of the gap in the first update after the settling,
  leaves Hertz's range (0.1 of the gap) within a few cycles. The same run without the check
  says when (its table), independently of the watch.
- A blow-up made by hand: the four-bar whose runs report fifty times the contact force from
  a given cycle on.
"""

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from jointwear.cli import app
from jointwear.engine.simulate import simulate
from jointwear.model import ModelError, load_model
from jointwear.studies.life import update as lifetime_update
from jointwear.studies.life.runaway import Watch, jump
from jointwear.studies.life.study import life

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
FAST_WEAR = ["joints.coupler_follower.clearance.wear_coefficient=4e-13"]  # 5 x the paper's
SLIDER_CRANK = ROOT / "examples" / "slider_crank_clearance.toml"
BRONZE_BUSH = [
    "joints.rod_slider.clearance.wear_coefficient=1.3e-10 1/Pa",
    "joints.rod_slider.clearance.journal_wear_share=0.1",
    "joints.rod_slider.clearance.friction_coefficient=0.15",
    'joints.rod_slider.clearance.youngs_modulus=["110 GPa", "207 GPa"]',
    "joints.rod_slider.clearance.poisson_ratio=[0.34, 0.3]",
]
HERTZ_RANGE = 0.1  # penetration / radial clearance of Hertz's law (docs/model-format.md)
PENETRATION = "coupler_follower.max_penetration_over_gap"


def test_a_jump_is_judged_against_the_median_of_the_last_updates():
    assert jump([1.0, 1.0, 1.0], [9.0], 10.0) is None
    assert jump([1.0, 1.0, 1.0], [11.0], 10.0) == 0
    assert jump([2.0, 2.0, 2.0], [5.0, 25.0, 30.0], 10.0) == 1  # the first above 20
    # The median: one odd update sets no level (their largest, 50, would hide the jump).
    assert jump([1.0, 50.0, 1.0], [11.0], 10.0) == 0
    assert jump([1.0, 3.0, 9.0], [29.0, 31.0], 10.0) == 1  # median 3
    # No verdict without a level to jump from.
    assert jump([], [1e9], 10.0) is None
    assert jump([0.0, 0.0, 1.0], [1e9], 10.0) is None


def cycle(force: float, rate: float, penetration: float):
    """A simulated cycle of the four-bar: its summary's figures and the depths it wore."""
    figures = {
        "max_contact_force_n": force,
        "outside_law_ranges": {"penetration_over_clearance": {"largest": penetration}},
    }
    wear = np.zeros((1, 2, 36))  # one revolute joint: journal and bearing, 36 sectors
    wear[0, 1, 7] = rate
    results = SimpleNamespace(summary={"clearance_joints": {"coupler_follower": figures}})
    return results, {"revolute": wear}


def update(number: int, force: float, rate: float = 1e-6, penetration: float = 0.42) -> dict:
    """A row of life.csv with the figures the watch reads."""
    return {
        "update": number,
        "cycles": 10 * number,
        "coupler_follower.max_contact_force_n": force,
        "coupler_follower.wear_rate_m_per_cycle": rate,
        PENETRATION: penetration,
    }


def test_the_watch_compares_a_cycle_with_the_last_three_updates():
    model = load_model(FOURBAR)
    # The settling (update 0) holds the start-up transient: no reference. Of the updates,
    # the last three: 80 kN.
    rows = [update(0, 1e3), update(1, 1e3), *(update(n, 80e3) for n in (2, 3, 4))]
    watch = Watch(model, 10.0, rows)
    assert watch.check(41, *cycle(9 * 80e3, 1e-6, 0.42)) is None
    found = watch.check(41, *cycle(11 * 80e3, 1e-6, 0.42))
    assert found.record() == {
        "cycle": 41, "joint": "coupler_follower", "key": "max_contact_force_n",
        "value": 880e3, "reference": 80e3, "what": "peak contact force", "ratio": 11.0,
    }  # fmt: skip
    assert "run-away in cycle 41: its peak contact force jumped to 880 kN, 11 times" in (
        found.message(40, 10.0, True)
    )
    # The wear per cycle of the fastest-wearing cell.
    found = watch.check(41, *cycle(80e3, 12e-6, 0.42))
    assert (found.key, found.value, found.reference) == ("wear_rate_m_per_cycle", 12e-6, 1e-6)
    # A further update moves the window: 1 kN drops out, and the median is 80 kN still.
    watch.record(update(5, 500e3))
    assert watch.check(51, *cycle(790e3, 1e-6, 0.42)) is None
    assert Watch(model, 0.0, rows).check(41, *cycle(1e12, 1.0, 1.0)) is None  # 0: no check


def test_the_watch_stops_a_joint_leaving_its_law_s_range():
    model = load_model(FOURBAR)
    # Beyond Hertz's range from the first update on (as the paper's four-bar is): no change.
    beyond = Watch(model, 10.0, [update(0, 80e3, penetration=0.05), update(1, 80e3)])
    assert beyond.check(11, *cycle(80e3, 1e-6, 0.9)) is None
    # Within it at the first update: a cycle beyond it is a run-away.
    within = Watch(model, 10.0, [update(1, 80e3, penetration=0.05), update(2, 80e3)])
    assert within.check(21, *cycle(80e3, 1e-6, HERTZ_RANGE)) is None
    found = within.check(21, *cycle(80e3, 1e-6, 0.12))
    assert (found.key, found.value, found.reference) == (PENETRATION.split(".")[1], 0.12, 0.1)


def test_a_joint_leaving_its_law_s_range_stops_the_run(tmp_path):
    settings = {"overrides": BRONZE_BUSH, "max_change": "2%", "band": (), "figures": False}
    res = life(SLIDER_CRANK, tmp_path / "run", cycles=30, **{**settings, "figures": True})
    assert res.status == "runaway", res.message
    entry = res.summary["runaway"]
    assert (entry["joint"], entry["key"], entry["reference"]) == (
        "rod_slider", "max_penetration_over_gap", HERTZ_RANGE,
    )  # fmt: skip
    assert entry["value"] > HERTZ_RANGE
    end = res.summary["cycles_reached"]
    assert res.table["cycles"].iloc[-1] == end < entry["cycle"]
    assert res.message.startswith(f"rod_slider: run-away in cycle {entry['cycle']}: its pene")
    assert f"The results end at the update before it, at {end} cycles" in res.message
    assert json.loads((tmp_path / "run" / "summary.json").read_text())["runaway"] == entry
    assert (tmp_path / "run" / "figures" / "life_wear.png").is_file()
    # The same run without the check: the same updates up to the stop, then one whose
    # measured cycles are beyond the range, which the first update was within.
    free = life(SLIDER_CRANK, tmp_path / "free", cycles=entry["cycle"] + 1, **settings,
                runaway_factor=0)  # fmt: skip
    assert free.status == "success", free.message
    kept = [c for c in res.table.columns if c != "wall_s"]
    rows = len(res.table)
    pd.testing.assert_frame_equal(free.table[kept].iloc[:rows], res.table[kept], check_exact=True)
    penetration = free.table["rod_slider.max_penetration_over_gap"].to_numpy()
    assert penetration[1] <= HERTZ_RANGE < penetration[rows]
    # A resumed run goes on only without the check (a larger factor leaves the range a stop).
    again = life(SLIDER_CRANK, tmp_path / "run", cycles=30, **settings, runaway_factor=20,
                 resume=True)  # fmt: skip
    assert again.status == "runaway" and again.summary["runaway"] == entry


def test_the_command_line_says_the_band_ran_away(tmp_path):
    result = CliRunner().invoke(app, [
        "life", str(SLIDER_CRANK), "--cycles", "30", "--out", str(tmp_path), "--max-change",
        "2%", "--band", "4%,8%", "--no-figures", *(f"--set={o}" for o in BRONZE_BUSH),
    ])  # fmt: skip
    assert result.exit_code == 1, result.output
    assert result.output.startswith("runaway: rod_slider: run-away in cycle ")
    summary = json.loads((tmp_path / "summary.json").read_text())
    band = summary["band"]
    assert band["all_ran_away"] and band["ran_away"] == ["2%", "4%", "8%"]
    cycles = [f"{r['max_change']} in cycle {r['runaway_cycle']:,}" for r in band["runs"]]
    assert f"no band: every run of it ran away ({', '.join(cycles)})" in result.output
    assert "band of the runs" not in result.output  # no band that looks tight


def test_a_blow_up_stops_the_run_before_it_is_extrapolated(tmp_path, monkeypatch):
    settings = {"cycles": 40, "overrides": FAST_WEAR, "max_change": "1%", "band": (),
                "figures": False}  # fmt: skip
    whole = life(FOURBAR, tmp_path / "whole", **settings)
    assert whole.status == "success", whole.message
    # From the second cycle of update 7 on: the settling's run, a run per cycle of updates
    # 1 to 6, then two more.
    row = whole.table.iloc[6]
    blow_up = int(row["cycles"]) + 2
    first = 1 + int(row["simulated_cycles"]) - 2 + 2  # the run that blows up
    calls = []

    def simulate_and_blow_up(*args, **kwargs):
        results = simulate(*args, **kwargs)
        calls.append(results.status)
        if len(calls) >= first:
            results.summary["clearance_joints"]["coupler_follower"]["max_contact_force_n"] *= 50
        return results

    monkeypatch.setattr(lifetime_update, "simulate", simulate_and_blow_up)
    res = life(FOURBAR, tmp_path / "run", **settings)
    assert res.status == "runaway"
    assert res.summary["runaway"]["cycle"] == blow_up
    assert res.summary["runaway"]["key"] == "max_contact_force_n"
    kept = [c for c in whole.table.columns if c != "wall_s"]
    pd.testing.assert_frame_equal(res.table[kept], whole.table[kept].iloc[:7], check_exact=True)
    level = np.median(whole.table["coupler_follower.max_contact_force_n"].iloc[4:7])
    assert res.summary["runaway"]["reference"] == level
    assert res.summary["runaway"]["ratio"] > 10.0
    assert len(calls) == first  # nothing simulated past the blow-up


def test_bad_run_away_and_process_settings_are_model_errors(tmp_path):
    for factor in (1.0, 0.5, -1, float("inf"), "10", True):
        with pytest.raises(ModelError, match=r"^runaway_factor: .* is not a finite number above"):
            life(FOURBAR, tmp_path, cycles=3, runaway_factor=factor)
    for workers in (0, 1.5):
        with pytest.raises(ModelError, match=r"^workers: got .*; expected a whole number"):
            life(FOURBAR, tmp_path, cycles=3, workers=workers)
    with pytest.raises(ModelError, match=r"^workers: only for local processes"):
        life(FOURBAR, tmp_path, cycles=3, workers=2, scheduler="tcp://127.0.0.1:8786")
    assert not (tmp_path / "life.csv").exists()  # refused before any work
