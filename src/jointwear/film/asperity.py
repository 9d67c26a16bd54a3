"""Greenwood-Tripp constants from a model's roughness keys (the kernel: kernels/laws/asperity.py).

Greenwood and Tripp (1970-71) describe two rough surfaces by the combined standard deviation
sigma of their summit heights, the summit density eta and the summit radius beta of each, and
the asperity pressure depends on them only through two products: the roughness parameter
eta sigma beta and the slope measure sigma / beta,

    k_gt = (16 sqrt(2) pi / 15) (eta sigma beta)^2 sqrt(sigma / beta),  p_a = k_gt E* F_5/2.

Typical values, as quoted from Greenwood and Tripp (1970-71) by the mixed-lubrication
literature: eta sigma beta about 0.03 to 0.05 for many engineering surfaces, sigma / beta about
1e-4 to 1e-2. With 0.04 and 1e-3 the constant is k_gt = 2.4e-4.

References
----------
J.A. Greenwood, J.H. Tripp, "The contact of two nominally flat rough surfaces", Proc. Instn
Mech. Engrs 185 (1970-71) 625-633, doi:10.1243/PIME_PROC_1970_185_069_02.
"""

import math

from ..model.errors import ModelError

_GT_FACTOR = 16.0 * math.sqrt(2.0) * math.pi / 15.0


def _check_positive(values: dict[str, float]) -> None:
    """ModelError naming each value that is not a finite positive number."""
    problems = [
        f"{name}: {value!r} is not allowed; give a finite number > 0"
        for name, value in values.items()
        if isinstance(value, bool)
        or not (isinstance(value, int | float) and math.isfinite(value) and value > 0)
    ]
    if problems:
        raise ModelError(problems)


def asperity_constant(roughness_parameter: float, slope: float) -> float:
    """Greenwood-Tripp constant k_gt = (16 sqrt(2) pi / 15) (eta sigma beta)^2 sqrt(sigma / beta).

    Parameters
    ----------
    roughness_parameter
        eta sigma beta [-], typically 0.03 to 0.05.
    slope
        sigma / beta [-], typically 1e-4 to 1e-2.

    Returns
    -------
    float
        k_gt [-]; the asperity pressure is k_gt E* F_5/2(h / sigma).

    References
    ----------
    Greenwood and Tripp (1970-71).
    """
    _check_positive({"roughness_parameter": roughness_parameter, "slope": slope})
    return _GT_FACTOR * roughness_parameter**2 * math.sqrt(slope)


def roughness_products(
    asperity_density: float, asperity_radius: float, roughness: float
) -> tuple[float, float]:
    """The products (eta sigma beta, sigma / beta) [-] from the asperity data.

    Parameters
    ----------
    asperity_density
        eta, summits per unit area of each surface [1/m^2].
    asperity_radius
        beta, summit radius of each surface [m].
    roughness
        sigma, combined standard deviation of the summit heights [m].
    """
    _check_positive(
        {
            "asperity_density": asperity_density,
            "asperity_radius": asperity_radius,
            "roughness": roughness,
        }
    )
    return asperity_density * roughness * asperity_radius, roughness / asperity_radius
