"""Command-line interface: thin wrappers over ``run``, ``load_model`` and the plots.

Exit codes: 0 success, 1 the run ended without reaching its end time (interrupted or a
solver failure; the results folder holds what was computed), 2 invalid input (one line per
problem on stderr, no traceback), 3 results that could not be written where asked (the
message says where they are), 130 interrupted outside a run (before it started, or after
its results were saved).

Help texts are plain text: ``rich_markup_mode=None`` keeps typer from reading them as rich
markup, which took "[s]" in "End time [s]." for a style and dropped it.
"""

from typing import Annotated

import typer

from .._version import __version__
from .citation_commands import citations
from .export_commands import export
from .run_commands import check, plot, run
from .sample_commands import sample
from .study_commands import life, sweep

HELP = (
    "Simulate planar mechanisms whose joints have clearance: the contact, friction and "
    "lubricant forces in the joints, and how their surfaces wear (after Flores 2009).\n\n"
    "Run a TOML model file, check it, sweep its parameters, sample its tolerances or predict "
    "its wear over millions of cycles. 'jointwear COMMAND --help' describes a command."
)

app = typer.Typer(no_args_is_help=True, help=HELP, rich_markup_mode=None)
for function in (run, check, plot, sweep, sample, life, citations, export):
    app.command()(function)


def _print_version(asked: bool) -> None:
    if asked:
        typer.echo(f"jointwear {__version__}")
        raise typer.Exit


@app.callback()
def _options(
    version: Annotated[
        bool,
        typer.Option(
            "--version", callback=_print_version, is_eager=True, help="Print the version and exit."
        ),
    ] = False,
) -> None:
    """The options before a command: --version, and shell completion."""
