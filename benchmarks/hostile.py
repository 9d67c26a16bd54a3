"""Hostile-testing campaign of the jointwear command line (issue 15).

Four categories of abuse, each checked for tracebacks, bad exit codes, "success" with
non-finite numbers, files touched outside the results folder or not written by the tool, and
finished computations lost:

1. ``mutations``: model files mutated from ``examples/`` (extreme numbers, odd units, wrong
   types, deep nesting, control characters in names, duplicate names, removed keys, degenerate
   geometry, long strings, corrupt text, odd ``extends``); ``check`` on each, ``run`` on a
   sample, a share of the runs with figures (``--figure-share``) and of those with the
   animation (``--animation-share``). Run in-process (``typer.testing.CliRunner`` on
   ``jointwear.cli.app``) by worker processes that a watchdog restarts after a crash or a
   hang.
2. ``cli``: odd arguments of ``run``, ``check``, ``plot``, ``sweep`` and ``life`` (times,
   ``--set``, ``--out`` that cannot be written, damaged folders, sweep files, cycles).
3. ``signals``: SIGINT or SIGTERM at a random moment of ``run``, ``life`` and ``sweep``
   subprocesses (the process or its whole group).
4. ``files``: symlinked, user-populated, locked (``chattr +i``), full (tmpfs) and vanishing
   results folders, with every file of a sandbox hashed before and after.

It prints a table of counts and writes one minimal reproducer per distinct failure class
(exception type + last traceback frame, or the kind of failure) to ``--findings``.
Nothing under ``src/`` or ``tests/`` is touched; scratch files go to ``--work``.

Usage (from the repository root; as root for the locked-folder and tmpfs cases)::

    .venv/bin/python benchmarks/hostile.py --quick            # about 5 minutes
    .venv/bin/python benchmarks/hostile.py --seed 1           # the full campaign
    .venv/bin/python benchmarks/hostile.py --only signals,files --signals 20
"""

from __future__ import annotations

