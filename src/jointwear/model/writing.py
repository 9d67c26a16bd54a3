"""A model's tables written as a TOML model file (``Model.to_toml``).

tomlkit writes the text: short arrays stay on one line (``position = [0.2, 0.0]``), arrays of
tables are ``[[bodies]]`` sections, and floats are written at full precision, so the file
reads back to the same numbers. TOML has no null: keys not given are left out beforehand.
"""

import tomlkit

from .._version import __version__

FIRST_KEYS = ("name", "type")  # what a reader looks for first in a table

HEADER = (
    "# Written by jointwear {version} (Model.to_toml). Every value is in SI units (m, kg, s,\n"
    "# rad, N, Pa and their products); every setting is written, defaults too.\n\n"
)


def model_toml(data: dict) -> str:
    """The TOML text of a model's tables (SI values, no None), behind a header comment."""
    return HEADER.format(version=__version__) + tomlkit.dumps(_name_first(data))


def _name_first(value: object) -> object:
    """``value`` with each table's name and type first, then its keys in their order."""
    if isinstance(value, dict):
        keys = [key for key in FIRST_KEYS if key in value]
        keys += [key for key in value if key not in FIRST_KEYS]
        return {key: _name_first(value[key]) for key in keys}
    if isinstance(value, list):
        return [_name_first(item) for item in value]
    return value
