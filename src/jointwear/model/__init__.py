"""The model file: its schema, units, overrides and error messages.

A validated :class:`Model` holds plain SI floats (tuples for vectors) and names; every
user-input problem is reported as a :class:`ModelError` with one line per problem.

The names below import their module on first use (PEP 562), so the joint types
(``jointwear.joints``), whose tables the schema's joints are, can import the parts of the
schema they build on (``model.tables``, ``model.clearance``) before the schema itself.
"""

from importlib import import_module
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .errors import ModelError
    from .schema import Model, load_model, parse_model

_PUBLIC = {"Model": ".schema", "ModelError": ".errors", "load_model": ".schema",
           "parse_model": ".schema"}  # fmt: skip
__all__ = ["Model", "ModelError", "load_model", "parse_model"]


def __getattr__(name: str) -> object:
    """Import a public name on first use."""
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(_PUBLIC[name], __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_PUBLIC})
