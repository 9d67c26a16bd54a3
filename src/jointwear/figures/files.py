"""Saving a figure under the file rule of ``jointwear.io``."""

from __future__ import annotations

from pathlib import Path

from matplotlib.figure import Figure

from ..io import make_folder, write_atomic


def save_png(figure: Figure, path: Path, dpi: int = 150) -> Path:
    """Write ``figure`` to ``path`` as PNG, whole or not at all; return the path."""
    make_folder(path.parent)
    return write_atomic(path, lambda temporary: figure.savefig(temporary, format="png", dpi=dpi))
