"""jointwear: planar mechanisms with revolute clearance joints, contact, friction and wear.

After P. Flores, "Modeling and simulation of wear in revolute clearance joints in multibody
systems", Mechanism and Machine Theory 44 (2009) 1211-1222.

``import jointwear`` is cheap: each public name below imports its module (pydantic, pandas,
numba, ...) the first time it is used (PEP 562).
"""

from importlib import import_module
from typing import TYPE_CHECKING

from ._version import __version__

if TYPE_CHECKING:
    from .citations import citations_for, print_citations
    from .engine.run_file import run
    from .engine.simulate import simulate
    from .engine.user_laws import LawKey, register_law, unregister_law
    from .model import (
        AngleDriver,
        AppliedTorque,
        Body,
        ConstantSpeed,
        DistanceDriver,
        Event,
        Fourier,
        Gravity,
        Ground,
        Harmonic,
        JointForce,
        JointPressure,
        Model,
        ModelError,
        PinInSlotClearance,
        PinInSlotJoint,
        PointForce,
        Polynomial,
        RevoluteClearance,
        RevoluteJoint,
        RotationalSpringDamper,
        Solver,
        SpringDamper,
        TableFunction,
        TranslationalClearance,
        TranslationalJoint,
        load_model,
        parse_model,
    )
    from .results import Results, load_results
    from .studies.life.study import LifeResults, life
    from .studies.sweep.study import sweep

_PUBLIC = {  # public name -> the module that defines it
    "LawKey": ".engine.user_laws",
    "LifeResults": ".studies.life.study",
    "Model": ".model",
    "ModelError": ".model",
    "Results": ".results",
    "citations_for": ".citations",
    "life": ".studies.life.study",
    "load_model": ".model",
    "load_results": ".results",
    "parse_model": ".model",
    "print_citations": ".citations",
    "register_law": ".engine.user_laws",
    "run": ".engine.run_file",
    "simulate": ".engine.simulate",
    "sweep": ".studies.sweep.study",
    "unregister_law": ".engine.user_laws",
    # the tables of a model file, to build a model in Python (docs/python-models.md)
    "AngleDriver": ".model",
    "AppliedTorque": ".model",
    "Body": ".model",
    "ConstantSpeed": ".model",
    "DistanceDriver": ".model",
    "Event": ".model",
    "Fourier": ".model",
    "Gravity": ".model",
    "Ground": ".model",
    "Harmonic": ".model",
    "JointForce": ".model",
    "JointPressure": ".model",
    "PinInSlotClearance": ".model",
    "PinInSlotJoint": ".model",
    "PointForce": ".model",
    "Polynomial": ".model",
    "RevoluteClearance": ".model",
    "RevoluteJoint": ".model",
    "RotationalSpringDamper": ".model",
    "Solver": ".model",
    "SpringDamper": ".model",
    "TableFunction": ".model",
    "TranslationalClearance": ".model",
    "TranslationalJoint": ".model",
}

__all__ = [
    "AngleDriver",
    "AppliedTorque",
    "Body",
    "ConstantSpeed",
    "DistanceDriver",
    "Event",
    "Fourier",
    "Gravity",
    "Ground",
    "Harmonic",
    "JointForce",
    "JointPressure",
    "LawKey",
    "LifeResults",
    "Model",
    "ModelError",
    "PinInSlotClearance",
    "PinInSlotJoint",
    "PointForce",
    "Polynomial",
    "Results",
    "RevoluteClearance",
    "RevoluteJoint",
    "RotationalSpringDamper",
    "Solver",
    "SpringDamper",
    "TableFunction",
    "TranslationalClearance",
    "TranslationalJoint",
    "__version__",
    "citations_for",
    "life",
    "load_model",
    "load_results",
    "parse_model",
    "print_citations",
    "register_law",
    "run",
    "simulate",
    "sweep",
    "unregister_law",
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
