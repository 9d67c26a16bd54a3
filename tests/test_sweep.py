"""Parameter studies: ``jointwear sweep`` and ``jointwear.sweep``.

Short runs (0.01 s, a quarter crank turn) of the paper's four-bar: what is checked is the
bookkeeping (cases, names, table, skipping, failures, interruption, the Dask path), not the
physics.
"""

import contextlib
import importlib
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pandas as pd
import pytest
from matplotlib.collections import PathCollection
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.figures.sweep import FIGURES_OF_MERIT, plot_sweep, quantity
from jointwear.io import write_text
from jointwear.model import ModelError
from jointwear.studies.sweep.cases import make_cases, make_plan, parse_vary, si_value
from jointwear.studies.sweep.runners import _start_method
from jointwear.studies.sweep.study import sweep

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
FRICTION = "joints.coupler_follower.clearance.friction_coefficient"
RADIUS = "joints.coupler_follower.clearance.bearing_radius"
VARY = [f"{FRICTION}=0.05,0.1", f"{RADIUS}=10.0 mm,10.1 mm"]
T_END = "0.01"
CASES = [
    "friction_coefficient=0.05__bearing_radius=10.0_mm",
    "friction_coefficient=0.05__bearing_radius=10.1_mm",
    "friction_coefficient=0.1__bearing_radius=10.0_mm",
    "friction_coefficient=0.1__bearing_radius=10.1_mm",
]
HEADLINE = (
    "max_contact_force_n",
    "contact_time_fraction",
    "impacts",
    "max_penetration_m",
    "max_wear_depth_journal_m",
    "max_wear_depth_bearing_m",
    "worn_volume_m3",
)
WALL_COLUMNS = ["wall_s", "simulation_wall_s"]  # differ from run to run
NARROW = {"COLUMNS": "60"}  # a one-line message must stay on one line


def invoke(*args: object, env: dict | None = None):
    return CliRunner().invoke(app, ["sweep", *(str(a) for a in args)], env=env)


def sweep_args(out: Path, *extra: object) -> list[object]:
    vary = [arg for v in VARY for arg in ("--vary", v)]
    return [FOURBAR, "--out", out, *vary, "--t-end", T_END, *extra]


def mtimes(folder: Path) -> dict[str, int]:
    return {p.parent.name: p.stat().st_mtime_ns for p in folder.glob("cases/*/summary.json")}


@pytest.fixture(scope="module")
def local_sweep(tmp_path_factory):
    """The 2 x 2 sweep through the CLI in local processes (one per core): (result, folder)."""
    out = tmp_path_factory.mktemp("sweep") / "local"
    return invoke(*sweep_args(out)), out


# The cases and the table ---------------------------------------------------------------------


def test_two_varied_values_give_their_product_as_cases(local_sweep):
    result, out = local_sweep
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("4 cases: 4 success\n")
    assert sorted(p.name for p in (out / "cases").iterdir()) == CASES
    table = pd.read_csv(out / "sweep.csv")
    assert table["case"].tolist() == CASES  # the first varied path varies slowest
    assert table[FRICTION].tolist() == [0.05, 0.05, 0.1, 0.1]
    assert table[RADIUS].tolist() == pytest.approx([0.01, 0.0101, 0.01, 0.0101], rel=1e-12)
    assert (table["status"] == "success").all()
    assert table["error"].isna().all()  # empty
    assert (table["wall_s"] > 0).all()
    for case in CASES:
        record = json.loads((out / "cases" / case / "case.json").read_text())
        row = table.set_index("case").loc[case]
        assert record["overrides"] == [
            f"solver.t_end={T_END}",
            f"{FRICTION}={row[FRICTION]:g}",
            f"{RADIUS}={case.rpartition('=')[2].replace('_', ' ')}",
        ]


def dotted(prefix: str, table: dict) -> list[tuple[str, object]]:
    """The leaves of a nested table as (``prefix.key.key...``, value)."""
    leaves = []
    for key, value in table.items():
        if isinstance(value, dict):
            leaves += dotted(f"{prefix}.{key}", value)
        else:
            leaves.append((f"{prefix}.{key}", value))
    return leaves


