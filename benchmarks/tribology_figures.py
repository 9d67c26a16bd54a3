"""The lubricated slider-crank's film pressure and Stribeck curve, for the user guide.

Sweeps ``examples/slider_crank_lubricated.toml`` over the viscosity (its own 0.01 Pa s among
them), copies the 0.01 Pa s case's film pressure figure and the sweep's Stribeck curve into
``docs/images/`` (``slider_crank_film_pressure.png``, ``slider_crank_stribeck.png``) and
prints the numbers the user guide quotes: the film at the instant of the largest film force,
and per case the Hersey number, friction coefficient, lambda_min and asperity share, with the
share of the film's power that is shear (Couette) rather than pressure flow (squeeze and
wedge), from the steady state's rows.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/tribology_figures.py            # about 15 s
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
from jointwear.kernels.laws.asperity import mean_gap

ROOT = Path(__file__).parents[1]
MODEL = ROOT / "examples" / "slider_crank_lubricated.toml"
IMAGES = ROOT / "docs" / "images"
JOINT = "rod_slider"
VISCOSITY = f"joints.{JOINT}.clearance.viscosity"
VALUES = ["0.001 Pa*s", "0.003 Pa*s", "0.01 Pa*s", "0.03 Pa*s", "0.1 Pa*s", "0.3 Pa*s"]
EXAMPLE_CASE = "viscosity=0.01_Pa_s"  # the example's own oil


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


def shear_share(results: jw.Results) -> float:
    """The Couette shear's share of the film's power over the steady state's rows [-].

    Couette power 2 pi mu (R w_rel)^2 R L / (c sqrt(1 - eps^2)) with the film's eps, from
    the mean gap as the kernel takes it (``film_field``); the rest of ``film_power`` is the
    pressure flow, -F . V.
    """
    c = results.model.joint(JOINT).clearance
    bearing, journal = results.model.joint(JOINT).bodies
    ts = results.timeseries
    rows = ts[ts["time"] >= results.summary["steady_state"]["from_s"]]
    t = rows["time"].to_numpy()
    delta = rows[f"{JOINT}_delta"].to_numpy()
    gap = np.hypot(rows[f"{JOINT}_ex"], rows[f"{JOINT}_ey"]).to_numpy() - delta
    eps = 1.0 - np.array([mean_gap(max(-d, 0.0), c.roughness) for d in delta]) / gap
    u = c.journal_radius * (rows[f"omega_{journal}"] - rows[f"omega_{bearing}"]).to_numpy()
    couette = 2 * math.pi * c.viscosity * u**2 * c.journal_radius * c.width
    couette /= gap * np.sqrt(1.0 - eps**2)
    return float(np.trapezoid(couette, t) / np.trapezoid(rows[f"{JOINT}_film_power"], t))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-images", action="store_true", help="do not write docs/images")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder) / "sweep"
        study = jw.sweep(MODEL, out, vary={VISCOSITY: VALUES})
        example = jw.load_results(out / "cases" / EXAMPLE_CASE)
        print(f"{JOINT}, {EXAMPLE_CASE}: {film_report(example)}")
        film = f"{JOINT}.film."
        print("| viscosity | Hersey number | friction coefficient | lambda_min | asperity share "
              "| shear share of film power |")  # fmt: skip
        print("|---|---|---|---|---|---|")
        for _, case in study.table.sort_values(VISCOSITY).iterrows():
            results = jw.load_results(out / "cases" / case["case"])
            print(
                f"| {case[VISCOSITY]:g} Pa s | {case[film + 'hersey_number']:.3g} "
                f"| {case[film + 'friction_coefficient']:.3f} | {case[film + 'min_lambda']:.2f} "
                f"| {case[film + 'asperity_load_share']:.1%} | {shear_share(results):.1%} |"
            )
        if not args.no_images:
            plot_film_pressure(example).savefig(IMAGES / "slider_crank_film_pressure.png", dpi=120)
            shutil.copyfile(out / "figures" / "stribeck.png", IMAGES / "slider_crank_stribeck.png")


if __name__ == "__main__":
    main()
