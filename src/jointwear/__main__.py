"""``python -m jointwear`` runs the command-line interface."""

from .cli.command import main

main()
