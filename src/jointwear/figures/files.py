"""Saving figures under the file rule of ``jointwear.io``."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from ..io import make_folder, write_atomic
from .render import DPI, PNG_COMPRESSION, render_pngs

if TYPE_CHECKING:
    from matplotlib.figure import Figure

Drawings = Mapping[str, Callable[[], "Figure"]]  # file name without .png -> draws that figure


def save_png(figure: Figure, path: Path, dpi: int = DPI) -> Path:
    """Write ``figure`` to ``path`` as PNG, whole or not at all; return the path."""
    make_folder(path.parent)
    options = {"format": "png", "dpi": dpi, "pil_kwargs": {"compress_level": PNG_COMPRESSION}}
    return write_atomic(path, lambda temporary: figure.savefig(temporary, **options))


def save_pngs(drawings: Drawings, folder: Path, dpi: int = DPI) -> list[Path]:
    """Draw each figure (side by side where possible) and write it as ``folder/<name>.png``.

    Returns the paths written. Nothing is written unless every figure could be drawn (and no
    folder made for none).
    """
    images = render_pngs(list(drawings.values()), dpi)
    return write_pngs(dict(zip(drawings, images, strict=True)), folder)


def write_pngs(images: Mapping[str, bytes], folder: Path) -> list[Path]:
    """Write each PNG image as ``folder/<name>.png``; return the paths (no folder for none)."""
    if not images:
        return []
    make_folder(folder)
    return [
        write_atomic(folder / f"{name}.png", partial(Path.write_bytes, data=image))
        for name, image in images.items()
    ]