import argparse
import contextlib
import copy
import hashlib
import json
import math
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import threading
import time
import tomllib
import traceback
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"
JOINTWEAR = REPO / ".venv" / "bin" / "jointwear"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
CLEARANCE_PATH = "joints.coupler_follower.clearance"
ALLOWED_EXITS = {0, 1, 2, 3}  # success, stopped early, invalid input, results rescued
SIGNAL_EXITS = ALLOWED_EXITS | {130}
MARKER = "ZQXJ"  # follows a line break injected into a name: a line starting with it is split
PWNED = Path("/tmp/hostile_pwned")  # a model value that got evaluated would create this
DEEP = 5000  # nesting depth of the deep-nesting cases
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u2028\u2029]")  # raw in output: a finding
NONFINITE_WORD = re.compile(r"(?<![A-Za-z_])-?(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)

# --------------------------------------------------------------------------------------------
# TOML writing (tomli_w is not installed): tables as sections, Raw text verbatim


class Raw(str):
    """TOML text written as it is (deep nesting, huge integers, dates)."""


def toml_string(text: str) -> str:
    """A TOML basic string of ``text``, control characters escaped."""
    out = ['"']
    for char in text:
        code = ord(char)
        if char in '"\\':
            out.append("\\" + char)
        elif code < 0x20 or code == 0x7F or 0xD800 <= code <= 0xDFFF:
            out.append(f"\\u{code:04x}")
        else:
            out.append(char)
    out.append('"')
    return "".join(out)


def toml_key(key: str) -> str:
    """A bare key if it can be one, else a quoted one."""
    return key if re.fullmatch(r"[A-Za-z0-9_-]+", key) else toml_string(key)


def toml_value(value: object) -> str:
    """An inline TOML value."""
    if isinstance(value, Raw):
        return str(value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return toml_string(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + "}"
    return toml_string(str(value))


def _is_table_array(value: object) -> bool:
    return (
        isinstance(value, list)
        and bool(value)
        and all(isinstance(v, dict) and not isinstance(v, Raw) for v in value)
    )


def dump_toml(data: dict) -> str:
    """A TOML document of ``data``: tables and arrays of tables as sections."""
    lines: list[str] = []

    def table(prefix: list[str], body: dict) -> None:
        nested = []
        for key, value in body.items():
            if (isinstance(value, dict) and not isinstance(value, Raw)) or _is_table_array(value):
                nested.append((key, value))
            else:
                lines.append(f"{toml_key(key)} = {toml_value(value)}")
        for key, value in nested:
            name = ".".join(toml_key(k) for k in [*prefix, key])
            if isinstance(value, dict):
                lines.append(f"\n[{name}]")
                table([*prefix, key], value)
            else:
                for item in value:
                    lines.append(f"\n[[{name}]]")
                    table([*prefix, key], item)

    table([], data)
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------------------------
# Mutations of model files

NAN, INF = float("nan"), float("inf")
EXTREMES = [0, 0.0, -1, -1.0, 1e-300, -1e-300, 1e300, -1e300, 5e-324, NAN, INF, -INF,
            10**30, -(10**30), 2**63, 2**64, 10**400, 1.7976931348623157e308, -0.0,
            Raw("1" + "0" * 5000)]  # fmt: skip
ODD_UNITS = ["1 kg^0", "50 percent", "1e400 Pa", "1 nan", "3 parsec", "", "kg", "nan mm",
             "inf kg", "1 m^1000", "1e-400 m", "1 kg/0", "1 rad^0", "1 deg^2", "1 (kg",
             "--1 m", "1 m m m", "1e308 km", "0x10 mm", "1_000 mm", "1 s^-0.5", "1 µm",
             "1 meter", "1 °", "1 Hz", "√2 m", "5e-324 m", "1e300 GPa", "1 dimensionless",
             "1 percent", "1e-320 rpm", "1 kg^1e300", "1 m**2**100", "1 kg^-0",
             "__import__('os').system('touch /tmp/hostile_pwned')", "1 m; import os",
             "{0.__class__.__mro__}", "1 % 2", "1 m " * 300]  # fmt: skip
MUST_REFUSE = {"1 kg^0", "1e400 Pa", "1 nan", "", "kg", "nan mm", "inf kg", "1 m^1000",
               "1 kg/0", "1 (kg", "1 m m m", "1 kg^1e300"}  # fmt: skip
WRONG_TYPES = [[], [1, 2], [[1.0]], {}, {"a": 1}, "x", "1", True, False, [True],
               {"value": 1, "unit": "m"}, Raw("1979-05-27T07:32:00Z"), Raw("07:32:00"),
               [1, "a", [2]], ["1 m", "2 m", "3 m"]]  # fmt: skip
NAMES = [f"a\n{MARKER}", f"x\r{MARKER}", f"y\u2028{MARKER}", f"z\x85{MARKER}", "\x00",
         "\t", "tab\tname", "ünïcödé", "名前", "emoji😀", "\u202eRTL", "a.b", "a=b", "", " ",
         "ground", "../../etc", "a/b", "\x1b[31mred", "x" * 10000, "zero\u200bwidth", "CON",
         "[bold]rich[/bold]", "[link=file:///etc/passwd]x[/link]", "%s%n", "{0}", "-rf",
         "a,b", "'quoted'", '"dq"', "\\", "*", "nul\x00in", "a[/x]", "[/]"]  # fmt: skip
SOLVER_EDGES = {
    "t_end": [5e-324, 1e-320, 0, -1, NAN, INF, 1e300, "1 parsec", "1 kg", 10**30],
    "max_step": [1e300, 5e-324, 0, -1, NAN, INF, "1 year"],
    "min_step": [1e300, 5e-324, 0, -1, NAN],
    "initial_step": [1e300, 5e-324, 0, -1, NAN],
    "output_interval": [5e-324, 1e-300, 0, 1e300, -1, NAN, INF],
    "wear_snapshot_interval": [5e-324, 0, 1e300, -1, NAN],
    "rtol": [0, -1, 1e300, 5e-324, NAN, 1],
    "atol": [0, -1, 1e300, 5e-324, NAN],
    "max_steps": [0, -1, 10**30, 1e300, 2**63, 1.5, NAN],
    "integrator": ["x", "", "ABM", 1, "dopri5\n"],
    "formulation": ["x", "", 0],
    "penalty": [0, -1, 1e300, NAN],
    "baumgarte_alpha": [0, -1, 1e300, NAN],
    "baumgarte_beta": [0, -1, 1e300, NAN],
    "max_constraint_violation": [0, -1, 1e300, NAN, INF],
    "max_energy_error": [0, -1, 1e300, NAN, INF],
    "assembly_tolerance": [0, -1, 1e300, NAN],
}
GEOMETRY = [  # (path pattern, values): degenerate but well-typed geometry
    (
        "axis",
        [
            [1e-200, 0.0],
            [0.0, 0.0],
            [NAN, 0.0],
            [1e300, 1e300],
            [5e-324, 5e-324],
            [1.0],
            [1.0, 0.0, 0.0],
        ],
    ),
    ("width", [1e300, 1e-300, 0, "1e300 mm", -1]),
    ("bearing_radius", [1e300, 0, "9.8 mm", "9.79 mm", 1e-300]),
    ("journal_radius", [1e300, 0, "10.0 mm", "10.5 mm", -1]),
    ("sectors", [0, 1, -1, 10**9, 1e300, 2.5]),
    ("wear_coefficient", [1e300, "1e300 1/Pa", -1, NAN, "1 1/Pa"]),
    ("youngs_modulus", [0, -1, 1e300, 5e-324]),
    ("poisson_ratio", [0.5, 1, -1, 1e300]),
    ("restitution_coefficient", [0, 1, 2, -1, 1e-300]),
    ("friction_coefficient", [-1, 1e300, 100]),
    ("mass", [1e-300, 0, 1e300, "1 g", 5e-324]),
    ("inertia", [0, 1e-300, 1e300]),
    ("position", [[1e300, 0.0], [0.0, 0.0], [NAN, NAN]]),
    ("gap", [0, 1e300, -1, 1e-300]),
    ("slider_length", [0, 1e300, 1e-300]),
    ("slider_height", [0, 1e300]),
    ("guide_length", [0, 1e-300, 1e300]),
    ("speed", ["1e300 rpm", 0, "-1500 rpm", 1e300]),
    ("amplitude", [1e300, 0, NAN]),
    ("frequency", [1e300, 0, -1]),
    ("acceleration", [[0.0, 1e300], [NAN, 0.0], [0.0, "-1e300 m/s^2"]]),
    ("viscosity", [0, -1, 1e300, "1e300 Pa*s"]),
]
EXTENDS = ["", "/dev/null", "/etc/passwd", "/proc/self/status", "nonexistent.toml", ".",
           "../" * 60 + "x.toml", "SELF", "/", "x" * 5000, "\x00", "flores2009_fourbar.toml\n",
           "/dev/zero"]  # fmt: skip


def walk(data: object, path: tuple = ()) -> list[tuple[tuple, object]]:
    """Every node of ``data`` with its path of keys and indices (iteratively)."""
    found, stack = [], [(path, data)]
    while stack:
        where, node = stack.pop()
        found.append((where, node))
        if isinstance(node, dict) and not isinstance(node, Raw):
            stack.extend(((*where, k), v) for k, v in node.items())
        elif isinstance(node, list):
            stack.extend(((*where, i), v) for i, v in enumerate(node))
    return found


def set_at(data: object, path: tuple, value: object) -> None:
    """Set the node at ``path`` (not the root)."""
    for key in path[:-1]:
        data = data[key]
    data[path[-1]] = value


def show(path: tuple) -> str:
    """A path as ``bodies[1].mass``."""
    text = ""
    for key in path:
        text += f"[{key}]" if isinstance(key, int) else (f".{key}" if text else str(key))
    return text or "<root>"


def brief(value: object, limit: int = 70) -> str:
    """A short repr."""
    text = repr(value) if not isinstance(value, Raw) else f"Raw({str(value)[:30]}...)"
    return text if len(text) <= limit else text[:limit] + f"...<{len(text)} chars>"


class Mutator:
    """Seeded mutations of the example models."""

    def __init__(self, rng: random.Random, bases: dict[str, dict]) -> None:
        self.rng, self.bases = rng, bases

    def make(self) -> tuple[str, bytes, list[str], dict]:
        """One mutated model: base name, file bytes, what was done, flags for the checks."""
        rng = self.rng
        base = rng.choice(sorted(self.bases))
        data = copy.deepcopy(self.bases[base])
        notes: list[str] = []
        flags: dict = {}
        count = rng.choices([1, 2, 3, 5], weights=[70, 15, 10, 5])[0]
        text_ops = []
        for _ in range(count):
            op = rng.choices(OPS, weights=[w for _, w in OPS_WEIGHTED])[0]
            result = op(self, data, notes, flags)
            if callable(result):
                text_ops.append(result)
        flags["refuse"] = [  # only values that a later mutation did not overwrite
            f"{show(path)}={brief(value)}"
            for path, value in flags.pop("_refuse", [])
            if repr(_get(data, path)) == repr(value)
        ]
        text = dump_toml(data).encode("utf-8", "surrogatepass")
        for edit in text_ops:
            text = edit(text)
        flags["ops"] = count
        return base, text, notes, flags

    def _leaf(self, data: dict, numeric_only: bool = False) -> tuple | None:
        leaves = [
            (p, v)
            for p, v in walk(data)
            if p and not isinstance(v, dict | list) and (not numeric_only or _quantity_like(p, v))
        ]
        return self.rng.choice(leaves) if leaves else None

    def extreme(self, data: dict, notes: list, flags: dict) -> None:
        """A number at the edges of what floats and integers hold."""
        leaf = self._leaf(data, numeric_only=self.rng.random() < 0.8)
        if leaf:
            value = self.rng.choice(EXTREMES)
            set_at(data, leaf[0], value)
            notes.append(f"{show(leaf[0])} = {brief(value)}")
            if isinstance(value, float) and not math.isfinite(value):
                flags.setdefault("_refuse", []).append((leaf[0], value))

    def odd_unit(self, data: dict, notes: list, flags: dict) -> None:
        """A quantity written with an odd unit."""
        leaf = self._leaf(data, numeric_only=True)
        if leaf:
            value = self.rng.choice(ODD_UNITS)
            set_at(data, leaf[0], value)
            notes.append(f"{show(leaf[0])} = {brief(value)}")
            angular = isinstance(leaf[1], str) and re.search(r"(deg|rad|rpm)", leaf[1])
            if value in MUST_REFUSE or (value in ("50 percent", "1 percent") and angular):
                flags.setdefault("_refuse", []).append((leaf[0], value))

    def wrong_type(self, data: dict, notes: list, flags: dict) -> None:
        """A list, table, string, boolean or date where something else is expected."""
        nodes = [(p, v) for p, v in walk(data) if p]
        path, _ = self.rng.choice(nodes)
        value = copy.deepcopy(self.rng.choice(WRONG_TYPES))
        set_at(data, path, value)
        notes.append(f"{show(path)} = {brief(value)}")

    def deep(self, data: dict, notes: list, flags: dict) -> object:
        """Thousands of nested arrays or tables."""
        kind = self.rng.choice(["array", "inline", "dotted", "dotted_table"])
        depth = self.rng.choice([DEEP, 1000, 200_000 // 7])
        if kind == "array":
            path, _ = self.rng.choice([(p, v) for p, v in walk(data) if p])
            set_at(data, path, Raw("[" * depth + "1" + "]" * depth))
            notes.append(f"{show(path)} = {depth} nested arrays")
        elif kind == "inline":
            path, _ = self.rng.choice([(p, v) for p, v in walk(data) if p])
            set_at(data, path, Raw("{a = " * depth + "1" + "}" * depth))
            notes.append(f"{show(path)} = {depth} nested inline tables")
        else:
            where = self.rng.choice(["solver", "zz", "bodies", "ground"])
            keys = ".".join(["a"] * depth)
            line = f"{where}.{keys} = 1\n" if kind == "dotted" else f"[{where}.{keys}]\nb = 1\n"
            notes.append(f"{where}.a.a... ({depth} dotted keys{', table' * (kind != 'dotted')})")
            if kind == "dotted":
                return lambda text: line.encode() + text
            return lambda text: text + b"\n" + line.encode()
        return None

    def name(self, data: dict, notes: list, flags: dict) -> None:
        """A body, joint, driver or point named with control characters or odd unicode."""
        new = self.rng.choice(NAMES)
        named = [(p, v) for p, v in walk(data) if p and p[-1] == "name" and isinstance(v, str)]
        if named and self.rng.random() < 0.7:
            path, old = self.rng.choice(named)
            consistent = self.rng.random() < 0.6 and path[0] != "name"
            if consistent:  # renamed everywhere it is referred to: still a valid model
                for p, v in walk(data):
                    if p and v == old:
                        set_at(data, p, new)
            else:
                set_at(data, path, new)
            notes.append(f"rename {old!r} -> {brief(new)}{' everywhere' * consistent}")
        else:  # a point name (a key)
            tables = [(p, v) for p, v in walk(data) if p and p[-1] == "points"
                      and isinstance(v, dict)]  # fmt: skip
            if not tables:
                return
            path, points = self.rng.choice(tables)
            if points:
                old = self.rng.choice(list(points))
                points[new] = points.pop(old)
                notes.append(f"{show(path)}: point {old!r} renamed {brief(new)}")

    def duplicate(self, data: dict, notes: list, flags: dict) -> None:
        """Two bodies, joints or drivers of the same name."""
        for section in self.rng.sample(["bodies", "joints", "drivers"], 3):
            items = data.get(section)
            if isinstance(items, list) and len(items) >= 2:
                first, second = self.rng.sample(range(len(items)), 2)
                if isinstance(items[first], dict) and isinstance(items[second], dict):
                    items[second]["name"] = items[first].get("name")
                    notes.append(f"{section}[{second}].name = {section}[{first}].name")
                    return
                return
        if isinstance(data.get("bodies"), list) and data["bodies"]:
            data["bodies"].append(copy.deepcopy(data["bodies"][0]))
            notes.append("bodies[0] appended twice")

    def remove(self, data: dict, notes: list, flags: dict) -> None:
        """A key removed (or an array emptied)."""
        nodes = [(p, v) for p, v in walk(data) if p and isinstance(p[-1], str)]
        if nodes:
            path, _ = self.rng.choice(nodes)
            parent = data
            for key in path[:-1]:
                parent = parent[key]
            del parent[path[-1]]
            notes.append(f"del {show(path)}")

    def unknown(self, data: dict, notes: list, flags: dict) -> None:
        """A key the schema does not know."""
        tables = [(p, v) for p, v in walk(data) if isinstance(v, dict)]
        path, table = self.rng.choice(tables)
        key = self.rng.choice(["nmae", "mass ", "Mass", "__class__", "💥", "", "a.b", "x" * 3000])
        table[key] = 1
        notes.append(f"{show(path)}.{brief(key, 20)} = 1 (unknown key)")

    def geometry(self, data: dict, notes: list, flags: dict) -> None:
        """Degenerate but well-typed geometry (zero lengths, huge widths, tiny axes)."""
        options = [(p, values) for p, _ in walk(data) for key, values in GEOMETRY
                   if p and p[-1] == key]  # fmt: skip
        if self.rng.random() < 0.25:  # a zero-length bar: both its points on one spot
            bars = [(p, v) for p, v in walk(data) if p and p[-1] == "points"
                    and isinstance(v, dict) and len(v) >= 2]  # fmt: skip
            if bars:
                path, points = self.rng.choice(bars)
                first, second = list(points)[:2]
                points[second] = copy.deepcopy(points[first])
                notes.append(f"{show(path)}.{second} = {first} (zero length)")
                return
        if options:
            path, values = self.rng.choice(options)
            value = copy.deepcopy(self.rng.choice(values))
            set_at(data, path, value)
            notes.append(f"{show(path)} = {brief(value)}")

    def solver(self, data: dict, notes: list, flags: dict) -> None:
        """A solver setting at the edges."""
        key = self.rng.choice(sorted(SOLVER_EDGES))
        value = self.rng.choice(SOLVER_EDGES[key])
        target = data.setdefault("set", {}) if "extends" in data else data
        if not isinstance(target, dict):  # an earlier mutation made [set] something else
            target = data["set"] = {}
        solver = target.get("solver")
        if not isinstance(solver, dict):
            solver = target["solver"] = {}
        solver[key] = value
        notes.append(f"solver.{key} = {brief(value)}")

    def long_string(self, data: dict, notes: list, flags: dict) -> None:
        """A very long string in place of a value or a name."""
        leaf = self._leaf(data)
        if leaf:
            size = self.rng.choice([10_000, 100_000, 1_000_000])
            value = self.rng.choice(["x", "1 ", "é", "\n"]) * size
            set_at(data, leaf[0], value)
            notes.append(f"{show(leaf[0])} = {size}-character string")

    def extends(self, data: dict, notes: list, flags: dict) -> None:
        """An ``extends`` pointing at something odd."""
        value = self.rng.choice(EXTENDS)
        data["extends"] = value
        data.setdefault("set", {}).setdefault("solver", {})["t_end"] = 0.001
        for key in list(data):
            if key not in ("extends", "set", "name", "description"):
                del data[key]
        notes.append(f"extends = {brief(value)}")
        flags["extends"] = value

    def text(self, data: dict, notes: list, flags: dict) -> object:
        """A corruption of the file's text."""
        kind = self.rng.choice(["truncate", "nul", "bom", "latin1", "crlf", "dup_header",
                                "drop_line", "huge_int", "bad_utf8"])  # fmt: skip
        rng = random.Random(self.rng.random())
        notes.append(f"text: {kind}")

        def edit(text: bytes) -> bytes:
            lines = text.split(b"\n")
            if kind == "truncate":
                return text[: rng.randrange(len(text) + 1)]
            if kind == "nul":
                at = rng.randrange(len(text) + 1)
                return text[:at] + b"\x00" + text[at:]
            if kind == "bom":
                return b"\xef\xbb\xbf" + text
            if kind == "latin1":
                return text.replace(b'name = "', b'name = "\xe9', 1)
            if kind == "crlf":
                return text.replace(b"\n", b"\r\n")
            if kind == "dup_header":
                return text + b"\n[solver]\nt_end = 1\n"
            if kind == "drop_line":
                del lines[rng.randrange(len(lines))]
                return b"\n".join(lines)
            if kind == "huge_int":
                return b"zz = " + b"9" * 10000 + b"\n" + text
            return text + b'\nname = "\xff\xfe"\n'

        return edit


def _get(data: object, path: tuple) -> object:
    """The node at ``path``, or a marker if there is none now."""
    try:
        for key in path:
            data = data[key]
    except (KeyError, IndexError, TypeError):
        return "<gone>"
    return data


def _quantity_like(path: tuple, value: object) -> bool:
    """Whether a leaf holds a number or a number with a unit."""
    if isinstance(value, bool):
        return False
    if isinstance(value, int | float):
        return True
    return isinstance(value, str) and bool(re.match(r"^\s*[-+]?[0-9.]+(e[-+]?\d+)?\s+\S", value))


OPS_WEIGHTED = [(Mutator.extreme, 20), (Mutator.odd_unit, 18), (Mutator.wrong_type, 10),
                (Mutator.deep, 5), (Mutator.name, 10), (Mutator.duplicate, 4),
                (Mutator.remove, 8), (Mutator.unknown, 3), (Mutator.geometry, 14),
                (Mutator.solver, 10), (Mutator.long_string, 2), (Mutator.extends, 2),
                (Mutator.text, 4)]  # fmt: skip
OPS = [op for op, _ in OPS_WEIGHTED]


def load_bases() -> dict[str, dict]:
    """The example models, parsed."""
    return {p.name: tomllib.loads(p.read_text()) for p in sorted(EXAMPLES.glob("*.toml"))}


def mutation_tasks(args: argparse.Namespace, work: Path) -> list[dict]:
    """Write the mutated models; one task (check, maybe run) per model."""
    rng = random.Random(args.seed)
    models = work / "models"
    models.mkdir(parents=True)
    for example in EXAMPLES.glob("*.toml"):  # so that `extends` finds its base
        shutil.copy(example, models / example.name)
    mutator = Mutator(rng, load_bases())
    tasks = []
    for i in range(args.mutations):
        base, text, notes, flags = mutator.make()
        name = f"m{i:05d}.toml"
        if flags.get("extends") == "SELF":
            text = text.replace(b'"SELF"', f'"{name}"'.encode())
        path = models / name
        path.write_bytes(text)
        out = work / "mruns" / f"m{i:05d}"
        steps = [{"kind": "check", "argv": ["check", str(path)], "timeout": args.timeout}]
        run_argv = ["run", str(path), "--out", str(out), "--t-end", "0.002", "--no-ideal"]
        if rng.random() < args.figure_share:  # figures drawn by the helpers, maybe animated
            run_argv += ["--animation"] if rng.random() < args.animation_share else []
        else:
            run_argv.append("--no-figures")
        when = (
            "always"
            if i % args.run_every == 0
            else ("if_valid" if rng.random() < args.run_valid_share else None)
        )
        if when:
            steps.append({"kind": "run", "argv": run_argv, "out": str(out), "when": when,
                          "timeout": args.timeout})  # fmt: skip
        tasks.append({"id": name[:-5], "cat": "mutations", "steps": steps, "base": base,
                      "notes": notes, "flags": flags, "model": str(path),
                      "size": len(text)})  # fmt: skip
    return tasks


# --------------------------------------------------------------------------------------------
# CLI-argument cases


def limit_memory() -> None:
    """At most 6 GiB of address space (a model that reads /dev/zero)."""
    resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))


def _sh(*argv: str, timeout: float = 120, **kw) -> subprocess.CompletedProcess:
    return subprocess.run(argv, capture_output=True, text=True, timeout=timeout, **kw)


def cli_fixtures(work: Path) -> dict[str, Path]:
    """Folders for the cases: a finished run, a life and a sweep folder, damaged copies."""
    fx = work / "fixtures"
    fx.mkdir(parents=True)
    run_dir, life_dir, sweep_dir = fx / "run", fx / "life", fx / "sweep"
    _sh(str(JOINTWEAR), "run", str(FOURBAR), "--out", str(run_dir), "--t-end", "0.01",
        "--no-figures")  # fmt: skip
    _sh(str(JOINTWEAR), "life", str(FOURBAR), "--out", str(life_dir), "--cycles", "10",
        "--no-figures")  # fmt: skip
    _sh(str(JOINTWEAR), "sweep", str(FOURBAR), "--out", str(sweep_dir), "--t-end", "0.005",
        "--vary", f"{CLEARANCE_PATH}.friction_coefficient=0,0.1", "--no-figures",
        "--workers", "1")  # fmt: skip
    paths = {"run": run_dir, "life": life_dir, "sweep": sweep_dir}

    def damaged(name: str, edit) -> None:
        target = fx / f"damaged_{name}"
        shutil.copytree(run_dir, target, symlinks=True)
        edit(target)
        paths[f"damaged_{name}"] = target

    def truncate(rel: str, size: int = 100):
        return lambda d: (d / rel).write_bytes((d / rel).read_bytes()[:size])

    damaged("parquet", truncate("timeseries.parquet"))
    damaged("parquet_empty", truncate("timeseries.parquet", 0))
    damaged("summary", truncate("summary.json", 50))
    damaged("summary_list", lambda d: (d / "summary.json").write_text("[]"))
    damaged("summary_nan", lambda d: (d / "summary.json").write_text('{"status": NaN}'))
    damaged("summary_deep", lambda d: (d / "summary.json").write_text("[" * 100000 + "]" * 100000))
    damaged("timeseries_csv", truncate("timeseries.csv", 300))
    damaged("no_parquet", lambda d: (d / "timeseries.parquet").unlink())
    damaged("no_wear", lambda d: (d / "wear.csv").unlink())
    damaged("wear_garbage", lambda d: (d / "wear.csv").write_text("a,b\n1,x\n"))
    damaged("model_json", truncate("model.json", 30))
    damaged("ideal_parquet", truncate("ideal/timeseries.parquet"))
    damaged("figures_file", lambda d: (d / "figures").write_text("not a folder"))
    damaged("parquet_dir", lambda d: ((d / "timeseries.parquet").unlink(),
                                      (d / "timeseries.parquet").mkdir()))  # fmt: skip
    life_damaged = fx / "damaged_life"
    shutil.copytree(life_dir, life_damaged, symlinks=True)
    with contextlib.suppress(OSError):
        ckpt = life_damaged / "checkpoint" / "checkpoint.json"
        ckpt.write_text(ckpt.read_text()[:20])
    paths["damaged_life"] = life_damaged
    life_nostate = fx / "life_nostate"
    shutil.copytree(life_dir, life_nostate, symlinks=True)
    for npz in (life_nostate / "checkpoint").glob("*.npz"):
        npz.write_bytes(b"PK\x03\x04garbage")
    paths["life_nostate"] = life_nostate
    (fx / "a_file").write_text("I am a file")
    paths["a_file"] = fx / "a_file"
    (fx / "empty").mkdir()
    paths["empty"] = fx / "empty"
    locked = fx / "locked"
    locked.mkdir()
    (fx / "locked_parent").mkdir()
    for folder in (locked, fx / "locked_parent"):
        _sh("chattr", "+i", str(folder))
    paths["locked"], paths["locked_parent"] = locked, fx / "locked_parent"
    full = fx / "full"
    full.mkdir()
    if _sh("mount", "-t", "tmpfs", "-o", "size=96k", "tmpfs", str(full)).returncode == 0:
        paths["full"] = full
    return paths


def sweep_file(folder: Path, name: str, text: str) -> str:
    """Write a sweep file; its path."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{name}.toml"
    path.write_text(text)
    return str(path)


def cli_tasks(args: argparse.Namespace, work: Path, fx: dict[str, Path]) -> list[dict]:
    """The argument cases (each one task of one step); ``--cli-cases`` of them, cycled."""
    m, pend, slider = (
        str(FOURBAR),
        str(EXAMPLES / "pendulum.toml"),
        str(EXAMPLES / "slider_crank_piston_clearance.toml"),
    )
    outs = work / "cliouts"
    counter = iter(range(10**6))

    def out() -> str:
        return str(outs / f"o{next(counter):04d}")

    quick = ["--t-end", "0.002", "--no-figures", "--no-ideal"]
    deep_value = "[" * DEEP + "1" + "]" * DEEP
    deep_table = "{a=" * DEEP + "1" + "}" * DEEP
    cases: list[tuple[str, list[str]]] = []
    for t in ["5e-324", "-1", "nan", "inf", "-inf", "1e300", "1 s", "0", "1e-320", "1e12",
              "0x10", "", "1e-15", " 0.001", "1e-16", "2e-15"]:  # fmt: skip
        cases.append((f"run --t-end {t!r}", ["run", m, "--out", out(), "--t-end", t,
                                              "--no-figures", "--no-ideal"]))  # fmt: skip
    sets = [f"solver.t_end={deep_value}", f"solver.t_end={deep_table}",
            "a." * DEEP + "b=1", "solver.max_step=1e300", "solver.max_step=5e-324",
            "solver.output_interval=5e-324", "solver.output_interval=1e300",
            "solver.wear_snapshot_interval=5e-324", "solver.rtol=0", "solver.atol=-1",
            "solver.max_steps=1e300", f"solver.max_steps={10**30}", "solver.max_steps=0",
            "solver.min_step=1", "solver.initial_step=1e300", "bodies.crank.mass=1e300",
            "bodies.crank.mass=5e-324", "bodies.nonexistent.mass=1", "=1", "noequals",
            "solver..t_end=1", "solver.t_end=", "bodies.0.mass=1", "bodies.99.mass=1",
            "bodies.-1.mass=1", "solver={}", "solver=1", "bodies=[]", "joints=[]",
            f"{CLEARANCE_PATH}.width=1e300", f"{CLEARANCE_PATH}.wear_coefficient=1e300 1/Pa",
            f"{CLEARANCE_PATH}.wear_coefficient=1e30 1/Pa", f"{CLEARANCE_PATH}.sectors=100000000",
            f"{CLEARANCE_PATH}.bearing_radius=9.8 mm", f"{CLEARANCE_PATH}=1",
            "drivers.motor.function.speed=1e300 rpm", "drivers.motor.function.speed=1e6 rpm",
            "drivers.motor.function={type='harmonic', amplitude=1e300, frequency=1e300}",
            "name=a\nZQXJ", "bodies.crank.name=a\nZQXJ", "solver.integrator=\"dopri5\"",
            "solver.t_end=1 parsec", "solver.t_end=1 kg", "extends=/etc/passwd",
            "bodies.crank.mass=\"1 kg^0\"", "bodies.crank.angle=50 percent",
            "bodies.crank.mass=1 nan", f"{CLEARANCE_PATH}.youngs_modulus=1e400 Pa",
            "bodies.crank.mass=__import__('os').system('touch /tmp/hostile_pwned')",
            "bodies.crank.mass={a=1}", "ground.points.crank_pivot=[1e300, 1e300]",
            "x" * 100000 + "=1", "solver.t_end=" + "9" * 5000]  # fmt: skip
    cases += [(f"run --set {brief(s, 60)}", ["run", m, "--out", out(), *quick, "--set", s])
              for s in sets]  # fmt: skip
    cases += [(f"check --set {brief(s, 60)}", ["check", m, "--set", s]) for s in sets[:6]]
    cases.append(("run with 2000 --set", ["run", m, "--out", out(), *quick,
                                          *["--set", "solver.rtol=1e-6"] * 2000]))  # fmt: skip
    cases.append(
        (
            "lock-up: coupler shortened",
            [
                "run",
                m,
                "--out",
                out(),
                "--t-end",
                "0.02",
                "--no-figures",
                "--no-ideal",
                "--set",
                "bodies.coupler.points.follower_end=[0.02, 0.0]",
                "--set",
                "bodies.coupler.points.crank_end=[-0.02, 0.0]",
            ],
        )
    )
    cases.append(
        (
            "check lock-up",
            [
                "check",
                m,
                "--set",
                "bodies.coupler.points.follower_end=[0.02, 0.0]",
                "--set",
                "bodies.coupler.points.crank_end=[-0.02, 0.0]",
            ],
        )
    )
    long_name = "n" * 300
    bad_outs = {"a file": str(fx["a_file"]), "under a file": str(fx["a_file"] / "x"),
                "/proc": "/proc/hostile_out", "/proc/self": "/proc/self/hostile",
                "/sys": "/sys/hostile", "/dev/null": "/dev/null", "/dev/full": "/dev/full",
                "name > 255 bytes": str(outs / long_name),
                "component > 255 bytes": str(outs / long_name / "x"),
                "path > 4096 bytes": str(outs / "/".join(["d" * 200] * 25)),
                "unicode > 255 bytes": str(outs / ("é" * 130)), "empty": "",
                "locked (chattr +i)": str(fx["locked"]),
                "in locked": str(fx["locked"] / "sub"),
                "locked parent": str(fx["locked_parent"] / "a" / "b"),
                "a run folder": str(fx["run"]), "a life folder": str(fx["life"]),
                "a sweep folder": str(fx["sweep"]), "newline": str(outs / f"a\n{MARKER}"),
                "NUL": str(outs / "a\x00b")}  # fmt: skip
    if "full" in fx:
        bad_outs["a full tmpfs"] = str(fx["full"] / "out")
    for what, target in bad_outs.items():
        cases.append((f"run --out {what}", ["run", m, "--out", target, *quick]))
        if what in (
            "a file",
            "/proc",
            "name > 255 bytes",
            "locked (chattr +i)",
            "a full tmpfs",
            "a run folder",
            "empty",
        ):
            cases.append((f"life --out {what}", ["life", m, "--out", target, "--cycles", "5",
                                                 "--no-figures"]))  # fmt: skip
            cases.append((f"sweep --out {what}", ["sweep", m, "--out", target, "--t-end",
                          "0.002", "--no-figures", "--workers", "1", "--vary",
                          f"{CLEARANCE_PATH}.friction_coefficient=0,0.1"]))  # fmt: skip
    if "full" in fx:
        cases.append(("run --out full tmpfs, figures", ["run", m, "--out", str(fx["full"] / "f"),
                      "--t-end", "0.01"]))  # fmt: skip
    swp = ["sweep", m, "--t-end", "0.002", "--no-figures", "--workers", "1"]
    fc = f"{CLEARANCE_PATH}.friction_coefficient"
    varies = [f"solver.t_end={deep_value}", "a." * DEEP + "b=1,2", "x", "a=", f"{fc}=0,,0.1",
              f"{fc}=[1,2", f"{fc}=\"a", f"{fc}=0", f"{fc}=0", "solver.t_end=5e-324,1e300",
              "name=../../escape,a/b,\x00", "name=" + ",".join(str(i) for i in range(3000)),
              f"{fc}=nan,inf", "bodies.crank.mass=1 kg^0,50 percent", f"{fc}={deep_table}",
              "=1,2", "..=1", f"{fc}=" + "0," * 100000 + "0"]  # fmt: skip
    for v in varies:
        cases.append((f"sweep --vary {brief(v, 50)}", [*swp, "--out", out(), "--vary", v]))
    cases.append(("sweep same path twice", [*swp, "--out", out(), "--vary", f"{fc}=0",
                                            "--vary", f"{fc}=0.1"]))  # fmt: skip
    cases.append(
        (
            "sweep 3 x 40 cases, cartesian of names",
            [
                *swp,
                "--out",
                out(),
                "--vary",
                "name=" + ",".join(f"n{i}" for i in range(40)),
                "--vary",
                "description=" + ",".join(f"d{i}" for i in range(40)),
                "--vary",
                "solver.rtol=" + ",".join(f"{i}e-6" for i in range(1, 41)),
            ],
        )
    )
    sfd = work / "sweepfiles"
    sweep_files = {
        "deep": f'[vary]\n"solver.t_end" = {deep_value}\n',
        "deep dotted": "[vary]\n" + "a." * DEEP + "b = [1]\n",
        "scalar vary": "vary = 1\n",
        "vary not list": '[vary]\n"solver.t_end" = 0.1\n',
        "empty list": '[vary]\n"solver.t_end" = []\n',
        "unknown table": '[bogus]\na = 1\n[vary]\n"solver.t_end" = [0.001]\n',
        "set deep": f'[set]\n"solver.t_end" = {deep_table}\n[vary]\n"solver.rtol" = [1e-6]\n',
        "nested vary": "[vary.solver]\nt_end = [0.001, 0.002]\n",
        "not toml": "this is not = = toml",
        "binary": "\x00\x01\x02",
        "nan values": '[vary]\n"solver.t_end" = [nan, inf]\n',
        "mixed types": '[vary]\n"solver.t_end" = [0.001, "1 ms", true, [1], {a = 1}]\n',
        "huge int": '[vary]\n"solver.max_steps" = [' + "9" * 5000 + "]\n",
    }
    for name, text in sweep_files.items():
        path = sweep_file(sfd, name.replace(" ", "_"), text)
        cases.append((f"sweep --file {name}", [*swp, "--out", out(), "--file", path]))
    for path in ["/nonexistent.toml", str(sfd), "/dev/null", "/etc/passwd"]:
        cases.append((f"sweep --file {path}", [*swp, "--out", out(), "--file", path]))
    for w in ["0", "-1", "1000000", "nan"]:
        cases.append((f"sweep --workers {w}", ["sweep", m, "--out", out(), "--t-end", "0.002",
                      "--no-figures", "--workers", w, "--vary", f"{fc}=0,0.1"]))  # fmt: skip
    for c in ["0", "-1", "1000000000000000000000", "9223372036854775808"]:
        cases.append((f"sweep --cycles {c}", [*swp, "--out", out(), "--cycles", c,
                                              "--vary", f"{fc}=0"]))  # fmt: skip
    for s in ["not a url", "tcp://127.0.0.1:1", "tcp://[::1", ""]:
        cases.append((f"sweep --scheduler {s!r}", [*swp, "--out", out(), "--scheduler", s,
                                                   "--vary", f"{fc}=0"]))  # fmt: skip
    life = ["life", m, "--no-figures"]
    life_opts = [
        ["--cycles", "0"],
        ["--cycles", "-1"],
        ["--cycles", "1000000000000000000000"],
        ["--cycles", "9223372036854775807"],
        ["--cycles", "1e3"],
        ["--cycles", "5", "--settle-cycles", "-1"],
        ["--cycles", "5", "--settle-cycles", "0"],
        ["--cycles", "5", "--measure-cycles", "0"],
        ["--cycles", "5", "--steady-tolerance", "nan"],
        ["--cycles", "5", "--steady-tolerance", "-1"],
        ["--cycles", "5", "--steady-tolerance", "inf"],
        ["--cycles", "5", "--max-update-cycles", "0"],
        ["--cycles", "50", "--max-change", "0%"],
        ["--cycles", "5", "--max-change", "-1 um"],
        ["--cycles", "5", "--max-change", "nan"],
        ["--cycles", "5", "--max-change", "1 kg"],
        ["--cycles", "5", "--max-change", "1e400%"],
        ["--cycles", "5", "--max-change", ""],
        ["--cycles", "5", "--max-change", "5e-324 m"],
        ["--cycles", "50", "--max-change", "1e300 m"],
        ["--cycles", "5", "--max-growth", "nan"],
        ["--cycles", "5", "--max-growth", "0"],
        ["--cycles", "5", "--max-growth", "-1"],
        ["--cycles", "5", "--max-growth", "inf"],
        ["--cycles", "50", "--max-growth", "1e300"],
        ["--cycles", "5", "--set", f"{CLEARANCE_PATH}.wear_coefficient=1e300 1/Pa"],
        ["--cycles", "5", "--set", "solver.t_end=5e-324"],
        ["--cycles", "5", "--set", f"drivers.motor.function.speed={deep_value}"],
    ]
    for opts in life_opts:
        cases.append((f"life {' '.join(opts)[:60]}", [*life, "--out", out(), *opts]))
    for name in ("empty", "run", "damaged_life", "life_nostate", "sweep"):
        target = work / "resume" / name
        if fx[name].is_dir():
            shutil.copytree(fx[name], target, symlinks=True)
        cases.append((f"life --resume on {name}", [*life, "--out", str(target), "--cycles",
                                                   "20", "--resume"]))  # fmt: skip
    cases.append(("life --resume nowhere", [*life, "--out", out(), "--cycles", "5", "--resume"]))
    cases.append(("life on pendulum (no clearance)", [*life, "--out", out(), "--cycles", "5"]))
    cases.append(("life on slider", ["life", slider, "--out", out(), "--cycles", "3",
                                     "--no-figures"]))  # fmt: skip
    cases.append(("run pendulum --t-end 5e-324", ["run", pend, "--out", out(), "--t-end",
                                                  "5e-324"]))  # fmt: skip
    for name, folder in fx.items():
        if name in ("a_file", "locked_parent", "full"):
            continue
        cases.append((f"plot {name}", ["plot", str(folder), "--no-animation"]))
    for target in ["/nonexistent", "/proc", "/dev/null", "", str(fx["a_file"]), "/"]:
        cases.append((f"plot {target!r}", ["plot", target, "--no-animation"]))
    for target in ["/nonexistent.toml", str(work), "/dev/null", "", "/etc/passwd", "/proc/self/mem",
                   str(REPO / ".venv" / "bin" / "python"), "/dev/zero"]:  # fmt: skip
        cases.append((f"check {target!r}", ["check", target]))
    cases.append(("run model /dev/null", ["run", "/dev/null", "--out", out(), *quick]))
    rng = random.Random(args.seed + 1)
    rng.shuffle(cases)
    tasks = []
    for i in range(args.cli_cases or len(cases)):
        label, argv = cases[i % len(cases)]
        kind = argv[0]
        outdir = argv[argv.index("--out") + 1] if "--out" in argv else None
        tasks.append({"id": f"c{i:04d}", "cat": "cli", "label": label, "size": len(str(argv)),
                      "steps": [{"kind": kind, "argv": argv, "out": outdir,
                                 "timeout": args.timeout}]})  # fmt: skip
    return tasks


# --------------------------------------------------------------------------------------------
# The worker: runs tasks in-process, one result line per task


class CaseTimeout(BaseException):
    """The per-step time limit passed (not an Exception: no ``except Exception`` catches it)."""


def _alarm(signum: int, frame: object) -> None:
    raise CaseTimeout


def short_file(name: str) -> str:
    """A traceback file name relative to the package or library."""
    found = re.search(r"(/src/|/site-packages/|/lib/python3\.\d+/)", name)
    return name[found.end() :] if found else name


def exception_info(exc: BaseException, tb) -> dict:
    """Type, last frame and deepest jointwear frame of an exception."""
    frames = traceback.extract_tb(tb)
    last = frames[-1] if frames else None
    own = [f for f in frames if "/jointwear/" in f.filename]
    return {
        "exc_type": type(exc).__name__,
        "message": " ".join(str(exc).split())[:300],
        "frame": f"{short_file(last.filename)}:{last.lineno}" if last else "?",
        "jw_frame": f"{short_file(own[-1].filename)}:{own[-1].lineno}" if own else None,
        "tb_tail": [f"{short_file(f.filename)}:{f.lineno} {f.name}" for f in frames[-4:]],
    }


def traceback_in_text(text: str) -> dict:
    """Exception type and last frame of a traceback printed in ``text``."""
    frames = re.findall(r'File "([^"]+)", line (\d+)', text)
    tail = text[text.rfind("Traceback") :].strip().splitlines()
    exc = next(
        (
            line
            for line in reversed(tail)
            if re.match(
                r"^\w[\w.]*(Error|Exception|"
                r"Interrupt|Exit)\b",
                line,
            )
        ),
        "?",
    )
    file, line = frames[-1] if frames else ("?", "?")
    own = [f for f in frames if "/jointwear/" in f[0]]
    return {
        "exc_type": exc.split(":")[0],
        "message": exc[:300],
        "frame": f"{short_file(file)}:{line}",
        "jw_frame": f"{short_file(own[-1][0])}:{own[-1][1]}" if own else None,
    }


def is_file(path: Path) -> bool:
    """``path.is_file()``, False for a path the system refuses (a name too long)."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def summary_problems(folder: Path, want_success: bool) -> list[str]:
    """What is wrong with a results folder's summary.json (empty: fine)."""
    path = folder / "summary.json"
    if not is_file(path):
        return ["no_summary"]
    try:
        text = path.read_text()
    except OSError:
        return ["unreadable_summary"]
    bad: list[str] = []

    def constant(name: str) -> float:
        bad.append(name)
        return float("nan")

    try:
        summary = json.loads(text, parse_constant=constant)
    except ValueError:
        return ["incomplete_summary"]
    problems = []
    if bad:
        problems.append("nonfinite_in_summary")
    for p, v in walk(summary):
        if isinstance(v, float) and not math.isfinite(v):
            problems.append(f"nonfinite_in_summary:{show(p)}")
            break
    if not isinstance(summary, dict) or "status" not in summary:
        problems.append("summary_without_status")
    elif want_success and summary["status"] != "success":
        problems.append(f"exit0_status_{summary['status']}")
    if want_success:
        for name in ("wear.csv", "timeseries.csv"):
            csv = folder / name
            if is_file(csv) and csv.stat().st_size < 50_000_000:
                body = csv.read_text(errors="replace").split("\n", 1)[-1]
                if NONFINITE_WORD.search(body):
                    problems.append(f"nonfinite_in_{name}")
    return problems


def figure_problems(folder: Path, animation: bool) -> list[str]:
    """What is missing of a successful run's figures: the energy PNG, and the GIF if asked."""
    problems = [] if is_file(folder / "energy.png") else ["run_without_figures"]
    if animation and not is_file(folder / "mechanism.gif"):
        problems.append("run_without_animation")
    return problems


def status_of(folder: Path) -> str | None:
    """The status in a folder's summary.json, if any."""
    with contextlib.suppress(OSError, ValueError, AttributeError):
        return json.loads((folder / "summary.json").read_text()).get("status")
    return None


def analyse(step: dict, exit_code: int, output: str, stderr: str, info: dict | None,
            task: dict) -> list[str]:  # fmt: skip
    """The failure kinds of one finished step."""
    kinds = []
    if info is not None:
        kinds.append("traceback")
    elif "Traceback (most recent call last)" in output:
        kinds.append("traceback_text")
    if info is None and exit_code not in ALLOWED_EXITS:
        kinds.append(f"bad_exit_{exit_code}")
    if CONTROL.search(output):
        kinds.append("raw_control_char_in_output")
    if exit_code == 2 and "Usage:" not in output:
        for line in output.split("\n"):
            if line.startswith(MARKER) or (line[:1].isspace() and line.strip()):
                kinds.append("problem_split_over_lines")
                break
    kind, out = step["kind"], step.get("out")
    if info is None and kind in ("run", "life") and out and exit_code in (0, 1):
        kinds += summary_problems(Path(out), want_success=exit_code == 0)
    if kind == "run" and exit_code == 0 and "--no-figures" not in step["argv"]:
        kinds += figure_problems(Path(out) / "figures", "--animation" in step["argv"])
    sweep_table = kind == "sweep" and out and is_file(Path(out) / "sweep.csv")
    if info is None and kind == "sweep" and out and exit_code in (0, 1) and not sweep_table:
        kinds.append("sweep_without_table")
    if exit_code == 3 and kind == "run":
        found = re.search(r"the results are in (\S+)", output)
        if not found or not is_file(Path(found.group(1)) / "summary.json"):
            kinds.append("exit3_results_not_found")
    if kind == "check" and exit_code == 0:
        if NONFINITE_WORD.search(output):
            kinds.append("check_valid_with_nonfinite")
        if task.get("flags", {}).get("refuse"):
            kinds.append("accepted_bad_value")
    if PWNED.exists():
        kinds.append("model_value_evaluated")
    return kinds


def worker(task_file: Path, result_file: Path) -> None:
    """Run the tasks of ``task_file`` not yet in ``result_file``, in this process."""
    limit_memory()
    from typer.testing import CliRunner

    from jointwear.cli import app

    done = set()
    if result_file.exists():
        for line in result_file.read_text().splitlines():
            record = json.loads(line)
            done.add(record["id"])
    tasks = [json.loads(line) for line in task_file.read_text().splitlines()]
    signal.signal(signal.SIGALRM, _alarm)
    runner = CliRunner()
    with result_file.open("a") as results:
        for task in tasks:
            if task["id"] in done:
                continue
            results.write(json.dumps({"id": task["id"], "started": True}) + "\n")
            results.flush()
            steps_out, valid, timed_out = [], None, False
            for step in task["steps"]:
                when = step.get("when", "always")
                if when == "if_valid" and valid is not True:
                    continue
                start = time.perf_counter()
                signal.alarm(int(step["timeout"]))
                info = None
                try:
                    result = runner.invoke(app, step["argv"], catch_exceptions=True)
                    signal.alarm(0)
                except CaseTimeout:
                    timed_out = True
                    steps_out.append({"kind": step["kind"], "argv": step["argv"],
                                      "problems": ["timeout"], "exit": None,
                                      "elapsed": time.perf_counter() - start})  # fmt: skip
                    break
                except RecursionError as error:  # escaped the runner's own net
                    signal.alarm(0)
                    steps_out.append(
                        {
                            "kind": step["kind"],
                            "argv": step["argv"],
                            "exit": None,
                            "problems": ["traceback"],
                            **exception_info(error, error.__traceback__),
                        }
                    )
                    continue
                exc = result.exception
                if exc is not None and not isinstance(exc, SystemExit):
                    info = exception_info(exc, result.exc_info[2])
                output = result.output
                kinds = analyse(step, result.exit_code, output, result.stderr, info, task)
                if info is None and "traceback_text" in kinds:
                    info = traceback_in_text(output)
                entry = {
                    "kind": step["kind"],
                    "argv": step["argv"],
                    "exit": result.exit_code,
                    "problems": kinds,
                    "elapsed": time.perf_counter() - start,
                    "tail": output.strip().splitlines()[-3:] if output.strip() else [],
                    "status": status_of(Path(step["out"])) if step.get("out") else None,
                }
                if info:
                    entry.update(info)
                if result.exit_code == 2 and "Usage:" not in output:
                    entry["messages"] = [line for line in output.splitlines() if line][:20]
                steps_out.append(entry)
                if step["kind"] == "check":
                    valid = result.exit_code == 0
            results.write(json.dumps({"id": task["id"], "steps": steps_out}) + "\n")
            results.flush()
            if timed_out:  # the process may be left in any state: start afresh
                os._exit(75)


def run_workers(tasks: list[dict], work: Path, name: str, n: int, hard_timeout: float) -> dict:
    """Run ``tasks`` in ``n`` restartable worker processes; the results by task id."""
    shards = [tasks[i::n] for i in range(n)]
    records: dict[str, dict] = {}
    lock = threading.Lock()
    cwd = work / "cwd"
    cwd.mkdir(exist_ok=True)

    def shard(index: int, items: list[dict]) -> None:
        task_file = work / f"{name}_tasks_{index}.jsonl"
        result_file = work / f"{name}_results_{index}.jsonl"
        task_file.write_text("".join(json.dumps(t) + "\n" for t in items))
        ids = {t["id"] for t in items}
        while True:
            proc = subprocess.Popen(
                [sys.executable, __file__, "--worker", str(task_file), str(result_file)],
                cwd=cwd,
                stdout=subprocess.DEVNULL,
                stderr=(work / f"{name}_worker_{index}.log").open("a"),
            )
            last_size, last_change = -1, time.monotonic()
            while proc.poll() is None:
                time.sleep(1.0)
                size = result_file.stat().st_size if result_file.exists() else 0
                if size != last_size:
                    last_size, last_change = size, time.monotonic()
                elif time.monotonic() - last_change > hard_timeout:
                    proc.kill()
                    proc.wait()
            finished, started = _read_results(result_file)
            pending = [i for i in started if i not in finished]
            with result_file.open("a") as out:
                for task_id in pending:  # the task the worker died or hung in
                    reason = "hang" if proc.returncode == -9 else f"worker_exit_{proc.returncode}"
                    if proc.returncode == 75:
                        continue
                    out.write(json.dumps({"id": task_id, "steps": [{"kind": "?", "argv": [],
                              "exit": None, "problems": [reason]}]}) + "\n")  # fmt: skip
            finished, _ = _read_results(result_file)
            if ids <= set(finished):
                with lock:
                    records.update(finished)
                return

    with ThreadPoolExecutor(n) as pool:
        list(pool.map(shard, range(n), shards))
    return records


def _read_results(path: Path) -> tuple[dict, list]:
    finished, started = {}, []
    if path.exists():
        for line in path.read_text().splitlines():
            record = json.loads(line)
            if record.get("started"):
                started.append(record["id"])
            else:
                finished[record["id"]] = record
    return finished, started


# --------------------------------------------------------------------------------------------
# Signals


def phase_times(argv: list[str], out: Path, cwd: Path) -> dict:
    """Times from start of an undisturbed run: first file, summary.json, exit."""
    start = time.monotonic()
    proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)  # fmt: skip
    first = summary = None
    marker = "sweep.csv" if argv[1] == "sweep" else "summary.json"
    while proc.poll() is None:
        now = time.monotonic() - start
        if first is None and out.exists() and any(out.iterdir()):
            first = now
        if summary is None and (out / marker).exists():
            summary = now
        time.sleep(0.005)
    end = time.monotonic() - start
    return {"first": first or end, "summary": summary or end, "exit": end}


def session_processes(session: int) -> list[int]:
    """Processes of a session (those a signalled command left behind)."""
    pids = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            with contextlib.suppress(OSError, IndexError, ValueError):
                fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
                if int(fields[3]) == session and fields[0] != "Z":
                    pids.append(int(entry.name))
    return pids


SIGNAL_COMMANDS = {
    "run": lambda out: ["run", str(FOURBAR), "--out", str(out), "--t-end", "0.3"],
    "run_noextras": lambda out: [
        "run",
        str(FOURBAR),
        "--out",
        str(out),
        "--t-end",
        "0.3",
        "--no-figures",
    ],
    "life": lambda out: ["life", str(FOURBAR), "--out", str(out), "--cycles", "1000"],
    "sweep": lambda out: [
        "sweep",
        str(FOURBAR),
        "--out",
        str(out),
        "--t-end",
        "0.1",
        "--vary",
        f"{CLEARANCE_PATH}.friction_coefficient=0,0.1,0.2",
        "--workers",
        "2",
    ],
    "sweep_life": lambda out: [
        "sweep",
        str(FOURBAR),
        "--out",
        str(out),
        "--cycles",
        "300",
        "--vary",
        f"{CLEARANCE_PATH}.friction_coefficient=0,0.1",
        "--workers",
        "2",
        "--no-figures",
    ],
}
SIGNAL_WEIGHTS = {"run": 5, "run_noextras": 2, "life": 2, "sweep": 2, "sweep_life": 1}


def signal_campaign(args: argparse.Namespace, work: Path) -> list[dict]:
    """SIGINT/SIGTERM at random moments; one record per case."""
    base = work / "signals"
    base.mkdir()
    cwd = work / "cwd"
    cwd.mkdir(exist_ok=True)
    phases = {}
    for kind, make in SIGNAL_COMMANDS.items():
        out = base / f"baseline_{kind}"
        phases[kind] = phase_times([str(JOINTWEAR), *make(out)[0:]], out, cwd)
    print("signal baselines [s]:", json.dumps(phases), flush=True)
    rng = random.Random(args.seed + 2)
    plan = []
    kinds = list(SIGNAL_WEIGHTS)
    for i in range(args.signals):
        kind = rng.choices(kinds, weights=[SIGNAL_WEIGHTS[k] for k in kinds])[0]
        times = phases[kind]
        if rng.random() < 0.5:
            delay = rng.uniform(0, min(8.0, times["exit"] + 0.5))
        else:  # near a boundary, where windows are narrow
            delay = max(
                0.0,
                rng.gauss(
                    rng.choice([times["first"], times["summary"], times["first"] - 0.1]), 0.08
                ),
            )
        sig = rng.choice([signal.SIGINT, signal.SIGTERM])
        group = rng.random() < 0.5
        double = rng.random() < 0.15  # a second signal shortly after
        plan.append((i, kind, delay, sig, group, double))

    def one(item: tuple) -> dict:
        i, kind, delay, sig, group, double = item
        out = base / f"s{i:03d}"
        argv = [str(JOINTWEAR), *SIGNAL_COMMANDS[kind](out)]
        stdout, stderr = base / f"s{i:03d}.out", base / f"s{i:03d}.err"
        with stdout.open("w") as o, stderr.open("w") as e:
            proc = subprocess.Popen(argv, cwd=cwd, stdout=o, stderr=e, start_new_session=True)
            with contextlib.suppress(subprocess.TimeoutExpired):
                proc.wait(timeout=delay)
            sent = proc.poll() is None
            if sent:
                with contextlib.suppress(ProcessLookupError):
                    (os.killpg if group else os.kill)(proc.pid, sig)
                if double:
                    time.sleep(rng.uniform(0.01, 0.5))
                    with contextlib.suppress(ProcessLookupError):
                        (os.killpg if group else os.kill)(proc.pid, sig)
            try:
                rc = proc.wait(timeout=180)
                hung = False
            except subprocess.TimeoutExpired:
                hung = True
                proc.kill()
                rc = proc.wait()
        time.sleep(0.3)
        orphans = session_processes(proc.pid)
        for pid in orphans:  # processes this case started, by id
            with contextlib.suppress(ProcessLookupError):
                os.kill(pid, signal.SIGKILL)
        err_text, out_text = stderr.read_text(errors="replace"), stdout.read_text(errors="replace")
        problems = []
        info = None
        if "Traceback (most recent call last)" in err_text + out_text:
            problems.append("traceback_text")
            info = traceback_in_text(err_text + out_text)
        if hung:
            problems.append("hang_after_signal")
        if rc not in SIGNAL_EXITS:
            problems.append(f"bad_exit_{rc}")
        if orphans:
            problems.append("orphan_processes")
        problems += _signal_folder_problems(
            kind, out, rc, out_text + err_text, delay, phases[kind], sent
        )
        record = {
            "id": f"s{i:03d}",
            "kind": kind,
            "delay": round(delay, 3),
            "sent": sent,
            "signal": signal.Signals(sig).name,
            "group": group,
            "double": double,
            "exit": rc,
            "problems": problems,
            "status": status_of(out),
            "argv": argv,
            "stderr_tail": err_text.strip().splitlines()[-3:],
        }
        if info:
            record.update(info)
        return record

    with ThreadPoolExecutor(2) as pool:
        return list(pool.map(one, plan))


def _signal_folder_problems(kind: str, out: Path, rc: int, stdout: str, delay: float,
                            times: dict, sent: bool) -> list[str]:  # fmt: skip
    """Whether the folder says what happened, and nothing finished was lost."""
    problems = []
    temporaries = [p for p in out.rglob("*.tmp")] if out.exists() else []
    if temporaries:
        problems.append("leftover_tmp_files")
    is_sweep = kind.startswith("sweep")
    marker = out / ("sweep.csv" if is_sweep else "summary.json")
    if is_sweep:
        cases = out / "cases"
        for case in cases.iterdir() if cases.is_dir() else []:
            if (case / "summary.json").exists() and "incomplete_summary" in summary_problems(
                case, False
            ):
                problems.append("incomplete_case_summary")
        finished_lines = re.findall(r"\] (\S+): success", stdout)
        for case in finished_lines:
            if (
                status_of(out / "cases" / case) != "success"
                and not (out / "cases" / case / "life.csv").exists()
            ):
                problems.append("finished_case_lost")
        if rc in (0, 1) and not marker.exists():
            problems.append("exit_0_1_without_table")
        return problems
    if marker.exists():
        summary_issues = summary_problems(out, want_success=rc == 0)
        problems += [p for p in summary_issues if not p.startswith("nonfinite_in_timeseries")]
    else:
        leftovers = [p for p in out.rglob("*") if p.is_file() and p.name != ".jointwear-files"
                     and "checkpoint" not in p.parts] if out.exists() else []  # fmt: skip
        if leftovers and kind.startswith("run"):
            problems.append("results_without_summary")
        if rc in (0, 1):
            problems.append("exit_0_1_without_summary")
    if "success:" in stdout and status_of(out) not in ("success",):
        problems.append("finished_run_lost")
    if kind.startswith("run") and sent and delay > times["summary"] + 0.6:
        summary = {}
        with contextlib.suppress(OSError, ValueError):
            summary = json.loads(marker.read_text())
        reached = summary.get("stats", {}).get("t_reached", 0) if isinstance(summary, dict) else 0
        if not reached or reached < 0.3 - 1e-9:
            problems.append("finished_run_lost")
    return problems


# --------------------------------------------------------------------------------------------
# Files: links, users' files, locked and full folders


def tree_state(root: Path) -> dict[str, str]:
    """Every path under ``root`` (links not followed) -> a hash of what it is."""
    state = {}
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False):
        for name in dirnames + filenames:
            path = Path(dirpath) / name
            rel = str(path.relative_to(root))
            if path.is_symlink():
                state[rel] = "link:" + os.readlink(path)
            elif path.is_file():
                state[rel] = "file:" + hashlib.sha256(path.read_bytes()).hexdigest()[:16]
            elif path.is_dir():
                state[rel] = "dir"
    return state


def files_campaign(args: argparse.Namespace, work: Path) -> list[dict]:
    """Runs, life runs and sweeps into folders holding links and the user's own files."""
    from jointwear.figures.names import ALL_FIGURES

    fig_names = sorted(ALL_FIGURES)
    cwd = work / "cwd"
    cwd.mkdir(exist_ok=True)
    records = []
    quick = ["--t-end", "0.005"]
    sweep_args = ["--t-end", "0.005", "--workers", "1", "--vary",
                  f"{CLEARANCE_PATH}.friction_coefficient=0,0.1"]  # fmt: skip
    commands = {
        "run": ["run", str(FOURBAR), *quick],
        "run_noideal": ["run", str(FOURBAR), *quick, "--no-ideal"],
        "sweep": ["sweep", str(FOURBAR), *sweep_args],
        "life": ["life", str(FOURBAR), "--cycles", "20"],
    }

    def sandbox(name: str) -> tuple[Path, Path]:
        box = work / "files" / name
        (box / "outside").mkdir(parents=True)
        (box / "outside" / "sentinel.txt").write_text("do not touch")
        for sub in ("ideal", "figures", "checkpoint", "cases", "plain"):
            target = box / "outside" / sub
            target.mkdir()
            (target / "sentinel.txt").write_text(f"sentinel {sub}")
            for fname in ("summary.json", "timeseries.csv", "wear.csv", "model.json",
                          ".jointwear-files", "checkpoint.json", *fig_names):  # fmt: skip
                (target / fname).write_text(f"user's {fname}")
        out = box / "OUT"
        out.mkdir()
        return box, out

    def user_files(out: Path) -> None:
        (out / "ideal").mkdir(exist_ok=True)
        (out / "figures").mkdir(exist_ok=True)
        (out / "wear.csv").write_text("my own wear table\n")
        (out / "ideal" / "x.csv").write_text("mine\n")
        (out / "figures" / "mine.png").write_bytes(b"\x89PNG mine")
        (out / "notes.txt").write_text("my notes\n")

    def named_like_tool(out: Path) -> None:  # to be refused, and left alone
        user_files(out)
        (out / "ideal" / "summary.json").write_text('{"mine": true}\n')
        (out / "figures" / "fig9_wear_polar.png").write_bytes(b"\x89PNG mine too")
        (out / "sweep.csv").write_text("mine\n")
        (out / "life.csv").write_text("mine\n")

    setups = {
        "link_ideal": lambda box, out: (out / "ideal").symlink_to(box / "outside" / "ideal"),
        "link_figures": lambda box, out: (out / "figures").symlink_to(box / "outside" / "figures"),
        "link_checkpoint": lambda box, out: (out / "checkpoint").symlink_to(
            box / "outside" / "checkpoint"
        ),
        "link_cases": lambda box, out: (out / "cases").symlink_to(box / "outside" / "cases"),
        "link_summary": lambda box, out: (out / "summary.json").symlink_to(
            box / "outside" / "plain" / "summary.json"
        ),
        "link_record": lambda box, out: (out / ".jointwear-files").symlink_to(
            box / "outside" / "plain" / ".jointwear-files"
        ),
        "record_traversal": lambda box, out: (out / ".jointwear-files").write_text(
            json.dumps(["../outside/sentinel.txt", "/etc/hostname", "..", "wear.csv"])
        ),
        "user_files": lambda box, out: user_files(out),
        "named_like_tool": lambda box, out: named_like_tool(out),
        "user_files_after_run": None,  # a finished run first, then the user's files
    }
    for setup_name, setup in setups.items():
        for cmd_name, argv in commands.items():
            if setup_name == "link_cases" and cmd_name != "sweep":
                continue
            if setup_name == "link_checkpoint" and cmd_name != "life":
                continue
            box, out = sandbox(f"{setup_name}_{cmd_name}")
            tool = tree_state(box)
            if setup is None:
                _sh(str(JOINTWEAR), *argv, "--out", str(out), cwd=cwd)
                tool = tree_state(box)
                user_files(out)
            else:
                setup(box, out)
            mine = {p for p, v in tree_state(box).items() if tool.get(p) != v}
            records.append(
                _files_case(
                    f"{setup_name}/{cmd_name}",
                    box,
                    out,
                    [str(JOINTWEAR), *argv, "--out", str(out)],
                    cwd,
                    mine,
                )
            )
    # folders that become unwritable, or vanish, while the run goes on
    for i, (how, kind, delay) in enumerate([("lock", "run", 1.2), ("lock", "run", 1.6),
                                            ("replace", "run", 1.4), ("lock", "life", 2.0),
                                            ("lock", "sweep", 2.5), ("lock_ideal", "run", 1.3),
                                            ("lock", "run", 3.0)]):  # fmt: skip
        box, out = sandbox(f"midrun_{how}_{kind}_{i}")
        argv = {
            "run": ["run", str(FOURBAR), "--t-end", "0.3"],
            "life": ["life", str(FOURBAR), "--cycles", "400"],
            "sweep": [
                "sweep",
                str(FOURBAR),
                "--t-end",
                "0.1",
                "--workers",
                "1",
                "--vary",
                f"{CLEARANCE_PATH}.friction_coefficient=0,0.1,0.2",
            ],
        }[kind]
        records.append(_midrun_case(f"midrun_{how}/{kind}", box, out,
                                    [str(JOINTWEAR), *argv, "--out", str(out)], cwd, how,
                                    delay))  # fmt: skip
    return records


def _files_case(label: str, box: Path, out: Path, argv: list[str], cwd: Path,
                mine: set[str]) -> dict:  # fmt: skip
    """Run ``argv`` and compare the sandbox before and after (``mine``: the user's paths)."""
    before = tree_state(box)
    result = _sh(*argv, cwd=cwd, timeout=300)
    after = tree_state(box)
    return _compare(label, box, out, argv, before, after, result.returncode,
                    result.stdout + result.stderr, mine)  # fmt: skip


def _midrun_case(label: str, box: Path, out: Path, argv: list[str], cwd: Path, how: str,
                 delay: float) -> dict:  # fmt: skip
    """Make the results folder unwritable (or replace it by a file) while the run goes on."""
    proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)  # fmt: skip
    time.sleep(delay)
    target = out / "ideal" if how == "lock_ideal" else out
    if how == "replace":
        shutil.rmtree(out, ignore_errors=True)
        out.write_text("now a file")
    else:
        target.mkdir(parents=True, exist_ok=True)
        _sh("chattr", "+i", str(target))
    before = tree_state(box)
    try:
        text, _ = proc.communicate(timeout=300)
    except subprocess.TimeoutExpired:
        proc.kill()
        text, _ = proc.communicate()
    _sh("chattr", "-i", str(target))
    after = tree_state(box)
    record = _compare(label, box, out, argv, before, after, proc.returncode, text, set())
    rescued = re.search(r"the results are in (\S+)", text)
    marker = {"sweep": "sweep.csv", "life": "checkpoint/checkpoint.json"}.get(
        argv[1], "summary.json"
    )
    kept = (out.is_dir() and is_file(out / marker)) or bool(
        rescued and is_file(Path(rescued.group(1)) / "summary.json")
    )
    if argv[1] == "sweep":  # finished cases kept in their folders
        kept = kept or any((out / "cases").glob("*/summary.json"))
    if (
        proc.returncode == 3
        and argv[1] == "run"
        and not (rescued and Path(rescued.group(1)).is_dir())
    ):
        record["problems"].append("rescue_folder_missing")
    if proc.returncode != 2 and not kept:
        record["problems"].append("computed_results_lost")
    record["delay"] = delay
    return record


