"""Odd input gives one line per problem and exit 2, odd numbers never a ``success``.

Each case is a class of input that once gave a traceback or a wrong ``success``; the
property tests at the end mutate the example models at random.
"""

import json
import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from jointwear.cli import app

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples"
PENDULUM = EXAMPLES / "pendulum.toml"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
SLIDER_CRANK = EXAMPLES / "slider_crank.toml"
CLEARANCE = "joints.coupler_follower.clearance"


def invoke(*args: object):
    return CliRunner().invoke(app, [str(a) for a in args])


def strict_json(path: Path) -> dict:
    """A JSON file read as the standard has it: Infinity and NaN are errors."""

    def refuse(constant: str) -> None:
        raise ValueError(f"{path} holds {constant}")

    return json.loads(path.read_text(), parse_constant=refuse)


def status_line(result) -> str:
    """The run's first line after the compile notice a kernel cache miss prints."""
    lines = result.output.splitlines()
    return next(line for line in lines if not line.startswith("compiling the kernels"))


def one_line_failure(result, code: int = 2) -> str:
    """The single line of a clean failure."""
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    assert "Traceback" not in result.output
    assert result.exit_code == code, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1, result.output
    return lines[0]


@pytest.mark.parametrize(
    ("model", "setting", "expected"),
    [
        (PENDULUM, "bodies.0.mass=1 kg^0", "cannot read '1 kg^0'"),
        (PENDULUM, "bodies.0.mass=3 percent", "'percent' is a pure number, not a unit"),
        (PENDULUM, "bodies.0.angle=50 percent", "expected an angle"),
        (PENDULUM, "bodies.0.angle=1 m/m", "has no angle unit"),
        (PENDULUM, "bodies.0.mass=1 nan", "expected a mass"),
        (PENDULUM, "bodies.0.mass=1e400 kg", "is not finite in SI units; expected a mass"),
        (PENDULUM, "solver.t_end=5e-324", "solver.t_end: got 5e-324; must be >= 1e-15"),
        (PENDULUM, "solver.max_step=1e300", "solver.max_step: got 1e+300; must be <= 1e+12"),
        (FOURBAR, f"{CLEARANCE}.width=1e300", "the contact cannot be computed"),
        (
            SLIDER_CRANK,
            'drivers.0.function={type="harmonic", amplitude=1e300, angular_frequency=1e300}',
            "the initial velocities are not finite numbers",
        ),
        (PENDULUM, "bodies.0.ma\nss=1", "unknown key 'ma\\nss'"),
    ],
)
@pytest.mark.parametrize("command", ["check", "run"])
def test_odd_values_fail_in_one_line(tmp_path, model, setting, expected, command):
    out = ["--out", tmp_path / "out", "--no-figures"] if command == "run" else []
    line = one_line_failure(invoke(command, model, "--set", setting, *out))
    assert expected in line
    assert "expected" in line or "must be" in line or "check" in line or "unknown" in line
    assert not (tmp_path / "out").exists()


def test_a_tiny_axis_is_a_direction():
    result = invoke("check", SLIDER_CRANK, "--set", "joints.3.axis=[1e-200, 0.0]")
    assert result.exit_code == 0, result.output


def test_a_huge_max_step_runs(tmp_path):
    result = invoke("run", PENDULUM, "--out", tmp_path, "--set", "solver.max_step=1e6",
                    "--t-end", "0.5", "--no-figures")  # fmt: skip
    assert result.exit_code == 0, result.output


def test_non_finite_wear_is_a_status_not_a_success(tmp_path):
    result = invoke("run", FOURBAR, "--out", tmp_path, "--t-end", "0.02", "--no-figures",
                    "--set", f"{CLEARANCE}.wear_coefficient=1e300")  # fmt: skip
    assert result.exit_code == 1, result.output
    assert status_line(result).startswith(
        "non_finite: the revolute clearance joints' contact totals became"
    )
    summary = strict_json(tmp_path / "summary.json")
    assert summary["status"] == "non_finite"
    assert summary["stats"]["t_reached"] > 0.0


