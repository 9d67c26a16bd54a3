"""Reading model files: TOML text, and files that extend another model file.

A file with ``extends = "other.toml"`` (a path relative to the file) is that model with the
keys listed in its ``unset`` array removed, then the values under its ``[set]`` table
changed, each dotted key addressing one value as in ``jointwear run --set`` (array items by
name). Beside them it may give its own ``name`` and ``description``; the name defaults to
the file's stem.

Removal is a list of paths of its own, not a special value under ``[set]``: TOML has no
null, and any string or table given there could be a value some key takes.

A table function's ``file`` is named relative to the file that names it.

A results folder stands for the model it was run with: its ``model.json``, which every run
writes (the resolved model, values in SI).
"""

import json
import re
import tomllib
from pathlib import Path

from .errors import TOO_DEEP, TOO_LONG, ModelError
from .overrides import REMOVE, apply_changes
from .table_files import resolve_files

EXTENDING_KEYS = ("extends", "unset", "set", "name", "description")
MAX_FILE_BYTES = 10**7  # a model file larger than this is not one
MAX_KEY_DEPTH = 200  # dotted parts in one key: far more than a model has
SAVED_MODEL = "model.json"  # in a results folder: the model it was run with


def read_model_data(path: Path) -> dict:
    """The model's tables from the TOML file at `path`, with its ``extends`` resolved.

    `path` may also be a results folder: the tables are then its ``model.json``.

    Raises
    ------
    ModelError
        If a file cannot be read or is not valid TOML, or an extending file is malformed or
        extends itself through a chain of files; if a folder has no readable model.json.
    """
    path = Path(path)
    if path.is_dir():
        return read_saved_model(path)
    return _resolve(path, ())


def read_saved_model(folder: Path) -> dict:
    """The tables of the model a results folder was run with (its ``model.json``).

    Raises
    ------
    ModelError
        If the folder has no ``model.json``, or it cannot be read as a JSON table.
    """
    path = folder / SAVED_MODEL
    if not path.is_file():
        raise ModelError(
            [
                f"{folder}: not a file, nor a results folder (no {SAVED_MODEL} in it); give a "
                "TOML model file or the folder of a run"
            ]
        )
    damaged = "the folder is damaged: give the model file, or run it again"
    try:
        if path.stat().st_size > MAX_FILE_BYTES:
            raise ModelError([f"{path}: larger than {MAX_FILE_BYTES // 10**6} MB; {damaged}"])
        data = json.loads(path.read_bytes().decode())
    except OSError as error:
        raise ModelError([f"{path}: cannot read the file; {error.strerror}"]) from None
    except UnicodeDecodeError:
        raise ModelError([f"{path}: not UTF-8 text; {damaged}"]) from None
    except RecursionError:
        raise ModelError([f"{path}: {TOO_DEEP}"]) from None
    except ValueError as error:  # invalid JSON, or a number of thousands of digits
        reason = " ".join(str(error).split())[:200]
        raise ModelError([f"{path}: not valid JSON ({reason}); {damaged}"]) from None
    if not isinstance(data, dict):
        raise ModelError([f"{path}: not a JSON table of a model; {damaged}"])
    return data


