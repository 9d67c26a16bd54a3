"""Every feature with every other: each model through every path a user takes.

The models are the example files and variants of them with every driver and load function
type and every joint kind (ideal, revolute clearance dry and lubricated, translational
clearance, several clearance joints). The paths: ``check``; ``run`` with figures and the
animation; ``plot`` on the folder; ``export`` to ``.nc`` and ``.mat``; the Python API
(``run``, ``load_results``, ``Results.export``); a two-case ``sweep`` with figures; a
five-case ``sample`` with its statistics and figures; a two-cycle ``life`` run. Each cell
either succeeds, or fails with exit code 2 and a message naming what is not supported; never
an escaped exception (exit code 70 from the executable), never a hang
(``pytest.mark.timeout`` bounds each cell).

End times are short (a few milliseconds to one crank turn): the matrix is about crossings,
the physics is checked elsewhere.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pandas as pd
import pytest
from PIL import Image
from runs import EXAMPLES
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

CELL_TIMEOUT = 300  # [s] a cell that takes longer hangs (a cold numba cache takes ~40 s)
pytestmark = pytest.mark.timeout(CELL_TIMEOUT)

# Short end times per example [s]: one crank turn or less.
EXAMPLE_END = {
    "flores2009_fourbar": 0.02,
    "flores2009_fourbar_johnson": 0.02,
    "flores2009_fourbar_lubricated": 0.02,
    "flores2009_fourbar_mixed": 0.02,
    "fourbar_two_clearances": 0.02,
    "fourbar_four_clearances": 0.02,
    "journal_bearing_rig": 0.01,
    "pendulum": 0.05,
    "slider_crank": 0.006,
    "slider_crank_clearance": 0.006,
    "slider_crank_lubricated": 0.006,
    "slider_crank_piston_clearance": 0.006,
    "slotted_link": 0.02,
    "single_cylinder_engine": 0.01,
}

PERIODIC_LOADS = """
[[forces]]
type = "point_force"
name = "gas"
body = "slider"
point = "pin"
force = [
    { type = "harmonic", offset = "-20 N", amplitude = "50 N", angular_frequency = "5000 rpm" },
    "3 N",
]

[[forces]]
type = "torque"
body = "rod"
[forces.torque]
type = "harmonic"
amplitude = "0.01 N*m"
angular_frequency = "5000 rpm"
phase = "30 deg"

[[forces]]
type = "torque"
body = "slider"
torque = "0.002 N*m"

[[forces]]
type = "spring_damper"
bodies = ["ground", "slider"]
points = ["crank_pivot", "pin"]
stiffness = "100 N/m"
damping = "0.5 N*s/m"
free_length = "0.15 m"

[[forces]]
type = "rotational_spring_damper"
bodies = ["crank", "rod"]
stiffness = "0.5 N*m/rad"
damping = "0.001 N*m*s/rad"
"""

LOADS = (
    PERIODIC_LOADS
    + """
[[forces]]
type = "point_force"
body = "rod"
point = "crank_end"
force = [{ type = "polynomial", coefficients = [0.0, 10.0, -5.0] }, "-1 N"]

[[forces]]
type = "torque"
body = "crank"
torque = { type = "polynomial", coefficients = [0.001, 0.1] }
"""
)

# Tables and series: of the crank's driver, of time, and of the state (slide, angular speed).
TABLE_LOADS = """
[[forces]]
type = "joint_pressure"
name = "gas"
joint = "slider_guide"
area = "20 cm^2"
[forces.pressure]
type = "table"
argument = "motor"
x = [0, 170, 190, 360, 540]
x_unit = "deg"
y = [1, 20, 60, 5, 1.1]
y_unit = "bar"
period = "720 deg"

[[forces]]
type = "torque"
body = "rod"
[forces.torque]
type = "fourier"
period = "12 ms"
mean = "0.01 N*m"
cosine = [0.02, 0.01]
sine = [0.005]

[[forces]]
type = "joint_force"
name = "gas_spring"
joint = "slider_guide"
[forces.force]
type = "table"
argument = "slider_guide.slide"
x = [0.0, 0.3]
y = ["50 N", "20 N"]
interpolation = "linear"

