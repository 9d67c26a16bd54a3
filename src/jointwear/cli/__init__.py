"""Command-line interface: thin wrappers over ``run``, ``load_model`` and the plots.

Exit codes: 0 success, 1 the run ended without reaching its end time (interrupted or a
solver failure; the results folder holds what was computed), 2 invalid input (one line per
problem on stderr, no traceback), 3 results that could not be written where asked (the
message says where they are), 130 interrupted outside a run (before it started, or after
its results were saved).
"""

import typer

from .run_commands import check, plot, run
from .study_commands import life, sweep

app = typer.Typer(add_completion=False, no_args_is_help=True, help=__doc__.splitlines()[0])
for command in (run, check, plot, sweep, life):
    app.command()(command)
