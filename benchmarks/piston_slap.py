"""Headline figures of the piston-slap example, at two tolerances (the user guide's table).

Runs ``examples/slider_crank_piston_clearance.toml`` (the slider-crank of Flores, Leine and
Glocker 2010 with a gap between slider and guide) at the file's tolerances and at rtol 1e-8,
and prints per run: the largest corner force (over every step, and the corner whose output
rows peak highest), time in contact, impacts per crank turn, the
deepest wear along the guide and on the slider, and the worn volume.

    python benchmarks/piston_slap.py
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import jointwear as jw

EXAMPLE = Path(__file__).parents[1] / "examples" / "slider_crank_piston_clearance.toml"
JOINT = "piston"
CORNERS = ("front_top", "front_bottom", "rear_top", "rear_bottom")
CASES = {"file's tolerances (rtol 1e-6)": [], "rtol 1e-8, atol 1e-10": [
    "solver.rtol=1e-8", "solver.atol=1e-10"]}  # fmt: skip


def headline(results: jw.Results) -> dict[str, str]:
    """The row of one run: forces [N], contact share, impacts per turn, wear [um] and where."""
    df = results.timeseries
    joint = results.summary["clearance_joints"][JOINT]
    turns = (df["phi_crank"].iloc[-1] - df["phi_crank"].iloc[0]) / (2.0 * math.pi)
    peaks = {c: df[f"{JOINT}_fn_{c}"].max() for c in CORNERS}
    corner = max(peaks, key=peaks.get)  # which one, from the output rows
    guide = max(("guide_top", "guide_bottom"), key=lambda s: joint[f"max_wear_depth_{s}_m"])
    slider = max(("slider_top", "slider_bottom"), key=lambda s: joint[f"max_wear_depth_{s}_m"])
    return {
        "max corner force": f"{joint['max_contact_force_n']:.4g} N ({corner})",
        "time in contact": f"{100 * joint['contact_time_fraction']:.1f} %",
        "impacts per turn": f"{joint['impacts'] / turns:.1f} ({joint['impacts']} in "
        f"{turns:.2f} turns)",
        "deepest wear, guide": f"{joint[f'max_wear_depth_{guide}_m'] * 1e6:.3g} µm ({guide}, "
        f"{joint[f'max_wear_position_{guide}_m'] * 1e3:+.0f} mm)",
        "deepest wear, slider": f"{joint[f'max_wear_depth_{slider}_m'] * 1e6:.3g} µm "
        f"({slider}, {joint[f'max_wear_position_{slider}_m'] * 1e3:+.1f} mm)",
        "worn volume": f"{joint['worn_volume_m3'] * 1e9:.3g} mm³",
        "max tilt": f"{np.abs(df[f'{JOINT}_tilt']).max() * 1e3:.3g} mrad",
    }


def main() -> None:
    rows = {}
    for case, overrides in CASES.items():
        results = jw.simulate(jw.load_model(EXAMPLE, overrides))
        assert results.status == "success", results.message
        rows[case] = headline(results)
    names = list(next(iter(rows.values())))
    print("| case | " + " | ".join(names) + " |")
    print("|---" * (len(names) + 1) + "|")
    for case, row in rows.items():
        print(f"| {case} | " + " | ".join(row[n] for n in names) + " |")


if __name__ == "__main__":
    main()
