"""Records of the elastic and damping laws of a contact (kernels: ``kernels.laws.normal``).

The stiffness formulas live here, in plain Python: the kernels read the constant K packed
into the element's table, never the formula. E* and R* are those of Johnson (1985); the
internal-cylinder K = 4/3 E* sqrt(R*) is Lankarani and Nikravesh's (1990) with the
relative radius of internal contact (Flores et al. 2008, SPEC sec. 3), and with R* the
corner's radius the same constant serves a rounded corner on a flat face (its bearing
radius taken to infinity).
"""

import math

from .record import (
    CONFORMAL,
    CORNER_ON_FLAT,
    HERTZ_PATCH,
    PENETRATION,
    Contact,
    Family,
    Kernel,
    Key,
    Law,
    Range,
    Stiffness,
    pack_in_order,
)

HERTZ_EXPONENT = 1.5  # the exponent the stiffness formula is for
DEPTH_LIMIT = 0.1  # penetration / c of Hertz, Liu and the foundation: small against the gap
PATCH_LIMIT = 0.1  # Hertz half-width b / R_J: a line contact's patch small against the pin
JOHNSON_LIMIT = 8.0 * math.exp(-3.0)  # delta_s / c, where Johnson's law hands over to its tangent


def effective_modulus(e_b: float, nu_b: float, e_j: float, nu_j: float) -> float:
    """Contact modulus E* [Pa], 1/E* = (1 - nu_b^2)/E_b + (1 - nu_j^2)/E_j (Johnson 1985)."""
    return 1.0 / ((1.0 - nu_b * nu_b) / e_b + (1.0 - nu_j * nu_j) / e_j)


def effective_radius(r_b: float, r_j: float) -> float:
    """Relative radius R* = R_B R_J / (R_B - R_J) [m] of a cylinder inside a cylinder."""
    return r_b * r_j / (r_b - r_j)


def foundation_modulus(e: float, nu: float) -> float:
    """K_f = (1 - nu) E / ((1 + nu)(1 - 2 nu)) [Pa] of a Winkler layer (Johnson 1985, 5.3)."""
    return (1.0 - nu) * e / ((1.0 + nu) * (1.0 - 2.0 * nu))


def _hertz_stiffness(values: dict, contact: Contact) -> float:
    """K = 4/3 E* sqrt(R*) [N/m^1.5] (module docstring)."""
    return 4.0 / 3.0 * contact.contact_modulus * math.sqrt(contact.relative_radius)


def _pack_hertz(values: dict) -> tuple[float, ...]:
    if values["exponent"] != HERTZ_EXPONENT and values["contact_stiffness"] is None:
        raise ValueError(
            f"exponent {values['exponent']:g} needs contact_stiffness "
            f"[N/m^{values['exponent']:g}]: the stiffness formula is for exponent "
            f"{HERTZ_EXPONENT:g}"
        )
    return ()


def _foundation_stiffness(values: dict, contact: Contact) -> float:
    """K = (K_f / h) R [Pa] of a layer of thickness h lining the seat of radius R."""
    radius, young, nu = contact.seat
    if nu >= 0.5:
        raise ValueError(
            "needs the bearing's poisson_ratio below 0.5 (its layer modulus "
            "(1 - nu) E / ((1 + nu)(1 - 2 nu)) is infinite at 0.5)"
        )
    return foundation_modulus(young, nu) / values["foundation_thickness"] * radius


def _kernels(force: str, arguments: str) -> tuple[Kernel, ...]:
    """An elastic law's force, stiffness and energy functions, which take the same arguments."""
    names = tuple(arguments.split())
    return tuple(Kernel(f"normal:{force}{part}", names) for part in ("", "_stiffness", "_energy"))


EXPONENT = Key("exponent", "", HERTZ_EXPONENT, positive=True, help="exponent n of K delta^n")
CONTACT_STIFFNESS = Key(
    "contact_stiffness", "N/m^n", None, positive=True,
    help="K of K delta^n, a plain number in N/m^n; replaces the formula",
)  # fmt: skip
LAYER = Key(
    "foundation_thickness", "m", None, positive=True,
    help="thickness h of the elastic layer, e.g. '2 mm'",
)  # fmt: skip
_CONFORMAL_LAW = (CONFORMAL,)

