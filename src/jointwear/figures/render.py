"""Figures to PNG bytes, drawn by helper processes on the machine's other cores.

Drawing is matplotlib's layout and text work, a few tenths of a second per figure, so a run's
seven or eight figures take seconds one after another. ``drawing_helper`` starts a fork server
(``multiprocessing``'s "forkserver": a fresh Python process, so the run's threads make no
fork unsafe) that imports matplotlib and the plotting modules once, while the run computes.
``start_pngs`` then forks up to two helpers from it, each with a pipe of its own; a thread
per helper hands it one drawing at a time and takes back the PNG, while the caller goes on.
Writing the files stays with the caller, so the file rule of ``jointwear.io`` holds in one
process.

What can go wrong, and what then happens:

1. A drawing that does not pickle or that fails in a helper, a helper that dies or cannot
   start, no fork server: that figure is drawn in the caller's process (where a drawing
   that fails raises its own exception).
2. Helpers that have not drawn a batch within ``PATIENCE`` of the caller asking for it
   (stuck, or a fork server that does not answer): they are killed, one line on stderr says
   so, and the figures left are drawn in the caller's process.
3. The command ends, however (return, exception, any signal, SIGKILL included): a helper,
   drawing or not, reads the end of a pipe that only the command holds open, and exits. The
   block's end closes it too, and kills a helper that has not left within ``GOODBYE``.

A fork server killed from outside is started again by ``multiprocessing`` at the next
helper's start, from a handing-over thread: without the block's signal dispositions, so a
Ctrl-C during its imports prints its traceback.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.forkserver
import os
import pickle
import queue
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager, suppress
from importlib import import_module
from io import BytesIO
from multiprocessing.connection import Connection
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.figure import Figure

DPI = 150  # resolution of the PNGs [dots per inch]
STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM}
HELPERS = min(2, os.cpu_count() or 1)  # processes that draw (the caller waits meanwhile)
HELPER_NICENESS = 5  # added to the helpers' niceness: the run they wait for comes first
PNG_COMPRESSION = 1  # zlib level of the PNGs: level 6 (the default) takes 20% of the drawing
PATIENCE = 120.0  # [s] the longest the caller waits for the helpers (a figure takes ~0.5 s)
GOODBYE = 1.0  # [s] the longest the block's end waits for a helper to leave before a kill
PRELOAD = f"{__package__}.helper_imports"  # the fork server imports it before it forks
COMMAND_VARIABLE = "JOINTWEAR_FIGURES_FOR"  # the fork server's command (helper_imports)
HANDOVER = "figure handover"  # the name of the threads that hand drawings to the helpers


class _Helper:
    """One helper process and the caller's end of its pipes; started at its first drawing."""

    def __init__(self, context: multiprocessing.context.BaseContext) -> None:
        self.context = context
        self.lock = threading.Lock()  # one drawing at a time on the pipe
        self.process: multiprocessing.process.BaseProcess | None = None
        self.pipe: Connection | None = None
        self.lifeline: Connection | None = None  # never written: its end tells the helper
        self.failed = False  # could not start, died or was given up: draw here

    def draw(self, message: bytes, patience: float) -> bytes | None:
        """Send one pickled (drawing, dpi); return the PNG, or None if it was not drawn.

        Called with ``lock`` held. A helper that has not answered within ``patience`` [s]
        is given up, and said.
        """
        if self.failed or not self._started():
            return None
        assert self.pipe is not None
        try:
            self.pipe.send_bytes(message)
            if self.pipe.poll(patience):
                return pickle.loads(self.pipe.recv_bytes())
            _say(
                f"a figure helper did not answer within {patience:.0f} s; "
                "drawing the remaining figures in this process"
            )
        except Exception:  # it died, was killed or given up: its pipe is closed or broken
            pass
        self.stop(idle=True)
        return None

    def _started(self) -> bool:
        if self.process is not None:
            return True
        try:
            self.pipe, theirs = self.context.Pipe()
            lifeline, self.lifeline = self.context.Pipe(duplex=False)
            try:  # forked by the server: born with its dispositions (stop signals ignored)
                process = self.context.Process(target=_serve, args=(theirs, lifeline), daemon=True)
                process.start()
            finally:
                theirs.close()
                lifeline.close()
        except Exception:  # no fork server (killed, gone), no file descriptors, no memory, ...
            self.stop(idle=True)
            return False
        self.process = process
        return True

    def let_go(self) -> None:
        """Tell the helper to leave at once, drawing or not (it exits)."""
        self.failed = True
        if self.lifeline is not None:
            self.lifeline.close()

    def stop(self, idle: bool) -> None:
        """Let go of the helper and wait up to ``GOODBYE`` for it to leave, then kill it.

        ``idle``: with ``lock`` held, so the pipe is closed too; else a thread drawing with
        the helper closes it when the helper is gone.
        """
        self.let_go()
        if idle and self.pipe is not None:
            self.pipe.close()
        if self.process is not None:
            self.process.join(GOODBYE)
            if self.process.is_alive():
                self.process.kill()
                self.process.join(GOODBYE)


