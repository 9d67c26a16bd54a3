"""Records of the lubrication laws of a journal bearing (kernels: ``kernels.laws.lubrication``).

The short and long bearings hand over to solid contact at ``film_breakdown``, a numerical
setting. The finite bearing is mixed: its film and the surfaces' asperities share the load
as the gap closes to the roughness, so the hand-over follows from ``roughness``.
"""

import math

from .record import CONFORMAL, ECCENTRICITY, Family, Kernel, Key, Law, Range, pack_in_order

VISCOSITY = Key(
    "viscosity", "Pa*s", None, positive=True,
    help="dynamic viscosity of the lubricant, e.g. '0.02 Pa*s'",
)  # fmt: skip
BREAKDOWN = Key(
    "film_breakdown", "", 0.95, positive=True, high=0.999,
    help="a numerical setting of the short and long bearings: the eccentricity ratio where "
    "their film starts handing over to solid contact (the finite bearing's follows from "
    "its roughness)",
)  # fmt: skip
ROUGHNESS = Key(
    "roughness", "m", None, positive=True,
    help="the surfaces' combined RMS roughness sqrt(Rq_1^2 + Rq_2^2), e.g. '0.4 um'",
)  # fmt: skip
ROUGHNESS_PARAMETER = Key(
    "roughness_parameter", "", 0.04, positive=True,
    help="eta sigma beta: asperity density x roughness x asperity radius",
)  # fmt: skip
ASPERITY_SLOPE = Key(
    "asperity_slope", "", 1e-3, positive=True, high=1.0,
    help="sigma / beta: roughness over the asperities' radius",
)  # fmt: skip
MAX_FILM_RATIO = 20.0  # the largest L/D of a finite bearing's table (film.impedance)
ASPERITY_START = 4.0  # film thickness / roughness below which asperities touch (Hu et al. 1994)
_FILM = ("eps", "eps_dot", "gamma_dot", "w", "mu", "r", "width", "c")
_RANGE = (Range(ECCENTRICITY, BREAKDOWN.name),)


def _dry(values: dict) -> tuple[float, float, float, float]:
    return (0.0, 0.0, 0.0, 0.0)


def _film_only(values: dict) -> tuple[float, float, float, float]:
    """(viscosity [Pa s], film_breakdown [-], no roughness, no asperities)."""
    return (*pack_in_order(VISCOSITY, BREAKDOWN)(values), 0.0, 0.0)


def reads_film_table(name: str) -> bool:
    """Whether the lubrication law ``name`` reads an impedance table (the finite bearing)."""
    return any("table" in kernel.arguments for kernel in LUBRICATION.by_name[name].kernels)


def asperity_constant(roughness_parameter: float, asperity_slope: float) -> float:
    """Greenwood and Tripp's K = (16 sqrt(2) pi / 15) (eta sigma beta)^2 sqrt(sigma / beta) [-].

    The asperity pressure is K E' F_5/2(h / sigma) (``kernels.laws.asperity``).
    """
    return (
        16.0 * math.sqrt(2.0) * math.pi / 15.0 * roughness_parameter**2 * math.sqrt(asperity_slope)
    )


def _mixed(values: dict) -> tuple[float, float, float, float]:
    """(viscosity [Pa s], breakdown 1 (none), roughness [m], Greenwood-Tripp K [-])."""
    viscosity, roughness = pack_in_order(VISCOSITY, ROUGHNESS)(values)
    k = asperity_constant(values[ROUGHNESS_PARAMETER.name], values[ASPERITY_SLOPE.name])
    return (viscosity, 1.0, roughness, k)


LUBRICATION = Family(
    "lubrication", "lubrication",
    (
        Law("none", 0, "dry joint", (), pack=_dry),
        Law(
            "short_bearing", 1,
            "pi-film short bearing (Pinkus, Sternlicht 1961; Flores et al. 2009)",
            ("flores2009lubricated", "pinkus1961"),
            keys=(VISCOSITY, BREAKDOWN), pack=_film_only,
            kernels=(Kernel("lubrication:short_bearing_forces", _FILM),),
            ranges=_RANGE, shapes=(CONFORMAL,),
        ),
        Law(
            "long_bearing", 2,
            "pi-film long (half-Sommerfeld) bearing (Hamrock et al. 2004; Flores et al. 2009)",
            ("flores2009lubricated", "hamrock2004"),
            keys=(VISCOSITY, BREAKDOWN), pack=_film_only,
            kernels=(Kernel("lubrication:long_bearing_forces", _FILM),),
            ranges=_RANGE, shapes=(CONFORMAL,),
        ),
        Law(
            "finite_bearing", 3,
            "finite bearing, Reynolds cavitation, tabulated by impedance (Childs et al. 1977), "
            "with Greenwood-Tripp asperity contact",
            ("childs1977", "raimondi1958", "greenwood1970", "hu1994", "patir1978"),
            keys=(VISCOSITY, ROUGHNESS, ROUGHNESS_PARAMETER, ASPERITY_SLOPE), pack=_mixed,
            kernels=(Kernel("lubrication:finite_bearing_forces", ("table", *_FILM)),),
            shapes=(CONFORMAL,),
        ),
    ),
    default="none",
    dispatchers=("lubrication:film_force_components",),
)  # fmt: skip
