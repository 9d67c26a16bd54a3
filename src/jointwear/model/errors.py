"""``ModelError``: pydantic's validation errors as one line per problem, and name checks.

Every line reads ``<field path>: <what was wrong>; <what is allowed>``, where the path uses
the model file's own keys and ``[i]`` for array items, e.g.
``joints[2].bodies[1]: unknown body 'coupler2'; bodies are ground, crank, coupler (did you
mean 'coupler'?)``.
"""

import difflib
import re
from collections.abc import Iterable, Sequence

from pydantic import BaseModel, ValidationError

TOO_DEEP = "nested too deeply to read (arrays or tables within each other); flatten it"
TOO_LONG = "a number has too many digits to read; write it with an exponent (e.g. 1e30)"

# Tag of the plain-quantity member in the "quantity or function table" unions of the schema.
SCALAR_TAG = "quantity"


class ModelError(Exception):
    """A model has problems; ``problems`` holds one line per problem."""

    def __init__(self, problems: Sequence[str]):
        super().__init__(list(problems))
        self.problems = list(problems)

    def __str__(self) -> str:
        return "\n".join(self.problems)


def did_you_mean(word: object, choices: Iterable[str]) -> str:
    """Return `` (did you mean 'x'?)`` for the closest choice, or an empty string."""
    close = difflib.get_close_matches(str(word), list(choices), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def unknown(what: str, word: object, choices: Sequence[str], plural: str) -> str:
    """Describe an unknown name: ``unknown body 'x'; bodies are a, b (did you mean 'a'?)``."""
    if not choices:
        return f"unknown {what} {word!r}; there are no {plural}"
    hint = did_you_mean(word, choices)
    return f"unknown {what} {word!r}; {plural} are {', '.join(choices)}{hint}"


def from_validation_error(error: ValidationError, data: object, root: str = "model") -> ModelError:
    """Rewrite a pydantic ``ValidationError`` raised while validating `data`.

    ``root`` names `data` itself in a line about the whole of it.
    """
    items = error.errors(include_url=False)
    return ModelError([_line(item, data, root) for item in items if not _follows_from_items(item)])


def _follows_from_items(item: dict) -> bool:
    # pydantic also reports an array as too short when some of its items are invalid
    given = item.get("input")
    return (
        item["type"] == "too_short"
        and isinstance(given, list | tuple)
        and len(given) >= item["ctx"]["min_length"]
    )


_BOUNDS = {  # pydantic's bound errors: the sign, and the key of the bound in the context
    "greater_than": (">", "gt"),
    "greater_than_equal": (">=", "ge"),
    "less_than": ("<", "lt"),
    "less_than_equal": ("<=", "le"),
}


def _line(item: dict, data: object, root: str) -> str:
    path = toml_path(data, item["loc"])
    kind, ctx = item["type"], item.get("ctx", {})
    given = _show(item.get("input"))
    if kind == "missing":
        message = "missing required key"
    elif kind == "union_tag_not_found":
        path, message = f"{path}.type", "missing required key"
    elif kind == "union_tag_invalid":
        types = [t for t in re.findall(r"'([^']*)'", ctx["expected_tags"]) if t != SCALAR_TAG]
        path, message = f"{path}.type", unknown("type", ctx["tag"], types, "types")
    elif kind == "value_error":
        message = item["msg"].removeprefix("Value error, ")
    elif kind == "model_type" and isinstance(item.get("input"), BaseModel):
        built = type(item["input"]).__name__
        message = f"got a {built}; expected a {ctx['class_name']} (or a table of its keys)"
    elif kind in ("model_type", "dict_type", "model_attributes_type"):
        message = f"got {given}; expected a table"
    elif kind in ("tuple_type", "list_type"):
        message = f"got {given}; expected an array"
    elif kind in ("too_short", "too_long"):
        limit = "at least {min_length}" if kind == "too_short" else "at most {max_length}"
        message = f"has {len(item['input'])} items; expected {limit.format(**ctx)}"
    elif kind in _BOUNDS:
        sign, key = _BOUNDS[kind]
        message = f"got {given}; must be {sign} {ctx[key]:g}"
    elif kind == "literal_error":
        message = f"got {given}; expected {ctx['expected']}"
    else:
        message = f"got {given}; {item['msg'][0].lower()}{item['msg'][1:]}"
    return f"{path or root}: {message}"


def toml_path(data: object, loc: Sequence[str | int]) -> str:
    """Turn a pydantic error location into a path such as ``forces[1].force[0]``.

    The location is walked through the input data, so that the tags pydantic inserts for
    discriminated unions (the table's ``type``, or ``SCALAR_TAG``) are left out. Tables built
    in Python are walked as the dicts of their values.
    """
    path, current, tagged = "", data, False
    for key in loc:
        if isinstance(current, BaseModel):
            current = dict(current)
        if isinstance(key, int) and isinstance(current, list | tuple):
            path += f"[{key}]"
            current = current[key] if -len(current) <= key < len(current) else None
        elif isinstance(current, dict) and not tagged and current.get("type") == key:
            tagged = True  # a table's tag comes once, before its keys
            continue
        elif isinstance(current, dict) or current is None:
            path += f".{key}" if path else str(key)
            current = current.get(key) if isinstance(current, dict) else None
        tagged = False
    return path


def _show(value: object, width: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= width else text[: width - 3] + "..."
