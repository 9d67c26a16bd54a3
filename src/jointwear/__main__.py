"""``python -m jointwear`` runs the command-line interface."""

from .command import main

main()
