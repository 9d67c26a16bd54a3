"""The figure helpers: whatever a drawing or a helper does, the figures come and nothing hangs.

The drawings here are small classes of this module: a helper process unpickles them by name
(the fork server has the test's ``sys.path``). Each misbehaves only in a helper, so what the
caller then draws itself is an ordinary figure.
"""

import os
import signal
import subprocess
import sys
import threading
import time

import pytest
from matplotlib.figure import Figure

from jointwear.figures import render

pytestmark = pytest.mark.timeout(180)  # a hang fails here, not the whole run


class _Blank:
    """A blank figure, drawn wherever it is called; it knows the process that made it."""

    def __init__(self) -> None:
        self.caller = os.getpid()

    def __call__(self) -> Figure:
        return Figure(figsize=(2, 2))


class _StuckInHelpers(_Blank):
    def __call__(self) -> Figure:
        if os.getpid() != self.caller:
            time.sleep(600)
        return super().__call__()


class _DiesInHelpers(_Blank):
    def __call__(self) -> Figure:
        if os.getpid() != self.caller:
            os.kill(os.getpid(), signal.SIGKILL)
        return super().__call__()


class _RaisesInHelpers(_Blank):
    def __call__(self) -> Figure:
        if os.getpid() != self.caller:
            raise LookupError("no such column")
        return super().__call__()


class _RaisesEverywhere(_Blank):
    def __call__(self) -> Figure:
        raise LookupError("no such column")


def _helper_processes() -> list:
    return [h.process for h in render._helpers if h.process is not None]


def test_helpers_draw_what_the_caller_draws_and_are_gone_after_the_block():
    expected = render._png(_Blank(), render.DPI)
    with render.drawing_helper():
        pngs = render.render_pngs([_Blank(), _Blank(), _Blank()])
        processes = _helper_processes()
    assert pngs == [expected] * 3
    assert processes  # the helpers drew them
    assert not any(p.is_alive() for p in processes)
    assert not [t for t in threading.enumerate() if t.name == render.HANDOVER]


def test_a_drawing_that_does_not_pickle_is_drawn_here():
    def local() -> Figure:  # a local function does not pickle
        return Figure(figsize=(2, 2))

    with render.drawing_helper():
        (png,) = render.render_pngs([local])
        assert all(h.process is None for h in render._helpers)  # none was given it
    assert png == render._png(_Blank(), render.DPI)


def test_a_helper_killed_while_drawing_leaves_its_figure_to_the_caller():
    with render.drawing_helper():
        pngs = render.render_pngs([_DiesInHelpers(), _Blank(), _DiesInHelpers(), _Blank()])
        assert any(h.failed for h in render._helpers)  # a helper died drawing
    assert pngs == [render._png(_Blank(), render.DPI)] * 4


def test_a_drawing_that_fails_in_a_helper_is_drawn_here_where_its_error_is_raised():
    with render.drawing_helper():
        pngs = render.render_pngs([_RaisesInHelpers(), _Blank()])
        assert not any(h.failed for h in render._helpers)  # the helper draws on
        with pytest.raises(LookupError, match="no such column"):
            render.render_pngs([_RaisesEverywhere()])
    assert pngs == [render._png(_Blank(), render.DPI)] * 2


def test_a_helper_that_does_not_answer_is_given_up_killed_and_said(monkeypatch, capsys):
    monkeypatch.setattr(render, "PATIENCE", 1.0)
    started = time.monotonic()
    with render.drawing_helper():
        pngs = render.render_pngs([_StuckInHelpers(), _StuckInHelpers(), _Blank()])
        processes = _helper_processes()
    assert time.monotonic() - started < 60.0  # the helpers start (~10 s cold), then 1 s each
    assert pngs == [render._png(_Blank(), render.DPI)] * 3
    assert not any(p.is_alive() for p in processes)
    assert "did not finish within 1 s" in capsys.readouterr().err


