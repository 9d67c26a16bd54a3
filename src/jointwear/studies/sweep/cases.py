"""The cases of a parameter study: ``--vary`` options and sweep files -> named sets of overrides.

A sweep varies model values addressed by the same dotted paths as ``--set``
(``joints.coupler_follower.clearance.friction_coefficient``); each path gets a list of values
written as ``--set`` would take them (``0.05``, ``"0.1 mm"``, ``abm``). The cases are the
Cartesian product of the lists, the first path varying slowest; linked paths (``--link``, a
sweep file's ``[link]``) step through their lists together, as one more axis of the product
(a crank speed with the load frequency it drives). Each case is named by its
varied values (``friction_coefficient=0.05__bearing_radius=10.1_mm``), a name that is stable
from one run of the same sweep to the next and safe as a folder name; where such names would
be long (many varied paths, long values) or alike but for letter case, every case is named by
its index instead (``case007``), its values in the study's table.
"""

from __future__ import annotations

import itertools
import json
import math
import os
import re
import tomllib
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from pydantic import BaseModel
from pydantic_core import to_jsonable_python

from ...model import Model
from ...model.errors import TOO_DEEP, TOO_LONG, ModelError, did_you_mean
from ...model.files import too_deep
from ...model.overrides import toml_value

VARY_EXAMPLE = "joints.coupler_follower.clearance.friction_coefficient=0.05,0.1"
SWEEP_FILE_KEYS = ("vary", "link", "set")
MAX_CASES = 10_000  # cases in one sweep: beyond this, a mistyped --vary rather than a plan
MAX_NAME_LENGTH = 64  # characters of a case name by values; longer: every case by its index
_UNSAFE = re.compile(r"[^A-Za-z0-9.+-]+")  # characters a case name does not keep


@dataclass(frozen=True)
class Plan:
    """What to vary and what to set, before the model is read.

    Attributes
    ----------
    vary
        Dotted path -> value texts, as ``--set`` takes them (``"0.1 mm"``, ``"0.05"``).
    overrides
        ``dotted.path=value`` settings common to every case.
    link
        Dotted path -> value texts, lists of one length, stepped through together.
    """

    vary: dict[str, list[str]]
    overrides: list[str]
    link: dict[str, list[str]] = field(default_factory=dict)


@dataclass(frozen=True)
class Case:
    """One case of a sweep: its name and the overrides that make it."""

    id: str
    values: dict[str, str]  # dotted path -> value text

    @property
    def overrides(self) -> list[str]:
        """The case's own ``path=value`` overrides (applied after the sweep's common ones)."""
        return [f"{path}={text}" for path, text in self.values.items()]


def parse_vary(options: Iterable[str], name: str = "--vary") -> dict[str, list[str]]:
    """Read ``--vary PATH=V1,V2,...`` options (or those of option ``name``, ``--link``).

    Commas inside brackets or quotes belong to their value, so arrays
    (``youngs_modulus=[2.07e11, 1.1e11],2.07e11``) and quoted strings can be varied too.

    Raises
    ------
    ModelError
        One line per malformed option or repeated path (``check_vary`` judges the values).
    """
    vary: dict[str, list[str]] = {}
    problems = []
    for option in options:
        path, equals, text = option.partition("=")
        path = path.strip()
        values = [value.strip() for value in split_values(text)]
        if not equals or not path or not all(path.split(".")) or not all(values):
            problems.append(f"{name} {option}: expected PATH=V1,V2,..., e.g. {VARY_EXAMPLE}")
        elif path in vary:
            problems.append(f"{name} {option}: {path} is varied twice; give its values once")
        else:
            vary[path] = values
    if problems:
        raise ModelError(problems)
    return vary


def split_values(text: str) -> list[str]:
    """Split at commas that are not inside brackets, braces or quotes."""
    values, start, depth, quote = [], 0, 0, ""
    for i, char in enumerate(text):
        if quote:
            quote = "" if char == quote else quote
        elif char in "\"'":
            quote = char
        elif char in "[{":
            depth += 1
        elif char in "]}":
            depth -= 1
        elif char == "," and depth == 0:
            values.append(text[start:i])
            start = i + 1
    return [*values, text[start:]]


def check_vary(vary: Mapping[str, Sequence[str]]) -> None:
    """Refuse an empty sweep, a path without values, and a value given twice for a path.

    Raises
    ------
    ModelError
        One line per problem.
    """
    if not vary:
        raise ModelError([f"--vary: nothing is varied; give e.g. --vary {VARY_EXAMPLE}"])
    problems = []
    for path, texts in vary.items():
        if isinstance(texts, str) or not isinstance(texts, Sequence) or not texts:
            problems.append(f"--vary {path}: expected a non-empty list of values")
            continue
        seen: dict[str, str] = {}
        for text in texts:
            key = json.dumps(toml_value(text), sort_keys=True)
            if key in seen:
                problems.append(
                    f"--vary {path}: value {text} repeats {seen[key]}; give each value once"
                )
            seen.setdefault(key, text)
    if problems:
        raise ModelError(problems)


