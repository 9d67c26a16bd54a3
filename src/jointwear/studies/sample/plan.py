"""What a sampled study draws: ``--dist`` and ``--correlate`` options and study files.

A study file is TOML::

    n = 64                   # optional: cases (the --n option wins)
    method = "lhs"           # optional: random, lhs, sobol or saltelli
    seed = 1                 # optional
    correlations = [["joints.a.clearance.friction_coefficient",
                     "joints.b.clearance.friction_coefficient", 0.8]]

    [distributions]          # dotted path = distribution text, or a list of values
    "joints.a.clearance.friction_coefficient" = "normal(0.1, 0.03)"
    "joints.a.clearance.radial_clearance" = "uniform(0.05 mm, 0.2 mm)"

    [set]                    # values common to every case, as --set
    "solver.t_end" = 0.2
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from ...model.errors import ModelError, did_you_mean
from ..sweep.cases import read_toml_file, table_leaves, value_text

STUDY_FILE_KEYS = ("n", "method", "seed", "correlations", "distributions", "set")
KIND_NAMES = {dict: "a table", list: "an array", int: "a whole number", str: "a string"}
DIST_EXAMPLE = "joints.crank_rod.clearance.friction_coefficient=normal(0.1, 0.03)"


@dataclass(frozen=True)
class SamplePlan:
    """A sampled study's inputs and settings, before the model is read.

    Attributes
    ----------
    distributions
        Dotted path -> distribution text or list of value texts.
    correlations
        (path, path) -> correlation of their normal scores.
    overrides
        ``dotted.path=value`` settings common to every case.
    n, method, seed
        As the study file gives them (None: not given).
    """

    distributions: dict[str, object]
    correlations: dict[tuple[str, str], float] = field(default_factory=dict)
    overrides: list[str] = field(default_factory=list)
    n: int | None = None
    method: str | None = None
    seed: int | None = None


def parse_dists(options: Iterable[str]) -> dict[str, str]:
    """Read ``--dist PATH=DISTRIBUTION`` options.

    Raises
    ------
    ModelError
        One line per malformed option or repeated path.
    """
    found: dict[str, str] = {}
    problems = []
    for option in options:
        path, equals, text = (part.strip() for part in option.partition("="))
        if not equals or not path or not all(path.split(".")) or not text:
            problems.append(f"--dist {option}: expected PATH=DISTRIBUTION, e.g. {DIST_EXAMPLE}")
        elif path in found:
            problems.append(f"--dist {option}: {path} has a distribution already; give one")
        else:
            found[path] = text
    if problems:
        raise ModelError(problems)
    return found


def parse_correlations(options: Iterable[str]) -> dict[tuple[str, str], float]:
    """Read ``--correlate PATH,PATH=RHO`` options (``design.correlation_matrix`` judges them).

    Raises
    ------
    ModelError
        One line per malformed option.
    """
    pairs: dict[tuple[str, str], float] = {}
    problems = []
    for option in options:
        names, equals, text = option.partition("=")
        paths = tuple(part.strip() for part in names.split(","))
        try:
            rho = float(text)
        except ValueError:
            rho = None
        if not equals or len(paths) != 2 or not all(paths) or rho is None:
            problems.append(f"--correlate {option}: expected PATH,PATH=RHO, e.g. a.b,c.d=0.5")
        else:
            pairs[paths] = rho
    if problems:
        raise ModelError(problems)
    return pairs


def read_study_file(path: str | os.PathLike) -> SamplePlan:
    """Read a study file (module docstring).

    Raises
    ------
    ModelError
        If the file cannot be read or is not of this form, one line per problem.
    """
    path = Path(path)
    data = read_toml_file(path, "study file")
    problems = [
        f"{path}: unknown key {key!r}; a study file has {', '.join(STUDY_FILE_KEYS)}"
        f"{did_you_mean(key, STUDY_FILE_KEYS)}"
        for key in data
        if key not in STUDY_FILE_KEYS
    ]
    kinds = {"distributions": dict, "set": dict, "correlations": list, "n": int, "seed": int,
             "method": str}  # fmt: skip
    for key, kind in kinds.items():
        value = data.get(key)
        if value is not None and (not isinstance(value, kind) or isinstance(value, bool)):
            problems.append(f"{path}: {key}: got {value!r}; expected {KIND_NAMES[kind]}")
    if problems:
        raise ModelError(problems)
    distributions = dict(table_leaves(data.get("distributions", {}), stop_at_lists=True))
    overrides = [f"{dotted}={value_text(v)}" for dotted, v in table_leaves(data.get("set", {}))]
    correlations = {}
    for entry in data.get("correlations", []):
        if not (isinstance(entry, list) and len(entry) == 3 and _number(entry[2])
                and all(isinstance(p, str) for p in entry[:2])):  # fmt: skip
            problems.append(f"{path}: correlations: {entry!r}; expected [path, path, rho]")
        else:
            correlations[(entry[0], entry[1])] = float(entry[2])
    settings = {key: data.get(key) for key in ("n", "method", "seed")}
    if problems:
        raise ModelError(problems)
    return SamplePlan(distributions, correlations, overrides, **settings)


def _number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def make_sample_plan(
    dist_options: Iterable[str] = (),
    study_file: str | os.PathLike | None = None,
    overrides: Iterable[str] = (),
    correlate_options: Iterable[str] = (),
) -> SamplePlan:
    """Merge a study file (if any) with ``--dist``, ``--correlate`` and ``--set`` options.

    Raises
    ------
    ModelError
        If an option or the file is malformed, or a path has a distribution in both.
    """
    plan = read_study_file(study_file) if study_file is not None else SamplePlan({})
    given = parse_dists(dist_options)
    twice = [
        f"--dist {path}: also in {study_file}; give its distribution in one place"
        for path in given
        if path in plan.distributions
    ]
    if twice:
        raise ModelError(twice)
    return SamplePlan(
        distributions={**plan.distributions, **given},
        correlations={**plan.correlations, **parse_correlations(correlate_options)},
        overrides=[*plan.overrides, *overrides],
        n=plan.n,
        method=plan.method,
        seed=plan.seed,
    )
