"""The promises about files and signals (docs/files-and-signals.md; ``jointwear.io``).

- Nothing outside the results folder is written or removed, and nothing in it that jointwear
  did not write: links are refused, users' files are kept.
- Results that cannot be written where asked are saved elsewhere, and the exit code says so.
- A Ctrl-C or SIGTERM at any moment gives no traceback, and a finished run is never lost.
- An error that escapes a command is one line (exit 70), deep nesting one line (exit 2).
"""

import hashlib
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app, command
from jointwear.io import RECORD

ROOT = Path(__file__).parents[1]
PENDULUM = ROOT / "examples" / "pendulum.toml"
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
SHORT = ["--t-end", "0.01", "--no-figures"]


def invoke(*args: object):
    return CliRunner().invoke(app, [str(a) for a in args])


def tree(folder: Path) -> dict[str, str]:
    """Every file under ``folder`` (links not followed) and a hash of its content."""
    files = {}
    for path in sorted(folder.rglob("*")):
        if path.is_symlink():
            files[str(path.relative_to(folder))] = f"link to {os.readlink(path)}"
        elif path.is_file():
            files[str(path.relative_to(folder))] = hashlib.sha256(path.read_bytes()).hexdigest()
    return files


@pytest.fixture
def outside(tmp_path):
    """A folder outside the results folder with a file in it, to link to."""
    folder = tmp_path / "elsewhere"
    folder.mkdir()
    (folder / "summary.json").write_text("not jointwear's")
    (folder / "energy.png").write_text("not jointwear's")
    (folder / "checkpoint.json").write_text("not jointwear's")
    return folder


@pytest.mark.parametrize(
    ("link", "args"),
    [
        ("ideal", ("run", FOURBAR, *SHORT)),
        ("figures", ("run", PENDULUM, "--t-end", "0.01")),
        ("checkpoint", ("life", FOURBAR, "--cycles", 1, "--no-figures")),
        ("cases", ("sweep", PENDULUM, "--vary", "solver.t_end=0.01,0.02", "--no-figures")),
    ],
)
def test_a_link_inside_the_results_folder_is_refused(tmp_path, outside, link, args):
    out = tmp_path / "out"
    out.mkdir()
    (out / link).symlink_to(outside, target_is_directory=True)
    before = tree(tmp_path)
    result = invoke(*args, "--out", out)
    assert result.exit_code == 2, result.output
    assert f"{out / link} is a symbolic link" in result.output
    assert "Traceback" not in result.output
    assert tree(tmp_path) == before  # nothing written, nothing removed, anywhere


def test_users_files_in_the_results_folder_are_kept(tmp_path):
    out = tmp_path / "out"
    (out / "ideal").mkdir(parents=True)
    (out / "ideal" / "notes.csv").write_text("the user's")
    (out / "figures").mkdir()
    (out / "figures" / "mine.png").write_text("the user's")
    (out / "impacts.csv").write_text("the user's")  # a name a clearance run writes
    # A run without clearance joints used to delete an earlier wear table; this one is not
    # jointwear's, so it stays.
    assert invoke("run", PENDULUM, "--out", out, "--t-end", "0.01").exit_code == 0
    assert (out / "impacts.csv").read_text() == "the user's"
    # A clearance run would write impacts.csv: refused before it starts, the file unchanged.
    refused = invoke("run", FOURBAR, "--out", out, *SHORT)
    assert refused.exit_code == 2
    assert "impacts.csv exists and was not written by jointwear" in refused.output
    (out / "impacts.csv").unlink()
    again = invoke("run", FOURBAR, "--out", out, *SHORT)  # with its ideal companion
    assert again.exit_code == 0, again.output
    assert (out / "ideal" / "notes.csv").read_text() == "the user's"
    assert (out / "ideal" / "summary.json").is_file()
    assert (out / "figures" / "mine.png").read_text() == "the user's"
    # Re-running replaces jointwear's own files, as recorded.
    recorded = set(json.loads((out / RECORD).read_text()))
    assert {"summary.json", "timeseries.csv", "impacts.csv"} <= recorded
    assert "notes.csv" not in json.loads((out / "ideal" / RECORD).read_text())


def test_results_are_readable_by_others_whatever_the_umask(tmp_path):
    import stat

    old = os.umask(0o077)  # a private umask: files made here would be 600 otherwise
    try:
        done = invoke("run", PENDULUM, "--out", tmp_path / "out", "--t-end", "0.01")
    finally:
        os.umask(old)
    assert done.exit_code == 0, done.output
    written = [p for p in (tmp_path / "out").rglob("*") if p.is_file()]
    assert {"summary.json", "timeseries.csv", "energy.png"} <= {p.name for p in written}
    assert {p.name: oct(stat.S_IMODE(p.stat().st_mode)) for p in written} == {
        p.name: "0o644" for p in written
    }