[[forces]]
type = "torque"
name = "motor_curve"
body = "crank"
[forces.torque]
type = "table"
argument = "crank.angular_speed"
x = ["0 rpm", "10000 rpm"]
y = [2, 0]
interpolation = "cubic"
"""

ANGLE_DRIVERS = {  # the crank's driver as each angle function type
    "harmonic_crank": {"type": "harmonic", "amplitude": "30 deg", "angular_frequency": "5000 rpm"},
    "polynomial_crank": {"type": "polynomial", "coefficients": [0.0, 400.0, 2000.0]},
    "table_crank": {
        "type": "table", "x": [0, 3, 6, 9], "x_unit": "ms", "y": [0, 30, 0, -30],
        "y_unit": "deg", "period": "12 ms", "interpolation": "cubic",
    },
}  # fmt: skip
DISTANCE_DRIVERS = {  # the slider's driver (the crank then free) as each distance function
    "harmonic_slide": {
        "type": "harmonic", "offset": "0.109 m", "amplitude": "10 mm",
        "angular_frequency": "300 rad/s",
    },
    "polynomial_slide": {"type": "polynomial", "coefficients": [0.109, -1.0]},
    "constant_speed_slide": {"type": "constant_speed", "speed": "-1 m/s"},
}  # fmt: skip
# The slider-crank posed with the crank at 90 deg, away from the dead centres, where a driven
# slide moves the crank: (initial lines of the example, the posed ones).
CRANK_UP = (
    ('position = [0.025, 0.0]\nangle = "0 deg"', 'position = [0.0, 0.025]\nangle = "90 deg"'),
    ('position = [0.110, 0.0]\nangle = "0 deg"', 'position = [0.0545, 0.025]\nangle = "-24.6 deg"'),
    ("position = [0.170, 0.0]", "position = [0.109, 0.0]"),
)


def _variant(base: str, extra: str = "", driver: dict | None = None) -> str:
    """The text of example ``base`` with ``extra`` appended and its driver replaced."""
    text = (EXAMPLES / f"{base}.toml").read_text() + extra
    if driver is None:
        return text
    head, _, rest = text.partition("[[drivers]]")
    return head + _driver_text(driver) + rest[rest.index("\n[") + 1 :]


def _driver_text(driver: dict) -> str:
    lines = "\n".join(f"{key} = {_toml(value)}" for key, value in driver.items())
    return f"[[drivers]]\n{lines}\n\n"


def _toml(value: object) -> str:
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {_toml(v)}" for k, v in value.items()) + " }"
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return json.dumps(value)


def _models() -> dict[str, tuple[str, float]]:
    """Name -> (model text, end time [s])."""
    models = {
        path.stem: (path.read_text(), EXAMPLE_END[path.stem])
        for path in sorted(EXAMPLES.glob("*.toml"))
    }
    for base in ("slider_crank", "slider_crank_clearance", "slider_crank_piston_clearance"):
        models[f"{base}+loads"] = (_variant(base, LOADS), 0.006)
    models["slider_crank_clearance+periodic_loads"] = (
        _variant("slider_crank_clearance", PERIODIC_LOADS),
        0.006,
    )
    models["slider_crank_clearance+tables"] = (
        _variant("slider_crank_clearance", TABLE_LOADS),
        0.006,
    )
    for name, function in ANGLE_DRIVERS.items():
        driver = {"name": "motor", "type": "angle", "body": "crank", "function": function}
        models[f"slider_crank_clearance+{name}"] = (
            _variant("slider_crank_clearance", PERIODIC_LOADS, driver),
            0.006,
        )
    for name, function in DISTANCE_DRIVERS.items():
        driver = {"name": "pusher", "type": "distance", "joint": "slider_guide",
                  "function": function}  # fmt: skip
        text = _variant("slider_crank", LOADS, driver)
        for initial, posed in CRANK_UP:
            assert initial in text
            text = text.replace(initial, posed)
        models[f"slider_crank+{name}"] = (text, 0.006)
    return {name: (_ending_at(text, end), end) for name, (text, end) in models.items()}


def _ending_at(text: str, end: float) -> str:
    """The model text with its solver's end time set to ``end`` [s], to be read anywhere."""
    for table in re.findall(r'(?m)^file = "(.*)"', text):  # a table's points, beside it
        text = text.replace(f'file = "{table}"', f'file = "{EXAMPLES / table}"')
    extends = re.search(r'(?m)^extends = "(.*)"$', text)
    if extends:  # a file named relative to the example's folder; its changes in [set]
        text = text.replace(extends[1], str(EXAMPLES / extends[1]))
        return f"{text}\n[set.solver]\nt_end = {end}\n"
    ends = re.findall(r"(?m)^t_end = .*$", text)
    assert len(ends) == 1
    return text.replace(ends[0], f"t_end = {end}")


