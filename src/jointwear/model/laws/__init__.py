"""The laws' records: names, keys, packing, citations, ranges, stiffness, kernel functions.

Numba-free: validating a model reads these and never the kernels (``kernels.laws``), which
the records name and ``Kernel.resolve`` imports on demand.
"""

from .friction import FRICTION
from .lubrication import LUBRICATION
from .normal import DAMPING, NORMAL
from .record import Contact, Family, Kernel, Key, Law, Range
from .wear import WEAR, WEAR_DISTRIBUTION

SHARED = (NORMAL, DAMPING, FRICTION, WEAR, LUBRICATION)  # the families every contact chooses
EVERY = (NORMAL, DAMPING, FRICTION, WEAR, WEAR_DISTRIBUTION, LUBRICATION)

__all__ = [
    "DAMPING",
    "EVERY",
    "FRICTION",
    "LUBRICATION",
    "NORMAL",
    "SHARED",
    "WEAR",
    "WEAR_DISTRIBUTION",
    "Contact",
    "Family",
    "Kernel",
    "Key",
    "Law",
    "Range",
]  # fmt: skip