def test_the_table_holds_each_case_summary(local_sweep):
    _, out = local_sweep
    table = pd.read_csv(out / "sweep.csv")
    fixed = ["case", FRICTION, RADIUS, "status", "error", "wall_s"]
    assert table.columns[: len(fixed)].tolist() == fixed
    for name in HEADLINE:
        assert f"coupler_follower.{name}" in table.columns
    for values in table.to_dict("records"):
        summary = json.loads((out / "cases" / values["case"] / "summary.json").read_text())
        assert summary["settings"]["t_end"] == float(T_END)
        joint = summary["clearance_joints"]["coupler_follower"]
        assert joint["radial_clearance_m"] == pytest.approx(values[RADIUS] - 0.0098)
        for column, value in dotted("coupler_follower", joint):  # nested tables: dotted
            if isinstance(value, str):  # the joint's type: the table holds numbers only
                continue
            expected = float("nan") if value is None else value
            assert values[column] == pytest.approx(expected, nan_ok=True)
        for key, value in summary["stats"].items():
            assert values[key] == pytest.approx(value)
    assert table["accepted_steps"].gt(0).all()


def test_csv_and_parquet_hold_the_same_table(local_sweep):
    _, out = local_sweep
    csv = pd.read_csv(out / "sweep.csv").drop(columns="error")
    parquet = pd.read_parquet(out / "sweep.parquet")
    assert (parquet["error"] == "").all()
    pd.testing.assert_frame_equal(
        csv, parquet.drop(columns="error"), check_dtype=False, check_exact=False, rtol=1e-11
    )


def test_one_comparison_figure_per_figure_of_merit(local_sweep):
    _, out = local_sweep
    figures = sorted(p.name for p in (out / "figures").glob("*.png"))
    assert {"max_contact_force.png", "max_wear_depth.png"} <= set(figures)
    assert set(figures) <= {f"{name}.png" for name, _, _ in FIGURES_OF_MERIT}
    assert all(p.stat().st_size > 5000 for p in (out / "figures").glob("*.png"))


def test_comparison_figures_speak_the_sweeps_units(local_sweep):
    _, out = local_sweep
    table = pd.read_parquet(out / "sweep.parquet")
    given = {FRICTION: {0.05: "0.05", 0.1: "0.1"}, RADIUS: {0.01: "10.0 mm", 0.0101: "10.1 mm"}}
    figure = plot_sweep(table, ["coupler_follower.max_wear_depth_journal_m"], given)
    ax = figure.axes[0]
    assert [t.get_text() for t in ax.get_xticklabels()] == ["0.05", "0.1"]
    assert [t.get_text() for t in figure.legends[0].get_texts()] == [
        "bearing radius 10.0 mm",
        "bearing radius 10.1 mm",
    ]
    assert ax.get_ylabel() == "max wear depth journal [µm]"
    for line, radius in zip(ax.get_lines(), (0.01, 0.0101), strict=True):
        rows = table[table[RADIUS] == radius]
        depth = rows["coupler_follower.max_wear_depth_journal_m"].to_numpy()
        assert line.get_ydata() == pytest.approx(depth * 1e6)


@pytest.mark.parametrize(
    ("column", "label", "factor"),
    [
        ("j.max_wear_depth_journal_m", "max wear depth journal [µm]", 1e6),
        ("j.worn_volume_m3", "worn volume [mm³]", 1e9),
        ("torque_range_motor_n_m", "torque range motor [N m]", 1.0),
        ("j.max_contact_force_n", "max contact force [kN]", 1e-3),
        ("j.contact_time_fraction", "contact time [%]", 100.0),
        ("accepted_steps", "accepted steps", 1.0),
    ],
)
def test_axis_units_come_from_the_column_suffix(column, label, factor):
    assert quantity(column) == (label, factor)
    assert quantity("j.sliding_distance_m", largest=0.6) == ("sliding distance [m]", 1.0)


