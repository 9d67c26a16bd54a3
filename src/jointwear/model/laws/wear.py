"""Records of the wear laws and of the revolute joint's wear distributions.

Kernels: ``kernels.laws.wear`` (the laws); the distributions are branches of the journal's
own wear step (``kernels.elements.journal``, ``I_SPREAD``), so their records name no kernel.
"""

from .normal import PATCH_LIMIT
from .record import CONFORMAL, HERTZ_PATCH, Family, Kernel, Key, Law, Range


def _pack_archard(values: dict) -> tuple[float, float]:
    k = values.get("wear_coefficient")
    by_hardness = (values.get("dimensionless_wear_coefficient"), values.get("hardness"))
    if k is None and None in by_hardness:
        raise ValueError(
            "needs wear_coefficient (e.g. '8e-14 1/Pa'), or dimensionless_wear_coefficient "
            "together with hardness"
        )
    if k is not None and by_hardness != (None, None):
        raise ValueError(
            "give wear_coefficient, or dimensionless_wear_coefficient with hardness, not both"
        )
    return (k if k is not None else by_hardness[0] / by_hardness[1], 0.0)


def _pack_reye(values: dict) -> tuple[float, float]:
    if values.get("shear_strength") is None:
        raise ValueError("needs shear_strength (a pressure, e.g. '300 MPa')")
    return (values["shear_strength"], 0.0)


WEAR = Family(
    "wear_law", "wear",
    (
        Law(
            "archard", 0, "dh/ds = k p (Archard 1953; Flores 2009, Eq. 13)", ("archard1953",),
            keys=(
                Key("wear_coefficient", "1/Pa", None),
                Key("dimensionless_wear_coefficient", "", None),
                Key("hardness", "Pa", None, positive=True),
            ),
            pack=_pack_archard, kernels=(Kernel("wear:archard", ("p0",)),),
            shown=(("Archard k (as used)", "1/Pa"),),
        ),
        Law(
            "reye", 1, "dh/ds = mu p / tau, mu = |F_T| / F_N (Flores 2009, Eq. 9)",
            ("reye1860",),
            keys=(Key("shear_strength", "Pa", None, positive=True),),
            pack=_pack_reye, kernels=(Kernel("wear:reye", ("mu", "p0")),),
        ),
    ),
    default="archard",
    dispatchers=("wear:wear_coefficient",),
)  # fmt: skip

_PATCH = (Range(HERTZ_PATCH, PATCH_LIMIT),)
WEAR_DISTRIBUTION = Family(
    "wear_distribution", "wear distribution",
    (
        Law("hertz", 0, "Hertz's elliptic pressure, averaged over the sectors it covers",
            ("johnson1985",), ranges=_PATCH, shapes=(CONFORMAL,)),
        Law("peak", 1, "Hertz's peak pressure into the one sector at the contact (Flores 2009)",
            ("flores2009",), ranges=_PATCH, shapes=(CONFORMAL,)),
        Law("elastic_foundation", 2, "the elastic foundation's pressure on the worn surfaces",
            ("mukras2010tribology",), shapes=(CONFORMAL,)),
    ),
    default="hertz",
)  # fmt: skip