_helpers: list[_Helper] = []  # the open drawing_helper's helpers


@contextmanager
def drawing_helper(wanted: bool = True) -> Iterator[None]:
    """Within the block, helper processes draw the figures; their fork server starts now.

    Nothing is started unless ``wanted``, in the main thread, on a POSIX machine with two
    cores or more. The helpers never act on Ctrl-C (this process does, as
    ``jointwear.interrupts`` says), and end with the block, or with this process however it
    ends; the fork server, idle, with this process. For the command line: a helper imports
    the ``__main__`` module of a script not guarded by ``if __name__ == "__main__"``.
    """
    global _helpers
    main = threading.current_thread() is threading.main_thread()  # signals are set there only
    posix = hasattr(signal, "pthread_sigmask")
    if not (wanted and main and posix) or _helpers or (os.cpu_count() or 1) < 2:
        yield
        return
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload([PRELOAD])
    try:
        with _signals_ignored_by_children(), _command_known_to_children():
            multiprocessing.forkserver.ensure_running()  # returns at once; the server imports
    except Exception:  # no process, no socket (a process limit, no temporary folder): draw here
        yield
        return
    helpers = [_Helper(context) for _ in range(HELPERS)]
    _helpers = helpers
    try:
        yield
    finally:
        _helpers = []
        for helper in helpers:  # all of them leave at once, then each is waited for
            helper.let_go()
        for helper in helpers:
            _stop(helper)


def _stop(helper: _Helper) -> None:
    """Stop ``helper`` at the block's end; a drawing may still be under way (an interrupt)."""
    idle = helper.lock.acquire(blocking=False)
    try:
        helper.stop(idle)
    finally:
        if idle:
            helper.lock.release()


@contextmanager
def _signals_ignored_by_children() -> Iterator[None]:
    """Processes started in the block ignore Ctrl-C and SIGTERM from birth; none is lost here.

    A child keeps an ignored disposition across ``exec``. The signals are blocked meanwhile,
    so one that arrives is kept pending (Linux does not discard a blocked signal on arrival,
    even while ignored) and delivered to this process's handlers when the block ends.
    """
    mask = signal.pthread_sigmask(signal.SIG_BLOCK, STOP_SIGNALS)
    handlers = {s: signal.signal(s, signal.SIG_IGN) for s in STOP_SIGNALS}
    try:
        yield
    finally:
        for s, handler in handlers.items():
            signal.signal(s, handler)
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)


@contextmanager
def _command_known_to_children() -> Iterator[None]:
    """Processes started in the block find this process's id in ``COMMAND_VARIABLE``."""
    before = os.environ.get(COMMAND_VARIABLE)
    os.environ[COMMAND_VARIABLE] = str(os.getpid())
    try:
        yield
    finally:
        if before is None:
            del os.environ[COMMAND_VARIABLE]
        else:
            os.environ[COMMAND_VARIABLE] = before


def render_pngs(drawings: Sequence[Callable[[], Figure]], dpi: int = DPI) -> list[bytes]:
    """Call each drawing and return its figure as PNG bytes, in the order given.

    Within ``drawing_helper``, the helper processes draw them (``start_pngs``).
    """
    return start_pngs(drawings, dpi)()


