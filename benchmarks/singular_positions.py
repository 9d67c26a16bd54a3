"""Errors through singular positions and with redundant constraints, over 20 s (issue 14).

Prints, for the cases of ``tests/test_singular_redundant.py`` and with that file's exact
references (the one-coordinate parallelogram motion and the chain in absolute angles, both
integrated by scipy at rtol 1e-12):

- the parallelogram and the double parallelogram with a redundant crank (20 s, 56 flat
  positions): each crank's and the coupler's largest angle error [rad], the largest change of
  kinetic plus potential energy [J], the largest error of the crank forces' sum on the coupler
  and of each crank's equal share [N] (shares away from the flat positions), and the largest
  difference between the two mechanisms' force sums [N];
- the 10-bar chain (2 s): largest tip error [m] and energy change [J];
- the paper's Baumgarte formulation on the same parallelogram: its status, where it
  stopped, and its largest angle error.

Usage (from the repository root, after ``make install``; about a minute)::

    .venv/bin/python benchmarks/singular_positions.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))  # the references

import test_singular_redundant as ref


def parallelogram_rows() -> None:
    print("| mechanism | integrator | crank angle [rad] | coupler angle [rad] | energy [J] "
          "| force sum [N] | equal shares [N] |")  # fmt: skip
    print("|---|---|---|---|---|---|---|")
    sums = {}
    for mechanism in ref.MECHANISMS:
        for integrator in ref.INTEGRATORS:
            res = ref.parallelogram_run(
                mechanism, integrator, "augmented_lagrangian", tuple(ref.TIGHT.items())
            )
            df = res.timeseries
            errors = ref.motion_errors(df, mechanism)
            coupler = errors.pop("coupler")
            total = (df["energy_kinetic"] + df["energy_potential"]).to_numpy()
            time = df["time"].to_numpy()
            exact, _ = ref.exact_coupler_force(time)
            forces = ref.coupler_forces(df, mechanism)
            total_force = sum(forces.values())
            sums[mechanism, integrator] = total_force
            away = np.abs(np.sin(ref.exact_motion(time)[0])) >= ref.FLAT_BAND
            share = max(np.abs(f - exact / len(forces))[away].max() for f in forces.values())
            print(
                f"| {mechanism} | {integrator} ({res.status}) | {max(errors.values()):.1e} "
                f"| {coupler:.1e} | {np.abs(total - total[0]).max():.1e} "
                f"| {np.abs(total_force - exact).max():.1e} | {share:.1e} |"
            )
    for integrator in ref.INTEGRATORS:
        difference = sums["double_parallelogram", integrator] - sums["parallelogram", integrator]
        print(f"\nforce sums, redundant against plain ({integrator}): "
              f"{np.abs(difference).max():.1e} N")  # fmt: skip


def chain_rows() -> None:
    _, tip_x, tip_y, _ = ref.chain_reference()
    print("\n| chain, 10 bars, 2 s | integrator | tip [m] | energy [J] |\n|---|---|---|---|")
    for formulation in ref.FORMULATIONS:
        for integrator in ref.INTEGRATORS:
            df = ref.chain_run(formulation, integrator)
            last = f"bar{ref.CHAIN_N}"
            phi = df[f"phi_{last}"].to_numpy()
            x = df[f"x_{last}"].to_numpy() + 0.5 * ref.CHAIN_LENGTH * np.cos(phi)
            y = df[f"y_{last}"].to_numpy() + 0.5 * ref.CHAIN_LENGTH * np.sin(phi)
            total = (df["energy_kinetic"] + df["energy_potential"]).to_numpy()
            print(f"| {formulation} | {integrator} | {np.hypot(x - tip_x, y - tip_y).max():.1e} "
                  f"| {np.abs(total - total[0]).max():.1e} |")  # fmt: skip


def baumgarte_rows() -> None:
    print("\n| Baumgarte on the parallelogram | integrator | status | reached [s] | "
          "angle error [rad] |\n|---|---|---|---|---|")  # fmt: skip
    for name, settings in ref.BAUMGARTE_SETTINGS.items():
        for integrator in ref.INTEGRATORS:
            res = ref.parallelogram_run("parallelogram", integrator, "baumgarte", settings)
            errors = ref.motion_errors(res.timeseries, "parallelogram")
            reached = res.summary["stats"]["t_reached"]
            print(
                f"| {name} | {integrator} | {res.status} | {reached:.2f} "
                f"| {max(errors.values()):.1e} |"
            )


if __name__ == "__main__":
    parallelogram_rows()
    chain_rows()
    baumgarte_rows()