def test_a_sweep_keeps_the_users_figures(tmp_path):
    out = tmp_path / "sweep"
    (out / "figures").mkdir(parents=True)
    (out / "figures" / "mine.png").write_text("the user's")
    result = invoke("sweep", FOURBAR, "--out", out, "--vary", "solver.t_end=0.005,0.01")
    assert result.exit_code == 0, result.output
    assert (out / "figures" / "mine.png").read_text() == "the user's"
    drawn = [p for p in (out / "figures").glob("*.png") if p.name != "mine.png"]
    assert drawn  # and the sweep's own figures are there


def test_results_that_cannot_be_written_are_saved_elsewhere(tmp_path):
    out = tmp_path / "out"
    out.mkdir()

    def take_the_folder_away(t: float, t_end: float) -> None:
        if out.is_dir():  # the folder is replaced by a file while the run goes on
            shutil.rmtree(out)
            out.write_text("in the way")

    results = jw.run(PENDULUM, out, overrides=["solver.t_end=0.05"], progress=take_the_folder_away)
    moved = results.summary["not_written"]
    assert moved["folder"] == str(out)
    rescue = Path(moved["saved_in"])
    try:
        assert rescue.name.startswith("jointwear-rescued-")
        saved = jw.load_results(rescue)
        assert saved.status == "success"
        assert len(saved.timeseries) == len(results.timeseries)
        assert out.read_text() == "in the way"
    finally:
        shutil.rmtree(rescue)


@pytest.mark.parametrize(
    "args",
    [
        ("run", PENDULUM, *SHORT),
        ("life", FOURBAR, "--cycles", 1, "--no-figures"),
        ("sweep", PENDULUM, "--vary", "solver.t_end=0.01,0.02", "--no-figures"),
    ],
    ids=["run", "life", "sweep"],
)
def test_an_output_folder_that_cannot_be_written_is_refused_before_the_run(tmp_path, args):
    blocker = tmp_path / "file"
    blocker.write_text("a file")
    for out in (blocker / "out", tmp_path / ("x" * 300)):
        result = invoke(*args, "--out", out)
        assert result.exit_code == 2, result.output
        assert result.output.startswith("out: "), result.output
        assert len(result.output.strip().splitlines()) == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


# the entry point ----------------------------------------------------------------------------


def test_an_escaped_error_is_one_line_with_exit_70(monkeypatch, capsys):
    def broken(*args, **kwargs):
        raise ValueError("something\nunexpected")

    monkeypatch.setattr("jointwear.engine.prepare.build_system", broken)
    monkeypatch.delenv(command.DEBUG_VARIABLE, raising=False)
    with pytest.raises(SystemExit) as stop:
        command.main(["check", str(PENDULUM)])
    assert stop.value.code == command.INTERNAL_ERROR
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith("internal error (a bug in jointwear")
    assert "ValueError: something unexpected" in err


def test_deep_nesting_is_one_line_with_exit_2(tmp_path, capsys):
    model = tmp_path / "deep.toml"
    model.write_text(PENDULUM.read_text() + "\nextra = " + "[" * 20000 + "]" * 20000 + "\n")
    with pytest.raises(SystemExit) as stop:
        command.main(["check", str(model)])
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err


# signals at random moments ------------------------------------------------------------------


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")
@pytest.mark.parametrize("seed", range(6))
def test_a_signal_at_a_random_moment_loses_nothing(tmp_path, seed):
    """From start-up to the last file: no traceback, and a folder complete or untouched."""
    rng = random.Random(seed)
    out = tmp_path / "out"
    signum = rng.choice([signal.SIGINT, signal.SIGTERM])
    command_line = [
        sys.executable, "-m", "jointwear", "run", str(FOURBAR), "--out", str(out),
        "--t-end", "0.05", "--no-figures",
    ]  # fmt: skip
    proc = subprocess.Popen(
        command_line, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    )
    time.sleep(rng.uniform(0.0, 3.0))
    proc.send_signal(signum)
    stdout, stderr = proc.communicate(timeout=120)
    assert "Traceback" not in stderr and "KeyboardInterrupt" not in stderr, stderr
    summary = out / "summary.json"
    if summary.is_file():  # written whole: the run's status says what happened
        status = json.loads(summary.read_text())["status"]
        assert status in ("success", "interrupted")
        # 130: the signal came after the results were saved (while printing the summary)
        assert proc.returncode in (0, 1, 130, -signum, 128 + signum), proc.returncode
        if stdout.startswith("success"):
            assert status == "success"
    else:  # stopped before any result: nothing of the run's left in the folder
        assert proc.returncode in (130, -signum, 128 + signum), (proc.returncode, stderr)
        assert not out.exists() or not any(p.name == "timeseries.csv" for p in out.iterdir())


