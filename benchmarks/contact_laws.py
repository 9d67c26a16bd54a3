"""The paper's four-bar with each contact law, and the laws' force against penetration.

Writes the user guide's comparison table (max contact force, time in contact, deepest wear, the
share of the time beyond the law's range) for the cases below, each the paper's four-bar
(``examples/flores2009_fourbar.toml``, or an example extending it) with its clearance joint
changed, and the figure ``docs/images/contact_laws.png``: force against penetration of every
elastic law on the paper's joint (Table 2: R_B 10 mm, R_J 9.8 mm, L 20 mm, steel 207 GPa, 0.3).

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/contact_laws.py            # 1 s runs, about a minute
    .venv/bin/python benchmarks/contact_laws.py --t-end 0.1 --no-figure   # smoke
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import jointwear as jw

ROOT = Path(__file__).parents[1]
EXAMPLES = ROOT / "examples"
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
JOINT = "coupler_follower"
KEY = f"joints.{JOINT}.clearance"
LAYER = "5 mm"  # elastic-foundation layer on the bearing (a bushing's wall), an assumption
CASES = {  # name: (model file, overrides)
    "Hertz (paper)": (FOURBAR, []),
    "Johnson": (EXAMPLES / "flores2009_fourbar_johnson.toml", []),
    "Liu et al.": (FOURBAR, [f"{KEY}.normal_law=liu"]),
    f"elastic foundation, h = {LAYER}": (
        FOURBAR,
        [
            f"{KEY}.normal_law=elastic_foundation",
            f"{KEY}.foundation_thickness={LAYER}",
            f"{KEY}.wear_distribution=elastic_foundation",
        ],
    ),
    # SAE 30 at 100 C, 0.01 Pa s (the example file gives the source)
    "Hertz, lubricated (SAE 30, short bearing)": (
        EXAMPLES / "flores2009_fourbar_lubricated.toml",
        [],
    ),
}


def table(t_end: float) -> str:
    """The comparison table (markdown) of the CASES over t_end [s]."""
    rows = [
        "| case | max contact force | time in contact | deepest wear (journal) | "
        "beyond the law's range (penetration / patch) |",
        "|---|---|---|---|---|",
    ]
    return "\n".join([*rows, *(row(name, t_end) for name in CASES)])


def row(name: str, t_end: float) -> str:
    """The table's row of case ``name`` over t_end [s] (also checked against docs/user-guide.md)."""
    path, overrides = CASES[name]
    model = jw.load_model(path, [f"solver.t_end={t_end}", *overrides])
    joint = jw.simulate(model).summary["clearance_joints"][JOINT]
    joint = {**joint, **joint["whole_run"]}  # the start-up included, as before
    ranges = joint["outside_law_ranges"]
    beyond = [
        f"{100 * ranges[check]['time_fraction_beyond']:.0f} %"
        for check in ("penetration_over_clearance", "hertz_half_width_over_journal_radius")
        if check in ranges
    ]
    return (
        f"| {name} | {joint['max_contact_force_n'] / 1e3:.1f} kN "
        f"| {100 * joint['contact_time_fraction']:.1f} % "
        f"| {joint['max_wear_depth_journal_m'] * 1e6:.3f} µm "
        f"| {' / '.join(beyond)} |"
    )


def figure(path: Path) -> None:
    """Force against penetration of every elastic law on the paper's joint."""
    import matplotlib.pyplot as plt

    base = jw.load_model(FOURBAR).joints[2].clearance
    laws = {
        "Hertz, K from Table 2 (n = 1.5)": {},
        "Johnson (conformal)": {"normal_law": "johnson"},
        "Liu et al. (conformal)": {"normal_law": "liu"},
        f"elastic foundation, h = {LAYER}": {
            "normal_law": "elastic_foundation",
            "foundation_thickness": LAYER,
        },
    }
    c = base.radial_clearance
    delta = np.linspace(0.0, 0.6, 400) * c
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, keys in laws.items():
        joint = base.model_validate({**base.model_dump(), **keys})
        force = [joint.elastic_force(d)[0] for d in delta]
        ax.plot(delta * 1e6, np.asarray(force) / 1e3, label=label)
    ax.axvline(0.1 * c * 1e6, color="0.6", lw=0.8, ls="--")
    ax.text(0.1 * c * 1e6, 5, " 10 % of c", color="0.4", fontsize=8)
    ax.axhline(84.2, color="0.6", lw=0.8, ls=":")
    ax.text(2, 87, "paper's peak, 84 kN", color="0.4", fontsize=8)
    ax.set_xlabel("penetration δ [µm]  (radial clearance c = 200 µm)")
    ax.set_ylabel("elastic force [kN]")
    ax.set_ylim(0, 400)
    ax.set_title("Contact laws on the paper's joint (Flores 2009, Table 2)")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=1.0, help="simulated time [s]")
    parser.add_argument("--no-figure", action="store_true", help="skip the figure")
    args = parser.parse_args()
    if not args.no_figure:
        path = ROOT / "docs" / "images" / "contact_laws.png"
        figure(path)
        print(f"figure: {path.relative_to(ROOT)}")
    print(table(args.t_end))


if __name__ == "__main__":
    main()
