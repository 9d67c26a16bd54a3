"""Laws written as a user would, outside the package: twins of built-in laws (tests only).

Each is the formula of a built-in law (``kernels.laws``), written again from its paper,
with the built-in law's keys renamed where a user law may not reuse them. Nothing is
registered here: the tests register them (``register_twins``), so a process that imports
this module (a Dask worker unpickling a law) gets no law unless a task brings it.
"""

from numba import njit

import jointwear as jw


@njit
def hertz(delta, k, n, e_star, d_r, width):
    """K delta^n [N] (Hertz; Flores 2009, Eq. 18 with D = 0)."""
    return k * delta**n


@njit
def lankarani_nikravesh(c_e):
    """chi = 3 (1 - c_e^2) / 4 (Lankarani and Nikravesh 1990)."""
    return 0.75 * (1.0 - c_e * c_e)


@njit
def _ramp(s, s0, s1):
    if s <= s0:
        return 0.0
    if s >= s1:
        return 1.0
    return (s - s0) / (s1 - s0)


@njit
def ambrosio(v_t, f_n, c_f, still_speed, full_speed):
    """-c_f c_d(v_T) f_n sign(v_T) [N] (Ambrosio 2002; Flores 2009, Eq. 19)."""
    sign = 1.0 if v_t > 0.0 else -1.0 if v_t < 0.0 else 0.0
    return -c_f * _ramp(abs(v_t), still_speed, full_speed) * f_n * sign


@njit
def ambrosio_sliding(v_t, still_speed, full_speed):
    """abs(v_T), 0 up to the speed where friction vanishes [m/s]."""
    s = abs(v_t)
    return s if s > still_speed else 0.0


@njit
def archard(mu, archard_k):
    """dh/ds / p = k [1/Pa] (Archard 1953; Flores 2009, Eq. 13)."""
    return archard_k


@njit
def hertz_energy(delta, k, n, e_star, d_r, width):
    """K delta^(n + 1) / (n + 1) [J]."""
    return k * delta ** (n + 1.0) / (n + 1.0)


TWINS = {  # built-in law -> the user twin's name
    "hertz": "user_hertz",
    "lankarani_nikravesh": "user_lankarani_nikravesh",
    "ambrosio": "user_ambrosio",
    "archard": "user_archard",
}
# The twins' keys in a model file, for the built-in laws' defaults and the four-bar's k.
TWIN_KEYS = {"still_speed": "1e-4 m/s", "full_speed": "1e-2 m/s", "archard_k": "8e-14 1/Pa"}


def register_twins() -> None:
    """Register the four twins (again: replaces them)."""
    jw.register_law("normal", "user_hertz", hertz, summary="K delta^n, as hertz")
    jw.register_law("damping", "user_lankarani_nikravesh", lankarani_nikravesh)
    jw.register_law(
        "friction",
        "user_ambrosio",
        ambrosio,
        keys={"still_speed": "m/s", "full_speed": "m/s"},
        sliding=ambrosio_sliding,
    )
    jw.register_law("wear", "user_archard", archard, keys={"archard_k": "1/Pa"})


def unregister_twins() -> None:
    """Remove the twins."""
    for name in TWINS.values():
        jw.unregister_law(name)