NORMAL = Family(
    "normal_law", "normal",
    (
        Law(
            "hertz", 0, "K delta^n (Flores 2009, Eq. 18)", ("hertz1882",),
            keys=(EXPONENT, CONTACT_STIFFNESS), pack=_pack_hertz,
            kernels=_kernels("hertz", "delta k n"),
            ranges=(Range(PENETRATION, DEPTH_LIMIT), Range(HERTZ_PATCH, PATCH_LIMIT)),
            stiffness=Stiffness(
                _hertz_stiffness, "N/m^n", "K (n = {exponent:g})",
                {CONFORMAL: ("lankarani1990", "flores2008book"), CORNER_ON_FLAT: ()},
                given_by="contact_stiffness",
            ),
        ),
        Law(
            "johnson", 1,
            "delta = F/(pi E* L) [ln(4 pi E* L dR / F) - 1] (Johnson 1985; Pereira et al. 2011)",
            ("johnson1985", "pereira2011"),
            kernels=_kernels("johnson", "delta e_star d_r width"),
            ranges=(Range(PENETRATION, JOHNSON_LIMIT),), shapes=_CONFORMAL_LAW,
        ),
        Law(
            "liu", 2, "(pi/2) E* L delta sqrt(delta / (2 (dR + delta))) (Liu, Zhang, Yang 2007)",
            ("liu2007",),
            kernels=_kernels("liu", "delta e_star d_r width"),
            ranges=(Range(PENETRATION, DEPTH_LIMIT),), shapes=_CONFORMAL_LAW,
        ),
        Law(
            "elastic_foundation", 3,
            "Winkler layer p = K_f u / h on the worn surfaces (Johnson 1985; Mukras et al. 2010)",
            ("johnson1985", "mukras2010tribology"),
            keys=(LAYER,), pack=pack_in_order(LAYER),
            kernels=(
                Kernel("normal:foundation_on_circles", ("delta", "k", "d_r", "width")),
                *_kernels("foundation", "delta k d_r width")[1:],
            ),
            ranges=(Range(PENETRATION, DEPTH_LIMIT),),
            stiffness=Stiffness(_foundation_stiffness, "Pa", "k = (K_f / h) R_B", {}),
            shapes=_CONFORMAL_LAW,
        ),
    ),
    default="hertz",
    dispatchers=("normal:elastic_force", "normal:elastic_stiffness", "normal:elastic_energy"),
)  # fmt: skip

RESTITUTION = Key(
    "restitution_coefficient", "", None, positive=True, high=1.0,
    help="coefficient of restitution c_e, 0 < c_e <= 1",
)  # fmt: skip
_PACK_RESTITUTION = pack_in_order(RESTITUTION)


def _undamped(values: dict) -> tuple[float]:
    return (1.0,)


DAMPING = Family(
    "damping", "damping",
    (
        Law("none", 0, "no damping: elastic contact", (), pack=_undamped,
            kernels=(Kernel("normal:undamped", ("c_e",)),)),
        Law(
            "lankarani_nikravesh", 1,
            "f_e [1 + 3 (1 - c_e^2)/4 delta_dot/delta_dot_minus] (Lankarani, Nikravesh 1990)",
            ("lankarani1990",), keys=(RESTITUTION,), pack=_PACK_RESTITUTION,
            kernels=(Kernel("normal:lankarani_nikravesh", ("c_e",)),),
        ),
        Law(
            "hunt_crossley", 2,
            "f_e [1 + 3 (1 - c_e)/2 delta_dot/delta_dot_minus] (Hunt, Crossley 1975)",
            ("hunt1975",), keys=(RESTITUTION,), pack=_PACK_RESTITUTION,
            kernels=(Kernel("normal:hunt_crossley", ("c_e",)),),
        ),
        Law(
            "flores2011", 3,
            "f_e [1 + 8 (1 - c_e)/(5 c_e) delta_dot/delta_dot_minus] (Flores et al. 2011)",
            ("flores2011",), keys=(RESTITUTION,), pack=_PACK_RESTITUTION,
            kernels=(Kernel("normal:flores2011", ("c_e",)),),
        ),
    ),
    default="lankarani_nikravesh",
    dispatchers=("normal:hysteresis_factor",),
)  # fmt: skip