def test_a_dask_cluster_gives_the_same_table(local_sweep, tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    _, out = local_sweep
    with distributed.LocalCluster(
        n_workers=1,
        threads_per_worker=1,
        processes=False,
        protocol="tcp://",  # a real connection, on loopback
        host="127.0.0.1",
        dashboard_address=None,
    ) as cluster:
        results = sweep(
            FOURBAR,
            tmp_path / "dask",
            vary={FRICTION: [0.05, 0.1], RADIUS: ["10.0 mm", "10.1 mm"]},
            overrides=[f"solver.t_end={T_END}"],
            scheduler=cluster.scheduler_address,
            figures=False,
        )
    assert results.failed == []
    assert not results.interrupted
    local = pd.read_parquet(out / "sweep.parquet").drop(columns=WALL_COLUMNS)
    on_dask = pd.read_parquet(tmp_path / "dask" / "sweep.parquet").drop(columns=WALL_COLUMNS)
    pd.testing.assert_frame_equal(on_dask, local, check_exact=True)
    assert (tmp_path / "dask" / "cases" / CASES[3] / "summary.json").is_file()


# Running the sweep again -------------------------------------------------------------------


def test_running_the_same_sweep_again_skips_the_finished_cases(local_sweep, tmp_path):
    _, first = local_sweep
    out = tmp_path / "again"
    shutil.copytree(first, out)
    before = mtimes(out)
    table_before = pd.read_parquet(out / "sweep.parquet")
    result = invoke(*sweep_args(out, "--no-figures"))
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("4 cases (4 finished before): 4 success\n")
    assert result.stderr.count("finished before, skipped") == 4
    assert mtimes(out) == before
    pd.testing.assert_frame_equal(pd.read_parquet(out / "sweep.parquet"), table_before)


def test_changed_unfinished_and_new_cases_run_again(local_sweep, tmp_path):
    _, first = local_sweep
    out = tmp_path / "changed"
    shutil.copytree(first, out)
    before = mtimes(out)
    changed, unfinished = out / "cases" / CASES[0], out / "cases" / CASES[1]
    record = json.loads((changed / "case.json").read_text())
    record["model"]["solver"]["t_end"] = 0.02  # as if it had been run with other settings
    write_text(changed / "case.json", json.dumps(record))  # as jointwear writes them
    summary = json.loads((unfinished / "summary.json").read_text())
    write_text(unfinished / "summary.json", json.dumps(summary | {"status": "interrupted"}))
    before[CASES[1]] = (unfinished / "summary.json").stat().st_mtime_ns
    time.sleep(0.01)  # mtimes of rewritten files differ

    more = ["--vary", f"{FRICTION}=0.05,0.1,0.2", "--vary", VARY[1]]
    result = invoke(FOURBAR, "--out", out, *more, "--t-end", T_END, "--no-figures")
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("6 cases (2 finished before): 6 success\n")
    after = mtimes(out)
    assert {case for case in CASES if after[case] != before[case]} == set(CASES[:2])
    assert set(after) - set(CASES) == {
        "friction_coefficient=0.2__bearing_radius=10.0_mm",
        "friction_coefficient=0.2__bearing_radius=10.1_mm",
    }
    record = json.loads((changed / "case.json").read_text())
    assert record["model"]["solver"]["t_end"] == float(T_END)


# Failures ----------------------------------------------------------------------------------


def test_a_failing_case_is_reported_and_the_others_finish(tmp_path):
    plan = tmp_path / "sweep.toml"
    plan.write_text('[vary]\n"solver.max_steps" = [5, 100000]\n\n[set.solver]\nt_end = 0.01\n')
    out = tmp_path / "out"
    result = invoke(FOURBAR, "--out", out, "--file", plan, "--workers", 1, "--no-figures")
    assert result.exit_code == 1, result.output
    assert "2 cases: 1 success, 1 max_steps" in result.stdout
    message = "solver.max_steps was reached; raise it or loosen the tolerances"
    assert f"max_steps=5: max_steps: {message}" in result.stdout
    table = pd.read_parquet(out / "sweep.parquet")
    assert table["case"].tolist() == ["max_steps=5", "max_steps=100000"]
    assert table["status"].tolist() == ["max_steps", "success"]
    assert table["error"].tolist() == [message, ""]
    assert table["accepted_steps"].iloc[0] <= 5 < table["accepted_steps"].iloc[1]
    summary = json.loads((out / "cases" / "max_steps=5" / "summary.json").read_text())
    assert summary["status"] == "max_steps"  # its partial results are kept


def test_an_exception_in_a_case_is_recorded_with_its_message(tmp_path, monkeypatch):
    run_module = importlib.import_module("jointwear.engine.run_file")
    real_run = run_module.run

    def failing_abm(model_path, out, *, overrides, **options):
        if "solver.integrator=abm" in overrides:
            raise RuntimeError("the abm case broke\non two lines")
        return real_run(model_path, out, overrides=overrides, **options)

    monkeypatch.setattr(run_module, "run", failing_abm)
    reports = []
    results = sweep(
        FOURBAR,
        tmp_path,
        vary={"solver.integrator": ["abm", "dopri5"]},
        overrides=["solver.t_end=0.005"],
        workers=1,
        progress=lambda report, done, total: reports.append((report, done, total)),
    )
    table = results.table
    assert table["status"].tolist() == ["error", "success"]
    assert table["error"].tolist() == ["RuntimeError: the abm case broke on two lines", ""]
    assert results.failed == ["integrator=abm"]
    assert reports[0] == (None, 0, 2)  # the runs start
    assert [(r.case, r.status, done, total) for r, done, total in reports[1:]] == [
        ("integrator=abm", "error", 1, 2),
        ("integrator=dopri5", "success", 2, 2),
    ]
    # With the failed case left out, one case is left: no value changes, so no figure.
    assert not list((tmp_path / "figures").glob("*.png"))


@pytest.mark.parametrize(
    ("vary", "message"),
    [
        (["friction"], "--vary friction: expected PATH=V1,V2,..., e.g. "),
        ([f"{FRICTION}=0.1,,0.2"], f"--vary {FRICTION}=0.1,,0.2: expected PATH=V1,V2,..., e.g."),
        ([f"{FRICTION}=0.1,1e-1"], f"--vary {FRICTION}: value 1e-1 repeats 0.1; give each"),
        ([f"{FRICTION}=0.1", f"{FRICTION}=0.2"], f"--vary {FRICTION}=0.2: {FRICTION} is varied"),
        (
            [f"{FRICTION}=0.05,-0.1"],
            "case friction_coefficient=-0.1: joints[2].clearance.friction_coefficient: got -0.1;"
            " must be >= 0",
        ),
        (
            ["joints.coupler_folower.clearance.width=1,2"],
            "joints.coupler_folower: no item 'coupler_folower'; names are ground_crank, ",
        ),
        (["solver.t_end=1,2"], "solver.t_end: both set (--set, --t-end or [set]) and varied"),
        ([], "--vary: nothing is varied; give e.g. --vary "),
    ],
    ids=["no-equals", "empty-value", "repeat", "twice", "bad-value", "bad-path", "set", "none"],
)
def test_invalid_vary_exits_2_with_one_line_before_anything_runs(tmp_path, vary, message):
    out = tmp_path / "never"
    options = [arg for v in vary for arg in ("--vary", v)]
    result = invoke(FOURBAR, "--out", out, *options, "--t-end", T_END, env=NARROW)
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert "Traceback" not in result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1, lines
    assert lines[0].startswith(message), lines[0]
    assert not out.exists()


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--cycles", 0], "--cycles: got 0; expected a whole number from 1 to 1e+15"),
        (["--workers", 0], "--workers: got 0; expected a whole number from 1 to 1e+15"),
        (
            ["--workers", 2, "--scheduler", "tcp://127.0.0.1:8786"],
            "--workers: only for local processes; with --scheduler the cluster's workers run",
        ),
    ],
    ids=["cycles", "workers", "workers-and-scheduler"],
)
def test_invalid_options_exit_2_before_anything_runs(tmp_path, options, message):
    out = tmp_path / "never"
    result = invoke(FOURBAR, "--out", out, "--vary", f"{FRICTION}=0.1,0.2", *options, env=NARROW)
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1, lines
    assert lines[0].startswith(message), lines[0]
    assert not out.exists()


