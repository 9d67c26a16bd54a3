"""Where a result came from: the command, the versions it ran with, and when (summary.json)."""

from __future__ import annotations

import platform
import shlex
import sys
from datetime import UTC, datetime
from importlib.metadata import PackageNotFoundError, version

from .._version import __version__

DEPENDENCIES = ("numpy", "numba", "llvmlite", "pandas", "pyarrow", "pydantic", "pint")


def provenance() -> dict:
    """The command line, Python and dependency versions, machine and start time (UTC)."""
    return {
        "command": shlex.join(sys.argv),
        "jointwear": __version__,
        "python": platform.python_version(),
        "platform": platform.platform(),
        "dependencies": {name: _version(name) for name in DEPENDENCIES},
        "started_utc": datetime.now(UTC).isoformat(timespec="seconds"),
    }


def _version(package: str) -> str | None:
    try:
        return version(package)
    except PackageNotFoundError:
        return None
