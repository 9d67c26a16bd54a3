"""The command line's usability (issue 16): --version, shell completion, whole help texts,
--t-end with units, `check` of a results folder, whole numbers in `check`'s tables, and life
runs whose speeds are written in rad/s.

In-process through typer's ``CliRunner``, as tests/test_cli.py; shell completion through
``python -m jointwear`` in a subprocess, as a shell calls it. Simulated times stay tiny.
"""

import io
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import click
import pytest
import typer
from rich.console import Console
from rich.table import Table
from typer.testing import CliRunner

import jointwear as jw
from jointwear._version import __version__
from jointwear.cli import app
from jointwear.cli.common import keep_whole, number, print_table
from jointwear.studies.life.settings import cycle_driver, divides

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples"
PENDULUM = EXAMPLES / "pendulum.toml"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
NARROW = {"COLUMNS": "60"}
WIDE = {"COLUMNS": "200"}
FAST = ("--no-figures", "--no-ideal")
RPM_5000 = 5000 * 2 * math.pi / 60  # [rad/s]
TORQUE_AT = (  # the four-bar's gravity, and a harmonic torque on the follower
    'forces=[{{type="gravity", acceleration=[0.0, -9.81]}}, {{type="torque", body="follower", '
    'torque={{type="harmonic", amplitude=1.0, angular_frequency="{}"}}}}]'
)


def invoke(*args: object, env: dict | None = None):
    return CliRunner().invoke(app, [str(a) for a in args], env=env)


def one_line_failure(result, code: int = 2) -> str:
    """Exit `code`, no traceback, nothing on stdout, one line on stderr: that line."""
    assert result.exit_code == code, result.output
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert result.stdout == ""
    lines = [
        line
        for line in result.stderr.splitlines()
        if not line.startswith("compiling the kernels")  # a kernel cache miss adds it
    ]
    assert len(lines) == 1, result.stderr
    return lines[0]


BOX = re.compile("[\u2500-\u257f]")  # box drawing, should the help be drawn in panels


def words(text: str) -> str:
    """``text`` with every run of whitespace one space: help wrapped at any width."""
    return " ".join(BOX.sub(" ", text).split())


# 1. --version ------------------------------------------------------------------------------


def test_version_prints_the_version_and_exits_0():
    result = invoke("--version")
    assert result.exit_code == 0, result.output
    assert result.stdout == f"jointwear {__version__}\n"
    assert "--version" in invoke("--help").stdout


# 2. Shell completion ------------------------------------------------------------------------


def test_shell_completion_is_offered_and_completes_commands_and_options():
    assert {"--install-completion", "--show-completion"} <= set(invoke("--help").stdout.split())
    command = [sys.executable, "-m", "jointwear"]
    # typer finds the shell among the process's parents (shellingham): start it from one,
    # since pytest may run orphaned (its parent the init process) where no shell is found.
    # ("; exit": bash would otherwise replace itself by a lone command)
    in_bash = ["bash", "-c", '"$0" -m jointwear --show-completion; exit', sys.executable]
    script = subprocess.run(in_bash, capture_output=True, text=True, timeout=60)
    assert script.returncode == 0, script.stderr
    assert "_JOINTWEAR_COMPLETE=complete_bash" in script.stdout
    for words_typed, cword, expected in (("jointwear ch", 1, "check"),
                                         ("jointwear run --t-", 2, "--t-end")):  # fmt: skip
        env = {**os.environ, "_JOINTWEAR_COMPLETE": "complete_bash",
               "COMP_WORDS": words_typed, "COMP_CWORD": str(cword)}  # fmt: skip
        completed = subprocess.run(command, capture_output=True, text=True, env=env, timeout=60)
        assert completed.returncode == 0, completed.stderr
        assert completed.stdout.split() == [expected]


# 3. Help texts ------------------------------------------------------------------------------