# Case names, values and plans --------------------------------------------------------------


def test_vary_values_split_at_top_level_commas_only():
    vary = parse_vary(['a.b=[1, 2],"x, y", 3 mm ', "c=abm"])
    assert vary == {"a.b": ["[1, 2]", '"x, y"', "3 mm"], "c": ["abm"]}


def test_case_names_are_short_unique_and_safe():
    short = make_cases({"joints.a.clearance.friction_coefficient": ["0.1", '"8e-14 1/Pa"']})
    assert [c.id for c in short] == ["friction_coefficient=0.1", "friction_coefficient=8e-14_1_Pa"]
    # names by values longer than MAX_NAME_LENGTH: every case by its index
    cases = make_cases(
        {
            "joints.a.clearance.friction_coefficient": ["0.1"],
            "joints.b.clearance.friction_coefficient": ["0.2", '"8e-14 1/Pa"'],
        }
    )
    assert [c.id for c in cases] == ["case001", "case002"]
    assert [c.values["joints.b.clearance.friction_coefficient"] for c in cases] == [
        "0.2",
        '"8e-14 1/Pa"',
    ]
    long = make_cases({"x": ["1" * 200, "1" * 199 + "2"]})
    assert [c.id for c in long] == ["case001", "case002"]
    clash = make_cases({"x": ["abm", "ABM", "a/b", "a b"]})  # alike but for letter case
    assert [c.id for c in clash] == ["case001", "case002", "case003", "case004"]
    apart = make_cases({"x": ["abm", "a/b"]})
    assert [c.id for c in apart] == ["x=abm", "x=a_b"]


