"""The command line: ``jointwear run``, ``check`` and ``plot``, exit codes, messages, signals.

In-process through typer's ``CliRunner``, except the Ctrl-C / SIGTERM tests, which run
``python -m jointwear`` in a subprocess and signal it while it simulates.
"""

import json
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from runs import FOURBAR_COLUMNS
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples"
PENDULUM = EXAMPLES / "pendulum.toml"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
RESULT_FILES = ("summary.json", "model.json", "timeseries.csv", "timeseries.parquet", "events.csv")
# A narrow terminal: a one-line message must stay on one line whatever the width.
NARROW = {"COLUMNS": "60"}


def invoke(*args: object, env: dict | None = None):
    return CliRunner().invoke(app, [str(a) for a in args], env=env)


def assert_clean_failure(result, code: int = 2) -> list[str]:
    """Exit `code`, no traceback, no stdout; return the stderr lines."""
    assert result.exit_code == code, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(
        result.exception
    )
    assert "Traceback" not in result.output
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert lines, "expected a message on stderr"
    return lines


def read_csv_and_parquet(folder: Path) -> tuple[pd.DataFrame, pd.DataFrame]:
    return pd.read_csv(folder / "timeseries.csv"), pd.read_parquet(folder / "timeseries.parquet")


# run --------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def pendulum_run(tmp_path_factory):
    """``jointwear run examples/pendulum.toml --t-end 0.05`` with figures: (result, folder)."""
    out = tmp_path_factory.mktemp("cli") / "pendulum"
    result = invoke("run", PENDULUM, "--out", out, "--t-end", 0.05)
    return result, out


def without_compile_notice(stderr: str) -> str:
    """stderr without the line a kernel cache miss adds (say, the first run after an install)."""
    notice = (
        "compiling the kernels for this run's integrator and formulation: they are not in "
        "numba's cache yet (a first run, an upgrade, an edited kernel or a new combination); "
        "later runs load them from the cache\n"
    )
    return stderr.replace(notice, "", 1)


def test_run_exits_0_and_reports(pendulum_run):
    result, out = pendulum_run
    assert result.exit_code == 0, result.output
    assert without_compile_notice(result.stderr) == ""
    assert result.stdout.startswith("success: reached the end time; t = 0.05 s")
    assert f"results in {out}" in result.stdout


def test_run_writes_the_results_folder(pendulum_run):
    _, out = pendulum_run
    for name in RESULT_FILES:
        assert (out / name).is_file(), name
    figures = sorted(p.name for p in (out / "figures").glob("*.png"))
    assert figures == ["energy.png"]  # undriven: no crank-cycle figure
    assert (out / "figures" / "energy.png").stat().st_size > 1000

    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "success"
    assert summary["message"] == "reached the end time"
    assert summary["model"] == "pendulum"
    assert summary["jointwear_version"] == jw.__version__
    assert summary["settings"]["t_end"] == 0.05
    assert summary["settings"]["integrator"] == "dopri5"
    assert summary["stats"]["t_reached"] == 0.05
    assert summary["stats"]["accepted_steps"] > 0

    model = json.loads((out / "model.json").read_text())
    assert model["name"] == "pendulum"
    assert model["solver"]["t_end"] == 0.05

    events = pd.read_csv(out / "events.csv")
    assert list(events.columns) == ["time", "event", "direction"]
    assert events.empty  # the bar reaches the bottom only after 0.48 s


def test_run_csv_and_parquet_hold_the_same_table(pendulum_run):
    _, out = pendulum_run
    csv, parquet = read_csv_and_parquet(out)
    assert list(csv.columns) == list(parquet.columns)
    assert csv.shape == parquet.shape == (51, len(parquet.columns))  # 0, 1 ms, ..., 50 ms
    assert (csv.dtypes == "float64").all()
    assert (parquet.dtypes == "float64").all()
    # The CSV keeps 12 significant digits; the parquet file is exact.
    np.testing.assert_allclose(csv.to_numpy(), parquet.to_numpy(), rtol=1e-11, atol=0.0)
    np.testing.assert_allclose(parquet["time"], np.arange(51) * 1e-3, rtol=1e-12, atol=1e-15)