MODELS = _models()
# What a life run refuses, by what its message names: a model without a periodic driver or
# with a load that never repeats, or without a clearance joint. Every other model runs.
NOT_PERIODIC = "never repeats"
NO_CYCLE = "periodic driver"
NO_CLEARANCE = "needs a clearance joint"
LIFE_REFUSED = {
    "pendulum": NO_CYCLE,
    "slider_crank": NO_CLEARANCE,
    "slider_crank+loads": NOT_PERIODIC,
    "slider_crank_clearance+loads": NOT_PERIODIC,
    "slider_crank_piston_clearance": NO_CYCLE,  # its crank turns freely
    "slider_crank_piston_clearance+loads": NOT_PERIODIC,
    "slider_crank_clearance+polynomial_crank": NO_CYCLE,
    "slider_crank+harmonic_slide": NO_CLEARANCE,
    "slider_crank+polynomial_slide": NOT_PERIODIC,
    "slider_crank+constant_speed_slide": NOT_PERIODIC,
}
CLEARANCE_FREE = {"pendulum", "slider_crank", "slider_crank+loads"} | {
    f"slider_crank+{name}" for name in DISTANCE_DRIVERS
}


def cli(*args: object, allowed: tuple[int, ...] = (0,)) -> str:
    """Run the command line in this process; insist on a code in ``allowed`` and no traceback.

    An exit code 2 must come with a message on stderr, each line naming a field or a file.
    Returns stderr.
    """
    result = CliRunner().invoke(app, [str(a) for a in args])
    escaped = result.exception is not None and not isinstance(result.exception, SystemExit)
    assert not escaped, f"{args}: escaped {result.exception!r} (exit 70 from the executable)"
    assert result.exit_code in allowed, f"{args}: exit {result.exit_code}\n{result.output}"
    assert "Traceback" not in result.output
    if result.exit_code == 2:
        lines = result.stderr.strip().splitlines()
        assert lines and all(":" in line for line in lines), result.stderr
    return result.stderr


@pytest.fixture(scope="module")
def folders(tmp_path_factory) -> dict[str, Path]:
    return {"root": tmp_path_factory.mktemp("matrix")}


def model_file(folders: dict[str, Path], name: str) -> Path:
    path = folders["root"] / "models" / f"{name}.toml"
    if not path.exists():
        path.parent.mkdir(exist_ok=True)
        path.write_text(MODELS[name][0])
    return path


def run_folder(folders: dict[str, Path], name: str) -> Path:
    """The folder of ``jointwear run`` with figures and the animation (run once per model)."""
    if name not in folders:
        out = folders["root"] / "runs" / name
        cli("run", model_file(folders, name), "--out", out, "--t-end", MODELS[name][1],
            "--animation", allowed=(0,))  # fmt: skip
        folders[name] = out
    return folders[name]


def _pngs(folder: Path) -> dict[str, int]:
    """File name -> bytes of each figure; each one a readable image."""
    sizes = {}
    for path in sorted(folder.glob("*.png")):
        with Image.open(path) as image:
            image.verify()
        sizes[path.name] = path.stat().st_size
    return sizes


@pytest.mark.parametrize("name", MODELS)
def test_check(folders, name):
    cli("check", model_file(folders, name))


@pytest.mark.parametrize("name", MODELS)
def test_run_with_figures_and_animation(folders, name):
    out = run_folder(folders, name)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "success", summary.get("message")
    figures = _pngs(out / "figures")
    assert {"energy.png"} <= set(figures)
    with Image.open(out / "figures" / "mechanism.gif") as gif:
        assert gif.n_frames > 1
    clearance = name not in CLEARANCE_FREE
    assert (out / "ideal").is_dir() == clearance


