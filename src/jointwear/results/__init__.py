"""What a run produces: ``Results``, their folder on disk, and the state a run ends in."""

from .run_results import IDEAL_FOLDER, Results, load_results
from .run_state import RunState, load_run_state

__all__ = ["IDEAL_FOLDER", "Results", "RunState", "load_results", "load_run_state"]