def test_run_without_figures_and_with_an_override(tmp_path):
    out = tmp_path / "abm"
    result = invoke(
        "run", PENDULUM, "--out", out, "--t-end", 0.01, "--no-figures",
        "--set", "solver.integrator=abm",
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    assert not (out / "figures").exists()
    for name in RESULT_FILES:
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "success"
    assert summary["settings"]["integrator"] == "abm"
    assert summary["settings"]["t_end"] == 0.01
    assert json.loads((out / "model.json").read_text())["solver"]["integrator"] == "abm"


def test_run_column_names_follow_the_model(tmp_path):
    out = tmp_path / "fourbar"
    result = invoke("run", FOURBAR, "--out", out, "--t-end", 0.01, "--no-figures")
    assert result.exit_code == 0, result.output
    csv, parquet = read_csv_and_parquet(out)
    expected = FOURBAR_COLUMNS
    assert list(csv.columns) == expected
    assert list(parquet.columns) == expected
    # Crank driven at 1500 rpm from 90 deg.
    np.testing.assert_allclose(
        parquet["phi_crank"], 0.5 * math.pi + 50.0 * math.pi * parquet["time"], atol=1e-8
    )


def test_run_that_hits_max_steps_exits_1_and_keeps_the_partial_results(tmp_path):
    out = tmp_path / "partial"
    result = invoke(
        "run", PENDULUM, "--out", out, "--t-end", 1.0, "--set", "solver.max_steps=50",
        env=NARROW,
    )  # fmt: skip
    assert result.exit_code == 1, result.output
    assert "Traceback" not in result.output
    first = result.stdout.splitlines()[0]
    assert first.startswith(
        "max_steps: solver.max_steps was reached; raise it or loosen the tolerances; t = "
    )
    assert f"results in {out}" in result.stdout
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "max_steps"
    t_reached = summary["stats"]["t_reached"]
    assert 0.0 < t_reached < 1.0
    loaded = jw.load_results(out)
    assert loaded.status == "max_steps"
    times = loaded.timeseries["time"].to_numpy()
    assert 1 < times.size < 1001
    assert times[-1] <= t_reached < times[-1] + 1e-3  # rows up to the time reached


# bad input --------------------------------------------------------------------------------


def pendulum_text() -> str:
    return PENDULUM.read_text()


@pytest.mark.parametrize("command", ["run", "check"])
def test_unknown_body_is_one_line_naming_field_problem_and_choices(tmp_path, command):
    model = tmp_path / "typo.toml"
    text = pendulum_text()
    assert text.count('bodies = ["ground", "pendulum"]') == 1
    model.write_text(
        text.replace('bodies = ["ground", "pendulum"]', 'bodies = ["ground", "pendulm"]')
    )
    out = tmp_path / "out"
    args = ("run", model, "--out", out) if command == "run" else ("check", model)
    lines = assert_clean_failure(invoke(*args, env=NARROW))
    assert lines == [
        "joints[0].bodies[1]: unknown body 'pendulm'; bodies are ground, pendulum "
        "(did you mean 'pendulum'?)"
    ]
    assert not out.exists()


@pytest.mark.parametrize(
    ("override", "message"),
    [
        (
            "joints.hinge.type=revolute",
            "joints.hinge: no item 'hinge'; names are pin; indices 0 to 0",
        ),
        ("joints.3.type=revolute", "joints.3: no item '3'; names are pin; indices 0 to 0"),
        ("solver.t_end.x=1", "solver.t_end.x: solver.t_end is a value, not a table or an array"),
        ("solver.t_end", "--set solver.t_end: expected path=value, e.g. solver.t_end=0.5"),
        ("solver.t_end=-1", "solver.t_end: got -1; must be >= 1e-15"),
    ],
)
def test_bad_override_exits_2(tmp_path, override, message):
    out = tmp_path / "out"
    lines = assert_clean_failure(
        invoke("run", PENDULUM, "--out", out, "--set", override, env=NARROW)
    )
    assert lines == [message]
    assert not out.exists()


def test_unknown_override_key_lists_the_known_keys_on_one_line(tmp_path):
    lines = assert_clean_failure(
        invoke("run", PENDULUM, "--out", tmp_path / "o", "--set", "solver.nope=1", env=NARROW)
    )
    assert len(lines) == 1
    assert lines[0].startswith("solver: unknown key 'nope'; known keys are integrator, ")
    assert "max_steps" in lines[0]


def test_toml_syntax_error_gives_file_line_and_column(tmp_path):
    model = tmp_path / "broken.toml"
    model.write_text('name = "broken"\n\n[[bodies]\nname = "a"\n')
    lines = assert_clean_failure(invoke("run", model, "--out", tmp_path / "o", env=NARROW))
    assert len(lines) == 1
    assert re.fullmatch(
        rf"{re.escape(str(model))}:3:\d+: invalid TOML: .+; fix the syntax there", lines[0]
    )


@pytest.mark.parametrize("command", ["run", "check"])
def test_missing_model_file_exits_2(tmp_path, command):
    missing = tmp_path / "no_such_model.toml"
    lines = assert_clean_failure(invoke(command, missing, env=NARROW))
    assert lines == [f"{missing}: cannot read the file; No such file or directory"]


@pytest.mark.parametrize("command", ["run", "check"])
def test_mechanism_that_cannot_be_assembled_names_the_joints(tmp_path, command):
    # A second pin ties the free end of the 1 m bar to a ground point 3 m from the pivot.
    text = pendulum_text()
    text = text.replace("pivot = [0.0, 0.0]\n", "pivot = [0.0, 0.0]\nfar = [3.0, 0.0]\n", 1)
    text = text.replace(
        "[[forces]]",
        '[[joints]]\nname = "tip_pin"\ntype = "revolute"\nbodies = ["ground", "pendulum"]\n'
        'points = ["far", "tip"]\n\n[[forces]]',
        1,
    )
    model = tmp_path / "stretched.toml"
    model.write_text(text)
    out = tmp_path / "out"
    args = ("run", model, "--out", out) if command == "run" else ("check", model)
    lines = assert_clean_failure(invoke(*args, env=NARROW))
    assert len(lines) == 1
    assert lines[0].startswith("assembly: the constraints cannot be met from the initial guess")
    assert "joint 'tip_pin'" in lines[0]
    assert lines[0].endswith(
        "check the body points and lengths, and the initial positions and angles"
    )
    assert not out.exists()


# check ------------------------------------------------------------------------------------


def test_check_prints_the_layout_of_a_translational_clearance_joint():
    # The piston example: gap 1 mm, guide 52 mm high and 440 mm long, steel corners of 1 mm
    # radius: K = 4/3 E* sqrt(r), E* = E / (2 (1 - nu^2)) = 113.736 GPa, K = 4.79554e9.
    result = invoke("check", EXAMPLES / "slider_crank_piston_clearance.toml",
                    env={"COLUMNS": "200"})  # fmt: skip
    assert result.exit_code == 0, result.output
    text = result.stdout
    assert "degrees of freedom: 3 (joints only), 3 with drivers, of which 2 from clearance" in text
    assert "translational clearance joint 'piston'" in text
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.split("│")[1:-1]]
        if len(cells) == 3:
            rows.setdefault(cells[0], cells[1])
    assert float(rows["gap on each side c"]) == 1.0
    assert float(rows["guide (on 'ground'): height"]) == 52.0
    assert float(rows["length"]) == 440.0
    assert rows["contacts"] == "4 corners + 4 guide ends"
    e_star = 207e9 / (2 * (1 - 0.3**2))
    stiffness = 4 / 3 * e_star * math.sqrt(1e-3)
    assert float(rows["contact stiffness K (n = 1.5)"]) == pytest.approx(stiffness, rel=1e-5)
    force = stiffness * (0.1e-3) ** 1.5  # at 10 % of the gap [N]
    assert float(rows["force F at delta = 10% of c"]) == pytest.approx(force / 1e3, rel=1e-5)


