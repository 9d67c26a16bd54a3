"""Non-finite numbers caught between chunks, named with the time they appeared.

The step loop stops on a non-finite state by itself; what it cannot see are the quantities
computed from the state: output columns (forces, energies) and the wear a step adds. After
every chunk :func:`first_non_finite` looks at the chunk's rows and at the wear and totals,
so a run never ends ``success`` with NaN or inf in its results.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


def first_non_finite(
    rows: np.ndarray,
    columns: Sequence[str],
    arrays: dict[str, np.ndarray],
    span: tuple[float, float],
) -> tuple[str, str, int] | None:
    """The first non-finite quantity of a chunk, or None if every number is finite.

    Parameters
    ----------
    rows
        The chunk's output rows (time first) [SI].
    columns
        Their names.
    arrays
        Other arrays the chunk updated, by name (the wear depths, the contact totals).
    span
        The chunk's start and end times [s]: when an array went non-finite.

    Returns
    -------
    tuple or None
        (name, when: "at t = ... s" or "between t = ... and ... s", rows to keep: those
        before the first non-finite one).
    """
    bad = ~np.isfinite(rows)
    if bad.any():
        row, column = np.argwhere(bad)[0]
        return f"output column '{columns[column]}'", f"at t = {rows[row, 0]:.6g} s", int(row)
    for name, array in arrays.items():
        if not np.all(np.isfinite(array)):
            return name, f"between t = {span[0]:.6g} and {span[1]:.6g} s", rows.shape[0]
    return None


def json_safe(value: object) -> object:
    """``value`` with every non-finite float replaced by None (``null`` in JSON)."""
    if isinstance(value, float):
        return value if np.isfinite(value) else None
    if isinstance(value, dict):
        return {key: json_safe(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [json_safe(item) for item in value]
    return value
