"""The translational joint's table in a model file, ideal or with clearance (docs/model-format.md).

The joint's first body carries the guide (its centreline through the joint's first point,
along the joint's ``axis``), the second the slider (a rectangle centred on the joint's second
point, its length along the axis). The slider's four corners touch the guide's two surfaces;
a finite guide's ends touch the slider's faces (``kernels.elements.slider``).

Contact stiffness: the corners and edges are sharp in the geometry; ``corner_radius`` only
sets the stiffness of every contact (the laws' ``CORNER_ON_FLAT`` contact, with the corner's
radius as R*): the same power law as the revolute joint, F = K delta^1.5 with
K = 4/3 E* sqrt(r), the sphere-on-plane Hertz constant, which is the revolute joint's
internal-cylinder formula with the bearing's radius taken to infinity, so both joints follow
one convention. A true line contact's stiffness also depends (weakly, logarithmically) on
the bodies' sizes, which a corner does not define; give ``contact_stiffness`` to use a
measured or computed one instead.
"""

from typing import Annotated, ClassVar, Literal

from annotated_types import Ge, Le
from pydantic import AfterValidator, model_validator

from ...kernels.codes import JointKind
from ...model.clearance import ClearanceTable, PositiveLength
from ...model.laws.normal import HERTZ_EXPONENT
from ...model.laws.record import CORNER_ON_FLAT, Contact
from ...model.tables import JointTable, Number, unit_axis


class TranslationalClearance(ClearanceTable):
    """A translational joint with clearance: slider in guide, contact, friction and wear (SI).

    Material pairs are [guide, slider]; the keys every clearance table has are those of
    ``ClearanceTable`` (width [m], moduli [Pa], laws and their keys).

    Attributes
    ----------
    slider_length, slider_height
        The slider's size along and across the axis [m].
    guide_height, gap
        The guide's inner height, or the gap on each side of the slider [m]; give one.
    guide_length
        Length of the guide [m], centred on the joint's first point; None: unbounded.
    corner_radius
        Rounding of the slider's corners and the guide's end edges [m]; it sets the
        contact stiffness only (or give ``contact_stiffness`` [N/m^n]).
    slider_wear_share
        The slider's share of the worn volume [-], 0 to 1.
    segments
        Segments per worn surface, along its length, 1 to 100000.
    """

    slider_length: PositiveLength
    slider_height: PositiveLength
    guide_height: PositiveLength | None = None
    gap: PositiveLength | None = None
    guide_length: PositiveLength | None = None
    corner_radius: PositiveLength | None = None
    slider_wear_share: Annotated[Number, Ge(0), Le(1)] = 0.5
    segments: Annotated[int, Ge(1), Le(100_000)] = 20

    @model_validator(mode="after")
    def _consistent(self) -> "TranslationalClearance":
        problems = [
            *self._unused_keys(),
            *self._law_problems(CORNER_ON_FLAT),
            *self._slide_problems(),
        ]
        if not problems:
            problems = self._stiffness_problems()
        if problems:
            raise ValueError("; ".join(problems))
        return self

    def _slide_problems(self) -> list[str]:
        lines = []
        if (self.guide_height is None) == (self.gap is None):
            which = "guide_height or gap" + ("" if self.gap is None else ", not both")
            lines.append(f"give {which} (the gap is the clearance on each side of the slider)")
        elif self.gap is None and self.guide_height <= self.slider_height:
            lines.append(
                f"guide_height {self.guide_height * 1e3:.12g} mm must be larger than "
                f"slider_height {self.slider_height * 1e3:.12g} mm (the gap is half their "
                "difference)"
            )
        elif self.contact_tolerance >= self.clearance_gap:
            lines.append(
                f"contact_tolerance {self.contact_tolerance:g} m must be much smaller than the "
                f"gap {self.clearance_gap:g} m (default 1e-10 m)"
            )
        given = (self.corner_radius is not None, self.contact_stiffness is not None)
        if given == (False, False) and self.exponent == HERTZ_EXPONENT:
            lines.append(
                "give corner_radius (the rounding of the slider's corners and the guide's "
                "ends, which sets K = 4/3 E* sqrt(r)) or contact_stiffness [N/m^1.5]"
            )
        elif all(given):
            lines.append(
                "give corner_radius or contact_stiffness, not both (contact_stiffness "
                "replaces the stiffness corner_radius sets)"
            )
        return lines

    @property
    def clearance_gap(self) -> float:
        """Clearance c on each side of the slider, (guide height - slider height) / 2 [m]."""
        if self.gap is not None:
            return self.gap
        return 0.5 * (self.guide_height - self.slider_height)

    @property
    def guide_half_height(self) -> float:
        """Half-height of the guide, slider_height / 2 + gap [m]."""
        return 0.5 * self.slider_height + self.clearance_gap

    @property
    def contact(self) -> Contact:
        """A corner, rounded to ``corner_radius`` (None: not given), on a flat face."""
        return Contact(
            CORNER_ON_FLAT, self.contact_modulus, self.corner_radius, self.clearance_gap,
            self.width,
        )  # fmt: skip


class TranslationalJoint(JointTable):
    """Slider along `axis` (first body's frame, any non-zero length).

    Ideal without `clearance`; with it, `bodies[0]` has the guide (its centreline through
    `points[0]`) and `bodies[1]` the slider (centred on `points[1]`), which touch through
    contact forces instead of constraints.

    Attributes
    ----------
    name
        The joint's name.
    bodies
        (first body, second body); ``"ground"`` allowed.
    points
        (a point of the first body, a point of the second).
    axis
        Direction of the slide in the first body's frame (any non-zero length).
    clearance
        A ``TranslationalClearance``, or None: an ideal joint.
    """

    kind: ClassVar = JointKind.TRANSLATIONAL
    type: Literal["translational"] = "translational"
    axis: Annotated[tuple[Number, Number], AfterValidator(unit_axis)]
    clearance: TranslationalClearance | None = None
