"""The film pressure of the lubricated slider-crank and the rig's Stribeck curve, for the docs.

Runs ``examples/slider_crank_lubricated.toml`` and draws its film pressure at the largest film
force; sweeps ``examples/journal_bearing_rig.toml`` over the viscosity and takes its Stribeck
curve. Writes ``docs/images/slider_crank_film_pressure.png`` and
``docs/images/journal_bearing_stribeck.png`` and prints the numbers the user guide quotes:
the film at that instant, and per case of the rig the Hersey number, friction coefficient,
lambda_min and asperity share.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/tribology_figures.py            # about three minutes
    .venv/bin/python benchmarks/tribology_figures.py --no-images
"""

from __future__ import annotations

import argparse
import math
import shutil
import tempfile
from pathlib import Path

import numpy as np

import jointwear as jw
from jointwear.joints.revolute.figures import plot_film_pressure
from jointwear.joints.revolute.film_field import film_field

ROOT = Path(__file__).parents[1]
MODEL = ROOT / "examples" / "slider_crank_lubricated.toml"
RIG = ROOT / "examples" / "journal_bearing_rig.toml"
IMAGES = ROOT / "docs" / "images"
JOINT = "rod_slider"
VISCOSITY = "joints.bush.clearance.viscosity"
VALUES = [f"{v} Pa*s" for v in ("0.0001", "0.0003", "0.001", "0.003", "0.01", "0.03", "0.1")]


def film_report(results: jw.Results) -> str:
    """The film at the row of largest film force, as the figure's title gives it."""
    field = film_field(results, JOINT)
    area = np.outer(np.diff(field.angle_faces), np.diff(field.axial_faces))
    cavitated = area[field.cavitated].sum() / area.sum()
    return (
        f"t = {field.time * 1e3:.4g} ms: eps = {field.eps:.4f}, thinnest film "
        f"{field.film_min * 1e6:.3g} um, film force {math.hypot(*field.force) / 1e3:.3g} kN, "
        f"peak pressure {field.pressure.max() / 1e6:.3g} MPa, cavitated {cavitated:.0%} "
        "of the film"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-images", action="store_true", help="do not write docs/images")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        example = jw.run(MODEL, Path(folder) / "slider_crank", figures=False, ideal=False)
        print(f"{JOINT}: {film_report(example)}")
        out = Path(folder) / "stribeck"
        study = jw.sweep(RIG, out, vary={VISCOSITY: VALUES})
        film = "bush.film."
        print("| viscosity | Hersey number | friction coefficient | lambda_min | asperity share |")
        print("|---|---|---|---|---|")
        for _, case in study.table.sort_values(VISCOSITY).iterrows():
            print(
                f"| {case[VISCOSITY]:g} Pa s | {case[film + 'hersey_number']:.3g} "
                f"| {case[film + 'friction_coefficient']:.4f} | {case[film + 'min_lambda']:.2f} "
                f"| {case[film + 'asperity_load_share']:.1%} |"
            )
        if not args.no_images:
            plot_film_pressure(example).savefig(IMAGES / "slider_crank_film_pressure.png", dpi=120)
            stribeck = IMAGES / "journal_bearing_stribeck.png"
            shutil.copyfile(out / "figures" / "stribeck.png", stribeck)


if __name__ == "__main__":
    main()
