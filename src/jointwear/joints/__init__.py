"""Joint types with clearance, each one subpackage: the registry the rest of the code reads.

``KINDS`` lists them in the order of the compiled kinds (``kernels.elements.Elements``). To add
a kind, write its subpackage (``kind.py`` says what it gives) and its compiled module, and add
it here and in ``kernels/elements/__init__.py``.
"""

from collections.abc import Iterator

from .kind import TOTALS, ClearanceKind
from .pin_in_slot import KIND as PIN_IN_SLOT
from .revolute import KIND as REVOLUTE
from .translational import KIND as TRANSLATIONAL

KINDS: tuple[ClearanceKind, ...] = (REVOLUTE, TRANSLATIONAL, PIN_IN_SLOT)
BY_NAME = {kind.name: kind for kind in KINDS}

__all__ = ["BY_NAME", "KINDS", "TOTALS", "ClearanceKind", "joints_by_kind"]


def joints_by_kind(model: object) -> Iterator[tuple[ClearanceKind, int, object]]:
    """(kind, index among the kind's, joint) of every clearance joint, registry then file order."""
    for kind in KINDS:
        for k, joint in enumerate(kind.joints(model)):
            yield kind, k, joint
