"""The set-up's long native calls on a worker thread, so that Ctrl-C and SIGTERM get through.

Python runs a signal handler on the main thread between bytecodes: through a long call into
LAPACK or SuperLU (a factorisation of a large mechanism) an interrupt would wait for it to
return (``engine.interrupts`` turns it into ``KeyboardInterrupt``). Those release the GIL, so
``off_main_thread`` runs such work on a daemon thread while the main thread waits on a lock,
which a signal interrupts at once.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TypeVar

T = TypeVar("T")


def off_main_thread(work: Callable[[], T]) -> T:
    """``work()`` on a worker thread while the main thread waits, answering signals.

    An exception of a signal handler (``KeyboardInterrupt``) comes out here at once; the
    work, abandoned, ends on its own or with the process. Off the main thread, ``work()`` is
    simply called.
    """
    if threading.current_thread() is not threading.main_thread():
        return work()
    outcome: list = []
    done = threading.Event()

    def run() -> None:
        try:
            outcome.append((True, work()))
        except BaseException as error:  # re-raised on the main thread
            outcome.append((False, error))
        finally:
            done.set()

    threading.Thread(target=run, name="jointwear-set-up", daemon=True).start()
    done.wait()
    finished, value = outcome[0]
    if not finished:
        raise value
    return value