def test_a_file_the_user_changed_since_is_the_users(tmp_path):
    out = tmp_path / "out"
    assert invoke("run", FOURBAR, "--out", out, *SHORT, "--no-ideal").exit_code == 0
    (out / "wear.csv").write_text("my own edits")  # over the file jointwear wrote there
    refused = invoke("run", FOURBAR, "--out", out, *SHORT, "--no-ideal")
    assert refused.exit_code == 2
    assert "wear.csv exists and was not written by jointwear, or was changed" in refused.output
    assert (out / "wear.csv").read_text() == "my own edits"
    # A run without clearance joints would remove the earlier wear table: not this one.
    assert invoke("run", PENDULUM, "--out", out, *SHORT).exit_code == 0
    assert (out / "wear.csv").read_text() == "my own edits"


def test_an_interrupt_lost_in_a_native_callback_is_delivered_again(capsys):
    """What Python does with a KeyboardInterrupt raised inside a ctypes callback (numba's
    compiler writing its cache): it calls sys.unraisablehook, and the exception is gone."""
    import ctypes

    from jointwear.engine.interrupts import redeliver_lost_interrupts

    received = []
    previous_handler = signal.signal(signal.SIGINT, lambda signum, frame: received.append(signum))
    previous_hook = sys.unraisablehook
    try:
        redeliver_lost_interrupts()

        @ctypes.CFUNCTYPE(None)
        def callback():
            raise KeyboardInterrupt

        callback()  # native code calling back into Python: the exception cannot pass
        for _ in range(100):  # the handler runs at the next bytecodes of the main thread
            if received:
                break
            time.sleep(0.001)
        assert received == [signal.SIGINT]

        @ctypes.CFUNCTYPE(None)
        def failing():
            raise ValueError("not an interrupt")

        failing()
        assert received == [signal.SIGINT]  # other errors are reported as Python does
        assert "ValueError: not an interrupt" in capsys.readouterr().err
    finally:
        sys.unraisablehook = previous_hook
        signal.signal(signal.SIGINT, previous_handler)


def test_a_lost_interrupt_is_raised_again_outside_the_hook():
    """The handler that catches the interrupt sent again raises KeyboardInterrupt itself (as
    the command line's handlers do): that must come out in ordinary code, not in the hook."""
    import ctypes

    from jointwear.engine.interrupts import redeliver_lost_interrupts

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    previous_handler = signal.signal(signal.SIGINT, interrupt)
    previous_hook = sys.unraisablehook
    caught = False
    try:
        redeliver_lost_interrupts()

        @ctypes.CFUNCTYPE(None)
        def callback():
            raise KeyboardInterrupt

        try:
            callback()  # the hook runs and returns: nothing raised here
            for _ in range(1000):
                time.sleep(0.001)
        except KeyboardInterrupt:
            caught = True
    finally:
        sys.unraisablehook = previous_hook
        signal.signal(signal.SIGINT, previous_handler)
    assert caught


# An interrupt that no command catches (here: one raised as `run` begins), which typer turns
# into exit 130 without a word. The process ends by os._exit then, hence a child process.
UNCAUGHT_INTERRUPT = """
import sys
import jointwear.cli.run_commands as run_commands
from jointwear.cli.command import main

def interrupted(*args, **kwargs):
    raise KeyboardInterrupt

run_commands._run = interrupted
main(sys.argv[1:])
"""


def test_an_interrupt_no_command_caught_is_said_in_one_line(tmp_path):
    child = subprocess.run(
        [sys.executable, "-c", UNCAUGHT_INTERRUPT, "run", str(PENDULUM), "--out", str(tmp_path)],
        cwd=ROOT, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert child.returncode == command.INTERRUPTED
    assert child.stderr == "interrupted\n"


def test_a_command_that_said_why_it_stopped_is_not_repeated(tmp_path, monkeypatch, capsys):
    # `run` interrupted in its set-up says so itself, and exits 130 with the context suppressed
    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    import jointwear.engine.run_file  # noqa: F401  (the module, loaded)

    monkeypatch.setattr(sys.modules["jointwear.engine.run_file"], "load_model", interrupted)
    monkeypatch.setattr("os._exit", lambda code: (_ for _ in ()).throw(SystemExit(code)))
    with pytest.raises(SystemExit) as stop:
        command.main(["run", str(PENDULUM), "--out", str(tmp_path / "out")])
    assert stop.value.code == command.INTERRUPTED
    assert capsys.readouterr().err == "interrupted before the run started; nothing was written\n"
