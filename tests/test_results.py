"""Results folders: save / load_results round trip, column names, partial runs."""

import json
import math
import signal
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from runs import EXAMPLES, FOURBAR_COLUMNS

import jointwear as jw
from jointwear.engine.status import status_message
from jointwear.io import RECORD
from jointwear.kernels.codes import Status

FILES = ("summary.json", "model.json", "timeseries.csv", "timeseries.parquet", "events.csv")
CLEARANCE_FILES = ("wear.csv", "wear_snapshots.csv", "impacts.csv", "cycles.csv")


def simulate(name: str, overrides: list[str], **kwargs) -> jw.Results:
    return jw.simulate(jw.load_model(EXAMPLES / f"{name}.toml", overrides), **kwargs)


@pytest.fixture(scope="module")
def pendulum() -> jw.Results:
    """0.6 s of the pendulum: past the first "bottom" crossing (about 0.483 s)."""
    results = simulate("pendulum", ["solver.t_end=0.6"])
    assert results.status == "success", results.message
    return results


@pytest.fixture(scope="module")
def fourbar() -> jw.Results:
    results = simulate("flores2009_fourbar", ["solver.t_end=0.01"])
    assert results.status == "success", results.message
    return results


def assert_same_results(loaded: jw.Results, saved: jw.Results) -> None:
    pd.testing.assert_frame_equal(loaded.timeseries, saved.timeseries, check_exact=True)
    # events.csv keeps 12 significant digits of the event times.
    pd.testing.assert_frame_equal(
        loaded.events, saved.events, check_exact=False, rtol=1e-11, atol=0.0
    )
    for table in ("wear", "wear_snapshots", "impacts"):  # 12 significant digits in CSV
        pd.testing.assert_frame_equal(
            getattr(loaded, table),
            getattr(saved, table),
            check_exact=False,
            rtol=1e-11,
            check_dtype=not getattr(saved, table).empty,  # an empty CSV reads back as text
        )
    assert loaded.summary == saved.summary
    assert loaded.model == saved.model
    assert loaded.status == saved.status
    assert loaded.message == saved.message


@pytest.mark.parametrize("example", ["pendulum", "fourbar"])
def test_save_then_load_gives_the_same_results(request, tmp_path, example):
    results = request.getfixturevalue(example)
    folder = results.save(tmp_path / "out")
    assert folder == tmp_path / "out"
    files = FILES + (CLEARANCE_FILES if example == "fourbar" else ())
    assert sorted(p.name for p in folder.iterdir()) == sorted((*files, RECORD))
    recorded = json.loads((folder / RECORD).read_text())  # each file, with size and time
    assert sorted(recorded) == sorted(files)
    assert all(recorded[name][0] == (folder / name).stat().st_size for name in files)
    assert_same_results(jw.load_results(folder), results)


def test_events_round_trip(pendulum, tmp_path):
    events = pendulum.events
    assert list(events.columns) == ["time", "event", "direction"]
    assert len(events) == 1
    assert events["event"].tolist() == ["bottom"]
    assert events["direction"].tolist() == ["falling"]
    assert events["time"].iloc[0] == pytest.approx(0.4833, abs=1e-3)  # a quarter period
    loaded = jw.load_results(pendulum.save(tmp_path)).events
    assert loaded["event"].tolist() == ["bottom"]
    assert loaded["direction"].tolist() == ["falling"]
    assert loaded["time"].iloc[0] == pytest.approx(events["time"].iloc[0], rel=1e-11)


def test_no_events_round_trip(fourbar, tmp_path):
    assert fourbar.events.empty
    loaded = jw.load_results(fourbar.save(tmp_path))
    assert loaded.events.empty
    assert list(loaded.events.columns) == ["time", "event", "direction"]


def test_summary_and_model_files_are_plain_json(pendulum, tmp_path):
    folder = pendulum.save(tmp_path)
    assert json.loads((folder / "summary.json").read_text()) == pendulum.summary
    model = json.loads((folder / "model.json").read_text())
    assert model["name"] == "pendulum"
    assert model["solver"]["t_end"] == 0.6
    assert model["bodies"][0]["mass"] == 1.0  # SI numbers, units resolved
    assert jw.load_results(folder).model.solver.t_end == 0.6


