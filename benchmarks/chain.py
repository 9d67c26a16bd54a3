"""How the cost of a run grows with the size of a mechanism: an N-link pendulum chain (issue 14).

The chain: N uniform bars, each 1 kg and 0.1 m long (inertia m l^2 / 12 about the centre),
the first pinned to the ground at the origin, each next one pinned to the previous bar's free
end, all ideal revolute joints, under gravity (9.81 m/s^2, -y). Released from rest as one
straight line 45 degrees below the horizontal (``--angle``), and simulated for 1 s with the
default solver settings but an output row every 1 ms (``--output-interval``), one per
maximum step, as in the issue's measurements (rows there cost a third of the time at N = 80).
``--integrator`` and ``--formulation`` change only those keys; when not given they are left
out of the model.

For each N: one warm-up run (it compiles the kernels), then ``--repeats`` timed runs; the wall
time is the median of ``jw.simulate`` alone (assembly and result tables included, model
building not). Printed as a markdown table: N, wall, accepted steps, right-hand-side (RHS)
evaluations (the run statistics' ``rhs_evaluations``, which count those of output rows too:
a row costs one unless a step ends on its time), output rows, microseconds per RHS
evaluation (wall over the evaluations), and the tip (the last bar's free end) at
t = 1 s, to compare formulations; then the growth exponent, the least-squares slope of
log(wall) against log(N) over the sizes from 10 to 80.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/chain.py                          # N = 2 ... 80, minutes
    .venv/bin/python benchmarks/chain.py --sizes 2 5 --repeats 1  # smoke
    .venv/bin/python benchmarks/chain.py --formulation augmented_lagrangian --integrator dopri5
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import time

import numpy as np

import jointwear as jw
from jointwear.model import Model, parse_model

MASS, LENGTH = 1.0, 0.1  # per bar [kg], [m]
GRAVITY = 9.81  # [m/s^2]
T_END = 1.0  # [s]
OUTPUT_INTERVAL = 1e-3  # [s]
SIZES = (2, 5, 10, 20, 40, 80)
GROWTH_RANGE = (10, 80)  # the sizes the growth exponent is fitted over


def chain_model(
    n: int, angle_deg: float, integrator: str | None, formulation: str | None, interval: float
) -> Model:
    """The n-link chain, straight at ``angle_deg`` from the horizontal, at rest."""
    angle = math.radians(angle_deg)
    cos, sin = math.cos(angle), math.sin(angle)
    bodies = [
        {
            "name": f"bar{k}",
            "mass": MASS,
            "inertia": MASS * LENGTH**2 / 12.0,
            "position": [(k - 0.5) * LENGTH * cos, (k - 0.5) * LENGTH * sin],
            "angle": angle,
            "points": {"start": [-0.5 * LENGTH, 0.0], "end": [0.5 * LENGTH, 0.0]},
        }
        for k in range(1, n + 1)
    ]
    joints = [
        {
            "name": f"pin{k}",
            "type": "revolute",
            "bodies": ["ground" if k == 1 else f"bar{k - 1}", f"bar{k}"],
            "points": ["pivot" if k == 1 else "end", "start"],
        }
        for k in range(1, n + 1)
    ]
    solver: dict = {"t_end": T_END, "output_interval": interval}
    if integrator is not None:
        solver["integrator"] = integrator
    if formulation is not None:
        solver["formulation"] = formulation
    data = {
        "ground": {"points": {"pivot": [0.0, 0.0]}},
        "bodies": bodies,
        "joints": joints,
        "forces": [{"type": "gravity", "acceleration": [0.0, -GRAVITY]}],
        "solver": solver,
    }
    return parse_model(data, name=f"chain_{n}")


def tip(results: jw.Results, n: int) -> tuple[float, float, float]:
    """Time of the last output row and the last bar's free end there [s], [m], [m]."""
    last = results.timeseries.iloc[-1]
    x, y, phi = last[f"x_bar{n}"], last[f"y_bar{n}"], last[f"phi_bar{n}"]
    half = 0.5 * LENGTH
    return last["time"], x + half * math.cos(phi), y + half * math.sin(phi)


def measure(model: Model, n: int, repeats: int) -> dict:
    """Warm up once, then the median wall time of ``repeats`` runs and the last run's figures."""
    jw.simulate(model)
    walls = []
    for _ in range(repeats):
        start = time.perf_counter()
        results = jw.simulate(model)
        walls.append(time.perf_counter() - start)
    stats = results.summary["stats"]
    t_last, x, y = tip(results, n)
    if results.status != "success" or abs(t_last - T_END) > 1e-9:
        print(f"N = {n}: {results.status} at t = {t_last:g} s: {results.message}", file=sys.stderr)
    wall = statistics.median(walls)
    return {
        "n": n,
        "wall": wall,
        "steps": stats["accepted_steps"],
        "rhs": stats["rhs_evaluations"],
        "us_per_rhs": 1e6 * wall / stats["rhs_evaluations"],
        "rows": len(results.timeseries),
        "tip": (x, y),
        "status": results.status,
    }


def growth_exponent(rows: list[dict]) -> float | None:
    """Least-squares slope of log(wall) against log(N) over the sizes in ``GROWTH_RANGE``."""
    fit = [r for r in rows if GROWTH_RANGE[0] <= r["n"] <= GROWTH_RANGE[1]]
    if len(fit) < 2:
        return None
    log_n = np.log([r["n"] for r in fit])
    log_wall = np.log([r["wall"] for r in fit])
    return float(np.polyfit(log_n, log_wall, 1)[0])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=SIZES, help="numbers of bars")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs per size (median)")
    parser.add_argument("--integrator", help="solver.integrator (default: the model default)")
    parser.add_argument("--formulation", help="solver.formulation (default: not set)")
    parser.add_argument("--angle", type=float, default=-45.0, help="initial angle [deg]")
    parser.add_argument(
        "--output-interval", type=float, default=OUTPUT_INTERVAL, help="between rows [s]"
    )
    args = parser.parse_args()

    print(
        f"N-link chain, {MASS:g} kg x {LENGTH:g} m bars from {args.angle:g} deg at rest, "
        f"{T_END:g} s, a row every {args.output_interval * 1e3:g} ms; integrator "
        f"{args.integrator or 'default'}, formulation {args.formulation or 'default'}; "
        f"median of {args.repeats} warm runs\n"
    )
    print(
        "| N | wall [s] | accepted steps | RHS evaluations | output rows | µs per RHS "
        "| tip x [m] | tip y [m] |"
    )
    print("|---|---|---|---|---|---|---|---|")
    rows = []
    for n in args.sizes:
        model = chain_model(n, args.angle, args.integrator, args.formulation, args.output_interval)
        row = measure(model, n, args.repeats)
        rows.append(row)
        flag = "" if row["status"] == "success" else f" ({row['status']})"
        print(
            f"| {n} | {row['wall']:.4f} | {row['steps']} | {row['rhs']} | "
            f"{row['rows']} | {row['us_per_rhs']:.1f} | "
            f"{row['tip'][0]:.9f} | {row['tip'][1]:.9f}{flag} |",
            flush=True,
        )
    exponent = growth_exponent(rows)
    low, high = GROWTH_RANGE
    text = "n/a (fewer than two sizes)" if exponent is None else f"{exponent:.2f}"
    print(f"\ngrowth exponent (slope of log wall against log N, N = {low}-{high}): {text}")


if __name__ == "__main__":
    main()