def _compare(label: str, box: Path, out: Path, argv: list[str], before: dict, after: dict,
             rc: int, text: str, mine: set[str] | None = None) -> dict:  # fmt: skip
    """Changes outside OUT, and to files in OUT the tool did not write."""
    out_rel = str(out.relative_to(box))
    problems = []
    touched = sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p)
                     and not (p == out_rel or p.startswith(out_rel + "/")))  # fmt: skip
    user = [p for p, v in before.items() if p.startswith(out_rel + "/")
            and (mine is None or p in mine) and v.startswith(("file:", "link:"))
            and after.get(p) != v and not p.endswith(".jointwear-files")]  # fmt: skip
    if touched:
        problems.append("touched_outside")
    if user:
        problems.append("user_file_changed")
    info = None
    if "Traceback (most recent call last)" in text:
        problems.append("traceback_text")
        info = traceback_in_text(text)
    if rc not in ALLOWED_EXITS:
        problems.append(f"bad_exit_{rc}")
    if CONTROL.search(text):
        problems.append("raw_control_char_in_output")
    record = {"id": label, "argv": argv, "exit": rc, "problems": problems,
              "touched_outside": touched[:10], "user_files_changed": user[:10],
              "tail": text.strip().splitlines()[-3:]}  # fmt: skip
    if info:
        record.update(info)
    return record


