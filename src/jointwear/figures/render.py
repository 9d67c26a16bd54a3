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

1. A drawing that does not pickle, a helper that dies or cannot start: that figure is drawn
   in the caller's process.
2. A helper that has not answered a drawing within ``PATIENCE``: it is killed, one line on
   stderr says so, and the figures left are drawn in the caller's process.
3. The command ends, however (return, exception, any signal, SIGKILL included): a helper,
   drawing or not, reads the end of a pipe that only the command holds open, and exits. The
   block's end closes it too, and kills a helper that has not left within ``GOODBYE``.
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
PATIENCE = 120.0  # [s] the longest a helper may take over one drawing (a figure takes ~0.5 s)
GOODBYE = 1.0  # [s] the longest the block's end waits for a helper to leave before a kill
PRELOAD = f"{__package__}.helper_imports"  # the fork server imports it before it forks
COMMAND_VARIABLE = "JOINTWEAR_FIGURES_FOR"  # the fork server's command (helper_imports)
HANDOVER = "figure handover"  # the name of the threads that hand drawings to the helpers

Answer = bytes | BaseException  # a PNG, or what the drawing raised


class _Helper:
    """One helper process and the caller's end of its pipe; started at its first drawing."""

    def __init__(self, context: multiprocessing.context.BaseContext) -> None:
        self.context = context
        self.lock = threading.Lock()  # one drawing at a time on the pipe
        self.process: multiprocessing.process.BaseProcess | None = None
        self.pipe: Connection | None = None
        self.lifeline: Connection | None = None  # never written: its end tells the helper
        self.failed = False  # could not start, died or was given up: draw here

    def draw(self, message: bytes, deadline: float) -> Answer | None:
        """Send one pickled (drawing, dpi) and return the answer; None if it was not drawn.

        ``deadline`` as ``time.monotonic()``: a helper that has not answered by then is
        killed and reported.
        """
        if self.failed or not self._started():
            return None
        assert self.pipe is not None
        try:
            self.pipe.send_bytes(message)
            if self.pipe.poll(max(0.0, deadline - time.monotonic())):
                return pickle.loads(self.pipe.recv_bytes())
        except (EOFError, OSError, pickle.UnpicklingError):  # it died (killed)
            self.failed = True
            return None
        _say(
            f"a figure helper did not answer within {PATIENCE:.0f} s; "
            "drawing the remaining figures in this process"
        )
        self.stop(at_once=True)
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
            self.failed = True
            return False
        self.process = process
        return True

    def stop(self, at_once: bool = False) -> None:
        """Ask the helper to leave; kill it if it has not within ``GOODBYE`` (or at once).

        Called with ``lock`` held, or ``at_once`` (a drawing may be under way).
        """
        self.failed = True
        if self.lifeline is not None:
            self.lifeline.close()  # the helper exits, drawing or not
        if self.pipe is not None and not at_once:
            self.pipe.close()
        if self.process is not None:
            self.process.join(0.0 if at_once else GOODBYE)
            if self.process.is_alive():
                self.process.kill()  # the thread waiting on its pipe then reads its end
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
    with _signals_ignored_by_children(), _command_known_to_children():
        multiprocessing.forkserver.ensure_running()  # returns at once; the server imports
    helpers = [_Helper(context) for _ in range(HELPERS)]
    _helpers = helpers
    try:
        yield
    finally:
        _helpers = []
        for helper in helpers:
            idle = helper.lock.acquire(blocking=False)  # else a drawing is under way: the
            helper.stop(at_once=not idle)  # block ends early (an exception, an interrupt)
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
    pickled; an exception it raises there is raised by the call as it was. A figure no helper
    drew (none, or as the module docstring says) the call draws itself.
    """
    tasks: queue.SimpleQueue[tuple[int, Callable[[], Figure]]] = queue.SimpleQueue()
    for task in enumerate(drawings):
        tasks.put(task)
    answers: dict[int, Answer] = {}
    threads = [
        threading.Thread(
            target=_hand_over, args=(helper, tasks, dpi, answers), name=HANDOVER, daemon=True
        )
        for helper in _helpers
    ]
    for thread in threads:
        thread.start()

    def wait() -> list[bytes]:
        for thread in threads:  # each is bounded: PATIENCE per drawing it sent
            thread.join()
        images = []
        for i, draw in enumerate(drawings):
            answer = answers.get(i)
            if isinstance(answer, BaseException):
                raise answer
            images.append(answer if answer is not None else _png(draw, dpi))
        return images

    return wait


def _hand_over(
    helper: _Helper,
    tasks: queue.SimpleQueue[tuple[int, Callable[[], Figure]]],
    dpi: int,
    answers: dict[int, Answer],
) -> None:
    """Give ``helper`` drawings from ``tasks`` one at a time, its answers into ``answers``.

    Stops when the tasks are done or the helper failed; what it leaves is drawn by the caller.
    """
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
            answer = helper.draw(message, time.monotonic() + PATIENCE)
        if answer is not None:
            answers[i] = answer


def _serve(pipe: Connection, lifeline: Connection) -> None:
    """A helper: draw each (drawing, dpi) that comes through ``pipe``.

    It ends when ``pipe`` or ``lifeline`` ends: the caller closed it, or is gone.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C reaches the command; it decides
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # SIGTERM ends a helper quietly
    os.nice(HELPER_NICENESS)
    threading.Thread(target=_leave_with, args=(lifeline,), daemon=True).start()
    import_module(PRELOAD)  # imported by the fork server already, unless another user of it
    while True:  # started it first
        try:
            message = pipe.recv_bytes()
        except (EOFError, OSError):  # the caller closed its end or is gone
            return
        try:
            answer: Answer = _png(*pickle.loads(message))
        except Exception as error:  # raised again by the caller
            answer = error
        try:
            reply = pickle.dumps(answer, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # an exception that does not pickle
            reply = pickle.dumps(RuntimeError(f"{type(answer).__name__}: {answer}"))
        try:
            pipe.send_bytes(reply)
        except OSError:
            return


def _leave_with(lifeline: Connection) -> None:
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