def check_link(link: Mapping[str, Sequence[str]], vary: Mapping[str, Sequence[str]]) -> None:
    """Refuse linked lists of different lengths, and a path both linked and varied.

    Raises
    ------
    ModelError
        One line per problem.
    """
    problems = [
        f"--link {path}: also varied (--vary); give it in one place"
        for path in link
        if path in vary
    ]
    for path, texts in link.items():
        if isinstance(texts, str) or not isinstance(texts, Sequence) or not texts:
            problems.append(f"--link {path}: expected a non-empty list of values")
    lengths = {path: len(texts) for path, texts in link.items() if not isinstance(texts, str)}
    if len(set(lengths.values())) > 1:
        listed = ", ".join(f"{path} {n}" for path, n in lengths.items())
        problems.append(
            f"--link: linked paths step through their values together and need as many each; "
            f"got {listed}"
        )
    if len(link) == 1:
        problems.append(f"--link {next(iter(link))}: one path alone; use --vary, or link two")
    if problems:
        raise ModelError(problems)


def value_text(value: object) -> str:
    """Write a value as ``--set`` reads it: strings as given, anything else as TOML."""
    if isinstance(value, str):
        return value.strip()
    return _toml(value)


def _toml(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value)  # also inf and nan, which TOML spells the same
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # a TOML basic string
    if isinstance(value, Mapping):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_toml(v)}" for k, v in value.items()) + "}"
    if isinstance(value, Sequence):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    raise ModelError([f"{value!r}: cannot be a model value; give a number, string or array"])


def read_sweep_file(path: str | os.PathLike) -> Plan:
    """Read a sweep file: TOML with ``[vary]``, ``[link]`` and ``[set]`` tables.

    ``[vary]`` and ``[link]`` map dotted paths to lists of values (linked lists all of one
    length), ``[set]`` dotted paths to values; keys
    may be quoted (``"solver.t_end" = 0.02``) or nested tables (``[set.solver]``).

    Raises
    ------
    ModelError
        If the file cannot be read or is not of this form.
    """
    path = Path(path)
    data = read_toml_file(path, "sweep file")
    problems = [
        f"{path}: unknown key {key!r}; a sweep file has the tables vary, link and set"
        f"{did_you_mean(key, SWEEP_FILE_KEYS)}"
        for key in data
        if key not in SWEEP_FILE_KEYS
    ]
    vary, link = (_value_lists(data, table, path, problems) for table in ("vary", "link"))
    overrides = [f"{dotted}={_toml(value)}" for dotted, value in table_leaves(data.get("set", {}))]
    if problems:
        raise ModelError(problems)
    return Plan(vary=vary, overrides=overrides, link=link)


def read_toml_file(path: Path, what: str) -> dict:
    """The tables of a TOML file (a sweep or study file).

    Raises
    ------
    ModelError
        If it cannot be read, is not TOML, or is nested or long beyond reason.
    """
    try:
        text = path.read_bytes().decode()
        if too_deep(text):
            raise ModelError([f"{path}: {TOO_DEEP}"])
        return tomllib.loads(text)
    except OSError as error:
        raise ModelError([f"{path}: cannot read the {what}; {error.strerror}"]) from None
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise ModelError([f"{path}: not a TOML {what}; {error}"]) from None
    except RecursionError:
        raise ModelError([f"{path}: {TOO_DEEP}"]) from None
    except ValueError:  # a number of thousands of digits
        raise ModelError([f"{path}: {TOO_LONG}"]) from None


def _value_lists(data: dict, table: str, path: Path, problems: list[str]) -> dict[str, list[str]]:
    """A sweep file's ``[vary]`` or ``[link]``: dotted path -> value texts (problems added)."""
    lists: dict[str, list[str]] = {}
    for dotted, values in table_leaves(data.get(table, {}), stop_at_lists=True):
        if not isinstance(values, list) or not values:
            problems.append(f"{path}: {table}.{dotted}: expected a non-empty array of values")
        else:
            lists[dotted] = [_toml(value) for value in values]
    return lists


def table_leaves(
    table: object, prefix: str = "", *, stop_at_lists: bool = False
) -> list[tuple[str, object]]:
    """The ``(dotted.path, value)`` leaves of nested TOML tables (``[set.solver]``)."""
    if not isinstance(table, dict) or not table:
        return [(prefix, table)] if prefix else []
    leaves = []
    for key, value in table.items():
        dotted = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict) and value:
            leaves += table_leaves(value, dotted, stop_at_lists=stop_at_lists)
        else:
            leaves.append((dotted, value))
    return leaves