# --------------------------------------------------------------------------------------------
# Report


COLUMNS = ["cases", "tracebacks", "bad exit", "non-finite ok", "touched outside", "user files",
           "lost", "timeouts", "other"]  # fmt: skip


def tally(problem_lists: list[list[str]]) -> dict[str, int]:
    """Counts per column of the table, over the cases (one list of kinds per case)."""
    row = dict.fromkeys(COLUMNS, 0)
    row["cases"] = len(problem_lists)
    for kinds in problem_lists:
        row["tracebacks"] += any(k.startswith("traceback") for k in kinds)
        row["bad exit"] += any(k.startswith("bad_exit") or k.startswith("worker_exit")
                               for k in kinds)  # fmt: skip
        row["non-finite ok"] += any("nonfinite" in k for k in kinds)
        row["touched outside"] += "touched_outside" in kinds
        row["user files"] += "user_file_changed" in kinds
        row["lost"] += any("lost" in k for k in kinds)
        row["timeouts"] += any(k in ("timeout", "hang", "hang_after_signal") for k in kinds)
        row["other"] += any(not k.startswith(("traceback", "bad_exit", "worker_exit", "timeout",
                                              "hang")) and "nonfinite" not in k and "lost" not in k
                            and k not in ("touched_outside", "user_file_changed")
                            for k in kinds)  # fmt: skip
    return row