def test_handing_over_returns_before_the_helpers_have_started(monkeypatch):
    handed_over = threading.Event()
    started = render._Helper._started
    waited_for_the_caller = []

    def slow_start(helper):  # as a fork server still importing
        waited_for_the_caller.append(handed_over.wait(20.0))
        return started(helper)

    monkeypatch.setattr(render._Helper, "_started", slow_start)
    with render.drawing_helper():
        wait = render.start_pngs([_Blank()])
        handed_over.set()
        (png,) = wait()
    assert waited_for_the_caller and all(waited_for_the_caller)
    assert png == render._png(_Blank(), render.DPI)


STUCK_COMMAND = """
import signal, sys, time
signal.signal(signal.SIGINT, signal.default_int_handler)  # ignored if run in the background
sys.path.insert(0, sys.argv[1])
from test_figure_helpers import _StuckInHelpers
from jointwear.figures import render

if __name__ == "__main__":
    with render.drawing_helper():
        wait = render.start_pngs([_StuckInHelpers(), _StuckInHelpers()])
        for _ in range(1200):  # a minute at most
            if len([h for h in render._helpers if h.process and h.process.pid]) == 2:
                break
            time.sleep(0.05)
        print(*(h.process.pid for h in render._helpers), flush=True)
        wait()
"""


@pytest.mark.parametrize("stop", [signal.SIGKILL, signal.SIGINT])
def test_the_helpers_never_outlive_the_command_whatever_ends_it(tmp_path, stop):
    # SIGKILL: nothing of the command runs; SIGINT: the block ends while the helpers draw
    script = tmp_path / "stuck.py"
    script.write_text(STUCK_COMMAND)
    here = os.path.dirname(__file__)
    command = subprocess.Popen([sys.executable, str(script), here], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, text=True)  # fmt: skip
    try:
        pids = [int(pid) for pid in command.stdout.readline().split()]
        assert len(pids) == 2
        command.send_signal(stop)
        command.wait(30)
        deadline = time.monotonic() + 10.0
        while any(_alive(pid) for pid in pids) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert not [pid for pid in pids if _alive(pid)]
    finally:
        command.kill()
        command.wait()


def _alive(pid: int) -> bool:
    """Whether process ``pid`` runs (a zombie, ended and not yet reaped, does not)."""
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().rpartition(")")[2].split()[0] != "Z"
    except FileNotFoundError:
        return False


def test_helpers_that_cannot_start_leave_the_figures_to_the_caller(monkeypatch):
    import multiprocessing.context

    def no_room(process):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(multiprocessing.context.ForkServerProcess, "start", no_room)
    with render.drawing_helper():  # its end stops helpers that never started
        pngs = render.render_pngs([_Blank(), _Blank()])
        assert all(h.failed and h.process is None for h in render._helpers)
    assert pngs == [render._png(_Blank(), render.DPI)] * 2


KILLED_AT_ONCE = """
import os, signal
from jointwear.figures import render

if __name__ == "__main__":
    with render.drawing_helper():  # the fork server starts importing matplotlib
        os.kill(os.getpid(), signal.SIGKILL)
"""


def test_the_fork_server_does_not_outlive_a_command_killed_while_it_imports(tmp_path):
    script = tmp_path / "killed.py"
    script.write_text(KILLED_AT_ONCE)
    command = subprocess.Popen([sys.executable, str(script)], start_new_session=True)
    command.wait(60)
    deadline = time.monotonic() + 1.0  # the imports take a second or two
    while _session(command.pid) and time.monotonic() < deadline:
        time.sleep(0.02)
    left = _session(command.pid)
    for pid in left:
        os.kill(pid, signal.SIGKILL)
    assert not left


def _session(session: int) -> list[int]:
    """The running (not zombie) processes of a session."""
    pids = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as stat:
                    fields = stat.read().rpartition(")")[2].split()
            except OSError:
                continue
            if int(fields[3]) == session and fields[0] != "Z":
                pids.append(int(entry))
    return pids
