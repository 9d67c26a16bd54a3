"""The run loop: chunking is invisible, outputs land on the requested times."""

import importlib

import numpy as np
import pandas as pd
import pytest
from runs import EXAMPLES

import jointwear as jw

drive_module = importlib.import_module("jointwear.engine.drive")  # the chunking's settings


@pytest.mark.parametrize("integrator", ["dopri5", "abm"])
def test_result_does_not_depend_on_chunking(monkeypatch, integrator):
    model = jw.load_model(
        EXAMPLES / "flores2009_fourbar.toml",
        [
            f"solver.integrator={integrator}",
            "solver.t_end=0.03",
            "solver.wear_snapshot_interval=0.01",
        ],
    )  # the example's clearance joint: contact onsets cut steps, wear accumulates per step
    one_go = jw.simulate(model)
    monkeypatch.setattr(drive_module, "CHUNK_WALL_S", 1e-9)  # a chunk per step or so
    monkeypatch.setattr(drive_module, "MIN_CHUNK_STEPS", 1)
    many = jw.simulate(model)
    assert one_go.summary["stats"]["accepted_steps"] == many.summary["stats"]["accepted_steps"]
    # Bit-identical: the chunk ends never shorten a step.
    np.testing.assert_array_equal(one_go.timeseries.to_numpy(), many.timeseries.to_numpy())
    assert len(one_go.impacts) > 0 and len(one_go.wear_snapshots) > 0
    for table in ("wear", "wear_snapshots", "impacts"):
        pd.testing.assert_frame_equal(getattr(one_go, table), getattr(many, table))
    joints = "clearance_joints"
    assert one_go.summary[joints] == many.summary[joints]


def test_rows_at_requested_times_and_end_time():
    model = jw.load_model(
        EXAMPLES / "pendulum.toml", ["solver.t_end=0.0105", "solver.output_interval=0.001"]
    )
    times = jw.simulate(model).timeseries["time"].to_numpy()
    # Every multiple of the interval up to t_end, then t_end itself (off the grid).
    expected = np.append(np.arange(11) * 0.001, 0.0105)
    np.testing.assert_array_equal(times, expected)


@pytest.mark.parametrize(("t_end", "interval"), [(0.3, 0.1), (0.03, 1e-4), (0.007, 1e-3)])
def test_last_row_is_at_the_end_time_on_the_grid(t_end, interval):
    # 3 * 0.1 > 0.3 in floating point: the last grid row must still be written, at t_end.
    model = jw.load_model(
        EXAMPLES / "pendulum.toml", [f"solver.t_end={t_end}", f"solver.output_interval={interval}"]
    )
    times = jw.simulate(model).timeseries["time"].to_numpy()
    assert times[-1] == t_end
    assert len(times) == round(t_end / interval) + 1


def test_absurd_output_size_is_refused_up_front():
    with pytest.raises(jw.ModelError) as error:
        jw.load_model(
            EXAMPLES / "pendulum.toml", ["solver.t_end=1000", "solver.output_interval=1e-9"]
        )
    assert "raise output_interval" in error.value.problems[0]


@pytest.mark.parametrize("integrator", ["dopri5", "abm"])
def test_contact_onsets_are_located_to_the_contact_tolerance(integrator):
    model = jw.load_model(
        EXAMPLES / "flores2009_fourbar.toml",
        [f"solver.integrator={integrator}", "solver.t_end=0.01"],
    )
    impacts = jw.simulate(model).impacts
    tolerance = model.joint("coupler_follower").clearance.contact_tolerance  # 1e-10 m
    # The journal starts centred, 0.2 mm from the wall, and hits it within the first turn.
    assert len(impacts) >= 1
    # The loop cuts the step where the penetration has just passed the tolerance: located
    # on the dense output until it exceeds the tolerance by at most the tolerance itself.
    assert (impacts["penetration_m"] > tolerance).all()
    assert (impacts["penetration_m"] <= 2 * tolerance).all()
    assert (impacts["penetration_velocity_m_s"] > 0).all()  # approaching at every onset
