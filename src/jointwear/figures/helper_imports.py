"""What the drawing helpers need, imported once by their fork server (``render.py``).

The helpers are forked from the server with these modules in memory. Their objects are set
apart from the garbage collector (``gc.freeze``): they live as long as the processes, and
collecting them would slow the drawing and each process's exit (about 0.4 s of it).

The server notices that its command has ended only after these imports (a second or two):
should the command end during them (an interrupt, a kill), a watcher ends the server at once.
"""

import gc
import os
import threading

from .render import COMMAND_VARIABLE

WATCH_INTERVAL = 0.05  # [s] how often the watcher looks for the command


def _exit_if_orphaned(command: int, imported: threading.Event) -> None:
    """End this process at once if it is no longer the child of ``command`` (which ended)."""
    while not imported.wait(WATCH_INTERVAL):
        if os.getppid() != command:
            os._exit(0)


_imported = threading.Event()
_command = os.environ.get(COMMAND_VARIABLE, "")  # without it, the parent (if not gone already)
_watched = int(_command) if _command.isdigit() else os.getppid()
_watcher = threading.Thread(target=_exit_if_orphaned, args=(_watched, _imported), daemon=True)
_watcher.start()

from importlib import import_module  # noqa: E402

from ..joints import KINDS  # noqa: E402
from . import run  # noqa: E402, F401  (the plotting modules a Drawing names)

for _kind in KINDS:
    import_module(_kind.figures_module)

_imported.set()
_watcher.join()  # no thread is left when the server forks the helpers
gc.freeze()
