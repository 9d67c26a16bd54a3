"""The model file: its schema, units, overrides and error messages.

A validated :class:`Model` holds plain SI floats (tuples for vectors) and names; every
user-input problem is reported as a :class:`ModelError` with one line per problem. The
tables of a model file are classes too (:class:`Body`, :class:`RevoluteJoint`, ...): a model
can be built from them in Python, with the values a file takes (docs/python-models.md).

The names below import their module on first use (PEP 562), so the joint types
(``jointwear.joints``), whose tables the schema's joints are, can import the parts of the
schema they build on (``model.tables``, ``model.clearance``) before the schema itself.
"""

from importlib import import_module
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..joints.pin_in_slot.schema import PinInSlotClearance, PinInSlotJoint
    from ..joints.revolute.schema import RevoluteClearance, RevoluteJoint
    from ..joints.translational.schema import TranslationalClearance, TranslationalJoint
    from .errors import ModelError
    from .functions import ConstantSpeed, Fourier, Harmonic, Polynomial, TableFunction
    from .schema import Model, load_model, parse_model
    from .sections import (
        AngleDriver,
        AppliedTorque,
        Body,
        DistanceDriver,
        Event,
        Gravity,
        Ground,
        JointForce,
        JointPressure,
        PointForce,
        RotationalSpringDamper,
        Solver,
        SpringDamper,
    )

_PUBLIC = {  # public name -> the module that defines it
    "Model": ".schema", "ModelError": ".errors", "load_model": ".schema",
    "parse_model": ".schema",
    # the tables of a model file, to build a model in Python
    "Ground": ".sections", "Body": ".sections",
    "RevoluteJoint": "..joints.revolute.schema",
    "RevoluteClearance": "..joints.revolute.schema",
    "TranslationalJoint": "..joints.translational.schema",
    "TranslationalClearance": "..joints.translational.schema",
    "PinInSlotJoint": "..joints.pin_in_slot.schema",
    "PinInSlotClearance": "..joints.pin_in_slot.schema",
    "AngleDriver": ".sections", "DistanceDriver": ".sections",
    "ConstantSpeed": ".functions", "Polynomial": ".functions", "Harmonic": ".functions",
    "TableFunction": ".functions", "Fourier": ".functions",
    "Gravity": ".sections", "PointForce": ".sections", "AppliedTorque": ".sections",
    "JointForce": ".sections", "JointPressure": ".sections",
    "SpringDamper": ".sections", "RotationalSpringDamper": ".sections",
    "Solver": ".sections", "Event": ".sections",
}  # fmt: skip
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
    "Model",
    "ModelError",
    "PinInSlotClearance",
    "PinInSlotJoint",
    "PointForce",
    "Polynomial",
    "RevoluteClearance",
    "RevoluteJoint",
    "RotationalSpringDamper",
    "Solver",
    "SpringDamper",
    "TableFunction",
    "TranslationalClearance",
    "TranslationalJoint",
    "load_model",
    "parse_model",
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
