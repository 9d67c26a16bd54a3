"""Figures to PNG bytes, drawn by helper processes on the machine's other cores.

Drawing is matplotlib's layout and text work, a few tenths of a second per figure, so a run's
seven or eight figures take seconds one after another. ``drawing_helper`` starts a fork server
(``multiprocessing``'s "forkserver": a fresh Python process, so the run's threads make no
fork unsafe) that imports matplotlib and the plotting modules once, while the run computes.
``start_pngs`` then forks two helpers from it, which draw the figures side by side while the
caller goes on. Writing the files stays with the caller, so the file rule of ``jointwear.io``
holds in one process.
"""

from __future__ import annotations

import multiprocessing
import multiprocessing.forkserver
import os
import signal
import threading
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from importlib import import_module
from io import BytesIO
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.figure import Figure

DPI = 150  # resolution of the PNGs [dots per inch]
STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM}
HELPERS = min(2, os.cpu_count() or 1)  # processes that draw (the caller waits meanwhile)
HELPER_NICENESS = 5  # added to the helpers' niceness: the run they wait for comes first
PNG_COMPRESSION = 1  # zlib level of the PNGs: level 6 (the default) takes 20% of the drawing
PRELOAD = f"{__package__}.helper_imports"  # the fork server imports it before it forks

_helper: ProcessPoolExecutor | None = None  # the open drawing_helper's processes


@contextmanager
def drawing_helper(wanted: bool = True) -> Iterator[None]:
    """Within the block, helper processes draw the figures; their fork server starts now.

    Nothing is started unless ``wanted``, in the main thread, on a POSIX machine with two
    cores or more. The helpers never act on Ctrl-C or SIGTERM (this process does, as
    ``jointwear.interrupts`` says), and end with the block; the fork server, idle, with this
    process. For the command line: a helper imports the ``__main__`` module of a script not
    guarded by ``if __name__ == "__main__"``.
    """
    global _helper
    main = threading.current_thread() is threading.main_thread()  # signals are set there only
    posix = hasattr(signal, "pthread_sigmask")
    if not (wanted and main and posix) or _helper is not None or (os.cpu_count() or 1) < 2:
        yield
        return
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload([PRELOAD])
    with _signals_ignored_by_children():  # the helpers inherit the server's dispositions
        multiprocessing.forkserver.ensure_running()  # returns at once; the server imports
    helper = ProcessPoolExecutor(HELPERS, mp_context=context, initializer=_prepare_helper)
    _helper = helper
    try:
        yield
    finally:
        _helper = None
        # Waits for the helpers to leave (drawings under way end first): an executor still
        # closing as the interpreter exits can make its exit hook write to a closed pipe.
        helper.shutdown(wait=True, cancel_futures=True)


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


def render_pngs(drawings: Sequence[Callable[[], Figure]], dpi: int = DPI) -> list[bytes]:
    """Call each drawing and return its figure as PNG bytes, in the order given.

    Within ``drawing_helper``, the helper processes draw them (``start_pngs``).
    """
    return start_pngs(drawings, dpi)()


def start_pngs(
    drawings: Sequence[Callable[[], Figure]], dpi: int = DPI
) -> Callable[[], list[bytes]]:
    """Hand the drawings to the helper processes; the call returned waits for the PNGs.

    A thread hands them over, so the caller goes on at once even while the helpers' fork
    server is still importing (the helpers are forked at the first drawing). The call returns
    each figure as PNG bytes, in the order given. Each drawing reaches a helper pickled; an
    exception it raises there is raised by the call as it was. Without helpers, or if they are
    gone (killed), the call draws the figures itself.
    """
    sent: dict[int, Future[bytes]] = {}
    handover = threading.Thread(target=_hand_over, args=(_helper, drawings, dpi, sent), daemon=True)
    handover.start()

    def wait() -> list[bytes]:
        handover.join()
        images = {i: _png(draw, dpi) for i, draw in enumerate(drawings) if i not in sent}
        for i, future in sent.items():
            try:
                images[i] = future.result()
            except BrokenProcessPool:
                images[i] = _png(drawings[i], dpi)
        return [images[i] for i in range(len(drawings))]

    return wait


def _hand_over(
    helper: ProcessPoolExecutor | None,
    drawings: Sequence[Callable[[], Figure]],
    dpi: int,
    sent: dict[int, Future[bytes]],
) -> None:
    """Submit each drawing to ``helper`` into ``sent`` by index; stop at a broken or shut pool."""
    if helper is None:
        return
    try:
        for i, draw in enumerate(drawings):
            sent[i] = helper.submit(_png, draw, dpi)
    except (BrokenProcessPool, RuntimeError):  # gone (killed) or shut: the rest drawn here
        pass


def _png(draw: Callable[[], Figure], dpi: int) -> bytes:
    buffer = BytesIO()
    draw().savefig(buffer, format="png", dpi=dpi, pil_kwargs={"compress_level": PNG_COMPRESSION})
    return buffer.getvalue()


def _prepare_helper() -> None:
    """In a helper: ignore stop signals, yield the CPU to the run, and have what drawing needs.

    The fork server has imported ``helper_imports`` (unless another user of the server
    started it first; then the helper imports it now).
    """
    for stop in STOP_SIGNALS:
        signal.signal(stop, signal.SIG_IGN)
    os.nice(HELPER_NICENESS)
    import_module(PRELOAD)
