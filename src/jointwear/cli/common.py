"""What the commands share: consoles, print style, model argument, --set, --t-end, tables.

Nothing here imports the library: each command imports what it needs when it runs, so that
``jointwear --help`` starts at once.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.cells import cell_len
from rich.console import Console
from rich.table import Table
from rich.text import Text

if TYPE_CHECKING:
    from ..joints import ClearanceKind
    from ..model import ModelError

err = Console(stderr=True)
out = Console()
PLAIN = {"soft_wrap": True, "markup": False, "highlight": False}  # text as written

ModelPath = Annotated[
    Path,
    typer.Argument(
        help="TOML model file, or a results folder (the model.json it was run with).",
        show_default=False,
    ),
]
Overrides = Annotated[
    list[str] | None,
    typer.Option(
        "--set",
        help="Override a model value: dotted.path=value; dotted.path= removes the key "
        "(repeatable).",
    ),
]
Animation = Annotated[
    bool,
    typer.Option(
        "--animation/--no-animation",
        help="Also write the mechanism's animation, figures/mechanism.gif (seconds more).",
    ),
]
EndTime = Annotated[
    str | None,
    typer.Option(
        "--t-end",
        help="End time: seconds, or with a unit as --set takes them ('50 ms').",
        metavar="TIME",
        show_default=False,
    ),
]
T_END = "solver.t_end"  # the model value --t-end sets


def end_time(overrides: list[str] | None, t_end: str | None) -> list[str]:
    """The --set values with --t-end's last (so it wins), read as --set reads its values.

    An empty --t-end is an empty text, refused as a time, not the removal of the key that
    ``solver.t_end=`` would be.
    """
    if t_end is None:
        return [*(overrides or [])]
    text = t_end if t_end.strip() else '""'  # TOML's empty string
    return [*(overrides or []), f"{T_END}={text}"]


def fail(error: ModelError, options: dict[str, str] | None = None) -> typer.Exit:
    """Print a ``ModelError``'s problems on stderr, one per line; the exit (code 2) to raise.

    ``options`` maps a model value to the option that set it (``{"solver.t_end":
    "--t-end"}``): a problem with that value is told as one with the option.
    """
    for line in error.problems:
        for path, option in (options or {}).items():
            if line.startswith(f"{path}:"):
                line = f"{option}{line.removeprefix(path)}"
        err.print(one_line(line), **PLAIN)
    return typer.Exit(code=2)


def number(value: float) -> str:
    """A number as the tables show it: 6 significant digits, and an exponent where needed."""
    return format(value, ".6g")


def keep_whole(table: Table, *numbers: int) -> Table:
    """Make ``table`` never cut the cells of its columns ``numbers``; let all text fold.

    Rich fits a table to the terminal by cutting its cells with an ellipsis: 1.22465e-17 in a
    narrow column showed as "1.224…", which reads as 1.224. Each column of numbers gets a
    fixed width, that of its widest cell (or header word), which rich never narrows; text
    (headers, names) folds onto more lines instead. ``print_table`` widens what still does
    not fit. A cell of several lines is as wide as its widest.
    """
    for index, column in enumerate(table.columns):
        column.overflow = "fold"
        if index in numbers:
            words = [line for cell in column.cells for line in _plain(cell).splitlines()]
            column.width = max(cell_len(word) for word in [*words, *_plain(column.header).split()])
    return table


def _plain(cell: object) -> str:
    return Text.from_markup(cell).plain if isinstance(cell, str) else str(cell)


def print_table(table: Table, console: Console = out) -> None:
    """Print ``table``, wider than the terminal where it cannot fit without cutting cells.

    A terminal too narrow for the columns ``keep_whole`` keeps whole wraps the table's lines
    itself; that is untidy, but no number is cut short.
    """
    needed = console.measure(table, options=console.options.update_width(10_000)).minimum
    if needed > console.width:
        table.width = needed
    console.print(table, crop=False)


def one_line(text: str) -> str:
    """``text`` with control characters (a newline in a name) shown as escapes: one line."""
    return "".join(
        char if char.isprintable() or char == " " else char.encode("unicode_escape").decode()
        for char in text
    )


def joint_kind(joint: dict) -> ClearanceKind:
    """The joint type of a clearance joint's summary (an older one's: the first kind)."""
    from ..joints import BY_NAME, KINDS

    return BY_NAME[joint.get("type", KINDS[0].name)]
