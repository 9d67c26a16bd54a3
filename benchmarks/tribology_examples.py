"""The mixed-lubrication examples' numbers in docs/tribology.md.

Prints three tables:

1. The lubricated slider-crank's time in solid contact and wear per crank turn: with the
   short bearing, as its numerical setting ``film_breakdown`` changes, and with the finite
   bearing in mixed lubrication, as its numerical settings (tolerances, the impedance
   table's nodes and the film's cells) are halved and doubled.
2. The slider-crank against the oil's viscosity: wear per turn, lambda, the asperities'
   share of the load, the friction power of the asperities and of the film, and the Hersey
   number.
3. The same for the paper's four-bar (examples/flores2009_fourbar_mixed.toml).

Usage (from the repository root, after ``make install``; about two minutes)::

    .venv/bin/python benchmarks/tribology_examples.py
"""

from __future__ import annotations

from pathlib import Path

import jointwear as jw
from jointwear.film import impedance

EXAMPLES = Path(__file__).parents[1] / "examples"
SLIDER_CRANK = EXAMPLES / "slider_crank_lubricated.toml"
FOURBAR = EXAMPLES / "flores2009_fourbar_mixed.toml"
VISCOSITIES = (0.001, 0.003, 0.01, 0.03, 0.1, 0.3)  # [Pa s]
SHORT = [
    "joints.rod_slider.clearance.lubrication=short_bearing",
    "joints.rod_slider.clearance.roughness=",
]


def steady(path: Path, joint: str, overrides: list[str]) -> dict:
    """The steady state's figures of ``joint``, and the wear per cycle [m^3]."""
    res = jw.simulate(jw.load_model(path, overrides=overrides))
    if res.status != "success":
        raise RuntimeError(f"{path.name} {overrides}: {res.message}")
    entry = res.summary["clearance_joints"][joint]
    return {
        **entry,
        "wear_per_cycle": entry["worn_volume_m3"] / res.summary["steady_state"]["windows"],
    }


def scaled_table(nodes: float, cells: float):
    """``impedance_table`` with the table's nodes and the film's cells scaled."""
    sizes = {
        "n_s": round((impedance.N_S - 1) * nodes) + 1,
        "n_chi": 2 * round(impedance.N_CHI * nodes / 2),
        "n_angle": 2 * round(impedance.N_ANGLE * cells / 2),
        "n_axial": round(impedance.N_AXIAL * cells),
    }
    return lambda ratio: impedance.build_table(ratio, **sizes)


def settings_table() -> None:
    print("| film | setting | time in solid contact | wear per turn [mm^3] |")
    print("|---|---|---|---|")
    for breakdown in (0.95, 0.99, 0.999):
        entry = steady(
            SLIDER_CRANK,
            "rod_slider",
            [*SHORT, f"joints.rod_slider.clearance.film_breakdown={breakdown}"],
        )
        share = entry["contact_time_fraction"]
        print(f"| short bearing | film_breakdown {breakdown} | {share:.1%} "
              f"| {entry['wear_per_cycle'] * 1e9:.4g} |")  # fmt: skip
    cases = {
        "defaults (rtol 1e-6)": ([], None),
        "tolerances halved": (["solver.rtol=5e-7", "solver.atol=5e-9"], None),
        "tolerances doubled": (["solver.rtol=2e-6", "solver.atol=2e-8"], None),
        "table nodes and film cells halved": ([], (0.5, 0.5)),
        "table nodes doubled": ([], (2.0, 1.0)),
        "film cells doubled": ([], (1.0, 2.0)),
    }
    built = impedance.impedance_table
    for name, (overrides, table) in cases.items():
        impedance.impedance_table = built if table is None else scaled_table(*table)
        try:
            entry = steady(SLIDER_CRANK, "rod_slider", overrides)
        finally:
            impedance.impedance_table = built
        print(f"| finite bearing, mixed | {name} | {entry['contact_time_fraction']:.2%} "
              f"| {entry['wear_per_cycle'] * 1e9:.4g} |")  # fmt: skip


def viscosity_table(path: Path, joint: str, overrides: list[str]) -> None:
    print("| viscosity [Pa s] | wear per turn [mm^3] | time in solid contact | min lambda "
          "| asperity share | boundary friction [W] | film [W] | Hersey number |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|")
    for viscosity in VISCOSITIES:
        entry = steady(path, joint, [*overrides, f"joints.{joint}.clearance.viscosity={viscosity}"])
        film = entry["film"]
        powers = film["friction_power_boundary_w"], film["friction_power_viscous_w"]
        print(f"| {viscosity:g} | {entry['wear_per_cycle'] * 1e9:.3g} "
              f"| {entry['contact_time_fraction']:.1%} | {film['min_lambda']:.2f} "
              f"| {film['asperity_load_share']:.3g} | {powers[0]:.3g} | {powers[1]:.3g} "
              f"| {film['hersey_number']:.3g} |")  # fmt: skip


if __name__ == "__main__":
    settings_table()
    print()
    viscosity_table(SLIDER_CRANK, "rod_slider", [])
    print()
    viscosity_table(FOURBAR, "coupler_follower", ["solver.t_end=0.12"])
