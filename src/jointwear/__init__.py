"""jointwear: planar mechanisms with revolute clearance joints, contact, friction and wear.

After P. Flores, "Modeling and simulation of wear in revolute clearance joints in multibody
systems", Mechanism and Machine Theory 44 (2009) 1211-1222.
"""

from ._version import __version__
from .model import Model, ModelError, load_model
from .results import Results, load_results
from .run import run
from .simulate import simulate
from .studies.life.study import LifeResults, life
from .studies.sweep.study import sweep

__all__ = [
    "LifeResults",
    "Model",
    "ModelError",
    "Results",
    "__version__",
    "life",
    "load_model",
    "load_results",
    "run",
    "simulate",
    "sweep",
]
