"""Files jointwear writes: whole or not at all, only its own, never through a link.

The rule, for every command:

- Writes go only inside the output folder the user named (``--out``), into files and
  subfolders jointwear creates there. A symbolic link inside that folder is never followed:
  a write or removal through one is refused.
- Each folder jointwear writes to keeps a record of the files it wrote there, with each
  one's size and modification time as written (``.jointwear-files``). A file is replaced or
  removed only if that record names it and it is unchanged since (or jointwear was writing
  it when it stopped); a file of the user's, one the user changed, or one an older version
  wrote without a record, is left as it is.
  Commands check the files they will write before any work (``claim``), so a run is refused
  at once rather than after hours.
- Every file is written whole or not at all (:func:`write_atomic`): a reader (a person, a
  resumed run, a sweep skipping finished cases) never finds half a file.
"""

from __future__ import annotations

import json
import os
import secrets
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import IO

from .model.errors import ModelError

RECORD = ".jointwear-files"  # in each folder jointwear writes: the names of its files there


class ForeignFileError(OSError):
    """A write or removal that the rule refuses: a link, or a file jointwear did not write."""


def owned(path: str | os.PathLike) -> bool:
    """Whether jointwear wrote ``path`` and nobody changed it since (not a link either)."""
    target = Path(path)
    if target.is_symlink():
        return False
    record = _record(target.parent)
    # None: jointwear was writing it when it stopped (a crash, a kill): its own, half done
    return target.name in record and record[target.name] in (None, _fingerprint(target))


def claim(folder: str | os.PathLike, names: Iterable[str]) -> None:
    """Refuse, before any work, to write ``names`` (paths relative to ``folder``).

    A name ending in ``/`` is a folder jointwear writes into.

    Raises
    ------
    ModelError
        Naming every one that exists and is a link, a file jointwear did not write, or not a
        folder where one is wanted, and every folder on the way that is a link.
    """
    root = Path(folder)
    problems = []
    for name in names:
        path = root / name
        for part in reversed(path.relative_to(root).parents[:-1]):
            if (root / part).is_symlink():
                problems.append(_link_problem(root / part))
        if path.is_symlink():
            problems.append(_link_problem(path))
        elif name.endswith("/"):
            if path.exists() and not path.is_dir():
                problems.append(f"out: {path} exists and is not a folder; move it away")
        elif path.exists() and not owned(path):
            problems.append(
                f"out: {path} exists and was not written by jointwear, or was changed since "
                f"(see {path.parent / RECORD}); move it away or choose another --out"
            )
    if problems:
        raise ModelError(list(dict.fromkeys(problems)))


def make_folder(folder: str | os.PathLike) -> Path:
    """Create ``folder`` (and its parents) for writing; a link there is refused.

    Raises
    ------
    ForeignFileError
        If ``folder`` is a symbolic link.
    """
    path = Path(folder)
    if path.is_symlink():
        raise ForeignFileError(_link_problem(path))
    path.mkdir(parents=True, exist_ok=True)
    return path


def write_atomic(path: str | os.PathLike, write: Callable[[Path], object]) -> Path:
    """Write ``path`` whole or not at all, and record it as jointwear's.

    Parameters
    ----------
    path
        The file to write (its folder must exist). An existing file is replaced only if
        jointwear wrote it; a link or another file raises ``ForeignFileError``.
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
    _check_writable(target)
    _add_to_record(target, writing=True)
    temporary = target.with_name(f"{target.name}.{secrets.token_hex(4)}.tmp")
    try:
        write(temporary)
        os.chmod(temporary, 0o644)  # results are for others to read too
        os.replace(temporary, target)
    finally:
        temporary.unlink(missing_ok=True)
    _add_to_record(target)
    return target


def append(path: str | os.PathLike, write: Callable[[IO[str]], object]) -> None:
    """Append to a text file jointwear wrote: ``write`` gets it open at its end."""
    target = Path(path)
    _check_writable(target)
    _add_to_record(target, writing=True)
    with open(target, "a", newline="") as file:
        write(file)
    _add_to_record(target)


def write_text(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` to ``path`` whole or not at all (:func:`write_atomic`)."""
    return write_atomic(path, lambda temporary: temporary.write_text(text))


