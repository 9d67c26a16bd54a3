"""CSV files of a table function: a header naming each column with its unit, then numbers.

A header cell reads ``name [unit]`` (``crank angle [deg]``, ``pressure [bar]``); a cell
without brackets is a column of SI numbers. Cells are separated by commas, semicolons or
tabs; blank lines and lines starting with ``#`` are skipped.
"""

import csv
import re
from pathlib import Path

from ..units import unit_of

MAX_ROWS = 100_000  # a table function's points: far more than a measured cycle has
_HEADER = re.compile(r"\s*(.*?)\s*(?:\[\s*(.*?)\s*\])?\s*")
_PARENTHESES = re.compile(r"(.*?)\s*\(\s*([^()]*?)\s*\)")  # "time (ms)": a unit?


def resolve_files(data: object, folder: Path) -> object:
    """``data`` with every table function's ``file`` made absolute against ``folder``."""
    if isinstance(data, list):
        return [resolve_files(item, folder) for item in data]
    if not isinstance(data, dict):
        return data
    resolved = {key: resolve_files(value, folder) for key, value in data.items()}
    if data.get("type") == "table" and isinstance(data.get("file"), str):
        resolved["file"] = str(folder / Path(data["file"]).expanduser())
    return resolved


def read_columns(
    path: str, columns: tuple[str, str] | None
) -> tuple[list[float], str | None, list[float], str | None]:
    """The x and y columns of a CSV file [as written], each with its unit (None: SI).

    ``columns`` names the two columns (header names without units); None takes the first two.
    ValueError, naming the file, row and column, if it cannot be read.
    """
    try:
        with open(path, newline="", encoding="utf-8-sig") as handle:
            text = handle.read()
        lines = [line for line in text.splitlines() if not line.lstrip().startswith("#")]
        rows = [r for r in csv.reader(lines, _dialect(lines)) if any(c.strip() for c in r)]
    except OSError as error:
        raise ValueError(f"cannot read the file {path}: {error.strerror}") from None
    except (UnicodeDecodeError, csv.Error) as error:
        raise ValueError(f"{path}: not a CSV text file ({error})") from None
    if len(rows) < 3:
        raise ValueError(f"{path}: needs a header row and at least two rows of numbers")
    if len(rows) > MAX_ROWS + 1:
        raise ValueError(f"{path}: has {len(rows) - 1} rows; at most {MAX_ROWS} are allowed")
    names, units = zip(*(_header_cell(path, cell) for cell in rows[0]), strict=True)
    picked = _pick(path, list(names), columns)
    values: list[list[float]] = [[], []]
    for number, row in enumerate(rows[1:], start=2):
        for out, column in zip(values, picked, strict=True):
            cell = row[column].strip() if column < len(row) else ""
            try:
                out.append(float(cell))
            except ValueError:
                raise ValueError(
                    f"{path}, row {number}, column '{names[column]}': {cell!r} is not a number"
                ) from None
    return values[0], units[picked[0]] or None, values[1], units[picked[1]] or None


def _header_cell(path: str, cell: str) -> tuple[str, str | None]:
    """A header cell's name and unit; ValueError for brackets that do not close around a unit."""
    name, unit = _HEADER.fullmatch(cell).groups()
    if "[" in name or "]" in name:
        raise ValueError(
            f"{path}: header cell {cell.strip()!r} does not read 'name [unit]'; give the unit "
            "in one pair of brackets at the cell's end (none: SI numbers)"
        )
    in_parentheses = _PARENTHESES.fullmatch(name)
    if unit is None and in_parentheses and unit_of(f"1 {in_parentheses.group(2)}"):
        bracketed = f"{in_parentheses.group(1)} [{in_parentheses.group(2)}]"
        raise ValueError(
            f"{path}: header cell {cell.strip()!r}: give the unit in square brackets, "
            f"{bracketed!r} (a cell without them is a column of SI numbers)"
        )
    return name, unit


def _dialect(lines: list[str]) -> type[csv.Dialect]:
    """Commas, or the semicolons or tabs of a spreadsheet's export (csv's sniffer)."""
    try:
        return csv.Sniffer().sniff("\n".join(lines[:20]), delimiters=",;\t")
    except csv.Error:
        return csv.excel


def _pick(path: str, names: list[str], columns: tuple[str, str] | None) -> tuple[int, int]:
    if columns is None:
        if len(names) < 2:
            raise ValueError(f"{path}: the header names {len(names)} column; need two")
        return 0, 1
    missing = [name for name in columns if name not in names]
    if missing:
        raise ValueError(
            f"{path}: no column {missing[0]!r}; the header names {', '.join(map(repr, names))}"
        )
    return names.index(columns[0]), names.index(columns[1])
