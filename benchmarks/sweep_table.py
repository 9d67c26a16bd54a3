"""The sweep table of docs/studies.md: the paper's four-bar at three clearances and three frictions.

Each case is the paper's four-bar (``examples/flores2009_fourbar.toml``) over 1 s (25 crank
turns) with the bearing radius and friction coefficient of its clearance joint changed, as
the page's ``jointwear sweep`` command runs them; a row gives the whole run's figures.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/sweep_table.py     # nine 1 s runs, about half a minute
"""

from __future__ import annotations

from pathlib import Path

import jointwear as jw

FOURBAR = Path(__file__).parents[1] / "examples" / "flores2009_fourbar.toml"
KEY = "joints.coupler_follower.clearance"
CLEARANCES_MM = (0.1, 0.2, 0.5)  # radial clearance: bearing radius - the journal's 9.8 mm
FRICTION = (0.0, 0.1, 0.2)
HEADER = (
    "| c [mm] | μ | max contact force [kN] | impacts | journal: max depth [µm] at "
    "| bearing: max depth [µm] at | worn volume [mm³] | friction energy [J] |\n"
    "|---|---|---|---|---|---|---|---|"
)


def row(c_mm: float, mu: float, t_end: float = 1.0) -> str:
    """The table's row of clearance ``c_mm`` [mm] and friction ``mu`` over ``t_end`` [s]."""
    journal_mm = jw.load_model(FOURBAR).joint("coupler_follower").clearance.journal_radius * 1e3
    overrides = [
        f"solver.t_end={t_end}",
        f"{KEY}.bearing_radius={journal_mm + c_mm:.6g} mm",
        f"{KEY}.friction_coefficient={mu}",
    ]
    joint = jw.simulate(jw.load_model(FOURBAR, overrides)).summary["clearance_joints"]
    joint = joint["coupler_follower"]
    whole = joint["whole_run"]
    depths = [
        f"{joint[f'max_wear_depth_{s}_m'] * 1e6:#.3g} at {joint[f'max_wear_angle_{s}_deg']:g}°"
        for s in ("journal", "bearing")
    ]
    return (
        f"| {c_mm:g} | {mu:g} | {whole['max_contact_force_n'] / 1e3:.1f} | {whole['impacts']} "
        f"| {depths[0]} | {depths[1]} | {whole['worn_volume_m3'] * 1e9:#.3g} "
        f"| {whole['energy_dissipated_friction_j']:.0f} |"
    )


def main() -> None:
    print(HEADER)
    for c_mm in CLEARANCES_MM:
        for mu in FRICTION:
            print(row(c_mm, mu), flush=True)


if __name__ == "__main__":
    main()