def remove(path: str | os.PathLike) -> None:
    """Remove ``path`` if jointwear wrote it and it is unchanged; anything else is left alone."""
    target = Path(path)
    if owned(target):
        target.unlink(missing_ok=True)
        names = _record(target.parent)
        names.pop(target.name, None)
        _write_record(target.parent, names)


def remove_folder(folder: str | os.PathLike) -> None:
    """Remove jointwear's files in ``folder``, then the folder if nothing else is left."""
    path = Path(folder)
    if path.is_symlink() or not path.is_dir():
        return
    for name in _record(path):
        remove(path / name)
    record = path / RECORD
    if not record.is_symlink() and not _record(path):
        record.unlink(missing_ok=True)
    if not any(path.iterdir()):
        path.rmdir()


def check_folder(folder: str | os.PathLike) -> None:
    """Refuse, before any work, an output folder that cannot be created or written.

    Raises
    ------
    ModelError
        If ``folder``, or the nearest of its parents that exists, is not a folder, or if the
        folder cannot be created or a file cannot be written in it (permissions, a name too
        long, a read-only file system).
    """
    path = Path(folder)
    try:
        existing = next(p for p in (path, *path.parents) if p.exists())
        if not existing.is_dir():
            raise ModelError([f"out: {existing} exists and is not a folder; give a folder path"])
        missing = [p for p in (path, *path.parents) if p != existing and existing in p.parents]
        path.mkdir(parents=True, exist_ok=True)
        try:
            probe = path / f".jointwear-probe-{secrets.token_hex(4)}"
            probe.write_bytes(b"")
            probe.unlink()
        finally:
            for created in missing:  # deepest first: the run creates them again when it writes
                created.rmdir()
    except OSError as error:
        raise ModelError([f"out: cannot write in {path}: {error.strerror or error}"]) from None


def _link_problem(path: Path) -> str:
    return f"out: {path} is a symbolic link; jointwear does not write through links"


def _check_writable(target: Path) -> None:
    if target.is_symlink() or target.parent.is_symlink():
        raise ForeignFileError(_link_problem(target if target.is_symlink() else target.parent))
    if target.exists() and not owned(target):
        raise ForeignFileError(
            f"out: {target} was not written by jointwear, or was changed since; it is left as it is"
        )


def _fingerprint(path: Path) -> list[int] | None:
    """Size [bytes] and modification time [ns] of a file, or None if there is none."""
    try:
        stat = path.stat()
    except (OSError, ValueError):
        return None
    return [stat.st_size, stat.st_mtime_ns]


def _record(folder: Path) -> dict[str, list[int] | None]:
    record = folder / RECORD
    if record.is_symlink() or not record.is_file():
        return {}
    try:
        names = json.loads(record.read_text())
    except (OSError, ValueError):
        return {}
    if not isinstance(names, dict):
        return {}
    return {
        name: written
        for name, written in names.items()
        if written is None or (isinstance(written, list) and len(written) == 2)
    }


def _add_to_record(target: Path, writing: bool = False) -> None:
    """Record ``target`` as jointwear's: being written (no fingerprint yet), or as it is now."""
    names = _record(target.parent)
    names[target.name] = None if writing else _fingerprint(target)
    _write_record(target.parent, names)


def _write_record(folder: Path, names: dict[str, list[int] | None]) -> None:
    """Replace the record at once."""
    record = folder / RECORD
    if record.is_symlink():
        raise ForeignFileError(_link_problem(record))
    temporary = folder / f"{RECORD}.{secrets.token_hex(4)}.tmp"
    try:
        temporary.write_text(json.dumps(names, indent=0, sort_keys=True))
        os.chmod(temporary, 0o644)
        os.replace(temporary, record)
    finally:
        temporary.unlink(missing_ok=True)
