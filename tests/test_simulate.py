"""The run loop: chunking is invisible, outputs land on the requested times."""

import importlib

import numpy as np
import pytest
from runs import EXAMPLES

import jointwear as jw

simulate_module = importlib.import_module("jointwear.simulate")  # the module, not the function


@pytest.mark.parametrize("integrator", ["dopri5", "abm"])
def test_result_does_not_depend_on_chunking(monkeypatch, integrator):
    model = jw.load_model(
        EXAMPLES / "flores2009_fourbar.toml",
        [f"solver.integrator={integrator}", "solver.t_end=0.03"],
    )
    one_go = jw.simulate(model)
    monkeypatch.setattr(simulate_module, "CHUNK_WALL_S", 1e-9)  # a chunk per step or so
    monkeypatch.setattr(simulate_module, "MIN_CHUNK_STEPS", 1)
    many = jw.simulate(model)
    assert one_go.summary["stats"]["accepted_steps"] == many.summary["stats"]["accepted_steps"]
    # Bit-identical: the chunk ends never shorten a step.
    np.testing.assert_array_equal(one_go.timeseries.to_numpy(), many.timeseries.to_numpy())


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