def test_csv_and_parquet_hold_the_same_table(fourbar, tmp_path):
    folder = fourbar.save(tmp_path)
    csv = pd.read_csv(folder / "timeseries.csv")
    parquet = pd.read_parquet(folder / "timeseries.parquet")
    pd.testing.assert_frame_equal(parquet, fourbar.timeseries, check_exact=True)
    assert list(csv.columns) == list(parquet.columns)
    assert csv.shape == parquet.shape
    np.testing.assert_allclose(csv.to_numpy(), parquet.to_numpy(), rtol=1e-11, atol=0.0)


def test_save_replaces_an_existing_folder(pendulum, fourbar, tmp_path):
    pendulum.save(tmp_path)
    fourbar.save(tmp_path)
    assert_same_results(jw.load_results(tmp_path), fourbar)


def test_column_names_follow_the_model(fourbar):
    expected = FOURBAR_COLUMNS
    assert list(fourbar.timeseries.columns) == expected
    ts = fourbar.timeseries
    assert ts["time"].iloc[-1] == 0.01
    assert len(ts) == 101  # every 0.1 ms
    assert np.isfinite(ts.to_numpy()).all()
    np.testing.assert_allclose(ts["omega_crank"], 50.0 * math.pi, rtol=1e-6)
    assert ts["torque_motor"].abs().max() > 0.0


def test_pendulum_column_names(pendulum):
    assert list(pendulum.timeseries.columns) == [
        "time",
        *(f"{c}_pendulum" for c in ("x", "y", "phi", "vx", "vy", "omega", "ax", "ay", "alpha")),
        "pin_fx",
        "pin_fy",
        "energy_kinetic",
        "energy_potential",
        "constraint_violation",
    ]


def assert_partial(results: jw.Results, status: str, tmp_path: Path) -> None:
    """A partial run: its status and message, rows up to the time reached, a loadable folder."""
    t_end = results.model.solver.t_end
    interval = results.model.solver.output_interval
    stats = results.summary["stats"]
    assert results.status == status
    assert results.message == results.summary["message"]
    t_reached = stats["t_reached"]
    assert 0.0 < t_reached < t_end
    times = results.timeseries["time"].to_numpy()
    assert times.size == math.floor(t_reached / interval * (1 + 1e-12)) + 1
    assert times[-1] <= t_reached < times[-1] + interval
    np.testing.assert_allclose(times, np.arange(times.size) * interval, rtol=1e-12, atol=1e-15)
    assert np.isfinite(results.timeseries.to_numpy()).all()
    folder = results.save(tmp_path / status)
    loaded = jw.load_results(folder)
    assert_same_results(loaded, results)
    assert loaded.status == status


def test_max_steps_run_is_partial_and_says_what_to_try(tmp_path):
    results = simulate("pendulum", ["solver.t_end=1.0", "solver.max_steps=50"])
    assert_partial(results, "max_steps", tmp_path)
    assert results.message == "solver.max_steps was reached; raise it or loosen the tolerances"
    stats = results.summary["stats"]
    assert stats["accepted_steps"] + stats["rejected_steps"] == 50
    assert results.summary["settings"]["max_steps"] == 50


def test_signal_during_a_run_gives_interrupted_partial_results(tmp_path):
    """SIGINT (Ctrl-C) while simulating sets the stop flag; the run ends after the chunk."""
    before = signal.getsignal(signal.SIGINT)
    calls = []

    def ctrl_c(t: float, t_end: float) -> None:
        calls.append(t)
        if len(calls) == 1:
            signal.raise_signal(signal.SIGINT)  # as if Ctrl-C came during the chunk

    results = simulate("flores2009_fourbar", ["solver.t_end=1.0"], progress=ctrl_c)
    assert len(calls) == 1  # stopped after the chunk in which the signal arrived
    assert_partial(results, "interrupted", tmp_path)
    assert results.message == status_message(Status.INTERRUPTED)
    assert results.message.startswith("interrupted by the user")
    assert results.summary["stats"]["t_reached"] == pytest.approx(calls[0])
    assert signal.getsignal(signal.SIGINT) is before  # the handler is put back


def test_summary_says_how_the_run_was_made(pendulum):
    import importlib.metadata
    import sys
    from datetime import UTC, datetime

    origin = pendulum.summary["provenance"]
    assert origin["jointwear"] == jw.__version__
    assert origin["python"] == ".".join(map(str, sys.version_info[:3]))
    assert origin["dependencies"]["numba"] == importlib.metadata.version("numba")
    assert origin["dependencies"]["numpy"] == np.__version__
    started = datetime.fromisoformat(origin["started_utc"])
    assert 0 <= (datetime.now(UTC) - started).total_seconds() < 3600
    assert origin["command"]  # the process's own command line, quoted for a shell