def failure_class(kind: str, entry: dict, record: dict, category: str) -> str:
    """The class key of one failure: exception and last frame, or kind and command."""
    if kind.startswith("traceback"):
        return f"{entry.get('exc_type', '?')} @ {entry.get('frame', '?')}"
    if category == "files":
        command = record["id"]
    else:
        command = entry.get("kind") or record.get("kind") or "?"
    detail = ""
    if kind == "accepted_bad_value":
        refused = record.get("flags", {}).get("refuse", ["?"])[0]
        detail = " " + refused.rpartition("=")[2]
    elif kind in ("timeout", "hang") and record.get("notes"):
        detail = " " + record["notes"][0].split(" = ")[0].rpartition(".")[2][:30]
    return f"{kind} [{category}:{command}]{detail}"


def collect(results: dict[str, list[dict]]) -> dict[str, dict]:
    """One reproducer per failure class (the smallest), with counts."""
    classes: dict[str, dict] = {}
    for category, records in results.items():
        for record in records:
            entries = record.get("steps") or [record]
            for entry in entries:
                for kind in entry.get("problems", []):
                    key = failure_class(kind, entry, record, category)
                    size = record.get("size", 0) + len(str(entry.get("argv")))
                    found = classes.setdefault(key, {"count": 0, "size": math.inf})
                    found["count"] += 1
                    if size < found["size"]:
                        found.update({
                            "size": size, "kind": kind, "category": category,
                            "case": record["id"], "argv": entry.get("argv"),
                            "exit": entry.get("exit"), "mutation": record.get("notes"),
                            "base": record.get("base"), "label": record.get("label"),
                            "exception": entry.get("exc_type"), "message": entry.get("message"),
                            "frame": entry.get("frame"), "jointwear_frame": entry.get("jw_frame"),
                            "tb_tail": entry.get("tb_tail"), "tail": entry.get("tail"),
                            "details": {k: entry.get(k) for k in ("delay", "signal", "group",
                                        "status", "touched_outside", "user_files_changed",
                                        "stderr_tail", "messages", "double") if entry.get(k)},
                        })  # fmt: skip
    return classes


