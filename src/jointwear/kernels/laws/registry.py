"""The record that describes one law of a family (normal force, friction, wear).

A family's module holds its law functions and one table, a tuple of ``Law`` records in code
order: ``FAMILY[code].name`` is the law's name in the model file. The model schema reads the
keys (what to accept, with which unit and bounds), ``pack`` turns the validated keys into the
parameters the kernel reads, and ``jointwear check`` prints ``summary``. The kernels see
only the code and the packed parameters.
"""

from typing import NamedTuple


class Key(NamedTuple):
    """A model-file key that a law reads.

    ``unit`` is a pint unit string of the SI unit ("" for a plain number); ``default`` None
    means the law cannot do without it (unless ``pack`` accepts an alternative); ``low`` and
    ``high`` bound the value, ``low`` exclusive when ``positive``.
    """

    name: str
    unit: str
    default: float | None
    low: float | None = 0.0
    positive: bool = False
    high: float | None = None
    help: str = ""


class Law(NamedTuple):
    """One law of a family: its name, code, keys, parameter packing and summary line."""

    name: str
    code: int
    keys: tuple[Key, ...]
    pack: object  # (values: dict[str, float | None]) -> tuple[float, ...]; ValueError if not
    summary: str  # one line for ``jointwear check``: what the law computes, with a citation


def by_name(family: tuple[Law, ...]) -> dict[str, Law]:
    """The family's laws by name."""
    return {law.name: law for law in family}


def family_keys(family: tuple[Law, ...]) -> dict[str, Key]:
    """Every key that some law of the family reads, by name (the first law's definition)."""
    keys: dict[str, Key] = {}
    for law in family:
        for key in law.keys:
            keys.setdefault(key.name, key)
    return keys


def pack_in_order(*keys: Key) -> object:
    """A ``pack`` that returns the keys' values in order, each required."""

    def pack(values: dict) -> tuple[float, ...]:
        missing = [k.name + (f" ({k.help})" if k.help else "") for k in keys
                   if values.get(k.name) is None]  # fmt: skip
        if missing:
            raise ValueError(f"needs {' and '.join(missing)}")
        return tuple(float(values[k.name]) for k in keys)

    return pack