def test_check_fourbar_prints_dof_and_initial_pose():
    result = invoke("check", FOURBAR, env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    assert result.stderr == ""
    text = result.stdout
    assert "model 'flores2009_fourbar': valid" in text
    assert (
        "degrees of freedom: 3 (joints only), 2 with drivers, of which 2 from clearance joints"
        in text
    )
    assert "contact stiffness K (n = 1.5)" in text and "1.06154e+11" in text  # Table 2 data
    assert re.search(r"assembled in \d+ Newton iterations, residual ", text)
    rows = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.split("│")[1:-1]]
        if len(cells) == 7 and cells[0] in ("crank", "coupler", "follower"):
            rows[cells[0]] = [float(c) for c in cells[1:]]
    assert set(rows) == {"crank", "coupler", "follower"}
    x, y, phi, vx, vy, omega = rows["crank"]
    assert phi == pytest.approx(90.0, abs=1e-9)
    assert (x, y) == pytest.approx((0.0, 0.2), abs=1e-9)
    assert omega == pytest.approx(50.0 * math.pi, rel=1e-5)  # 1500 rpm
    assert (vx, vy) == pytest.approx((-0.2 * 50.0 * math.pi, 0.0), rel=1e-5, abs=1e-9)
    # The loop-closure pose of the example's header comment.
    assert rows["coupler"][:3] == pytest.approx((0.127792, 0.423859, 10.5757), abs=1e-4)
    assert rows["follower"][:3] == pytest.approx((0.202792, 0.223859, 76.7306), abs=1e-4)