def start_pngs(
    drawings: Sequence[Callable[[], Figure]], dpi: int = DPI
) -> Callable[[], list[bytes]]:
    """Hand the drawings to the helper processes; the call returned waits for the PNGs.

    Threads hand them over, so the caller goes on at once even while the helpers' fork
    server is still importing (the helpers are forked at their first drawing). The call
    returns each figure as PNG bytes, in the order given. Each drawing reaches a helper
    pickled. A figure no helper drew (there are none, or as the module docstring says) the
    call draws itself, and raises what that drawing raises.
    """
    tasks: queue.SimpleQueue[tuple[int, Callable[[], Figure]]] = queue.SimpleQueue()
    for task in enumerate(drawings):
        tasks.put(task)
    pngs: dict[int, bytes] = {}
    helpers = list(_helpers)
    threads = [
        threading.Thread(
            target=_hand_over, args=(helper, tasks, dpi, pngs), name=HANDOVER, daemon=True
        )
        for helper in helpers
    ]
    for thread in threads:
        thread.start()

    def wait() -> list[bytes]:
        deadline = time.monotonic() + PATIENCE
        for thread in threads:
            thread.join(max(0.0, deadline - time.monotonic()))
        if any(thread.is_alive() for thread in threads):
            _say(
                f"the figure helpers did not finish within {PATIENCE:.0f} s; "
                "drawing the remaining figures in this process"
            )
            for helper in helpers:
                helper.let_go()  # a thread waiting on a helper then finds it gone
        drawn = dict(pngs)
        return [drawn[i] if i in drawn else _png(draw, dpi) for i, draw in enumerate(drawings)]

    return wait


def _hand_over(
    helper: _Helper,
    tasks: queue.SimpleQueue[tuple[int, Callable[[], Figure]]],
    dpi: int,
    pngs: dict[int, bytes],
) -> None:
    """Give ``helper`` drawings from ``tasks`` one at a time, its PNGs into ``pngs``.

    Stops when the tasks are done or the helper failed; what it leaves is drawn by the caller.
    Ctrl-C and SIGTERM are blocked here, so they reach the main thread: one delivered to this
    thread would not wake the caller waiting for it.
    """
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_BLOCK, STOP_SIGNALS)
    while not helper.failed:
        try:
            i, draw = tasks.get_nowait()
        except queue.Empty:
            return
        try:
            message = pickle.dumps((draw, dpi), protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # any pickling failure: the caller draws it
            continue
        with helper.lock:
            png = helper.draw(message, PATIENCE)
        if png is not None:
            pngs[i] = png


def _serve(pipe: Connection, lifeline: Connection) -> None:
    """A helper: draw each (drawing, dpi) that comes through ``pipe``; answer PNG or None.

    None for a drawing that fails here: the caller draws it again, and raises what it
    raises. The helper ends when ``pipe`` or ``lifeline`` ends: the caller closed it, or is
    gone.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the command; it decides
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # SIGTERM ends a helper quietly
    os.nice(HELPER_NICENESS)
    threading.Thread(target=_exit_when_closed, args=(lifeline,), daemon=True).start()
    import_module(PRELOAD)  # imported by the fork server already, unless another user of it
    while True:  # started it first
        try:
            message = pipe.recv_bytes()
        except (EOFError, OSError):  # the caller closed its end or is gone
            return
        try:
            png: bytes | None = _png(*pickle.loads(message))
        except Exception:  # drawn again by the caller, which raises what it raises
            png = None
        try:
            pipe.send_bytes(pickle.dumps(png, protocol=pickle.HIGHEST_PROTOCOL))
        except OSError:
            return


def _exit_when_closed(lifeline: Connection) -> None:
    """Wait for the end of ``lifeline`` (never written), then end this process at once."""
    with suppress(EOFError, OSError):
        lifeline.recv_bytes()
    os._exit(0)


def _png(draw: Callable[[], Figure], dpi: int) -> bytes:
    buffer = BytesIO()
    draw().savefig(buffer, format="png", dpi=dpi, pil_kwargs={"compress_level": PNG_COMPRESSION})
    return buffer.getvalue()


def _say(text: str) -> None:
    with suppress(OSError):  # stderr closed: nothing more to do
        print(f"jointwear: {text}", file=sys.stderr, flush=True)
