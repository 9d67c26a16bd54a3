"""The model file: its schema, units, overrides and error messages.

A validated :class:`Model` holds plain SI floats (tuples for vectors) and names; every
user-input problem is reported as a :class:`ModelError` with one line per problem.
"""

from .errors import ModelError
from .schema import Model, load_model, parse_model

__all__ = ["Model", "ModelError", "load_model", "parse_model"]