# plot -------------------------------------------------------------------------------------


def test_plot_redraws_the_figures(tmp_path):
    out = tmp_path / "fourbar"
    run = invoke("run", FOURBAR, "--out", out, "--t-end", 0.05, "--no-figures")
    assert run.exit_code == 0, run.output
    assert not (out / "figures").exists()
    result = invoke("plot", out, "--animation", env={"COLUMNS": "500"})
    assert result.exit_code == 0, result.output
    names = ["energy.png", "cycle.png", "fig7_dynamics.png", "fig7d_orbit.png"]
    names += ["fig8_wear_sectors.png", "fig9_wear_polar.png", "fig10_profile.png"]
    expected = [out / "figures" / name for name in [*names, "mechanism.gif"]]
    assert result.stdout.splitlines() == [str(p) for p in expected]
    assert (out / "ideal" / "summary.json").is_file()  # the companion run, for Fig. 7
    for path in expected:
        assert path.stat().st_size > 1000
    # Again, over the existing figures, without the animation (the default): the GIF stays.
    again = invoke("plot", out, env={"COLUMNS": "500"})
    assert again.exit_code == 0, again.output
    assert again.stdout.splitlines() == [str(p) for p in expected[:-1]]
    assert expected[-1].is_file()
    # A new run without --animation removes it (it would show the earlier run); with, writes it.
    rerun = invoke("run", FOURBAR, "--out", out, "--t-end", 0.01, "--no-ideal")
    assert rerun.exit_code == 0, rerun.output
    assert not expected[-1].exists()
    assert (out / "figures" / "fig8_wear_sectors.png").is_file()
    animated = invoke("run", FOURBAR, "--out", out, "--t-end", 0.01, "--no-ideal", "--animation")
    assert animated.exit_code == 0, animated.output
    assert expected[-1].stat().st_size > 1000


def test_plot_of_a_folder_without_results_exits_2(tmp_path):
    lines = assert_clean_failure(invoke("plot", tmp_path, env=NARROW))
    assert lines == [f"{tmp_path}: not a results folder (no summary.json)"]
    missing = tmp_path / "nothing_here"
    lines = assert_clean_failure(invoke("plot", missing, env=NARROW))
    assert lines == [f"{missing}: not a results folder (no summary.json)"]
    assert not missing.exists()


# signals ----------------------------------------------------------------------------------


