"""The finite journal bearing's numbers in docs/theory.md (section 6, finite bearing).

    PYTHONPATH=src python benchmarks/finite_bearing.py

prints the steady Sommerfeld numbers and attitude angles of the Reynolds solver against
Raimondi and Boyd's (the rows of the page's table, from ``row``), the time to build one table,
and the kernel's interpolation error against direct solves.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

from jointwear.film.impedance import build_table
from jointwear.film.reynolds import film_force
from jointwear.kernels.laws.impedance import film_impedance

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))  # the references
from references import RAIMONDI_BOYD, RAIMONDI_BOYD_EPS


def steady(ratio: float, eps: float) -> tuple[float, float]:
    """S and phi [deg] of the steadily loaded journal (psi = -90 deg)."""
    w_r, w_t = film_force(eps, -0.5 * math.pi, ratio)
    return 2.0 / (math.pi * eps * math.hypot(w_r, w_t)), math.degrees(math.atan2(w_t, -w_r))


def row(ratio: float, eps: float) -> str:
    """The page's table row of one L / D and eps."""
    s_pub, phi_pub = (v[RAIMONDI_BOYD_EPS.index(eps)] for v in RAIMONDI_BOYD[ratio])
    s, phi = steady(ratio, eps)
    return (
        f"| {ratio:g} | {eps:g} | {s_pub:.3g} | {s:.4g} | {100 * (s / s_pub - 1):+.1f} % "
        f"| {phi_pub:g} | {phi:.1f} | {100 * (phi / phi_pub - 1):+.1f} % |"
    )


def centre_ratio(ratio: float) -> float:
    """|W| of V pointing away from e_r over |W| towards it, at eps = 0 (the inlet's price)."""
    away = math.hypot(*film_force(0.0, math.pi, ratio))
    return away / math.hypot(*film_force(0.0, 0.0, ratio))


def periodic_angle_error(ratio: float, eps: float) -> float:
    """phi of the periodic film (no inlet) over Raimondi and Boyd's, minus 1."""
    w_r, w_t = film_force(eps, -0.5 * math.pi, ratio, supply=False)
    phi_pub = RAIMONDI_BOYD[ratio][1][RAIMONDI_BOYD_EPS.index(eps)]
    return math.degrees(math.atan2(w_t, -w_r)) / phi_pub - 1.0


def interpolation_errors(table, ratio: float, samples: int = 200, seed: int = 3) -> dict:
    """Largest |W_kernel - W_solver| / |W_solver| by eps band, towards or away from the wall."""
    rng = np.random.default_rng(seed)
    worst: dict = {}
    for lo, hi in [(0.0, 0.9), (0.9, 0.99), (0.99, 0.999), (0.999, 0.9999)]:
        for _ in range(samples // 4):
            eps = rng.uniform(lo, hi)
            psi = rng.uniform(-math.pi, math.pi)
            direct = np.array(film_force(eps, psi, ratio))
            error = np.linalg.norm(np.array(film_impedance(table, eps, psi)) - direct)
            key = (lo, hi, "towards" if math.cos(psi) >= 0.0 else "away from")
            worst[key] = max(worst.get(key, 0.0), error / np.linalg.norm(direct))
    return worst


def main() -> None:
    print("| L / D | eps | S, R-B | S | error | phi, R-B [deg] | phi [deg] | error |")
    print("|---|---|---|---|---|---|---|---|")
    for ratio in sorted(RAIMONDI_BOYD):
        for eps in RAIMONDI_BOYD_EPS:
            print(row(ratio, eps))
    for ratio in sorted(RAIMONDI_BOYD):
        print(
            f"L / D = {ratio:g}: at eps = 0, |W| away from e_r / towards = "
            f"{centre_ratio(ratio):.2f}; periodic film's phi at eps = 0.1: "
            f"{100 * periodic_angle_error(ratio, 0.1):+.0f} % off Raimondi and Boyd"
        )
    for ratio in sorted(RAIMONDI_BOYD):
        start = time.perf_counter()
        table = build_table(ratio)
        print(f"L / D = {ratio:g}: table built in {time.perf_counter() - start:.1f} s")
        for (lo, hi, side), error in sorted(interpolation_errors(table, ratio).items()):
            print(f"  {lo} < eps < {hi}, V {side} the wall: kernel within {100 * error:.2f} %")


if __name__ == "__main__":
    main()