def test_many_linked_paths_without_vary_give_indexed_cases():
    link = {f"joints.j{i}.clearance.friction_coefficient": [str(0.01 * k) for k in range(1, 51)]
            for i in range(6)}  # fmt: skip
    cases = make_cases({}, link)
    assert len(cases) == 50
    assert cases[0].id == "case001" and cases[-1].id == "case050"
    assert all(c.values[path] == link[path][i] for i, c in enumerate(cases) for path in link)


def test_varied_values_in_the_table_are_the_model_si_values():
    model = jw.load_model(
        FOURBAR, ["drivers.motor.function.speed=750 rpm", "solver.integrator=dopri5"]
    )
    assert si_value(model, "drivers.motor.function.speed", "750 rpm") == pytest.approx(78.5398163)
    assert si_value(model, "solver.integrator", "dopri5") == "dopri5"
    youngs = si_value(model, "joints.coupler_follower.clearance.youngs_modulus", "207 GPa")
    assert youngs == pytest.approx(2.07e11)


def test_a_key_the_model_turns_into_another_gives_its_si_value_too():
    # radial_clearance is no field of the model: it sets the bearing radius
    path = "joints.coupler_follower.clearance.radial_clearance"
    model = jw.load_model(FOURBAR, [f"{path}=0.1 mm"])
    assert si_value(model, path, "0.1 mm") == pytest.approx(1e-4, rel=1e-9)
    assert si_value(model, "joints.2.clearance.radial_clearance", "0.1 mm") == pytest.approx(1e-4)


def test_a_sweep_file_and_options_make_one_plan(tmp_path):
    plan_file = tmp_path / "plan.toml"
    plan_file.write_text(
        '[vary]\n"solver.max_step" = ["1 ms", 0.0005]\n'
        "[vary.joints.coupler_follower.clearance]\nwidth = [0.02, 0.03]\n"
        '[set]\n"solver.t_end" = 0.02\n'
    )
    plan = make_plan([f"{FRICTION}=0.1,0.2"], plan_file, ["solver.rtol=1e-7"])
    assert plan.vary == {
        "solver.max_step": ['"1 ms"', "0.0005"],
        "joints.coupler_follower.clearance.width": ["0.02", "0.03"],
        FRICTION: ["0.1", "0.2"],
    }
    assert plan.overrides == ["solver.t_end=0.02", "solver.rtol=1e-7"]
    with pytest.raises(ModelError, match="also varied in"):
        make_plan(["solver.max_step=1"], plan_file)
    plan_file.write_text("[vari]\nx = [1]\n")
    with pytest.raises(ModelError, match=r"unknown key 'vari'.*did you mean 'vary'"):
        make_plan([], plan_file)