@pytest.mark.parametrize("damage", ["truncate", "model", "life"])
def test_plot_on_a_damaged_or_foreign_folder_is_one_line(tmp_path, damage):
    folder = tmp_path / "out"
    assert (
        invoke("run", PENDULUM, "--out", folder, "--t-end", "0.05", "--no-figures").exit_code == 0
    )
    if damage == "truncate":
        parquet = folder / "timeseries.parquet"
        parquet.write_bytes(parquet.read_bytes()[:100])
    elif damage == "model":
        (folder / "model.json").write_text('{"bodies": 3}')
    else:
        (folder / "life.csv").write_text("update\n")
    line = one_line_failure(invoke("plot", folder, "--no-animation"))
    assert line.startswith(str(folder))


# property tests: random mutations of the examples -------------------------------------------

ODD_VALUES = st.one_of(
    st.sampled_from([0, -1, 1e-300, 1e300, 5e-324, 2**70, "", "kg", "1 kg^0", "50 percent",
                     "1e400 Pa", "1 nan", "3 parsec", "\n", True, [], {}, [1e300, 1e-300]]),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=12),
)  # fmt: skip


def _paths(data: object, prefix: str = "") -> list[str]:
    """Every dotted path to a leaf of a model table (list items by index)."""
    if isinstance(data, dict):
        return [p for k, v in data.items() for p in _paths(v, f"{prefix}{k}.")]
    if isinstance(data, list) and data and isinstance(data[0], dict):
        return [p for i, v in enumerate(data) for p in _paths(v, f"{prefix}{i}.")]
    return [prefix[:-1]]


def _leaf_paths(model: Path) -> list[str]:
    import tomllib

    return _paths(tomllib.loads(model.read_text()))


def _toml_value(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string is a JSON string
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{}"
    return repr(value)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    model=st.sampled_from([PENDULUM, FOURBAR, SLIDER_CRANK]),
    data=st.data(),
    value=ODD_VALUES,
)
def test_check_never_tracebacks_on_a_mutated_model(model, data, value):
    path = data.draw(st.sampled_from(_leaf_paths(model)))
    result = invoke("check", model, "--set", f"{path}={_toml_value(value)}")
    assert result.exit_code in (0, 2), result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    if result.exit_code == 2:
        assert all(line.strip() for line in result.output.strip().splitlines())


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    model=st.sampled_from([PENDULUM, FOURBAR]),
    data=st.data(),
    value=ODD_VALUES,
)
def test_a_mutated_run_succeeds_with_finite_results_or_says_why(tmp_path_factory, model, data,
                                                                value):  # fmt: skip
    path = data.draw(st.sampled_from(_leaf_paths(model)))
    out = tmp_path_factory.mktemp("run")
    result = invoke("run", model, "--out", out, "--t-end", "0.01", "--no-figures", "--no-ideal",
                    "--set", f"{path}={_toml_value(value)}")  # fmt: skip
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    assert result.exit_code in (0, 1, 2), result.output
    if result.exit_code == 2:
        return
    summary = strict_json(out / "summary.json")
    assert (summary["status"] == "success") == (result.exit_code == 0)
    if result.exit_code == 0:
        import pandas as pd

        table = pd.read_parquet(out / "timeseries.parquet")
        assert table.notna().all().all()


DEEP = "[" * 3000 + "]" * 3000  # deeper than Python's recursion limit