def all_commands() -> list[tuple[list[str], click.Command]]:
    """(arguments that reach it, command) for the app itself and each of its commands."""
    group = typer.main.get_command(app)
    with click.Context(group) as context:
        names = group.list_commands(context)
        return [([], group)] + [([name], group.get_command(context, name)) for name in names]


def test_the_walk_finds_every_command_and_their_options():
    found = {tuple(path): command for path, command in all_commands()}
    assert {("run",), ("check",), ("plot",), ("sweep",), ("life",)} <= set(found)
    options = {option for param in found[("sweep",)].params for option in param.opts}
    assert {"--t-end", "--workers", "--file", "--vary"} <= options


@pytest.mark.parametrize("path, command", all_commands(), ids=lambda x: "-".join(x) or "app"
                         if isinstance(x, list) else "")  # fmt: skip
def test_every_help_text_is_shown_whole(path, command):
    for env in (NARROW, WIDE):
        result = invoke(*path, "--help", env=env)
        assert result.exit_code == 0, result.output
        shown = words(result.stdout)
        texts = [command.help or ""] + [
            getattr(param, "help", None) or "" for param in command.params
        ]
        for text in texts:
            assert words(text.partition("\f")[0]) in shown, (path, text)


def test_the_help_says_what_the_tool_does_and_lists_every_command():
    result = invoke("--help", env=WIDE)
    assert result.exit_code == 0, result.output
    shown = words(result.stdout)
    assert "Simulate planar mechanisms whose joints have clearance" in shown
    assert "how their surfaces wear" in shown
    assert "Command-line interface" not in shown  # the module's docstring is for developers
    commands = result.stdout.partition("Commands:")[2].split()
    for name in ("run", "check", "plot", "sweep", "life", "citations", "export"):
        assert name in commands, name


def test_square_brackets_in_help_texts_are_kept():
    sweep = words(invoke("sweep", "--help", env=WIDE).stdout)
    assert "Local processes [default: one per core]." in sweep
    assert "Sweep file: TOML with [vary] and [link] (path = [values]) and [set]." in sweep
    assert "End time: seconds, or with a unit as --set takes them ('50 ms')." in sweep
    assert "End time" in words(invoke("run", "--help", env=WIDE).stdout)


# 4. --t-end with units ----------------------------------------------------------------------


@pytest.fixture(scope="module")
def pendulum_folder(tmp_path_factory) -> Path:
    """A results folder of the pendulum, run for "2 ms"."""
    out = tmp_path_factory.mktemp("usability") / "pendulum"
    result = invoke("run", PENDULUM, "--out", out, "--t-end", "2 ms", *FAST)
    assert result.exit_code == 0, result.output
    return out


def test_t_end_takes_a_unit(pendulum_folder):
    summary = json.loads((pendulum_folder / "summary.json").read_text())
    assert summary["settings"]["t_end"] == pytest.approx(0.002, rel=1e-15)
    assert summary["stats"]["t_reached"] == pytest.approx(0.002, rel=1e-12)


def test_t_end_takes_plain_seconds(tmp_path):
    result = invoke("run", PENDULUM, "--out", tmp_path, "--t-end", "0.002", *FAST)
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / "summary.json").read_text())["settings"]["t_end"] == 0.002


@pytest.mark.parametrize(
    "value, message",
    [
        ("fast", "cannot read 'fast' as a number and a unit; expected a time, e.g. '0.5 ms'"),
        ("50 kg", "'50 kg' has units of mass; expected a time"),
        ("-1", "got -1; must be >= 1e-15"),
        ("-3 ms", "got '-3 ms'; must be >= 1e-15"),
        ("inf", "inf is not a finite number"),
        ("", "cannot read ''"),
    ],
)
@pytest.mark.parametrize("command", ["run", "sweep"])
def test_a_bad_t_end_is_one_line_naming_it(tmp_path, command, value, message):
    args = ["--vary", "solver.rtol=1e-6,1e-7"] if command == "sweep" else []
    result = invoke(command, PENDULUM, "--out", tmp_path / "out", "--t-end", value, *args,
                    "--no-figures", env=NARROW)  # fmt: skip
    line = one_line_failure(result)
    assert line.startswith("--t-end: ")
    assert message in line
    assert not (tmp_path / "out").exists()