class _Stream(threading.Thread):
    """Reads a pipe to its end in the background; ``seen`` is set once `marker` appears."""

    def __init__(self, pipe, marker: bytes) -> None:
        super().__init__(daemon=True)
        self.pipe, self.marker = pipe, marker
        self.data = b""
        self.seen = threading.Event()

    def run(self) -> None:
        while chunk := os.read(self.pipe.fileno(), 65536):
            self.data += chunk
            if self.marker in self.data:
                self.seen.set()

    def text(self) -> str:
        return self.data.decode(errors="replace")


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
def test_signal_ends_the_run_cleanly_with_partial_results(tmp_path, signum):
    out = tmp_path / "interrupted"
    t_end, interval = 1000.0, 1e-2  # far more than the few seconds the run is given
    command = [
        sys.executable, "-m", "jointwear", "run", str(FOURBAR), "--out", str(out),
        "--t-end", str(t_end), "--set", f"solver.output_interval={interval}", "--no-figures",
    ]  # fmt: skip
    # Rich draws its progress bar on stderr as on a terminal, and it only appears once the
    # run has lasted a second and its first chunk is done: the signal handlers are in place.
    env = os.environ | {"TTY_COMPATIBLE": "1", "TTY_INTERACTIVE": "1", "TERM": "xterm"}
    env.pop("NO_COLOR", None)
    proc = subprocess.Popen(
        command, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE
    )
    stderr = _Stream(proc.stderr, b"simulating")
    stderr.start()
    try:
        # Generous: without a warm JIT cache the kernels compile first.
        assert stderr.seen.wait(timeout=180), f"no progress bar; stderr: {stderr.text()}"
        time.sleep(2.0)  # let it simulate for a while
        assert proc.poll() is None, "the run ended before the signal"
        proc.send_signal(signum)
        code = proc.wait(timeout=60)
        stdout = proc.stdout.read().decode()
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        stderr.join(timeout=10)
        proc.stdout.close()
        proc.stderr.close()

    assert code == 1, f"exit {code}; stdout: {stdout}; stderr: {stderr.text()}"
    assert "Traceback" not in stderr.text()
    assert "KeyboardInterrupt" not in stderr.text()
    assert stdout.startswith(
        "interrupted: interrupted by the user; the results hold what was computed so far"
    )
    for name in RESULT_FILES:
        assert (out / name).is_file(), name
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    t_reached = summary["stats"]["t_reached"]
    assert 0.0 < t_reached < t_end
    assert summary["settings"]["t_end"] == t_end

    results = jw.load_results(out)
    assert results.status == "interrupted"
    times = results.timeseries["time"].to_numpy()
    # Every output row up to the time reached, none beyond.
    assert times.size == math.floor(t_reached / interval * (1 + 1e-12)) + 1
    np.testing.assert_allclose(times, np.arange(times.size) * interval, rtol=1e-12, atol=1e-12)
    assert times[-1] <= t_reached < times[-1] + interval
    assert np.isfinite(results.timeseries.to_numpy()).all()
    csv = pd.read_csv(out / "timeseries.csv")
    assert csv.shape == results.timeseries.shape


def test_check_reports_redundant_constraints_by_formulation(tmp_path):
    # The pendulum with a second pin at its pivot: 4 equations of rank 2.
    path = tmp_path / "double_pin.toml"
    path.write_text(
        PENDULUM.read_text()
        + '\n[[joints]]\nname = "pin2"\ntype = "revolute"\nbodies = ["ground", "pendulum"]\n'
        'points = ["pivot", "pivot"]\n'
    )
    result = invoke("check", path, env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    assert "degrees of freedom: 1 (joints only), 1 with drivers" in result.stdout
    assert "redundant constraints: 2 equation(s) depend on others" in result.stdout
    refused = invoke("check", path, "--set", "solver.formulation=baumgarte", env=NARROW)
    (line,) = assert_clean_failure(refused)
    assert "rank 2 for 4 equations" in line and "augmented_lagrangian" in line


def test_plot_redraws_the_figures_of_sweep_and_life_folders(tmp_path):
    sweep_folder = tmp_path / "sweep"
    swept = invoke("sweep", FOURBAR, "--out", sweep_folder, "--t-end", "0.005", "--workers", 1,
                   "--vary", "bodies.crank.mass=1,2", "--no-figures")  # fmt: skip
    assert swept.exit_code == 0, swept.output
    assert not (sweep_folder / "figures").exists()
    drawn = invoke("plot", sweep_folder, env={"COLUMNS": "500"})
    assert drawn.exit_code == 0, drawn.output
    paths = [Path(line) for line in drawn.stdout.splitlines()]
    assert paths and all(p.parent == sweep_folder / "figures" and p.is_file() for p in paths)
    assert not any("whole_run" in p.name for p in paths)  # the steady state's figures
    life_folder = tmp_path / "life"
    lived = invoke("life", FOURBAR, "--out", life_folder, "--cycles", 2, "--no-figures")
    assert lived.exit_code == 0, lived.output
    drawn = invoke("plot", life_folder, env={"COLUMNS": "500"})
    assert drawn.exit_code == 0, drawn.output
    names = sorted(Path(line).name for line in drawn.stdout.splitlines())
    assert names == ["life_profiles.png", "life_wear.png"]
    assert all((life_folder / "figures" / name).stat().st_size > 1000 for name in names)