# Ctrl-C --------------------------------------------------------------------------------------


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize(
    ("workers", "statuses"),
    [(1, ["success", "interrupted", "not_run"]), (2, ["success", "interrupted", "interrupted"])],
    ids=["serial", "processes"],
)
def test_ctrl_c_keeps_finished_cases_and_writes_the_table(tmp_path, workers, statuses):
    out = tmp_path / "interrupted"
    command = [
        sys.executable, "-m", "jointwear", "sweep", str(FOURBAR), "--out", str(out),
        "--vary", "solver.t_end=0.01,1000,1001", "--set", "solver.output_interval=0.01",
        "--workers", str(workers), "--no-figures",
    ]  # fmt: skip
    proc = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        first = out / "cases" / "t_end=0.01" / "case.json"
        deadline = time.monotonic() + 180  # generous: the kernels may compile first
        while not first.is_file() and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.1)
        time.sleep(1.5)  # the long cases are simulating
        assert proc.poll() is None, "the sweep ended before the signal"
        proc.send_signal(signal.SIGINT)  # to the sweep's own process only
        stdout, stderr = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    stdout, stderr = stdout.decode(), stderr.decode()
    assert proc.returncode == 1, f"stdout: {stdout}; stderr: {stderr}"
    assert "Traceback" not in stderr
    assert "interrupted: the table holds the cases finished so far" in stderr
    table = pd.read_parquet(out / "sweep.parquet")
    assert table["case"].tolist() == ["t_end=0.01", "t_end=1000", "t_end=1001"]
    assert table["status"].tolist() == statuses
    assert 0 < table["t_reached"].iloc[1] < 1000
    summary = json.loads((out / "cases" / "t_end=1000" / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    assert os.path.getsize(out / "sweep.csv") > 0


def test_local_processes_are_forked_only_from_a_single_threaded_process():
    release = threading.Event()
    other = threading.Thread(target=release.wait)
    other.start()
    try:
        assert _start_method() in {"forkserver", "spawn"}
    finally:
        release.set()
        other.join()
    if sys.platform == "linux":  # a fresh process has no other thread: workers are forked
        code = "from jointwear.studies.sweep.runners import _start_method; print(_start_method())"
        fresh = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        assert fresh.stdout.strip() == "fork", fresh.stderr


@pytest.mark.skipif(sys.platform != "linux", reason="/proc lists a process's children")
def test_a_worker_that_dies_ends_the_sweep_with_errors_not_a_hang(tmp_path):
    out = tmp_path / "killed"
    command = [
        sys.executable, "-m", "jointwear", "sweep", str(FOURBAR), "--out", str(out),
        "--vary", "solver.t_end=1000,1001,1002", "--set", "solver.output_interval=0.01",
        "--workers", "2", "--no-figures",
    ]  # fmt: skip
    proc = subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True
    )
    children = Path(f"/proc/{proc.pid}/task/{proc.pid}/children")
    try:
        deadline = time.monotonic() + 180  # generous: the kernels may compile first
        while len(list((out / "cases").glob("*/"))) < 2 and time.monotonic() < deadline:
            time.sleep(0.1)  # both workers have begun a case
        time.sleep(2.0)  # and simulate it
        workers = children.read_text().split()
        assert len(workers) == 2, workers
        os.kill(int(workers[0]), signal.SIGKILL)  # as the out-of-memory killer would
        _, stderr = proc.communicate(timeout=60)  # the survivor is not waited for
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)  # the workers too, whatever happened
        proc.communicate()
    assert proc.returncode == 1, stderr.decode()
    table = pd.read_parquet(out / "sweep.parquet")
    assert (table["status"] == "error").all()
    assert table["error"].str.startswith("BrokenProcessPool").all()