def confirm(classes: dict[str, dict], work: Path) -> None:
    """Re-run each in-process reproducer through the real executable: its exit and last line."""
    repro = Path("/tmp/hostile_repro")
    shutil.rmtree(repro, ignore_errors=True)
    repro.mkdir()
    for example in EXAMPLES.glob("*.toml"):  # the bases of reproducers that extend one
        shutil.copy(example, repro / example.name)
    for found in classes.values():
        argv = found.get("argv")
        if found["category"] not in ("mutations", "cli") or not argv or argv[0] == "?":
            continue
        argv = list(argv)
        for i, arg in enumerate(argv):
            if arg.endswith(".toml") and "/models/m" in arg:
                kept = repro / Path(arg).name
                shutil.copy(arg, kept)
                argv[i] = str(kept)
        for i, arg in enumerate(argv[:-1]):
            if arg == "--out" and "/mruns/" in argv[i + 1]:
                argv[i + 1] = str(repro / ("out_" + Path(argv[i + 1]).name))
        found["argv"] = argv
        if found["kind"] in ("timeout", "hang"):
            continue
        try:
            result = _sh(
                str(JOINTWEAR), *argv, cwd=work / "cwd", timeout=90, preexec_fn=limit_memory
            )
            lines = (result.stderr.strip() or result.stdout.strip()).splitlines()
            found["cli_exit"] = result.returncode
            found["cli_last_line"] = lines[-1][:300] if lines else ""
        except subprocess.TimeoutExpired:
            found["cli_exit"] = "timeout"


