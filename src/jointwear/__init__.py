"""jointwear: planar mechanisms with revolute clearance joints, contact, friction and wear.

After P. Flores, "Modeling and simulation of wear in revolute clearance joints in multibody
systems", Mechanism and Machine Theory 44 (2009) 1211-1222.

``import jointwear`` is cheap: each public name below imports its module (pydantic, pandas,
numba, ...) the first time it is used (PEP 562).
"""

from importlib import import_module
from typing import TYPE_CHECKING

from ._version import __version__
from .model import __all__ as _model_names  # a light package: its names import lazily

if TYPE_CHECKING:
    from .citations import citations_for, print_citations
    from .engine.run_file import run
    from .engine.simulate import simulate
    from .engine.user_laws import LawKey, register_law, unregister_law
    from .model import *  # noqa: F403 - for type checkers: the model and its tables
    from .results import Results, load_results
    from .studies.life.study import LifeResults, life
    from .studies.sample.study import SampleResults, sample
    from .studies.sweep.study import sweep

_PUBLIC = {  # public name -> the module that defines it
    "LawKey": ".engine.user_laws",
    "LifeResults": ".studies.life.study",
    "Results": ".results",
    "citations_for": ".citations",
    "life": ".studies.life.study",
    "load_results": ".results",
    "print_citations": ".citations",
    "register_law": ".engine.user_laws",
    "run": ".engine.run_file",
    "sample": ".studies.sample.study",
    "SampleResults": ".studies.sample.study",
    "simulate": ".engine.simulate",
    "sweep": ".studies.sweep.study",
    "unregister_law": ".engine.user_laws",
} | dict.fromkeys(_model_names, ".model")  # the model and its tables (docs/python-models.md)

__all__ = [
    "LawKey",
    "LifeResults",
    "Results",
    "__version__",
    "citations_for",
    "life",
    "load_results",
    "print_citations",
    "register_law",
    "run",
    "sample",
    "SampleResults",
    "simulate",
    "sweep",
    "unregister_law",
    *_model_names,
]


def __getattr__(name: str) -> object:
    """Import a public name on first use."""
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(_PUBLIC[name], __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_PUBLIC})
