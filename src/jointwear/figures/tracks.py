"""Where a body's points go over a run's rows (no matplotlib)."""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..model import Model


def track(model: Model, rows: pd.DataFrame, body: str, point: str) -> np.ndarray:
    """Global positions [m] of ``point`` of ``body`` over ``rows``, shape (rows, 2)."""
    local = np.asarray(model.point(body, point), dtype=float)
    if body == "ground":
        return np.tile(local, (len(rows), 1))
    phi = rows[f"phi_{body}"].to_numpy()
    cos, sin = np.cos(phi), np.sin(phi)
    x = rows[f"x_{body}"].to_numpy() + cos * local[0] - sin * local[1]
    y = rows[f"y_{body}"].to_numpy() + sin * local[0] + cos * local[1]
    return np.column_stack([x, y])


def angle(rows: pd.DataFrame, body: str) -> np.ndarray:
    """Angle [rad] of ``body`` over ``rows`` (0 for the ground)."""
    return np.zeros(len(rows)) if body == "ground" else rows[f"phi_{body}"].to_numpy()