def print_table(rows: dict[str, dict[str, int]]) -> None:
    """The summary table."""
    print("\n" + "category".ljust(10) + "".join(c.rjust(len(c) + 2) for c in COLUMNS))
    total = dict.fromkeys(COLUMNS, 0)
    for name, row in rows.items():
        print(name.ljust(10) + "".join(str(row[c]).rjust(len(c) + 2) for c in COLUMNS))
        for c in COLUMNS:
            total[c] += row[c]
    print("total".ljust(10) + "".join(str(total[c]).rjust(len(c) + 2) for c in COLUMNS))


# --------------------------------------------------------------------------------------------


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    """Command-line options."""
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--quick", action="store_true", help="200 mutations, 30 CLI, 10 signals")
    p.add_argument("--mutations", type=int, default=3000)
    p.add_argument("--cli-cases", type=int, default=None, help="default: every case once")
    p.add_argument("--signals", type=int, default=60)
    p.add_argument("--run-every", type=int, default=10, help="run every Nth mutated model")
    p.add_argument(
        "--run-valid-share",
        type=float,
        default=0.25,
        help="also run this share of the other models that pass check",
    )
    p.add_argument(
        "--figure-share",
        type=float,
        default=0.3,
        help="share of the mutated models' runs that draw figures",
    )
    p.add_argument(
        "--animation-share",
        type=float,
        default=0.3,
        help="share of the runs with figures that also write the animation",
    )
    p.add_argument("--timeout", type=float, default=60.0, help="per check or run [s]")
    p.add_argument("--workers", type=int, default=2)
    p.add_argument("--only", default="mutations,cli,signals,files")
    p.add_argument("--work", type=Path, default=Path("/tmp/hostile"))
    p.add_argument("--findings", type=Path, default=Path("/tmp/hostile_findings.json"))
    p.add_argument("--worker", nargs=2, type=Path, help=argparse.SUPPRESS)
    args = p.parse_args(argv)
    if args.quick:
        args.mutations, args.signals = 200, 10
        args.cli_cases = args.cli_cases or 30
    return args