def test_t_end_wins_over_set_and_a_varied_t_end_is_named_as_varied(tmp_path):
    result = invoke("run", PENDULUM, "--out", tmp_path, "--set", "solver.t_end=-1",
                    "--t-end", "1 ms", *FAST)  # fmt: skip
    assert result.exit_code == 0, result.output
    assert json.loads((tmp_path / "summary.json").read_text())["settings"]["t_end"] == 0.001
    line = one_line_failure(invoke("sweep", PENDULUM, "--out", tmp_path / "s", "--vary",
                                   "solver.t_end=-1,1", "--t-end", "1 ms"))  # fmt: skip
    assert line.startswith("solver.t_end: both set (--set, --t-end or [set]) and varied")


# 5. check of a results folder ----------------------------------------------------------------


def test_check_reads_a_results_folder(pendulum_folder):
    from_folder = invoke("check", pendulum_folder, env=WIDE)
    assert from_folder.exit_code == 0, from_folder.output
    assert from_folder.stdout.startswith("model 'pendulum': valid\n")
    # The folder's model is the file's with --t-end applied: check prints the same.
    assert from_folder.stdout == invoke("check", PENDULUM, env=WIDE).stdout
    changed = invoke("check", pendulum_folder, "--set", "name=renamed", env=WIDE)
    assert changed.stdout.startswith("model 'renamed': valid\n")


def test_check_of_a_folder_without_model_json_is_one_line(tmp_path):
    line = one_line_failure(invoke("check", tmp_path, env=NARROW))
    assert line == (
        f"{tmp_path}: not a file, nor a results folder (no model.json in it); give a TOML "
        "model file or the folder of a run"
    )


@pytest.mark.parametrize(
    "content, message",
    [(b"{", "not valid JSON"), (b"[1, 2]", "not a JSON table"), (b"\xff", "not UTF-8 text")],
)
def test_check_of_a_damaged_model_json_is_one_line(tmp_path, content, message):
    (tmp_path / "model.json").write_bytes(content)
    line = one_line_failure(invoke("check", tmp_path, env=NARROW))
    assert line.startswith(f"{tmp_path / 'model.json'}: {message}")
    assert line.endswith("the folder is damaged: give the model file, or run it again")


# 6. Numbers in check's tables ----------------------------------------------------------------


def table_rows(text: str, cells: int) -> list[list[str]]:
    """The rows of ``cells`` cells of the box tables in ``text``, header rows left out."""
    rows = []
    for line in text.splitlines():
        parts = [part.strip() for part in line.split("│")[1:-1]]
        if len(parts) == cells:
            rows.append(parts)
    return rows


def test_number_keeps_the_exponent():
    assert number(1.84e-18) == "1.84e-18"
    assert number(-7.39557e-32) == "-7.39557e-32"
    assert number(1.06154e11) == "1.06154e+11"
    assert number(0.2) == "0.2"


def test_a_table_on_a_narrow_console_keeps_its_numbers_whole():
    table = Table(title="tiny values")
    for header in ("name of the quantity", "value [unit]", "other value [unit]"):
        table.add_column(header, justify="right")
    table.add_row("a rather long quantity name", number(1.84e-18), number(-2.5e-300))
    console = Console(file=io.StringIO(), width=20, color_system=None)
    print_table(keep_whole(table, 1, 2), console)
    text = console.file.getvalue()
    assert "1.84e-18" in text and "-2.5e-300" in text
    assert "…" not in text


