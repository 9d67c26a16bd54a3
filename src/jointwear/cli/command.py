"""The ``jointwear`` executable: the command-line app, with signals and surprises as one line.

Ctrl-C and SIGTERM are alike everywhere: inside a run they are requests the run acts on at a
safe point (``interrupts``); anywhere else (imports, validation) the process ends at once with
one line and exit code 130. An error that escapes a command is a bug: it is reported in one
line with exit code 70, and ``JOINTWEAR_DEBUG=1`` shows its traceback.
"""

from __future__ import annotations

import contextlib
import gc
import os
import signal
import sys

INTERRUPTED = 130  # 128 + SIGINT, the shells' convention
INTERNAL_ERROR = 70  # EX_SOFTWARE (sysexits.h)
DEBUG_VARIABLE = "JOINTWEAR_DEBUG"


def _interrupt(signum: int, frame: object) -> None:
    raise KeyboardInterrupt


def main(argv: list[str] | None = None) -> None:
    """Run the command line ``argv`` (default ``sys.argv[1:]``) and exit with its code."""
    from ..engine.interrupts import cut_short, redeliver_lost_interrupts

    signal.signal(signal.SIGTERM, _interrupt)
    redeliver_lost_interrupts()
    try:
        code = _run(argv)
    except SystemExit as exit_request:  # typer ends every command this way
        code = exit_request.code
        if code == INTERRUPTED and _caused_by_interrupt(exit_request, shown_only=True):
            _say("interrupted")  # typer turns one that no command caught into exit 130, mute
    except KeyboardInterrupt:
        _say("interrupted")
        code = INTERRUPTED
    if cut_short() or code == INTERRUPTED:  # the interpreter's clean-up could crash on what
        _flush()  # the interrupt left half-built, or end the process on the interrupt again
        os._exit(code if isinstance(code, int) else 1 if code else 0)
    gc.freeze()  # the interpreter's last collections of what is about to go: ~0.5 s of numba's
    sys.exit(code)  # and pandas' objects after a run


def _flush() -> None:
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):
            stream.flush()


def _run(argv: list[str] | None) -> int:
    from . import app  # inside main's try: a Ctrl-C during these imports is an interrupt

    try:  # typer handles usage errors (exit 2), typer.Exit and Ctrl-C (exit 130) itself
        app(args=argv, prog_name="jointwear")
    except RecursionError:
        _say("error: the input is nested too deeply to read (a model, --set, --vary or sweep file)")
        return 2
    except Exception as error:  # the last net: one line, never a traceback
        if _caused_by_interrupt(error):  # Python wrapped it (a class built during an import)
            raise KeyboardInterrupt from error
        if os.environ.get(DEBUG_VARIABLE):
            raise
        _say(
            f"internal error (a bug in jointwear; please report it with the command): "
            f"{type(error).__name__}: {_one_line(str(error))}; {DEBUG_VARIABLE}=1 shows the "
            "traceback"
        )
        return INTERNAL_ERROR
    return 0


def _caused_by_interrupt(error: BaseException, shown_only: bool = False) -> bool:
    """Whether a KeyboardInterrupt is among the causes or contexts of ``error``.

    ``shown_only``: only those Python would show, leaving out a context suppressed by
    ``raise ... from None`` (as the commands do when they have said why they stop).
    """
    seen: set[int] = set()
    link: BaseException | None = error
    while link is not None and id(link) not in seen:
        if isinstance(link, KeyboardInterrupt):
            return True
        seen.add(id(link))
        hidden = shown_only and link.__suppress_context__
        link = link.__cause__ or (None if hidden else link.__context__)
    return False


def _one_line(text: str) -> str:
    return " ".join(text.split())


def _say(text: str) -> None:
    with contextlib.suppress(OSError):  # stderr closed: nothing more to do
        print(text, file=sys.stderr, flush=True)