@pytest.mark.parametrize("name", MODELS)
def test_plot_draws_the_figures_again(folders, name):
    out = run_folder(folders, name)
    before = _pngs(out / "figures")
    for png in (out / "figures").glob("*.png"):
        png.unlink()
    cli("plot", out)  # the animation is drawn by the same code as the run's
    assert set(_pngs(out / "figures")) == set(before)


@pytest.mark.parametrize("name", MODELS)
def test_export_from_the_command_line(folders, name):
    import h5py
    import scipy.io

    out = run_folder(folders, name)
    cli("export", out, out / "export.nc")
    cli("export", out, out / "export.mat")
    with h5py.File(out / "export.nc") as nc:
        assert "time" in nc
    assert "timeseries" in scipy.io.loadmat(out / "export.mat")


@pytest.mark.parametrize("name", MODELS)
def test_python_api(folders, name, tmp_path):
    model = jw.load_model(model_file(folders, name), overrides=[f"solver.t_end={MODELS[name][1]}"])
    results = jw.simulate(model)
    assert results.status == "success", results.message
    results.save(tmp_path / "run")
    loaded = jw.load_results(tmp_path / "run")
    assert loaded.model == model
    assert list(loaded.timeseries.columns) == list(results.timeseries.columns)
    assert set(loaded.units()) == set(results.timeseries.columns)
    per_load = {"gravity": 0, "point_force": 2, "joint_pressure": 2}  # columns; others one
    loads = [c for c in results.timeseries.columns if c.startswith("load_")]
    assert len(loads) == sum(per_load.get(load.type, 1) for load in model.forces)
    loaded.plot(results.timeseries.columns[1])
    loaded.export(tmp_path / "api.nc")


@pytest.mark.parametrize("name", MODELS)
def test_sweep_of_two_cases_with_figures(folders, name):
    path = model_file(folders, name)
    body = jw.load_model(path).bodies[-1]  # the follower, the slider, the pendulum
    out = folders["root"] / "sweeps" / name
    cli("sweep", path, "--out", out, "--workers", 1,
        "--vary", f"bodies.{body.name}.mass={body.mass},{1.5 * body.mass}")  # fmt: skip
    table = (out / "sweep.csv").read_text().splitlines()
    assert len(table) == 3  # a header and two cases
    assert all(",success," in row for row in table[1:]), table
    pngs = _pngs(out / "figures")
    assert bool(pngs) == (name not in CLEARANCE_FREE)  # figures of the clearance joints


@pytest.mark.parametrize("name", MODELS)
def test_sample_of_five_cases_with_statistics(folders, name):
    path = model_file(folders, name)
    body = jw.load_model(path).bodies[-1]
    out = folders["root"] / "samples" / name
    mass = f"uniform({body.mass}, {1.5 * body.mass})"
    cli("sample", path, "--out", out, "--workers", 1, "--n", 5, "--method", "random",
        "--dist", f"bodies.{body.name}.mass={mass}")  # fmt: skip
    table = pd.read_csv(out / "sample.csv")
    assert (table["status"] == "success").all(), table["error"].tolist()
    assert table[f"bodies.{body.name}.mass"].between(body.mass, 1.5 * body.mass).all()
    stats = pd.read_csv(out / "statistics.csv")
    assert (stats["n"] == 5).all()
    assert (stats["p5"] <= stats["p95"]).all()
    if name not in CLEARANCE_FREE:  # the clearance joints' forces are drawn
        assert {"distributions.png", "convergence.png"} <= set(_pngs(out / "figures"))


@pytest.mark.parametrize("name", MODELS)
def test_life_of_two_cycles(folders, name):
    out = folders["root"] / "lives" / name
    refused = LIFE_REFUSED.get(name)
    message = cli("life", model_file(folders, name), "--out", out, "--cycles", 2, "--no-band",
                  "--settle-cycles", 1, allowed=(2,) if refused else (0,))  # fmt: skip
    assert (out / "summary.json").is_file() == (refused is None)
    assert refused is None or refused in message
