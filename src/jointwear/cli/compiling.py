"""Notice of numba compiling the kernels, so that a cache miss does not look like a hang.

numba compiles a kernel on a cache miss: on the first run after an install, an upgrade or a
kernel edit, and for a type signature not compiled before (the step loop is specialised to
the run's integrator and formulation). It then takes seconds before the first step.
"""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from numba.core import event
from numba.core.registry import CPUDispatcher

Report = Callable[[int, int], None]  # (functions compiled so far, functions expected)


def kernel_count() -> int:
    """Compiled functions the loaded kernel modules define: the expected number to compile."""
    prefix = __package__ + ".kernels"
    return sum(
        isinstance(value, CPUDispatcher) and value.py_func.__module__ == name
        for name, module in list(sys.modules.items())
        if name.startswith(prefix) and module is not None
        for value in vars(module).values()
    )


class _Counter(event.Listener):
    """Counts the functions numba compiles (cache misses only) and reports each one done."""

    def __init__(self, on_start: Callable[[], None], report: Report) -> None:
        self.on_first_start, self.report = on_start, report
        self.started = self.done = self.expected = 0

    def on_start(self, ev: event.Event) -> None:
        if self.started == 0:
            self.expected = kernel_count()  # the kernel modules are loaded by now
            self.on_first_start()
        self.started += 1

    def on_end(self, ev: event.Event) -> None:
        self.done += 1
        self.report(self.done, max(self.expected, self.done))


@contextmanager
def compile_notice(on_start: Callable[[], None], report: Report) -> Iterator[None]:
    """Call ``on_start()`` when numba first compiles inside the block, and ``report`` after."""
    with event.install_listener("numba:compile", _Counter(on_start, report)):
        yield