# linked variations ------------------------------------------------------------------------

SPEED = "drivers.motor.function.speed"


def test_linked_paths_step_together_as_one_axis_of_the_product():
    link = {SPEED: ["2500 rpm", "5000 rpm"], "bodies.crank.mass": ["1", "2"]}
    cases = make_cases({"solver.integrator": ["abm", "dopri5"]}, link)
    assert [c.values for c in cases] == [
        {"solver.integrator": i, SPEED: s, "bodies.crank.mass": m}
        for i in ("abm", "dopri5")
        for s, m in (("2500 rpm", "1"), ("5000 rpm", "2"))
    ]
    assert cases[0].id == "integrator=abm__speed=2500_rpm__mass=1"


@pytest.mark.parametrize(
    ("link", "vary", "words"),
    [
        ({SPEED: ["1", "2"], "bodies.crank.mass": ["1"]}, {}, "need as many each; got"),
        ({SPEED: ["1", "2"]}, {}, "one path alone; use --vary, or link two"),
        ({SPEED: ["1", "2"], "bodies.crank.mass": ["1", "2"]}, {SPEED: ["3"]}, "also varied"),
    ],
)
def test_links_that_do_not_fit_are_refused(link, vary, words, tmp_path):
    with pytest.raises(ModelError, match=words):
        jw.sweep(FOURBAR, tmp_path, vary=vary, link=link, workers=1)
    assert not any(tmp_path.iterdir())  # refused before anything is written


def test_link_on_the_command_line_and_in_a_sweep_file(tmp_path):
    result = invoke(FOURBAR, "--out", tmp_path / "cli", "--t-end", "0.003",
                    "--workers", 1, "--no-figures", "--link", f"{SPEED}=2500 rpm,5000 rpm",
                    "--link", "bodies.crank.mass=1,2")  # fmt: skip
    assert result.exit_code == 0, result.output
    table = pd.read_csv(tmp_path / "cli" / "sweep.csv")
    assert table[SPEED].tolist() == pytest.approx([2500 * math.pi / 30, 5000 * math.pi / 30])
    assert table["bodies.crank.mass"].tolist() == [1.0, 2.0]
    sweep_file = tmp_path / "sweep.toml"
    sweep_file.write_text(f'[link]\n"{SPEED}" = ["2500 rpm", "5000 rpm"]\n'
                          '"bodies.crank.mass" = [1, 2]\n')  # fmt: skip
    plan = make_plan([], sweep_file)
    assert plan.link == {SPEED: ['"2500 rpm"', '"5000 rpm"'], "bodies.crank.mass": ["1", "2"]}
    assert plan.vary == {}


def test_linked_values_with_units_are_si_numbers_in_the_table_and_drawn_as_points(tmp_path):
    clearance = "joints.coupler_follower.clearance.radial_clearance"
    results = jw.sweep(FOURBAR, tmp_path, vary={}, overrides=["solver.t_end=0.003"], workers=1,
                       link={clearance: ["0.2 mm", "0.1 mm"], FRICTION: [0.1, 0.05]})  # fmt: skip
    assert results.table["status"].eq("success").all()
    for table in (pd.read_csv(tmp_path / "sweep.csv"), pd.read_parquet(tmp_path / "sweep.parquet")):
        assert table[clearance].dtype == float
        assert table[clearance].tolist() == pytest.approx([2e-4, 1e-4], rel=1e-9)
    assert 0 < len(results.figures) <= len(FIGURES_OF_MERIT)
    given = {clearance: {2e-4: "0.2 mm", 1e-4: "0.1 mm"}, FRICTION: {0.1: "0.1", 0.05: "0.05"}}
    figure = plot_sweep(results.table, ["coupler_follower.max_contact_force_n"], given)
    ax = figure.axes[0]
    assert not ax.get_lines()  # two linked values: points, not a line
    assert isinstance(ax.collections[0], PathCollection)
    assert sorted(ax.collections[0].get_offsets()[:, 0]) == pytest.approx([0.1, 0.2])  # mm
