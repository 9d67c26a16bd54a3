"""The command-line defaults the documentation states are the code's.

Each command with options has a table on some page, headed "| `jointwear CMD` option |
default | what |", with a row for every option. The default cell is the value in backticks
(a flag pair names the flag in effect), "required", "off" for a lone flag, or words without
backticks where the code's default is None (the model's value, one per core, ...). A
sentence outside the tables that gives an option's default in parentheses, "`--max-growth`
times the nominal (default 1)", must give the code's too.
"""

import re
from pathlib import Path

import pytest
import typer
from typer.core import TyperOption

from jointwear.cli import app

ROOT = Path(__file__).parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
HEADER = re.compile(r"^\| `jointwear (\w+)` option \| default \|")
OPTION = re.compile(r"`(--[a-z][\w-]*)")
PROSE = re.compile(r"`(--[a-z][\w-]*)[^`]*`([^.;`()]*)\(([^)]*\bdefault\b[^)]*)\)")
NUMBER = re.compile(r"\d+(?:\.\d+)?\s?%?")

COMMANDS = typer.main.get_command(app).commands


def options(command: str) -> dict[str, TyperOption]:
    """The command's options by every name they go by (--help left out)."""
    named = {}
    for param in COMMANDS[command].params:
        if isinstance(param, TyperOption) and "--help" not in param.opts:
            for name in (*param.opts, *param.secondary_opts):
                named[name] = param
    return named


def expected(param: TyperOption) -> str | None:
    """The default cell for ``param``; None: words, no value (the code's default is None)."""
    if param.required:
        return "required"
    if param.is_flag and param.secondary_opts:
        if param.default is None:
            return None
        return f"`{param.opts[0] if param.default else param.secondary_opts[0]}`"
    if param.is_flag:
        assert param.default is False, param.opts
        return "off"
    if param.default is None:
        return None
    return f"`{param.default}`"


def same(documented: str, code: str) -> bool:
    """Whether two default texts say the same value (numbers compared as numbers)."""
    if documented == code:
        return True
    try:
        return float(documented.strip("`")) == float(code.strip("`"))
    except ValueError:
        return False


def tables(text: str) -> dict[str, list[list[str]]]:
    """Every option table of a page: command -> rows of cells."""
    found: dict[str, list[list[str]]] = {}
    lines = text.splitlines()
    for i, line in enumerate(lines):
        head = HEADER.match(line)
        if head:
            rows = found.setdefault(head[1], [])
            for row in lines[i + 2 :]:
                if not row.startswith("|"):
                    break
                rows.append([cell.strip() for cell in row.strip("|").split("|")])
    return found


def table_problems(command: str, rows: list[list[str]]) -> list[str]:
    """One line per row whose default is not the code's, and per option left out."""
    named, problems, seen = options(command), [], set()
    for cells in rows:
        names = OPTION.findall(cells[0])
        if not names or names[0] not in named:
            problems.append(f"{command}: {cells[0]} is no option of the command")
            continue
        param = named[names[0]]
        seen.add(param.name)
        want, cell = expected(param), cells[1]
        if want is None:
            if cell.startswith("`"):
                problems.append(f"{command} {names[0]}: {cell} documented, the code has none")
        elif not same(cell, want):
            problems.append(f"{command} {names[0]}: {cell} documented, the code's is {want}")
    for param in {p.name: p for p in named.values()}.values():
        if param.name not in seen:
            problems.append(f"{command}: {param.opts[0]} is missing from its table")
    return problems


def prose_problems(text: str) -> list[str]:
    """One line per default stated in a sentence that no command has for that option."""
    kept, fenced = [], False
    for line in text.splitlines():
        fenced ^= line.startswith("```")
        kept.append("" if fenced or line.startswith(("```", "|")) else line)
    problems = []
    for paragraph in "\n".join(kept).split("\n\n"):
        for name, _, said in PROSE.findall(" ".join(paragraph.split())):
            values = [n.replace(" ", "") for n in NUMBER.findall(said)]
            defaults = [
                str(params[name].default).split(",")
                for params in map(options, COMMANDS)
                if name in params and params[name].default is not None
            ]
            if values and not any(
                len(values) >= len(d) and all(map(same, values, d)) for d in defaults
            ):
                problems.append(f"{name}: ({said}) says {values}, the code's is {defaults}")
    return problems


def test_every_command_with_options_has_a_table_of_them():
    documented = {}
    for page in PAGES:
        documented.update(tables(page.read_text()))
    with_options = {name for name in COMMANDS if options(name)}
    assert with_options == set(documented), "option tables: jointwear CMD option | default |"
    assert {"run", "sweep", "life"} <= with_options


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_the_defaults_a_page_states_are_the_code_s(page):
    text = page.read_text()
    problems = prose_problems(text)
    for command, rows in tables(text).items():
        problems += table_problems(command, rows)
    assert problems == []


def test_a_wrong_default_is_caught():
    page = (
        "| `jointwear life` option | default | what |\n|---|---|---|\n"
        "| `--max-change BOUND` | `1%` | the bound |\n| `--cycles N` | `5` | cycles |\n\n"
        "within `--max-change` (1 % of the clearance by default), and `--max-growth`\n"
        "times the nominal (default 1: doubled).\n"
    )
    assert prose_problems(page) == ["--max-change: (1 % of the clearance by default) says "
                                    "['1%'], the code's is [['0.25%']]"]  # fmt: skip
    problems = table_problems("life", tables(page)["life"])
    assert "life --max-change: `1%` documented, the code's is `0.25%`" in problems
    assert "life --cycles: `5` documented, the code's is required" in problems
    assert "life: --max-growth is missing from its table" in problems
