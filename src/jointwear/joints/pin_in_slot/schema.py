"""The pin-in-slot joint's table in a model file, ideal or with clearance (docs/model-format.md).

The joint's first body carries the slot: a straight slot with round ends, its centre line
through the joint's first point along ``axis`` (first body's frame). The second body carries
the pin, centred on the joint's second point. Ideal, the pin's centre stays on the slot's
centre line (``JointKind.POINT_ON_LINE``, one constraint), with no end to the slot; with a
``[joints.clearance]`` table the pin touches the slot's sides and ends through contact forces
(``kernels.elements.pin_slot``).

The slot is given by its width, not its half-width: the width is what a drawing dimensions and
a gauge measures, and a milled slot's ends are half circles of that diameter. The pin by its
radius, as the revolute joint's journal. ``sectors`` counts the cells of a full turn: the pin
has that many and each end, a half turn, half as many, so every round surface is cut into
cells of one angular size, and a slot of length 0 is the revolute joint's bearing cut as it
would be. The contact stiffness is one K for sides and ends (the kernel's docstring says why):
by default the internal-cylinder formula of the revolute joint with the slot's half-width and
the pin's radius, so that a slot of length 0 is the revolute clearance joint.
"""

from typing import Annotated, ClassVar, Literal

from annotated_types import Ge, Le
from pydantic import AfterValidator, model_validator

from ...kernels.codes import JointKind
from ...model.clearance import ClearanceTable, PositiveLength
from ...model.laws.normal import effective_radius
from ...model.laws.record import CONFORMAL, CORNER_ON_FLAT, SHAPE_NAMES, Contact
from ...model.tables import JointTable, Number, unit_axis
from ...units import Length

SHAPES = (CORNER_ON_FLAT, CONFORMAL)  # the pin on a side, the pin in an end


def _even(sectors: int) -> int:
    if sectors % 2:
        raise ValueError(
            f"got {sectors}; give an even number (each end, a half turn, gets half of them)"
        )
    return sectors


class PinInSlotClearance(ClearanceTable):
    """A pin-in-slot joint with clearance: pin in a round-ended slot (SI).

    Material pairs are [slot, pin]; the keys every clearance table has are those of
    ``ClearanceTable`` (width [m], moduli [Pa], laws and their keys).

    Attributes
    ----------
    pin_radius
        R_p [m].
    slot_width
        2 R_s [m], > 2 R_p.
    slot_length
        Distance between the centres of the slot's round ends [m], centred on the joint's
        first point; 0 is a round hole.
    pin_wear_share
        The pin's share of the worn volume [-], 0 to 1.
    segments
        Wear cells along each side, 1 to 100000.
    sectors
        Wear cells of a full turn (the pin; each end has half), even, 4 to 100000.
    """

    pin_radius: PositiveLength
    slot_width: PositiveLength
    slot_length: Annotated[Length, Ge(0)]
    pin_wear_share: Annotated[Number, Ge(0), Le(1)] = 0.5
    segments: Annotated[int, Ge(1), Le(100_000)] = 20
    sectors: Annotated[int, Ge(4), Le(100_000), AfterValidator(_even)] = 36

    @model_validator(mode="after")
    def _consistent(self) -> "PinInSlotClearance":
        problems = [*self._unused_keys(), *self._shape_problems()]
        if self.pin_radius >= self.slot_half_width:
            problems.append(
                f"pin_radius {self.pin_radius * 1e3:.12g} mm must be smaller than half the "
                f"slot_width {self.slot_width * 1e3:.12g} mm (the gap is their difference)"
            )
        elif self.contact_tolerance >= self.gap:
            problems.append(
                f"contact_tolerance {self.contact_tolerance:g} m must be much smaller than the "
                f"gap {self.gap:g} m (default 1e-10 m)"
            )
        if not problems:
            problems = self._stiffness_problems()
        if problems:
            raise ValueError("; ".join(problems))
        return self

    def _shape_problems(self) -> list[str]:
        """Laws that do not hold for both contacts of a pin in a slot, or lack their keys."""
        lines = []
        for family, law in self.chosen_laws():
            if not set(SHAPES) <= set(law.shapes):
                where = " or ".join(SHAPE_NAMES[s] for s in law.shapes)
                lines.append(
                    f"{family.key} '{law.name}' applies to {where} only, and a pin in a slot "
                    "touches a flat side (as a corner on a flat face) and a round end (as a "
                    f"journal in its bearing): choose another {family.key}"
                )
        # every law left applies to both shapes: what remains are missing keys
        return lines or self._law_problems(CONFORMAL)

    @property
    def slot_half_width(self) -> float:
        """R_s, the slot's half-width and the radius of its ends [m]."""
        return 0.5 * self.slot_width

    @property
    def gap(self) -> float:
        """Clearance c = R_s - R_p [m]: how far the pin's centre moves off the centre line."""
        return self.slot_half_width - self.pin_radius

    @property
    def end_radius(self) -> float:
        """R* = R_s R_p / c [m] of the pin in an end (on a side it is R_p)."""
        return effective_radius(self.slot_half_width, self.pin_radius)

    @property
    def contact(self) -> Contact:
        """The pin in an end (the conforming contact the stiffness formula is for)."""
        return Contact(CONFORMAL, self.contact_modulus, self.end_radius, self.gap, self.width)

    def hertz_patch(self, force: float, *, on_side: bool = False) -> tuple[float, float]:
        """Half-width b [m] and peak pressure p_max [Pa] of the line contact under force [N].

        In an end (R* = ``end_radius``), or on a side (R* = R_p). Evaluates the kernels.
        """
        from ...kernels.laws.wear import hertz_line_contact

        radius = self.pin_radius if on_side else self.end_radius
        return hertz_line_contact(force, radius, self.contact_modulus, self.width)


class PinInSlotJoint(JointTable):
    """A pin (`points[1]` of `bodies[1]`) in a slot along `axis` through `points[0]` of `bodies[0]`.

    Ideal without `clearance`: the pin's centre on the slot's centre line, which has no end.
    With it, `bodies[0]` has the slot and `bodies[1]` the pin, which touch through contact
    forces instead of the constraint.

    Attributes
    ----------
    name
        The joint's name.
    bodies
        (first body, second body); ``"ground"`` allowed.
    points
        (a point of the first body, a point of the second).
    axis
        Direction of the slot in the first body's frame (any non-zero length).
    clearance
        A ``PinInSlotClearance``, or None: an ideal joint.
    """

    kind: ClassVar = JointKind.POINT_ON_LINE
    type: Literal["pin_in_slot"] = "pin_in_slot"
    axis: Annotated[tuple[Number, Number], AfterValidator(unit_axis)]
    clearance: PinInSlotClearance | None = None
