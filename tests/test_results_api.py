"""Results in a notebook: repr, to_dataframe, units, plot, export to .nc and .mat."""

import json
import re
import sys

import h5py
import numpy as np
import pandas as pd
import pytest
import xarray as xr
from matplotlib.figure import Figure
from runs import EXAMPLES, simulate_ok
from scipy.io import loadmat
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.engine.finite import json_safe
from jointwear.results.column_units import column_unit
from jointwear.results.export import matlab_names
from jointwear.results.run_results import TABLES

SHORT = ["solver.t_end=0.02"]
INSTALL = "pip install 'jointwear[export]'"


@pytest.fixture(scope="module")
def fourbar() -> jw.Results:
    return simulate_ok(EXAMPLES / "flores2009_fourbar.toml", SHORT)


@pytest.fixture(scope="module")
def piston_folder(tmp_path_factory):
    """The piston slider example's results folder (read back, its tables as CSV gives them)."""
    results = simulate_ok(EXAMPLES / "slider_crank_piston_clearance.toml", SHORT)
    return results.save(tmp_path_factory.mktemp("piston") / "run")


@pytest.fixture(scope="module")
def piston(piston_folder) -> jw.Results:
    return jw.load_results(piston_folder)


@pytest.fixture(params=["fourbar", "piston"])
def either(request) -> jw.Results:
    return request.getfixturevalue(request.param)


def test_repr_is_a_few_lines_naming_the_run_its_joints_and_tables(fourbar):
    text = repr(fourbar)
    assert len(text) < 1000 and len(text.splitlines()) <= 8, text
    assert "flores2009_fourbar" in text
    assert f"{fourbar.status} ({fourbar.message})" in text
    assert "time reached 0.02 s" in text
    rows, columns = fourbar.timeseries.shape
    assert f"{rows} rows x {columns} columns" in text
    entry = fourbar.summary["clearance_joints"]["coupler_follower"]
    line = next(line for line in text.splitlines() if "coupler_follower" in line)
    assert f"{entry['max_contact_force_n']:.4g} N" in line
    assert f"{entry['impacts']} impacts" in line
    assert all(table in text for table in TABLES)
    assert fourbar._repr_html_().startswith("<pre>")


def test_repr_of_a_model_without_clearance_joints_lists_its_two_tables():
    results = simulate_ok(EXAMPLES / "pendulum.toml", ["solver.t_end=0.01"])
    text = repr(results)
    assert "clearance" not in text and "wear" not in text
    assert "tables: timeseries, events (0 rows)" in text


@pytest.mark.parametrize("table", TABLES)
def test_to_dataframe_gives_a_copy_of_each_table(either, table):
    frame = either.to_dataframe(table)
    original = getattr(either, table)
    pd.testing.assert_frame_equal(frame, original)
    assert not original.empty or table in ("events", "wear_snapshots")
    frame["added"] = 0.0
    assert "added" not in original
    for column in original.select_dtypes("number"):
        assert not np.shares_memory(frame[column].to_numpy(), original[column].to_numpy())


def test_to_dataframe_of_an_unknown_table_names_the_tables(fourbar):
    with pytest.raises(ValueError, match="no table 'wears'; the tables are timeseries, events"):
        fourbar.to_dataframe("wears")
    with pytest.raises(ValueError, match="cycles"):
        fourbar.units("summary")


def test_every_column_of_both_examples_has_a_unit(fourbar, piston):
    for results in (fourbar, piston):
        for table in TABLES:
            units = results.units(table)
            assert list(units) == list(getattr(results, table).columns)
            unknown = [column for column, unit in units.items() if unit == "?"]
            assert not unknown, f"{results.model.name} {table}: no unit for {unknown}"
    units = fourbar.units()
    expected = {
        "time": "s",
        "x_crank": "m",
        "phi_follower": "rad",
        "vy_coupler": "m/s",
        "omega_follower": "rad/s",
        "ax_follower": "m/s^2",
        "alpha_follower": "rad/s^2",
        "torque_motor": "N m",
        "ground_crank_fx": "N",
        "coupler_follower_ex": "m",
        "coupler_follower_delta": "m",
        "coupler_follower_fn": "N",
        "energy_kinetic": "J",
        "constraint_violation": "m",
    }
    assert {column: units[column] for column in expected} == expected
    sliders = piston.units()
    assert sliders["piston_tilt"] == "rad" and sliders["piston_lateral"] == "m"
    assert sliders["piston_fn_edge_front_top"] == "N"
    assert piston.units("wear")["position_m"] == "m"
    assert piston.units("impacts")["penetration_velocity_m_s"] == "m/s"
    assert piston.units("impacts")["contact"] == ""  # text
    assert fourbar.units("cycles")["worn_volume_m3"] == "m^3"
    assert fourbar.units("wear")["angle_deg"] == "deg"


def test_units_tell_a_joint_from_a_body_by_the_models_names(fourbar):
    # "coupler_follower" is a joint between the bodies "coupler" and "follower".
    assert column_unit("coupler_follower_fy", fourbar.model) == "N"
    assert column_unit("y_coupler", fourbar.model) == "m"
    assert column_unit("lubricated_joint_film_power") == "?"  # without the model
    assert column_unit("not_a_column") == "?"


def test_plot_draws_the_asked_columns_against_time_with_units(fourbar):
    fig = fourbar.plot("omega_follower", "omega_coupler")
    assert isinstance(fig, Figure)
    (ax,) = fig.axes
    lines = ax.get_lines()
    assert [line.get_label() for line in lines] == [
        "omega_follower [rad/s]",
        "omega_coupler [rad/s]",
    ]
    for line, column in zip(lines, ("omega_follower", "omega_coupler"), strict=True):
        np.testing.assert_array_equal(line.get_xdata(), fourbar.timeseries["time"])
        np.testing.assert_array_equal(line.get_ydata(), fourbar.timeseries[column])
    assert ax.get_xlabel() == "time [s]"
    assert ax.get_ylabel() == "[rad/s]"


