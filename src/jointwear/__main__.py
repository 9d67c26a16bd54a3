"""``python -m jointwear`` runs the command-line interface."""

from .cli import app

app()
