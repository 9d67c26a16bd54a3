"""What the commands share: the consoles, the print style, the model argument and --set.

Nothing here imports the library: each command imports what it needs when it runs, so that
``jointwear --help`` starts at once.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console

if TYPE_CHECKING:
    from ..model import ModelError

err = Console(stderr=True)
out = Console()
PLAIN = {"soft_wrap": True, "markup": False, "highlight": False}  # text as written

ModelPath = Annotated[Path, typer.Argument(help="TOML model file.", show_default=False)]
Overrides = Annotated[
    list[str] | None,
    typer.Option("--set", help="Override a model value: dotted.path=value (repeatable)."),
]


def fail(error: ModelError) -> typer.Exit:
    """Print a ``ModelError``'s problems on stderr, one per line; the exit (code 2) to raise."""
    for line in error.problems:
        err.print(one_line(line), **PLAIN)
    return typer.Exit(code=2)


def one_line(text: str) -> str:
    """``text`` with control characters (a newline in a name) shown as escapes: one line."""
    return "".join(
        char if char.isprintable() or char == " " else char.encode("unicode_escape").decode()
        for char in text
    )
