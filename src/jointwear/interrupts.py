"""Ctrl-C and SIGTERM as a request checked at safe points, not an exception mid-write."""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager


@contextmanager
def stop_requests() -> Iterator[list[bool]]:
    """Within the block, SIGINT and SIGTERM set ``flag[0]`` instead of stopping the process.

    Only the main thread can install handlers; elsewhere the flag simply stays False.
    """
    flag = [False]
    if threading.current_thread() is not threading.main_thread():
        yield flag
        return

    def request_stop(signum: int, frame: object) -> None:
        flag[0] = True

    previous = {s: signal.signal(s, request_stop) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        yield flag
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
