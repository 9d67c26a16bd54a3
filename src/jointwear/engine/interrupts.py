"""Ctrl-C and SIGTERM as a request checked at safe points, not an exception mid-write."""

from __future__ import annotations

import os
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager

_open: tuple[int, list[bool]] | None = None  # (process id, flag) of the outermost open block
_cut_short = False  # an interrupt raised inside an interruptible block (see cut_short)
REDELIVERY_DELAY_S = 0.01  # a lost interrupt is sent again this long after [s]


@contextmanager
def stop_requests() -> Iterator[list[bool]]:
    """Within the block, SIGINT and SIGTERM set ``flag[0]`` instead of stopping the process.

    Blocks nest: an inner block (a run inside a life run or a sweep) shares the outer one's
    flag, so a request that the inner block's code did not act on (it arrived as a run was
    ending) still reaches the outer loop. A forked child opens its own. Only the main
    thread can install handlers; elsewhere the flag simply stays False.
    """
    global _open
    if _open is not None and _open[0] == os.getpid():
        yield _open[1]
        return
    flag = [False]
    if threading.current_thread() is not threading.main_thread():
        yield flag
        return

    def request_stop(signum: int, frame: object) -> None:
        flag[0] = True

    previous = {s: signal.signal(s, request_stop) for s in (signal.SIGINT, signal.SIGTERM)}
    _open = (os.getpid(), flag)
    try:
        yield flag
    finally:
        _open = None
        for s, handler in previous.items():
            signal.signal(s, handler)


@contextmanager
def interruptible() -> Iterator[None]:
    """Within the block, SIGINT and SIGTERM raise ``KeyboardInterrupt`` at once.

    Even inside an open ``stop_requests`` block, whose flag they also set (the loops around
    it stop too): for work that loses nothing when cut short (a run's set-up and compiling).
    A request already made raises on entry. An error the interrupt caused inside a library
    (numba loading its cache) comes out as the ``KeyboardInterrupt`` it was.
    """
    outer = _open[1] if _open is not None and _open[0] == os.getpid() else None
    if outer is not None and outer[0]:
        raise KeyboardInterrupt
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    hit = [False]

    def interrupt(signum: int, frame: object) -> None:
        global _cut_short
        hit[0] = _cut_short = True
        if outer is not None:
            outer[0] = True
        raise KeyboardInterrupt

    previous = {s: signal.signal(s, interrupt) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield
    except Exception as error:
        if hit[0]:
            raise KeyboardInterrupt from error
        raise
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        if hit[0]:  # objects the interrupt left half-built complain as they go: the process
            sys.unraisablehook = _quiet  # is ending on the interrupt, and says so once


def _quiet(unraisable: object) -> None:
    """An ``sys.unraisablehook`` that says nothing."""


def redeliver_lost_interrupts() -> None:
    """From now on, an interrupt raised where Python cannot pass it on is delivered again.

    A signal handler that raises ``KeyboardInterrupt`` while native code is calling back into
    Python (numba's compiler writing its cache through a ctypes callback) has its exception
    printed as "ignored" and lost: the process would go on as if never interrupted. Under
    this ``sys.unraisablehook`` such an interrupt is sent again as a SIGINT instead, a moment
    later, which Python then handles in ordinary code; any other unraisable exception is
    printed as usual.
    """
    sys.unraisablehook = _redeliver


def _redeliver(unraisable: sys.UnraisableHookArgs) -> None:
    if unraisable.exc_type is not None and issubclass(unraisable.exc_type, KeyboardInterrupt):
        # Raised here, the signal's handler would run inside this hook, and its
        # KeyboardInterrupt, escaping the hook, would be lost again: a helper thread sends it
        # once the hook has returned, so that it reaches the main thread in ordinary code.
        resend = threading.Timer(REDELIVERY_DELAY_S, os.kill, (os.getpid(), signal.SIGINT))
        resend.daemon = True
        resend.start()
        return
    sys.__unraisablehook__(unraisable)


def cut_short() -> bool:
    """Whether an interrupt was raised inside an ``interruptible`` block of this process.

    The block may have been in a library's work (numba loading or compiling kernels) whose
    native objects it left half-built; freeing them as the interpreter shuts down can crash
    it (a double free, SIGABRT), so the command line ends such a process without that.
    """
    return _cut_short
