"""Records of the lubrication laws of a journal bearing (kernels: ``kernels.laws.lubrication``)."""

from .record import CONFORMAL, ECCENTRICITY, Family, Kernel, Key, Law, Range, pack_in_order

VISCOSITY = Key(
    "viscosity", "Pa*s", None, positive=True,
    help="dynamic viscosity of the lubricant, e.g. '0.02 Pa*s'",
)  # fmt: skip
BREAKDOWN = Key(
    "film_breakdown", "", 0.95, positive=True, high=0.999,
    help="eccentricity ratio where the film starts handing over to solid contact",
)  # fmt: skip
_FILM = ("eps", "eps_dot", "gamma_dot", "w", "mu", "r", "width", "c")
_RANGE = (Range(ECCENTRICITY, BREAKDOWN.name),)


def _dry(values: dict) -> tuple[float, float]:
    return (0.0, 0.0)


LUBRICATION = Family(
    "lubrication", "lubrication",
    (
        Law("none", 0, "dry joint", (), pack=_dry),
        Law(
            "short_bearing", 1,
            "pi-film short bearing (Pinkus, Sternlicht 1961; Flores et al. 2009)",
            ("flores2009lubricated", "pinkus1961"),
            keys=(VISCOSITY, BREAKDOWN), pack=pack_in_order(VISCOSITY, BREAKDOWN),
            kernels=(Kernel("lubrication:short_bearing_forces", _FILM),),
            ranges=_RANGE, shapes=(CONFORMAL,),
        ),
        Law(
            "long_bearing", 2,
            "pi-film long (half-Sommerfeld) bearing (Hamrock et al. 2004; Flores et al. 2009)",
            ("flores2009lubricated", "hamrock2004"),
            keys=(VISCOSITY, BREAKDOWN), pack=pack_in_order(VISCOSITY, BREAKDOWN),
            kernels=(Kernel("lubrication:long_bearing_forces", _FILM),),
            ranges=_RANGE, shapes=(CONFORMAL,),
        ),
    ),
    default="none",
    dispatchers=("lubrication:film_force_components",),
)  # fmt: skip
