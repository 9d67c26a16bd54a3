"""What a run produces: ``Results``, their folder on disk, and the state a run ends in."""

from .run_results import Results, load_results
from .run_state import RunState, load_run_state

__all__ = ["Results", "RunState", "load_results", "load_run_state"]