def main(argv: list[str] | None = None) -> None:
    """Run the campaign and report."""
    args = parse_args(argv)
    if args.worker:
        worker(*args.worker)
        return
    only = set(args.only.split(","))
    PWNED.unlink(missing_ok=True)
    if args.work.exists():
        for line in Path("/proc/mounts").read_text().splitlines():
            if f" {args.work}/" in line:
                _sh("umount", line.split()[1])
        _unlock(args.work)
        shutil.rmtree(args.work)
    args.work.mkdir(parents=True)
    started = time.monotonic()
    results: dict[str, list[dict]] = {}
    fixtures: dict[str, Path] = {}
    try:
        if "mutations" in only:
            tasks = mutation_tasks(args, args.work)
            print(
                f"mutations: {len(tasks)} models, "
                f"{sum(len(t['steps']) - 1 for t in tasks)} runs planned",
                flush=True,
            )
            records = run_workers(tasks, args.work, "mut", args.workers, args.timeout * 2 + 60)
            results["mutations"] = [{**t, **records[t["id"]]} for t in tasks]
            print(f"  done in {time.monotonic() - started:.0f} s", flush=True)
        if "cli" in only:
            fixtures = cli_fixtures(args.work)
            tasks = cli_tasks(args, args.work, fixtures)
            distinct = len({t["label"] for t in tasks})
            print(f"cli: {len(tasks)} cases ({distinct} distinct)", flush=True)
            records = run_workers(tasks, args.work, "cli", args.workers, args.timeout + 60)
            results["cli"] = [{**t, **records[t["id"]]} for t in tasks]
            print(f"  done in {time.monotonic() - started:.0f} s", flush=True)
        if "signals" in only:
            results["signals"] = signal_campaign(args, args.work)
            print(f"  signals done in {time.monotonic() - started:.0f} s", flush=True)
        if "files" in only:
            results["files"] = files_campaign(args, args.work)
            print(f"  files done in {time.monotonic() - started:.0f} s", flush=True)
        classes = collect(results)
        confirm(classes, args.work)
    finally:
        _unlock(args.work)
        if "full" in fixtures:
            _sh("umount", str(fixtures["full"]))
    rows = {}
    for name, records in results.items():
        per_case = [[k for e in (r.get("steps") or [r]) for k in e.get("problems", [])]
                    for r in records]  # fmt: skip
        rows[name] = tally(per_case)
    print_table(rows)
    print(f"\n{len(classes)} distinct failure classes ({time.monotonic() - started:.0f} s):")
    for key, found in sorted(classes.items(), key=lambda kv: -kv[1]["count"]):
        what = found.get("mutation") or found.get("label") or ""
        cli = f" | cli exit {found.get('cli_exit')}" if "cli_exit" in found else ""
        print(f"  [{found['count']:4d}] {key}{cli}\n         {found['case']}: {what}")
    counts = Counter(k for r in rows.values() for k in r)
    args.findings.write_text(json.dumps({
        "seed": args.seed, "table": rows, "elapsed_s": time.monotonic() - started,
        "classes": {k: {kk: vv for kk, vv in v.items() if kk != "size"}
                    for k, v in classes.items()}, "columns": list(counts),
    }, indent=1, default=str))  # fmt: skip
    print(f"\nfindings in {args.findings}; reproducer files in /tmp/hostile_repro")


def _unlock(root: Path) -> None:
    """Undo ``chattr +i`` anywhere under ``root`` (the locked-folder cases)."""
    if root.exists():
        subprocess.run(["chattr", "-R", "-i", str(root)], capture_output=True)


if __name__ == "__main__":
    main()
