"""Time-series columns computed from a run's rows after it (``ClearanceKind.derived_columns``).

Each clearance joint's derived columns follow its own columns.
"""

from __future__ import annotations

import pandas as pd

from ..joints import KINDS
from ..model import Model


def with_derived_columns(model: Model, timeseries: pd.DataFrame) -> pd.DataFrame:
    """``timeseries`` with each clearance joint's derived columns after its own."""
    extra: dict[str, object] = {}
    after: dict[str, list[str]] = {}  # the joint's last own column: the derived columns
    for kind in KINDS:
        for joint in kind.joints(model):
            derived = kind.derived_columns(joint, timeseries)
            if derived:
                extra |= derived
                last = kind.derived_after or kind.columns(joint)[-1]
                after[f"{joint.name}_{last}"] = list(derived)
    if not extra:
        return timeseries
    order = []
    for column in timeseries.columns:
        order += [column, *after.get(column, [])]
    return pd.concat([timeseries, pd.DataFrame(extra, index=timeseries.index)], axis=1)[order]
