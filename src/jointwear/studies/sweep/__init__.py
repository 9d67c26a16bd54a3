"""Parameter sweeps: many runs of one model with some values varied, and their table."""

from .study import CaseReport, SweepResults, sweep

__all__ = ["CaseReport", "SweepResults", "sweep"]
