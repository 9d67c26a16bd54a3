"""Tabulate the cylinder pressure of examples/single_cylinder_engine.toml over 720 deg.

A single-zone finite heat-release model of a spark-ignition engine: ideal gas with constant
specific heat ratio gamma, no heat loss, heat released after a Wiebe function,

    dp/dtheta = -gamma p / V dV/dtheta + (gamma - 1) / V Q_in dx_b/dtheta,
    x_b = 1 - exp(-a ((theta - theta_s) / theta_d)^n),

as in C.R. Ferguson, A.T. Kirkpatrick, "Internal Combustion Engines: Applied
Thermosciences", 3rd ed., Wiley (2015), ch. 2 (the finite heat-release model), with their
example's parameters a = 5, n = 3, theta_s = -20 deg, theta_d = 40 deg, gamma = 1.4. The
Wiebe function is I.I. Wiebe's (1956); J.I. Ghojel, "Review of the development and
applications of the Wiebe function", Int. J. Engine Res. 11 (2010) 297-312, reviews it.
We read those parameters as a third-party re-implementation of the book's example quotes
them (the book's text could not be read here); check them against it.

The engine is the one a user brought (crank 40 mm, rod 140 mm, bore 80 mm): our choices are
the compression ratio 10 (with gamma = 1.4 it gives the user's 25 bar at the end of
compression), the intake at 1 bar, the heat input, set so that the peak is the user's 60 bar,
and the gas exchange: the exhaust valve opens at bottom dead centre, and the pressure falls
linearly to 1.05 bar over the next 30 deg and stays there to the end of the exhaust stroke.

Crank angle 0 is top dead centre of firing; the table runs from -360 deg (top dead centre of
the gas exchange: intake begins) to 358 deg, every 2 deg, and repeats every 720 deg.

Run it from the repository's root: ``python examples/engine/cylinder_pressure.py``; it
rewrites ``examples/engine/cylinder_pressure.csv`` and prints the curve's landmarks.
"""

import math
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

CRANK, ROD, BORE = 0.040, 0.140, 0.080  # [m]
COMPRESSION_RATIO = 10.0
GAMMA = 1.4
WIEBE_A, WIEBE_N = 5.0, 3.0
START, DURATION = math.radians(-20.0), math.radians(40.0)  # of heat release [rad]
INTAKE = 1.0e5  # [Pa]
EXHAUST, BLOWDOWN = 1.05e5, math.radians(30.0)  # [Pa], [rad]
PEAK = 60.0e5  # [Pa], the user's
STEP = 2.0  # [deg]

AREA = math.pi * BORE**2 / 4.0
SWEPT = AREA * 2.0 * CRANK
CLEARANCE_VOLUME = SWEPT / (COMPRESSION_RATIO - 1.0)


def volume(theta: float) -> tuple[float, float]:
    """Cylinder volume [m^3] and its rate [m^3/rad] at crank angle theta [rad] from TDC."""
    s, c = math.sin(theta), math.cos(theta)
    root = math.sqrt(ROD**2 - (CRANK * s) ** 2)
    pin = CRANK * c + root  # wrist pin above the crank's axis
    rate = -CRANK * s - CRANK**2 * s * c / root
    return CLEARANCE_VOLUME + AREA * (CRANK + ROD - pin), -AREA * rate


def burn_rate(theta: float) -> float:
    """dx_b/dtheta of the Wiebe function [1/rad]."""
    if theta <= START:
        return 0.0
    z = (theta - START) / DURATION
    return WIEBE_A * WIEBE_N / DURATION * z ** (WIEBE_N - 1.0) * math.exp(-WIEBE_A * z**WIEBE_N)


def closed_cycle(heat: float) -> object:
    """Pressure from bottom dead centre of compression to that of expansion (dense output)."""

    def rate(theta: float, p: np.ndarray) -> list[float]:
        v, dv = volume(theta)
        return [-GAMMA * p[0] / v * dv + (GAMMA - 1.0) / v * heat * burn_rate(theta)]

    return solve_ivp(rate, (-math.pi, math.pi), [INTAKE], method="DOP853", rtol=1e-11,
                     atol=1e-6, dense_output=True, max_step=math.radians(0.5))  # fmt: skip


def peak(heat: float) -> float:
    """Largest pressure of the closed cycle [Pa] for a heat input [J]."""
    theta = np.radians(np.arange(-30.0, 60.0, 0.05))
    return float(closed_cycle(heat).sol(theta)[0].max())


def pressure_table(heat: float) -> tuple[np.ndarray, np.ndarray]:
    """Crank angles [deg] and pressures [Pa] over the four strokes."""
    angles = np.arange(-360.0, 360.0, STEP)
    closed = closed_cycle(heat).sol
    open_at = closed(math.pi)[0]  # at the exhaust valve's opening
    values = []
    for angle in angles:
        theta = math.radians(angle)
        if theta < -math.pi:
            values.append(INTAKE)
        elif theta <= math.pi:
            values.append(float(closed(theta)[0]))
        else:
            share = min((theta - math.pi) / BLOWDOWN, 1.0)
            values.append(open_at + share * (EXHAUST - open_at))
    return angles, np.array(values)


def main() -> None:
    """Fit the heat input to the peak, write the table, print its landmarks."""
    heat = brentq(lambda q: peak(q) - PEAK, 10.0, 2000.0, xtol=1e-9)
    angles, pressures = pressure_table(heat)
    out = Path(__file__).with_suffix(".csv")
    lines = ["crank angle [deg], pressure [bar]"]
    lines += [f"{a:.0f}, {p / 1e5:.6f}" for a, p in zip(angles, pressures, strict=True)]
    out.write_text("\n".join(lines) + "\n")
    dense = np.radians(np.arange(-30.0, 60.0, 0.05))
    at = closed_cycle(heat).sol(dense)[0]
    print(f"heat input {heat:.2f} J; peak {at.max() / 1e5:.2f} bar at "
          f"{math.degrees(dense[at.argmax()]):.1f} deg after TDC; end of compression "
          f"{closed_cycle(heat).sol(START)[0] / 1e5:.2f} bar (at -20 deg), at TDC without "
          f"burning {INTAKE * COMPRESSION_RATIO**GAMMA / 1e5:.2f} bar; at the exhaust valve's "
          f"opening {closed_cycle(heat).sol(math.pi)[0] / 1e5:.2f} bar; wrote {out}")  # fmt: skip


if __name__ == "__main__":
    main()