def _resolve(path: Path, chain: tuple[Path, ...]) -> dict:
    data = resolve_files(_read_toml(path), path.parent)
    if "extends" not in data:
        for key in ("unset", "set"):
            if key in data:
                raise ModelError([f"{path}: {key}: only a file with 'extends' may change values"])
        return data
    base = data["extends"]
    if not isinstance(base, str) or not base or "\x00" in base:
        raise ModelError([f"{path}: extends: expected the path of a model file, as a string"])
    extra = [key for key in data if key not in EXTENDING_KEYS]
    if extra:
        raise ModelError(
            [
                f"{path}: {key}: a file that extends another may only give "
                f"{', '.join(EXTENDING_KEYS)}; change values under [set], remove keys with unset"
                for key in extra
            ]
        )
    changes = data.get("set", {})
    if not isinstance(changes, dict):
        raise ModelError([f"{path}: set: expected a table of values to change"])
    removals = _removals(path, data.get("unset", []), changes)
    here = path.resolve()
    base_path = path.parent / base
    if base_path.resolve() in (*chain, here):
        files = " -> ".join(str(p) for p in (*chain, here, base_path.resolve()))
        raise ModelError([f"{path}: extends: the files extend each other in a loop: {files}"])
    try:
        resolved = _resolve(base_path, (*chain, here))
    except ModelError as error:
        raise ModelError([f"{path}: extends {base!r}: {line}" for line in error.problems]) from None
    leaves = [_file_beside(path.parent, key, value) for key, value in _leaves(changes, ())]
    resolved = apply_changes(resolved, [*removals, *leaves])
    resolved["name"] = data.get("name", path.stem)
    if "description" in data:
        resolved["description"] = data["description"]
    return resolved


def _removals(path: Path, unset: object, changes: dict) -> list[tuple[str, None]]:
    """The changes that remove the keys an ``unset`` array lists."""
    example = 'e.g. unset = ["joints.pin.clearance.wear_coefficient"], above [set]'
    if "unset" in changes:  # written below the [set] header, TOML reads it as set.unset
        raise ModelError([f"{path}: set.unset: write the unset array above [set] ({example})"])
    if not isinstance(unset, list) or not all(
        isinstance(item, str) and all(item.split(".")) for item in unset
    ):
        raise ModelError([f"{path}: unset: expected an array of dotted paths ({example})"])
    return [(item, REMOVE) for item in unset]


def _leaves(table: dict, prefix: tuple[str, ...]) -> list[tuple[str, object]]:
    """The (dotted path, value) of every value in a nested table; tables are walked into."""
    out: list[tuple[str, object]] = []
    for key, value in table.items():
        if isinstance(value, dict) and value:
            out += _leaves(value, (*prefix, key))
        else:
            out.append((".".join((*prefix, key)), value))
    return out


def _file_beside(folder: Path, key: str, value: object) -> tuple[str, object]:
    """A change of a table function's ``file``, named relative to ``folder``."""
    if key.rpartition(".")[2] == "file" and isinstance(value, str):
        return key, str(folder / Path(value).expanduser())
    return key, value


def _read_toml(path: Path) -> dict:
    try:
        if path.exists() and not path.is_file():
            raise ModelError([f"{path}: not a file; give the path of a TOML model file"])
        if path.stat().st_size > MAX_FILE_BYTES:
            raise ModelError(
                [f"{path}: larger than {MAX_FILE_BYTES // 10**6} MB; a model file is a few kB"]
            )
        text = path.read_bytes().decode()
        if too_deep(text):  # tomllib takes minutes over such keys
            raise ModelError([f"{path}: {TOO_DEEP}"])
        return tomllib.loads(text)
    except OSError as error:
        raise ModelError([f"{path}: cannot read the file; {error.strerror}"]) from None
    except UnicodeDecodeError:
        raise ModelError([f"{path}: not UTF-8 text; a model file is TOML"]) from None
    except RecursionError:
        raise ModelError([f"{path}: {TOO_DEEP}"]) from None
    except tomllib.TOMLDecodeError as error:
        where = re.fullmatch(r"(.*) \(at line (\d+), column (\d+)\)", str(error))
        place, what = (f"{path}:{where[2]}:{where[3]}", where[1]) if where else (path, error)
        raise ModelError([f"{place}: invalid TOML: {what}; fix the syntax there"]) from None
    except ValueError:  # a number of thousands of digits
        raise ModelError([f"{path}: {TOO_LONG}"]) from None


def too_deep(text: str) -> bool:
    """Whether a TOML text has a key of more than ``MAX_KEY_DEPTH`` dotted parts.

    Counts the dots left of an ``=`` on each line: an upper bound on a key's depth.
    """
    depth = max((line.partition("=")[0].count(".") for line in text.splitlines()), default=0)
    return depth > MAX_KEY_DEPTH