def test_plot_on_given_axes_against_another_column(fourbar):
    fig = Figure()
    ax = fig.subplots()
    assert fourbar.plot("coupler_follower_fn", x="phi_crank", ax=ax) is fig
    (line,) = ax.get_lines()
    np.testing.assert_array_equal(line.get_xdata(), fourbar.timeseries["phi_crank"])
    np.testing.assert_array_equal(line.get_ydata(), fourbar.timeseries["coupler_follower_fn"])
    assert ax.get_xlabel() == "phi_crank [rad]"
    assert ax.get_ylabel() == "coupler_follower_fn [N]"


def test_plot_of_an_unknown_column_suggests_close_names(fourbar):
    with pytest.raises(ValueError, match=r"column 'omega_folower'.*'omega_follower'"):
        fourbar.plot("omega_folower")
    with pytest.raises(ValueError, match="'phi_crank'"):
        fourbar.plot("omega_crank", x="phi_crnk")
    with pytest.raises(ValueError, match="at least one"):
        fourbar.plot()


def _same_column(read: np.ndarray, frame: pd.DataFrame, column: str, unit: str) -> None:
    if unit == "":  # text
        assert [str(v) for v in read] == [str(v) for v in frame[column]], column
    else:
        expected = pd.to_numeric(frame[column]).to_numpy(dtype=float)
        np.testing.assert_array_equal(np.asarray(read, dtype=float), expected, err_msg=column)


def test_netcdf_opens_with_xarray_and_h5py_with_the_same_numbers_and_units(either, tmp_path):
    path = either.export(tmp_path / "run.nc")
    with xr.open_dataset(path, engine="h5netcdf") as ds:
        assert list(ds.sizes) == ["time"]
        assert json.loads(ds.attrs["summary"]) == json_safe(either.summary)
        assert jw.parse_model(json.loads(ds.attrs["model"])) == either.model
        for column, unit in either.units().items():
            assert ds[column].attrs["units"] == unit, column
            _same_column(ds[column].values, either.timeseries, column, unit)
    for table in TABLES[1:]:
        frame = either.to_dataframe(table)
        with xr.open_dataset(path, group=table, engine="h5netcdf") as ds:
            assert ds.sizes.get("row", 0) == len(frame), table
            for column, unit in either.units(table).items():
                assert ds[column].attrs["units"] == unit, (table, column)
                _same_column(ds[column].values, frame, column, unit)
    with h5py.File(path, "r") as file:  # plain HDF5, as MATLAB's h5read sees it
        np.testing.assert_array_equal(file["time"][:], either.timeseries["time"])
        assert set(TABLES[1:]) <= set(file)
        assert file["phi_crank"].attrs["units"] in ("rad", b"rad")


def test_mat_file_loads_with_scipy_with_the_same_numbers_and_units(either, tmp_path):
    path = either.export(tmp_path / "run.mat")
    content = loadmat(path, simplify_cells=True)
    assert json.loads(content["summary"]) == json_safe(either.summary)
    for table in TABLES:
        frame = either.to_dataframe(table)
        names = matlab_names(list(frame.columns))
        struct, units = content[table], content["units"][table]
        assert list(struct) == list(names.values())
        for column, unit in either.units(table).items():
            read = units[names[column]]
            assert (read if np.size(read) else "") == unit, (table, column)  # '' reads as []
            values = np.atleast_1d(struct[names[column]])
            _same_column(values, frame, column, unit)


def test_matlab_names_are_valid_and_distinct():
    names = matlab_names(["time", "1st", "a-b", "a_b", "x" * 70, "x" * 70 + "y"])
    assert list(names.values())[:4] == ["time", "x1st", "a_b", "a_b_2"]
    assert all(re.fullmatch(r"[A-Za-z]\w{0,62}", name) for name in names.values())
    assert len(set(names.values())) == len(names)


def test_export_without_the_extra_says_how_to_install_it(fourbar, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "xarray", None)  # import fails as if absent
    with pytest.raises(ImportError, match=re.escape(INSTALL)):
        fourbar.export(tmp_path / "run.nc")
    monkeypatch.setitem(sys.modules, "scipy.io", None)
    with pytest.raises(ImportError, match=re.escape(INSTALL)):
        fourbar.export(tmp_path / "run.mat")
    assert not list(tmp_path.iterdir())


def test_export_to_another_suffix_names_the_formats(fourbar, tmp_path):
    with pytest.raises(ValueError, match=r"\.nc or \.mat"):
        fourbar.export(tmp_path / "run.csv")


def test_export_command_writes_the_file(piston_folder, tmp_path):
    runner = CliRunner()
    result = runner.invoke(app, ["export", str(piston_folder), str(tmp_path / "run.mat")])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "run.mat").is_file()
    result = runner.invoke(app, ["export", str(tmp_path), str(tmp_path / "run.nc")])
    assert result.exit_code == 2
    assert "not a results folder" in result.stderr
    result = runner.invoke(app, ["export", str(piston_folder), str(tmp_path / "run.txt")])
    assert result.exit_code == 2
    assert ".nc or .mat" in result.stderr


def test_plot_of_several_columns_puts_the_legend_beside_the_axes(fourbar):
    fig = fourbar.plot("omega_follower", "omega_coupler")
    fig.draw_without_rendering()  # lays the figure out
    (ax,) = fig.axes
    box = ax.get_legend().get_window_extent()
    assert box.x0 >= ax.get_window_extent().x1  # it hides no part of the lines
    assert fig.bbox.contains(box.x1, box.y0)