@pytest.mark.parametrize("where", ["model", "set", "vary", "sweep_file"])
def test_deep_nesting_is_one_line(tmp_path, where):
    model, args = PENDULUM, []
    if where == "model":
        model = tmp_path / "deep.toml"
        model.write_text(PENDULUM.read_text() + f"\nextra = {DEEP}\n")
        args = ["check", model]
    elif where == "set":
        args = ["check", model, "--set", f"solver.t_end={DEEP}"]
    elif where == "vary":
        args = ["sweep", model, "--out", tmp_path / "out", "--vary", f"solver.t_end={DEEP}"]
    else:
        plan = tmp_path / "sweep.toml"
        plan.write_text(f"[vary]\n'solver.t_end' = {DEEP}\n")
        args = ["sweep", model, "--out", tmp_path / "out", "--file", plan]
    line = one_line_failure(invoke(*args))
    assert "nested too deeply" in line
    assert len(line) < 300


def test_numbers_of_thousands_of_digits_and_special_files_are_one_line(tmp_path):
    digits = "1" * 5001  # past Python's limit on converting integers from text
    line = one_line_failure(invoke("check", PENDULUM, "--set", f"bodies.0.mass={digits}"))
    assert "too many digits" in line
    model = tmp_path / "long.toml"
    model.write_text(PENDULUM.read_text().replace('mass = "1 kg"', f"mass = {digits}"))
    assert "too many digits" in one_line_failure(invoke("check", model))
    extending = tmp_path / "extends.toml"
    extending.write_text('extends = "/dev/zero"\n')
    assert "not a file" in one_line_failure(invoke("check", extending))
    assert "not a file" in one_line_failure(invoke("check", tmp_path))


@pytest.mark.parametrize(
    "args",
    [
        ("check", PENDULUM, "--set", "name=a[/x]"),  # rich markup in the model's name
        ("check", PENDULUM, "--set", "name=\x1b[31mred"),  # a terminal escape in it
    ],
)
def test_the_models_name_is_printed_as_text(args):
    result = invoke(*args)
    assert result.exit_code == 0, result.output
    first = result.output.splitlines()[0]
    assert first.isprintable() and first.endswith("': valid")


def test_deep_keys_huge_sweeps_and_null_paths_are_refused_at_once(tmp_path):
    deep = tmp_path / "deep.toml"
    deep.write_text(PENDULUM.read_text() + "\nzz" + ".a" * 28571 + " = 1\n")
    assert "nested too deeply" in one_line_failure(invoke("check", deep))
    null = tmp_path / "null.toml"
    null.write_text('extends = "\\u0000"\n')
    assert "extends: expected the path" in one_line_failure(invoke("check", null))
    many = ",".join(str(i) for i in range(1, 41))
    line = one_line_failure(invoke("sweep", PENDULUM, "--out", tmp_path / "s", "--vary",
                                   f"solver.rtol={many}", "--vary", f"solver.atol={many}",
                                   "--vary", f"solver.max_step={many}"))  # fmt: skip
    assert "64,000 cases" in line
    line = one_line_failure(invoke("life", FOURBAR, "--out", tmp_path / "l", "--cycles", 10**21))
    assert "cycles" in line
    line = one_line_failure(invoke("life", FOURBAR, "--out", tmp_path / "l", "--cycles", 5,
                                   "--max-growth", "inf"))  # fmt: skip
    assert "max_growth" in line


def test_a_kernel_division_by_zero_is_a_status(tmp_path):
    # A journal of 1e-300 m: the contact's geometry underflows inside the compiled loop.
    result = invoke("run", FOURBAR, "--out", tmp_path, "--t-end", "0.01", "--no-figures",
                    "--no-ideal", "--set", f"{CLEARANCE}.journal_radius=1e-300")  # fmt: skip
    assert result.exit_code == 1, result.output
    assert status_line(result).startswith("non_finite: ZeroDivisionError in the compiled step loop")
    assert strict_json(tmp_path / "summary.json")["status"] == "non_finite"


def test_gravity_beyond_a_million_g_is_refused():
    line = one_line_failure(
        invoke("check", PENDULUM, "--set", "forces.0.acceleration=[0, 18446744073709551616]")
    )
    assert "a million g" in line
