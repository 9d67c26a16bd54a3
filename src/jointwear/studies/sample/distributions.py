"""The distributions of a sampled study's inputs, read from texts like ``normal(10 mm, 0.01 mm)``.

An input's distribution is one of

- ``uniform(low, high)``;
- ``normal(mean, sd)``;
- ``truncnormal(mean, sd, low, high)``: the normal cut to ``[low, high]``;
- ``lognormal(median, sigma)``: ``ln x`` normal with mean ``ln median`` and standard deviation
  ``sigma`` (a plain number; a factor ``f`` either side covers 68 % at ``sigma = ln f``);
- ``loguniform(low, high)``: ``ln x`` uniform, for a value known to a factor;
- ``triangular(low, mode, high)``;
- a list of values, ``[0.05, 0.1, 0.2]`` or ``["abm", "dopri5"]``, drawn with equal chances.

The numbers may carry units (``0.01 mm``); those of one distribution share a dimension, and
the drawn values are written back in the unit of its first number, so the model reads them as
it reads ``--set``. Each distribution is scipy's (``scipy.stats``), drawn by its inverse
distribution function from points of the unit cube (``design``).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from numpy.typing import NDArray

from ...model import ModelError
from ...model.overrides import toml_value
from ...units import dimension_of, to_si, unit_of
from ..sweep.cases import split_values, value_text

KINDS = {  # name: (its numbers, which of them may be negative or zero)
    "uniform": ("low, high", True),
    "normal": ("mean, sd", True),
    "truncnormal": ("mean, sd, low, high", True),
    "lognormal": ("median, sigma", False),
    "loguniform": ("low, high", False),
    "triangular": ("low, mode, high", True),
}
EXAMPLE = "normal(10 mm, 0.01 mm)"
_CALL = re.compile(r"\s*([a-z_]+)\s*\((.*)\)\s*", re.DOTALL)


@dataclass(frozen=True)
class Distribution:
    """The distribution of one input: a path's values, as ``text`` gives them.

    Attributes
    ----------
    path
        The dotted path it draws values for.
    text
        As given: ``normal(10 mm, 0.01 mm)`` or a list ``[0.05, 0.1]``.
    kind
        A name of ``KINDS``, or ``choice`` for a list.
    numbers
        The distribution's numbers in SI (a ``lognormal``'s sigma as it is).
    unit
        The unit the drawn values are written in, and its size in SI; None for plain numbers.
    choices
        A list's values, as ``--set`` reads them.
    """

    path: str
    text: str
    kind: str
    numbers: tuple[float, ...] = ()
    unit: tuple[str, float] | None = None
    choices: tuple[str, ...] = ()

    @cached_property
    def frozen(self) -> object:
        """The scipy distribution of the values in SI (None for a list)."""
        from scipy import stats

        a, b, *rest = self.numbers if self.kind != "choice" else (0.0, 0.0)
        if self.kind == "uniform":
            return stats.uniform(loc=a, scale=b - a)
        if self.kind == "normal":
            return stats.norm(loc=a, scale=b)
        if self.kind == "truncnormal":
            low, high = rest
            return stats.truncnorm((low - a) / b, (high - a) / b, loc=a, scale=b)
        if self.kind == "lognormal":
            return stats.lognorm(s=b, scale=a)
        if self.kind == "loguniform":
            return stats.loguniform(a, b)
        if self.kind == "triangular":
            return stats.triang((b - a) / (rest[0] - a), loc=a, scale=rest[0] - a)
        return None

    def values(self, points: NDArray[np.float64]) -> list[str]:
        """The value texts at points ``points`` of the unit interval, as ``--set`` reads them."""
        if self.kind == "choice":
            picks = np.minimum((points * len(self.choices)).astype(int), len(self.choices) - 1)
            return [self.choices[i] for i in picks]
        drawn = self.frozen.ppf(points)
        if self.unit is None:
            return [repr(float(x)) for x in drawn]
        unit, size = self.unit
        return [f"{float(x) / size!r} {unit}" for x in drawn]

    def describe(self) -> dict[str, object]:
        """What ``sample.json`` keeps of it."""
        return {"distribution": self.text, "kind": self.kind, "unit": self.unit and self.unit[0]}


def read_distribution(path: str, given: object) -> Distribution:
    """The distribution of ``path`` that ``given`` describes (a text, or a list of values).

    Raises
    ------
    ModelError
        Naming the path, what was wrong and what is allowed.
    """
    where = f"--dist {path}"
    if isinstance(given, str) and given.strip().startswith("[") and given.strip().endswith("]"):
        given = [text.strip() for text in split_values(given.strip()[1:-1]) if text.strip()]
    if isinstance(given, Sequence) and not isinstance(given, str):
        choices = tuple(value_text(value) for value in given)
        if not choices:
            raise ModelError([f"{where}: an empty list; give the values to draw from"])
        if len(set(choices)) < len(choices):
            raise ModelError([f"{where}: {list(choices)} repeats a value; give each once"])
        return Distribution(path, f"[{', '.join(choices)}]", "choice", choices=choices)
    match = _CALL.fullmatch(given) if isinstance(given, str) else None
    if match is None or match.group(1) not in KINDS:
        raise ModelError([f"{where}: cannot read {given!r}; {_allowed()}"])
    kind, inner = match.groups()
    names, may_be_negative = KINDS[kind]
    texts = [part.strip() for part in inner.split(",")]
    if len(texts) != len(names.split(", ")) or not all(texts):
        raise ModelError([f"{where}: {kind} takes {kind}({names}); got {given!r}"])
    numbers, unit = _numbers(where, kind, texts)
    problem = _problem(kind, numbers, may_be_negative)
    if problem:
        raise ModelError([f"{where}: {given.strip()}: {problem}"])
    return Distribution(path, given.strip(), kind, numbers, unit)


def _numbers(where: str, kind: str, texts: list[str]) -> tuple[tuple[float, ...], object]:
    """A distribution's numbers in SI, and the unit of its first (checked to be alike)."""
    scale_free = {1} if kind == "lognormal" else set()  # sigma: a plain number
    numbers, dimension, unit = [], None, None
    for i, text in enumerate(texts):
        try:
            value = toml_value(text)
            found = dimension_of(text) if isinstance(value, str) else None
            si = float(value) if found is None else to_si(text, found)
        except (ValueError, TypeError) as error:
            raise ModelError([f"{where}: {error}"]) from None
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            raise ModelError([f"{where}: {text!r} is not a number (with a unit or without)"])
        if i in scale_free:
            if found is not None:
                raise ModelError([f"{where}: {kind}'s sigma is a plain number (of ln x)"])
            numbers.append(si)
            continue
        if i == 0:
            dimension, unit = found, unit_of(text) if found is not None else None
        elif found != dimension:
            raise ModelError(
                [f"{where}: {texts[0]!r} and {text!r} differ in unit; give them alike"]
            )
        numbers.append(si)
    if not all(math.isfinite(x) for x in numbers):
        raise ModelError([f"{where}: its numbers must be finite; got {', '.join(texts)}"])
    return tuple(numbers), unit


def _problem(kind: str, numbers: tuple[float, ...], may_be_negative: bool) -> str:
    """What is wrong with a distribution's numbers, or ''."""
    if not may_be_negative and numbers[0] <= 0:
        return f"{kind} needs a positive {KINDS[kind][0].split(',')[0]}"
    if kind in ("uniform", "loguniform") and not numbers[0] < numbers[1]:
        return "low must be below high"
    if kind in ("normal", "truncnormal", "lognormal") and not numbers[1] > 0:
        return "its spread (sd, sigma) must be positive"
    if kind == "truncnormal" and not numbers[2] < numbers[3]:
        return "low must be below high"
    if kind == "triangular" and not numbers[0] <= numbers[1] <= numbers[2] > numbers[0]:
        return "expected low <= mode <= high, low below high"
    return ""


def _allowed() -> str:
    calls = ", ".join(f"{name}({numbers})" for name, (numbers, _) in KINDS.items())
    return f"expected one of {calls}, or a list [v1, v2, ...]; e.g. {EXAMPLE}"
