"""Laws of your own, from Python: the paper's four laws written again and registered.

Each function below is the formula of one of the built-in laws of the paper's four-bar
(P. Flores, Mechanism and Machine Theory 44 (2009) 1211-1222), written from its paper as a
user would write a law of their own: an ``@numba.njit`` function of the arguments its family
gives (docs/user-laws.md), then its own keys. ``register()`` names them; a model file then
chooses them like built-in laws, with the keys in the joint's clearance table:

    normal_law = "user_hertz"
    damping = "user_lankarani_nikravesh"
    friction_law = "user_ambrosio"
    still_speed = "0.1 mm/s"
    full_speed = "10 mm/s"
    wear_law = "user_archard"
    archard_k = "8e-14 1/Pa"

Run it (``python examples/user_laws.py``) to simulate the four-bar for two crank turns with
the built-in laws and with these, and see that they agree. The tests and
``benchmarks/user_law_cost.py`` use the same functions. Nothing is registered on import.
"""

from pathlib import Path

from numba import njit

import jointwear as jw


@njit
def hertz(delta, k, n, e_star, d_r, width):
    """K delta^n [N] (Hertz; Flores 2009, Eq. 18 without damping); called with delta > 0."""
    return k * delta**n


@njit
def lankarani_nikravesh(c_e):
    """Hysteresis factor chi = 3 (1 - c_e^2) / 4 [-] (Lankarani and Nikravesh 1990)."""
    return 0.75 * (1.0 - c_e * c_e)


@njit
def _ramp(s, s0, s1):
    """0 up to s0, linear to 1 at s1, 1 beyond."""
    if s <= s0:
        return 0.0
    if s >= s1:
        return 1.0
    return (s - s0) / (s1 - s0)


@njit
def ambrosio(v_t, f_n, c_f, still_speed, full_speed):
    """-c_f c_d(v_T) F_N sign(v_T) [N] (Ambrosio 2002; Flores 2009, Eq. 19)."""
    sign = 1.0 if v_t > 0.0 else -1.0 if v_t < 0.0 else 0.0
    return -c_f * _ramp(abs(v_t), still_speed, full_speed) * f_n * sign


@njit
def ambrosio_sliding(v_t, still_speed, full_speed):
    """Sliding speed [m/s]: abs(v_T), 0 up to still_speed, where the friction vanishes."""
    s = abs(v_t)
    return s if s > still_speed else 0.0


@njit
def archard(mu, archard_k):
    """Wear coefficient dh/ds / p = k [1/Pa] (Archard 1953; Flores 2009, Eq. 13)."""
    return archard_k


LAWS = {  # the model-file key -> (built-in law, its twin here)
    "normal_law": ("hertz", "user_hertz"),
    "damping": ("lankarani_nikravesh", "user_lankarani_nikravesh"),
    "friction_law": ("ambrosio", "user_ambrosio"),
    "wear_law": ("archard", "user_archard"),
}
# The twins' keys at the built-in laws' values in the paper's four-bar.
KEYS = {"still_speed": "1e-4 m/s", "full_speed": "1e-2 m/s", "archard_k": "8e-14 1/Pa"}


def register() -> None:
    """Register the four laws (again: replaces them)."""
    jw.register_law("normal", "user_hertz", hertz, summary="K delta^n, as hertz")
    jw.register_law("damping", "user_lankarani_nikravesh", lankarani_nikravesh)
    jw.register_law(
        "friction",
        "user_ambrosio",
        ambrosio,
        keys={"still_speed": "m/s", "full_speed": "m/s"},
        sliding=ambrosio_sliding,
        summary="c_f c_d(v_T) F_N, as ambrosio",
    )
    jw.register_law("wear", "user_archard", archard, keys={"archard_k": "1/Pa"})


def unregister() -> None:
    """Remove the four laws."""
    for _, twin in LAWS.values():
        jw.unregister_law(twin)


def twin_model(t_end: float) -> jw.Model:
    """The paper's four-bar, its clearance joint with the four laws here (registered)."""
    joint = "joints.coupler_follower.clearance"
    changes = {f"{joint}.{family}": twin for family, (_, twin) in LAWS.items()}
    changes |= {f"{joint}.{key}": value for key, value in KEYS.items()}
    changes |= {f"{joint}.wear_coefficient": None, "solver.t_end": t_end}  # archard's key
    return jw.load_model(FOURBAR).with_values(changes)


FOURBAR = Path(__file__).parent / "flores2009_fourbar.toml"

if __name__ == "__main__":
    register()
    built_in = jw.simulate(jw.load_model(FOURBAR).with_values({"solver.t_end": 0.08}))
    twins = jw.simulate(twin_model(0.08))
    column = "coupler_follower_fn"
    gap = (built_in.timeseries[column] - twins.timeseries[column]).abs().max()
    print(f"largest contact force: {built_in.timeseries[column].max():.6g} N (built-in)")
    print(f"largest difference of the contact force, built-in against user laws: {gap:g} N")
