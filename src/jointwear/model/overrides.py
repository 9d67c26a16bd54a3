"""Dotted ``path=value`` overrides of a model's data, as given to ``jointwear run --set``.

``path=`` with no value removes the key, so that its default applies or another key can
replace it; ``Model.with_values`` and an extending file's ``unset`` do the same.
"""

import copy
import tomllib
from collections.abc import Iterable

from .errors import TOO_DEEP, TOO_LONG, ModelError, did_you_mean

REMOVE = None  # the value of a change that removes its key: ``--set path=``, ``unset``


def apply_overrides(data: dict, overrides: Iterable[str]) -> dict:
    """Return a copy of `data` with ``dotted.path=value`` overrides applied.

    Array items are addressed by ``name`` or by index; the value is read as a TOML value,
    or else taken as a string. Missing tables on the way are created; the schema judges them.
    ``dotted.path=`` with nothing after ``=`` removes the key (or array item).

    Raises
    ------
    ModelError
        If an override is malformed, its path runs through a missing array item or a value,
        or it removes a key that is not there.
    """
    return apply_changes(data, parse_overrides(overrides))


def parse_overrides(overrides: Iterable[str]) -> list[tuple[str, object]]:
    """The ``(dotted.path, value)`` pairs that ``dotted.path=value`` texts stand for.

    The value of ``dotted.path=``, nothing after ``=``, is ``REMOVE``.
    """
    changes = []
    for override in overrides:
        dotted, equals, text = override.partition("=")
        if not equals or not all(dotted.strip().split(".")):
            raise ModelError([f"--set {override}: expected path=value, e.g. solver.t_end=0.5"])
        changes.append((dotted.strip(), toml_value(text) if text.strip() else REMOVE))
    return changes


def apply_changes(data: dict, changes: Iterable[tuple[str, object]]) -> dict:
    """Return a copy of `data` with each ``(dotted.path, value)`` set, as ``apply_overrides``.

    A value of ``REMOVE`` (None: TOML has no null, so no value read from a file is None)
    removes the key or array item at the path.
    """
    data = copy.deepcopy(data)
    for dotted, value in changes:
        keys = dotted.split(".")
        container = data
        for depth, key in enumerate(keys[:-1]):
            where = ".".join(keys[: depth + 1])
            if isinstance(container, dict):
                if value is REMOVE and key not in container:
                    raise ModelError([_not_there(container, key, where)])
                container = container.setdefault(key, {})
            else:
                container = container[_index(container, key, where)]
        if value is REMOVE:
            _remove(container, keys[-1], dotted)
        else:
            _assign(container, keys[-1], value, dotted)
    return data


def _assign(container: object, key: str, value: object, where: str) -> None:
    if isinstance(container, dict):
        container[key] = value
    else:
        container[_index(container, key, where)] = value


def _remove(container: object, key: str, where: str) -> None:
    if not isinstance(container, dict):
        del container[_index(container, key, where)]
    elif key in container:
        del container[key]
    else:
        raise ModelError([_not_there(container, key, where)])


def _not_there(table: dict, key: str, where: str) -> str:
    keys = [str(k) for k in table]
    there = f"the keys there are {', '.join(keys)}" if keys else "the table there is empty"
    return f"{where}: no key {key!r} to remove; {there}{did_you_mean(key, keys)}"


def _index(container: object, key: str, where: str) -> int:
    if not isinstance(container, list):
        parent = where.rpartition(".")[0]
        raise ModelError([f"{where}: {parent} is a value, not a table or an array"])
    if key.isascii() and key.isdigit() and int(key) < len(container):
        return int(key)
    names = [item.get("name") if isinstance(item, dict) else None for item in container]
    if key in names:
        return names.index(key)
    listing = [str(name) for name in names if name is not None]
    allowed = f"names are {', '.join(listing)}; " if listing else ""
    indices = f"indices 0 to {len(container) - 1}" if container else "the array is empty"
    raise ModelError([f"{where}: no item {key!r}; {allowed}{indices}{did_you_mean(key, listing)}"])


def toml_value(text: str) -> object:
    """The value a ``--set`` or ``--vary`` text stands for: a TOML value, or else the text."""
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text.strip()
    except RecursionError:
        raise ModelError([f"{text[:40]}...: {TOO_DEEP}"]) from None
    except ValueError:  # a number of thousands of digits
        raise ModelError([f"{text[:40]}...: {TOO_LONG}"]) from None