def make_plan(
    vary_options: Sequence[str] = (),
    sweep_file: str | os.PathLike | None = None,
    overrides: Sequence[str] = (),
    link_options: Sequence[str] = (),
) -> Plan:
    """Merge a sweep file (if any) with ``--vary``, ``--link`` and ``--set`` options.

    The options' ``--set`` values come after the file's ``[set]``, so they win.

    Raises
    ------
    ModelError
        If an option or the file is malformed, or a path is varied in both.
    """
    plan = read_sweep_file(sweep_file) if sweep_file is not None else Plan({}, [])
    given = parse_vary(vary_options)
    linked = {
        path.removeprefix("--vary "): values for path, values in parse_vary(link_options).items()
    }
    twice = [
        f"--vary {path}: also varied in {sweep_file}; vary it in one place"
        for path in given
        if path in plan.vary or path in plan.link
    ]
    if linked and plan.link:
        twice.append(f"--link: {sweep_file} links paths already ([link]); link them in one place")
    if twice:
        raise ModelError(twice)
    return Plan(
        vary={**plan.vary, **given},
        overrides=[*plan.overrides, *overrides],
        link=linked or plan.link,
    )


def make_cases(
    vary: Mapping[str, Sequence[str]], link: Mapping[str, Sequence[str]] | None = None
) -> list[Case]:
    """The Cartesian product of the varied values, each case named by its values.

    Parameters
    ----------
    vary
        Dotted path -> value texts (``parse_vary``), in the order they vary (first slowest).
    link
        Dotted path -> value texts of one length (``check_link``): stepped through together,
        as the fastest axis of the product.
    """
    axes = [[{path: text} for text in texts] for path, texts in vary.items()]
    if link:
        steps = zip(*link.values(), strict=True)
        axes.append([dict(zip(link, texts, strict=True)) for texts in steps])
    count = math.prod(len(axis) for axis in axes)
    if count > MAX_CASES:
        raise ModelError(
            [f"vary: the values give {count:,} cases; at most {MAX_CASES:,} run in one sweep"]
        )
    keys = short_keys([*vary, *(link or {})])
    values = [
        {path: text for part in parts for path, text in part.items()}
        for parts in itertools.product(*axes)
    ]
    names = ["__".join(f"{keys[p]}={_safe(t)}" for p, t in case.items()) for case in values]
    readable = max(map(len, names)) <= MAX_NAME_LENGTH
    if not readable or len({name.lower() for name in names}) < len(names):  # any file system
        return indexed_cases(values)
    return [Case(id=name, values=case) for name, case in zip(names, values, strict=True)]


def indexed_cases(values: Sequence[Mapping[str, str]]) -> list[Case]:
    """Cases named by their index (``case007``), for values too many or long to name them by."""
    width = max(3, len(str(len(values))))
    return [Case(id=f"case{i:0{width}d}", values=dict(v)) for i, v in enumerate(values, 1)]


def short_keys(paths: list[str]) -> dict[str, str]:
    """The shortest trailing part of each path that tells the paths apart."""
    keys = {}
    for path in paths:
        parts = path.split(".")
        for n in range(1, len(parts) + 1):
            key = ".".join(parts[-n:])
            others = [other for other in paths if other != path]
            if not any(other == key or other.endswith(f".{key}") for other in others):
                break
        keys[path] = key
    return keys


def _safe(text: str) -> str:
    value = toml_value(text)
    shown = value if isinstance(value, str) else text
    return _UNSAFE.sub("_", shown.strip()).strip("_") or "_"


def si_value(model: Model, path: str, text: str) -> object:
    """The value a varied path has in the validated model: SI for quantities.

    The path is followed through the model's fields and properties, so a key that only the
    model file knows and the model turns into its own (``clearance.radial_clearance``, which
    sets the bearing radius) gives its SI value too. A number or a string stays as it is; any
    other value (e.g. a pair of moduli) is given as its JSON text. Where the path does not
    lead to a model value, the value as given.
    """
    current: object = model
    for key in path.split("."):
        current = _part(current, key)
        if current is _MISSING:
            return toml_value(text)
    if isinstance(current, bool | int | float | str):
        return current
    return json.dumps(to_jsonable_python(current))


_MISSING = object()


def _part(value: object, key: str) -> object:
    """A table's field or property, an array's item (by name or index), a mapping's entry."""
    if isinstance(value, BaseModel):
        kind = type(value)
        known = key in kind.model_fields or isinstance(getattr(kind, key, None), property)
        return getattr(value, key) if known else _MISSING
    if isinstance(value, Mapping):
        return value.get(key, _MISSING)
    if isinstance(value, tuple | list):
        names = [getattr(item, "name", None) for item in value]
        if key in names:
            return value[names.index(key)]
        if key.isdigit() and int(key) < len(value):
            return value[int(key)]
    return _MISSING