def test_check_tables_never_cut_numbers_on_a_narrow_terminal():
    narrow, wide = invoke("check", FOURBAR, env=NARROW), invoke("check", FOURBAR, env=WIDE)
    assert narrow.exit_code == wide.exit_code == 0, narrow.output
    assert "…" not in narrow.stdout
    pose = table_rows(narrow.stdout, 7)
    assert [row[0] for row in pose] == ["crank", "coupler", "follower"]
    assert pose == table_rows(wide.stdout, 7)
    assert pose[0][1] == "1.22465e-17"  # the crank at 90 deg: x is zero but for rounding
    values = {row[0]: row[1] for row in table_rows(narrow.stdout, 3) if row[1]}
    assert values["contact stiffness K (n = 1.5)"] == "1.06154e+11"
    assert values["Archard k (as used)"] == "8e-14"
    for row in pose:
        [float(cell) for cell in row[1:]]


# 7. Life runs with speeds in rad/s ------------------------------------------------------------


@pytest.mark.parametrize(
    "period, cycle, expected",
    [
        (0.012, 0.012, True),
        (2 * math.pi / 523.5987755982989, 2 * math.pi / RPM_5000, True),
        (0.012 * (1 - 1e-10), 0.012, True),
        (0.012 * (1 - 1e-8), 0.012, False),
        (0.006, 0.012, True),
        (0.004, 0.012, True),
        (0.005, 0.012, False),
    ],
)
def test_periods_divide_to_a_relative_tolerance(period, cycle, expected):
    assert divides(period, cycle) is expected


@pytest.mark.parametrize("speed", ["523.5987755982989", '"523.5987755982989 rad/s"',
                                   '"5000 rpm"', repr(RPM_5000)])  # fmt: skip
def test_5000_rpm_in_rad_s_is_one_cycle_with_a_5000_rpm_load(speed):
    model = jw.load_model(FOURBAR, [f"drivers.motor.function.speed={speed}",
                                    TORQUE_AT.format("5000 rpm")])  # fmt: skip
    assert cycle_driver(model) == ("motor", pytest.approx(0.012, rel=1e-15))


def test_a_speed_a_few_digits_short_of_5000_rpm_is_told_so():
    model = jw.load_model(FOURBAR, ['drivers.motor.function.speed="523.59878 rad/s"',
                                    TORQUE_AT.format("5000 rpm")])  # fmt: skip
    with pytest.raises(jw.ModelError) as error:
        cycle_driver(model)
    [line] = error.value.problems
    assert line.startswith(
        "drivers[0]: its period 0.0119999999 s does not divide the cycle 0.012 s of "
        "forces[1] (the longest period)"
    )
    assert line.endswith(
        "; drivers[0] 'motor' runs at 5000.00004203 rpm: if 5000 rpm is meant, give it as "
        "'5000 rpm', exact where a number in rad/s is rounded"
    )
    # Periods far apart: no hint about rpm, and six digits tell them apart.
    model = jw.load_model(FOURBAR, [TORQUE_AT.format("2000 rpm")])
    with pytest.raises(jw.ModelError) as error:
        cycle_driver(model)
    [line] = error.value.problems
    assert line == (
        "forces[1]: its period 0.03 s does not divide the cycle 0.04 s of drivers[0] 'motor' "
        "(the longest period); a life run needs one cycle for the whole model"
    )


def test_a_life_run_at_5000_rpm_in_rad_s_runs(tmp_path):
    sets = ["--set", "drivers.motor.function.speed=523.5987755982989 rad/s",
            "--set", TORQUE_AT.format("5000 rpm")]  # fmt: skip
    quick = ["--cycles", 1, "--settle-cycles", 0, "--no-extrapolate", "--no-figures"]
    result = invoke("life", FOURBAR, "--out", tmp_path / "life", *sets, *quick)
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("success: reached 1 cycles")
    refused = invoke("life", FOURBAR, "--out", tmp_path / "refused", *quick, "--set",
                     'drivers.motor.function.speed="523.59878 rad/s"', "--set",
                     TORQUE_AT.format("5000 rpm"), env=NARROW)  # fmt: skip
    line = one_line_failure(refused)
    assert "0.0119999999 s does not divide the cycle 0.012 s" in line
    assert "give it as '5000 rpm'" in line
