"""Dotted ``path=value`` overrides of a model's data, as given to ``jointwear run --set``."""

import copy
import tomllib
from collections.abc import Iterable

from .errors import TOO_DEEP, TOO_LONG, ModelError, did_you_mean


def apply_overrides(data: dict, overrides: Iterable[str]) -> dict:
    """Return a copy of `data` with ``dotted.path=value`` overrides applied.

    Array items are addressed by ``name`` or by index; the value is read as a TOML value,
    or else taken as a string. Missing tables on the way are created; the schema judges them.

    Raises
    ------
    ModelError
        If an override is malformed or its path runs through a missing array item or a value.
    """
    return apply_changes(data, parse_overrides(overrides))


def parse_overrides(overrides: Iterable[str]) -> list[tuple[str, object]]:
    """The ``(dotted.path, value)`` pairs that ``dotted.path=value`` texts stand for."""
    changes = []
    for override in overrides:
        dotted, equals, text = override.partition("=")
        if not equals or not all(dotted.strip().split(".")):
            raise ModelError([f"--set {override}: expected path=value, e.g. solver.t_end=0.5"])
        changes.append((dotted.strip(), toml_value(text)))
    return changes


def apply_changes(data: dict, changes: Iterable[tuple[str, object]]) -> dict:
    """Return a copy of `data` with each ``(dotted.path, value)`` set, as ``apply_overrides``."""
    data = copy.deepcopy(data)
    for dotted, value in changes:
        keys = dotted.split(".")
        container = data
        for depth, key in enumerate(keys[:-1]):
            where = ".".join(keys[: depth + 1])
            if isinstance(container, dict):
                container = container.setdefault(key, {})
            else:
                container = container[_index(container, key, where)]
        _assign(container, keys[-1], value, dotted)
    return data


def _assign(container: object, key: str, value: object, where: str) -> None:
    if isinstance(container, dict):
        container[key] = value
    else:
        container[_index(container, key, where)] = value


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
