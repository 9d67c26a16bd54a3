"""Applied loads in the time series (issue 28): each load of ``[[forces]]`` as applied."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from runs import EXAMPLES
from scipy.io import loadmat
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.mechanism.system import column_names
from jointwear.model import parse_model
from jointwear.results.column_units import column_unit

G = 9.81  # [m/s^2]
# The gas force on the slider-crank's piston: harmonic at the crank's 5000 rpm.
GAS = {"offset": -50.0, "amplitude": 40.0, "angular_frequency": 5000 * math.pi / 30, "phase": 0.3}
HARMONIC_TOML = (
    f'{{ type = "harmonic", offset = "{GAS["offset"]} N", amplitude = "{GAS["amplitude"]} N", '
    f'angular_frequency = "5000 rpm", phase = {GAS["phase"]} }}'
)
GAS_TOML = f"""
[[forces]]
name = "gas"
type = "point_force"
body = "slider"
point = "pin"
force = [{HARMONIC_TOML}, 0.0]

[[forces]]
type = "torque"
body = "rod"
torque = "0.2 N*m"
"""


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[0] * b[1] - a[1] * b[0]


def _arm(phi: np.ndarray, point: tuple[float, float]) -> np.ndarray:
    """Body point ``point`` [m] in global axes, at body angles phi [rad]."""
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([c * point[0] - s * point[1], s * point[0] + c * point[1]])


@pytest.fixture(scope="module")
def piston(tmp_path_factory) -> Path:
    """`jointwear run` of the slider-crank with a gas force and a torque, half a crank turn."""
    folder = tmp_path_factory.mktemp("piston")
    model = folder / "slider_crank.toml"
    model.write_text((EXAMPLES / "slider_crank.toml").read_text() + GAS_TOML)
    args = ["run", str(model), "--out", str(folder / "out"), "--no-figures", "--t-end", "6 ms"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    return folder / "out"


def test_a_harmonic_force_and_a_torque_are_columns_of_the_run(piston):
    results = jw.load_results(piston)
    df = results.timeseries
    t = df["time"].to_numpy()
    assert len(t) == 121
    gas = GAS["offset"] + GAS["amplitude"] * np.sin(GAS["angular_frequency"] * t + GAS["phase"])
    np.testing.assert_allclose(df["load_gas_fx"], gas, rtol=1e-14, atol=1e-12)
    np.testing.assert_array_equal(df["load_gas_fy"], 0.0)
    np.testing.assert_array_equal(df["load_rod_torque"], 0.2)  # unnamed: after its body
    columns = list(df.columns)
    start = columns.index("torque_motor") + 1  # after the drivers, before the joints
    assert columns[start : start + 4] == [
        "load_gas_fx", "load_gas_fy", "load_rod_torque", "ground_crank_fx"
    ]  # fmt: skip
    units = results.units()
    assert [units[c] for c in columns[start : start + 3]] == ["N", "N", "N m"]


def test_the_csv_the_parquet_and_the_exports_hold_the_same_load_columns(piston, tmp_path):
    results = jw.load_results(piston)
    loads = ["load_gas_fx", "load_gas_fy", "load_rod_torque"]
    expected = results.timeseries[loads]
    csv = pd.read_csv(piston / "timeseries.csv")[loads]  # an all-zero column reads as int
    pd.testing.assert_frame_equal(csv, expected, check_dtype=False)
    netcdf = xr.open_dataset(results.export(tmp_path / "run.nc"), engine="h5netcdf")
    mat = loadmat(results.export(tmp_path / "run.mat"), simplify_cells=True)
    for column in loads:
        np.testing.assert_array_equal(netcdf[column].to_numpy(), expected[column])
        np.testing.assert_array_equal(mat["timeseries"][column], expected[column])
        unit = "N m" if column.endswith("torque") else "N"
        assert netcdf[column].attrs["units"] == mat["units"]["timeseries"][column] == unit
    netcdf.close()


def _free_bodies(forces: list[dict], gravity: float, t_end: float) -> pd.DataFrame:
    """Two free bodies ``a`` and ``b``, each with points ``c`` (centre) and ``end``, spinning."""
    bodies = [
        {"name": "a", "mass": 2.0, "inertia": 0.05, "position": [0.0, 0.0], "angle": 0.2,
         "velocity": [0.1, -0.2], "angular_velocity": 1.0,
         "points": {"c": [0.0, 0.0], "end": [0.1, 0.05]}},
        {"name": "b", "mass": 0.8, "inertia": 0.004, "position": [0.4, 0.1], "angle": -0.3,
         "velocity": [-0.3, 0.2], "angular_velocity": -2.0,
         "points": {"c": [0.0, 0.0], "end": [-0.04, 0.03]}},
    ]  # fmt: skip
    model = parse_model({
        "bodies": bodies,
        "forces": [{"type": "gravity", "acceleration": [0.0, -gravity]}, *forces],
        "solver": {"t_end": t_end, "output_interval": 1e-4, "rtol": 1e-10, "atol": 1e-12},
    })  # fmt: skip
    results = jw.simulate(model)
    assert results.status == "success", results.message
    return results.timeseries


def test_spring_damper_columns_are_the_law_of_the_saved_motion():
    k, c, free_length = 200.0, 3.0, 0.3  # [N/m], [N s/m], [m]
    k_r, c_r, free_angle = 0.5, 0.02, 0.1  # [N m/rad], [N m s/rad], [rad]
    spring = {"type": "spring_damper", "name": "link", "bodies": ["a", "b"],
              "points": ["end", "end"], "stiffness": k, "damping": c,
              "free_length": free_length}  # fmt: skip
    rotational = {"type": "rotational_spring_damper", "bodies": ["a", "b"], "stiffness": k_r,
                  "damping": c_r, "free_angle": free_angle}  # fmt: skip
    df = _free_bodies([spring, rotational], gravity=0.0, t_end=0.05)
    ends, rates = [], []
    for body, end in (("a", (0.1, 0.05)), ("b", (-0.04, 0.03))):
        arm = _arm(df[f"phi_{body}"].to_numpy(), end)
        ends.append(np.stack([df[f"x_{body}"], df[f"y_{body}"]]) + arm)
        omega = df[f"omega_{body}"].to_numpy()
        rates.append(np.stack([df[f"vx_{body}"], df[f"vy_{body}"]]) + omega * [-arm[1], arm[0]])
    span = ends[1] - ends[0]
    length = np.hypot(*span)
    length_rate = np.sum(span / length * (rates[1] - rates[0]), axis=0)
    force = -k * (length - free_length) - c * length_rate  # on b's end, pushing the ends apart
    assert np.ptp(force) > 0.5  # [N] it varies: the check is not of a constant
    np.testing.assert_allclose(df["load_link_force"], force, rtol=1e-12, atol=1e-12)
    relative = df["phi_b"] - df["phi_a"] - free_angle
    torque = -k_r * relative - c_r * (df["omega_b"] - df["omega_a"])  # on b
    np.testing.assert_allclose(df["load_a_b_torque"], torque, rtol=1e-12, atol=1e-14)


def test_mass_times_acceleration_is_gravity_plus_the_load_columns():
    # Body a, free (b falls beside it), its motion differentiated from the saved velocities:
    # m a = m g + F and J alpha = T + (A s) x F, F the point force's columns at body point s,
    # T the torque's.
    point = (0.1, 0.05)
    harmonic = {"type": "harmonic", "offset": 1.0, "amplitude": 3.0,
                "angular_frequency": 20.0, "phase": 0.4}  # fmt: skip
    force = {"type": "point_force", "body": "a", "point": "end",
             "force": [harmonic, {"type": "polynomial", "coefficients": [2.0, 5.0]}]}  # fmt: skip
    brake = {"type": "torque", "name": "brake", "body": "a", "torque": -0.3}
    df = _free_bodies([force, brake], gravity=G, t_end=0.2)
    t = df["time"].to_numpy()
    fx, fy = df["load_a_end_fx"].to_numpy(), df["load_a_end_fy"].to_numpy()
    np.testing.assert_allclose(fx, 1.0 + 3.0 * np.sin(20.0 * t + 0.4), rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(fy, 2.0 + 5.0 * t, rtol=1e-14)
    torque = df["load_brake_torque"].to_numpy()
    np.testing.assert_array_equal(torque, -0.3)
    moment = torque + _cross(_arm(df["phi_a"].to_numpy(), point), [fx, fy])
    dt = t[2:] - t[:-2]

    def rate(column: str) -> np.ndarray:  # central differences of the saved motion
        return (df[column].to_numpy()[2:] - df[column].to_numpy()[:-2]) / dt

    # Central differences err by dt^2/6 times the third derivative: ~1e-6 of these ~10 N.
    np.testing.assert_allclose(2.0 * rate("vx_a"), fx[1:-1], rtol=0, atol=1e-5)
    np.testing.assert_allclose(2.0 * rate("vy_a"), fy[1:-1] - 2.0 * G, rtol=0, atol=1e-5)
    np.testing.assert_allclose(0.05 * rate("omega_a"), moment[1:-1], rtol=0, atol=1e-5)


def _slider_crank(forces: list[dict], rename_joint: dict[str, str]) -> jw.Model:
    data = tomllib.loads((EXAMPLES / "slider_crank.toml").read_text())
    for joint in data["joints"]:
        joint["name"] = rename_joint.get(joint["name"], joint["name"])
    data["forces"] += forces
    return parse_model(data, name="slider_crank")


def test_load_columns_are_named_after_the_loads_and_unique():
    gas = {"type": "point_force", "name": "gas", "body": "slider", "point": "pin",
           "force": [1.0, 0.0]}  # fmt: skip
    spring = {"type": "spring_damper", "bodies": ["ground", "slider"], "points": ["guide", "pin"],
              "stiffness": 1e3, "free_length": 0.1}  # fmt: skip
    model = _slider_crank(
        [
            gas,
            {"type": "torque", "body": "crank", "torque": 1.0},  # load_crank, taken by name
            {"type": "torque", "body": "crank", "torque": 2.0},
            {"type": "torque", "name": "crank", "body": "rod", "torque": 3.0},
            spring,
            {"type": "rotational_spring_damper", "bodies": ["crank", "rod"], "stiffness": 1.0},
        ],
        rename_joint={"rod_slider": "load_gas"},  # its columns load_gas_fx, load_gas_fy
    )
    names = column_names(model)
    assert len(set(names)) == len(names)
    loads = [n for n in names if n.startswith("load_") and not n.startswith("load_gas_f")]
    assert loads == [
        "load_gas_2_fx", "load_gas_2_fy", "load_crank_2_torque", "load_crank_3_torque",
        "load_crank_torque", "load_ground_slider_force", "load_crank_rod_torque",
    ]  # fmt: skip
    units = {n: column_unit(n, model) for n in loads}
    assert units == {n: "N m" if n.endswith("torque") else "N" for n in loads}
    assert column_unit("load_gas_fx", model) == "N"  # the joint's reaction
