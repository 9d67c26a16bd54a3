"""examples/notebook.py, the user guide's Python API in notebook cells, runs as written."""

import os
import subprocess
import sys
from pathlib import Path

import xarray as xr
from scipy.io import loadmat

ROOT = Path(__file__).parents[1]


def test_the_notebook_example_runs(tmp_path):
    env = {**os.environ, "JOINTWEAR_NOTEBOOK_OUT": str(tmp_path), "MPLBACKEND": "Agg"}
    done = subprocess.run([sys.executable, "examples/notebook.py"], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=600)  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "has units of length; expected a mass" in done.stdout
    assert "steady-state peak force" in done.stdout
    assert "Flores" in done.stdout  # the citations
    for name in ("pressure.png", "fourbar/summary.json", "fourbar/cycles.csv"):
        assert (tmp_path / name).stat().st_size > 0, name
    with xr.open_dataset(tmp_path / "fourbar.nc") as data:
        assert data["coupler_follower_p_max"].attrs["units"] == "Pa"
    assert "timeseries" in loadmat(tmp_path / "fourbar.mat")
