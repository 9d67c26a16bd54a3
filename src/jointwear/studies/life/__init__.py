"""Long-life wear: simulate a few steady cycles, extrapolate their wear, update, repeat."""

from .study import LifeResults, life

__all__ = ["LifeResults", "life"]
