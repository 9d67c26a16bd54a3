"""Steady state after the start-up, and the per-cycle table (``results.cycles``).

The slider-crank with a clearance at the wrist pin starts with its journal centred: the first
crank turn's impact is nearly twice the later peaks, as in a new user's engine.
"""

import numpy as np
import pandas as pd
import pytest
from runs import EXAMPLES, simulate_ok

import jointwear as jw
from jointwear.results.cycles import WINDOW_KEYS

ENGINE = EXAMPLES / "slider_crank_clearance.toml"  # crank at 5000 rpm: a 12 ms cycle
SHORT = ["solver.t_end=0.06"]  # five turns


@pytest.fixture(scope="module")
def engine():
    return simulate_ok(ENGINE, SHORT)


def test_cycles_add_up_to_the_whole_run(engine):
    whole = engine.summary["clearance_joints"]["rod_slider"]["whole_run"]
    cycles = engine.cycles
    assert list(cycles["cycle"]) == [1, 2, 3, 4, 5]
    assert cycles["t_start_s"].iloc[0] == 0.0
    assert cycles["t_end_s"].iloc[-1] == pytest.approx(0.06, rel=1e-12)
    # Each window ends at the first step end at or past its cycle's end (steps <= 1 ms).
    ends = cycles["t_end_s"].to_numpy()[:-1]
    assert np.all(
        (ends >= 0.012 * np.arange(1, 5) * (1 - 1e-12)) & (ends < 0.012 * np.arange(1, 5) + 1e-3)
    )
    np.testing.assert_array_equal(cycles["t_start_s"].to_numpy()[1:], ends)
    # The elements' whole-run totals, gathered by the compiled loop without windows:
    assert cycles["impacts"].sum() == whole["impacts"]
    assert cycles["max_contact_force_n"].max() == whole["max_contact_force_n"]
    assert cycles["max_penetration_m"].max() == whole["max_penetration_m"]
    for column, key in [
        ("worn_volume_m3", "worn_volume_m3"),
        ("sliding_distance_m", "sliding_distance_m"),
    ]:
        assert cycles[column].sum() == pytest.approx(whole[key], rel=1e-12)
    energy = whole["energy_dissipated_damping_j"] + whole["energy_dissipated_friction_j"]
    assert cycles["energy_dissipated_j"].sum() == pytest.approx(energy, rel=1e-12)
    spans = cycles["t_end_s"] - cycles["t_start_s"]
    contact = (cycles["contact_time_fraction"] * spans).sum() / 0.06
    assert contact == pytest.approx(whole["contact_time_fraction"], rel=1e-9)


def test_the_steady_state_leaves_out_the_start_up(engine):
    span = engine.summary["steady_state"]
    assert span["settle_s"] == pytest.approx(0.012, rel=1e-12)
    assert span["windows"] == 4
    joint = engine.summary["clearance_joints"]["rod_slider"]
    cycles = engine.cycles
    assert list(cycles["steady"]) == [False, True, True, True, True]
    steady = cycles[cycles["steady"]]
    assert joint["max_contact_force_n"] == steady["max_contact_force_n"].max()
    assert joint["impacts"] == steady["impacts"].sum()
    assert joint["worn_volume_m3"] == pytest.approx(steady["worn_volume_m3"].sum(), rel=1e-12)
    # The start-up impact of the centred journal dominates the whole run's peak.
    first = cycles["max_contact_force_n"].iloc[0]
    assert joint["whole_run"]["max_contact_force_n"] == first
    assert joint["max_contact_force_n"] < 0.75 * first
    assert list(joint)[:2] == ["type", "max_contact_force_n"]  # the summary leads with it
    assert set(joint["whole_run"]) <= set(WINDOW_KEYS)


def test_windows_do_not_change_the_solution(engine):
    """Cutting mid-cycle (a settling time) hands back to Python at other times: same steps."""
    cut = simulate_ok(ENGINE, [*SHORT, "solver.settle_time=0.0171"])
    pd.testing.assert_frame_equal(cut.timeseries, engine.timeseries)
    assert cut.summary["stats"]["accepted_steps"] == engine.summary["stats"]["accepted_steps"]
    mine = engine.summary["clearance_joints"]["rod_slider"]["whole_run"]
    assert cut.summary["clearance_joints"]["rod_slider"]["whole_run"] == mine
    # The cut splits the second turn: a window of its own, flagged as the steady state's start.
    assert cut.summary["steady_state"]["from_s"] == pytest.approx(0.0171)
    assert len(cut.cycles) == 6
    assert list(cut.cycles["cycle"]) == [1, 2, 2, 3, 4, 5]
    assert list(cut.cycles["steady"]) == [False, False, True, True, True, True]


def test_settling_in_cycles_and_the_defaults():
    three = simulate_ok(ENGINE, [*SHORT, "solver.settle_cycles=3"])
    assert three.summary["steady_state"]["settle_s"] == pytest.approx(0.036, rel=1e-12)
    assert list(three.cycles["steady"]) == [False, False, False, True, True]
    # Shorter than two cycles: nothing is left out by default.
    short = simulate_ok(ENGINE, ["solver.t_end=0.02"])
    assert short.summary["steady_state"]["settle_s"] == 0.0
    joint = short.summary["clearance_joints"]["rod_slider"]
    assert {k: joint[k] for k in joint["whole_run"]} == joint["whole_run"]
    # Going on from a run's end state: settled already.
    model = jw.load_model(ENGINE, SHORT)
    more = jw.simulate(model, initial=short.final)
    assert more.summary["steady_state"]["settle_s"] == 0.0
    assert more.cycles["t_start_s"].iloc[0] == short.final.time


@pytest.mark.parametrize(
    ("overrides", "words"),
    [
        (["solver.settle_time=0.1", "solver.settle_cycles=1"], "both given"),
        (["solver.settle_cycles=5"], "need fewer than 5"),
        (["solver.settle_time=0.06"], "need settle_time < t_end"),
        (["solver.settle_cycles=-1"], "settle_cycles"),
    ],
)
def test_settling_that_does_not_fit_is_refused(overrides, words):
    with pytest.raises(jw.ModelError, match=words):
        jw.load_model(ENGINE, [*SHORT, *overrides])


def test_settle_cycles_needs_something_periodic():
    with pytest.raises(jw.ModelError, match="no periodic driver or load"):
        jw.load_model(EXAMPLES / "slider_crank_piston_clearance.toml", ["solver.settle_cycles=1"])
