"""The revolute joint's table in a model file, ideal or with clearance (docs/model-format.md).

With a ``[joints.clearance]`` table, the joint's first body carries the bearing (the hole,
centred on the joint's first point), the second the journal (the pin, centred on its second
point). Laws are chosen by name from their records (``model.laws``); validation reads only
the records, and the derived numbers that need a kernel import it at the point of use.
"""

from typing import Annotated, ClassVar, Literal

from annotated_types import Ge, Le
from pydantic import model_validator

from ...kernels.codes import JointKind
from ...model.clearance import ClearanceTable, PositiveLength, law_name
from ...model.laws import EVERY, WEAR_DISTRIBUTION
from ...model.laws.lubrication import ASPERITY_START, MAX_FILM_RATIO, reads_film_table
from ...model.laws.normal import effective_radius
from ...model.laws.record import CONFORMAL, Contact, Family
from ...model.tables import JointTable, Number
from ...units import to_si


class RevoluteClearance(ClearanceTable):
    """A revolute joint with clearance: journal in bearing, contact, friction and wear (SI).

    Material pairs are [bearing, journal]; the keys every clearance table has are those of
    ``ClearanceTable`` (width [m], moduli [Pa], laws and their keys).

    Attributes
    ----------
    bearing_radius
        R_B, radius of the hole [m].
    journal_radius
        R_J, radius of the pin [m], < R_B.
    radial_clearance
        c [m], instead of ``bearing_radius``: R_B = R_J + c.
    journal_wear_share
        The journal's share of the worn volume [-], 0 to 1.
    wear_distribution
        How a step's wear goes into the sectors: ``"hertz"``, ``"peak"`` or
        ``"elastic_foundation"``.
    sectors
        Sectors per surface, 4 to 100000.
    """

    FAMILIES: ClassVar[tuple[Family, ...]] = EVERY

    bearing_radius: PositiveLength
    journal_radius: PositiveLength
    journal_wear_share: Annotated[Number, Ge(0), Le(1)] = 0.5
    wear_distribution: law_name(WEAR_DISTRIBUTION) = WEAR_DISTRIBUTION.default
    sectors: Annotated[int, Ge(4), Le(100_000)] = 36

    @model_validator(mode="before")
    @classmethod
    def _radial_clearance(cls, data: object) -> object:
        """Read ``radial_clearance`` c as the bearing radius journal_radius + c [m]."""
        if not isinstance(data, dict) or "radial_clearance" not in data:
            return data
        rest = {key: value for key, value in data.items() if key != "radial_clearance"}
        if "journal_radius" not in data:
            raise ValueError(
                "radial_clearance needs journal_radius: the bearing radius is the journal's "
                "plus the clearance"
            )
        clearance = to_si(data["radial_clearance"], "[length]", "radial_clearance")
        journal = to_si(data["journal_radius"], "[length]", "journal_radius")
        if not clearance > 0.0:
            raise ValueError(f"radial_clearance: got {clearance:g} m; must be > 0")
        return {**rest, "bearing_radius": journal + clearance}

    @model_validator(mode="after")
    def _consistent(self) -> "RevoluteClearance":
        problems = [*self._unused_keys(), *self._law_problems(CONFORMAL)]
        if self.journal_radius >= self.bearing_radius:
            problems.append(
                f"journal_radius {self.journal_radius * 1e3:.12g} mm must be smaller than "
                f"bearing_radius {self.bearing_radius * 1e3:.12g} mm (the radial clearance is "
                "their difference)"
            )
        elif self.contact_tolerance >= self.radial_clearance:
            problems.append(
                f"contact_tolerance {self.contact_tolerance:g} m must be much smaller than the "
                f"radial clearance {self.radial_clearance:g} m (default 1e-10 m)"
            )
        if not problems:
            problems = self._stiffness_problems() + self._film_problems()
        if problems:
            raise ValueError("; ".join(problems))
        return self

    def _film_problems(self) -> list[str]:
        """A finite bearing's L/D beyond its table, or a roughness the clearance cannot hold."""
        if not reads_film_table(self.lubrication):
            return []
        problems = []
        ratio = self.width / (2.0 * self.journal_radius)
        if ratio > MAX_FILM_RATIO:
            problems.append(
                f"width / journal diameter L/D = {ratio:.4g} is beyond the finite bearing's "
                f"{MAX_FILM_RATIO:g}; give a width up to {MAX_FILM_RATIO:g} diameters (the "
                "film barely changes beyond: at L/D = 20 it is the infinitely long bearing's "
                "within 0.3 %)"
            )
        if self.wear_distribution == "elastic_foundation":
            problems.append(
                "wear_distribution 'elastic_foundation' spreads the wear over where the worn "
                "surfaces interfere, and the asperities of a finite bearing's mixed film also "
                'touch before they do: choose wear_distribution "hertz" or "peak"'
            )
        if ASPERITY_START * self.roughness >= self.radial_clearance:
            problems.append(
                f"roughness {self.roughness * 1e6:.4g} um: its asperities would touch with the "
                f"journal centred (4 x roughness >= the radial clearance "
                f"{self.radial_clearance * 1e6:.4g} um); roughness is the surfaces' combined "
                "RMS height, typically 0.05 to 2 um"
            )
        return problems

    @property
    def radial_clearance(self) -> float:
        """Radial clearance c = R_B - R_J [m]."""
        return self.bearing_radius - self.journal_radius

    @property
    def relative_radius(self) -> float:
        """R* = R_B R_J / (R_B - R_J) [m]."""
        return effective_radius(self.bearing_radius, self.journal_radius)

    @property
    def contact(self) -> Contact:
        """A journal in its bearing; an elastic layer lines the bearing."""
        return Contact(
            CONFORMAL, self.contact_modulus, self.relative_radius, self.radial_clearance,
            self.width, (self.bearing_radius, self.moduli[0], self.poisson_ratios[0]),
        )  # fmt: skip

    def hertz_patch(self, force: float) -> tuple[float, float]:
        """Half-width b [m] and peak pressure p_max [Pa] of the line contact under force [N].

        Evaluates the kernels (imports them).
        """
        from ...kernels.laws.wear import hertz_line_contact

        return hertz_line_contact(force, self.relative_radius, self.contact_modulus, self.width)


class RevoluteJoint(JointTable):
    """Pin joining `points[0]` of `bodies[0]` and `points[1]` of `bodies[1]`.

    Ideal without `clearance`; with it, `bodies[0]` has the bearing and `bodies[1]` the
    journal, and the joint acts through contact forces instead of constraints.

    Attributes
    ----------
    name
        The joint's name.
    bodies
        (first body, second body); ``"ground"`` allowed.
    points
        (a point of the first body, a point of the second).
    clearance
        A ``RevoluteClearance``, or None: an ideal joint.
    """

    kind: ClassVar = JointKind.REVOLUTE
    type: Literal["revolute"] = "revolute"
    clearance: RevoluteClearance | None = None
