"""Files written whole or not at all, and the folders they go in.

Every file jointwear writes that a reader (a person, a resumed run, a sweep skipping finished
cases) might find half-written goes through :func:`write_atomic`.
"""

from __future__ import annotations

import os
import secrets
from collections.abc import Callable
from pathlib import Path

from .model.errors import ModelError


def write_atomic(path: str | os.PathLike, write: Callable[[Path], object]) -> Path:
    """Write ``path`` whole or not at all: a reader never sees half a file.

    Parameters
    ----------
    path
        The file to write (its folder must exist); an existing file is replaced.
    write
        Called with a temporary path in the same folder, which it creates and fills. Once it
        returns, the temporary file replaces ``path`` in one step (``os.replace``); if it
        raises, the temporary file is removed and ``path`` is left as it was.

    Returns
    -------
    Path
        ``path``.
    """
    target = Path(path)
    temporary = target.with_name(f"{target.name}.{secrets.token_hex(4)}.tmp")
    try:
        write(temporary)
        os.replace(temporary, target)
    finally:
        temporary.unlink(missing_ok=True)
    return target


def write_text(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` to ``path`` whole or not at all (:func:`write_atomic`)."""
    return write_atomic(path, lambda temporary: temporary.write_text(text))


def check_folder(folder: str | os.PathLike) -> None:
    """Refuse, before any work, an output path that cannot become a folder.

    Raises
    ------
    ModelError
        If ``folder``, or the nearest of its parents that exists, is not a folder.
    """
    path = Path(folder)
    existing = next(p for p in (path, *path.parents) if p.exists())
    if not existing.is_dir():
        raise ModelError([f"out: {existing} exists and is not a folder; give a folder path"])
