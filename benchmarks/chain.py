"""How a run's cost grows with the size of a mechanism: an N-link pendulum chain (issues 14, 32).

The chain: N uniform bars, each 1 kg and 0.1 m long (inertia m l^2 / 12 about the centre),
the first pinned to the ground at the origin, each next one pinned to the previous bar's free
end, all ideal revolute joints, under gravity (9.81 m/s^2, -y). Released from rest as one
straight line 45 degrees below the horizontal (``--angle``), and simulated for 1 s with the
default solver settings but an output row every 1 ms (``--output-interval``), one per
maximum step, as in the issues' measurements. ``--integrator`` and ``--formulation`` change
only those keys; when not given they are left out of the model.

Each size runs in a child process of its own, so that its peak memory is its own: one run of
a two-bar chain loads the compiled kernels, then ``--repeats`` timed runs of the N-bar one.
Printed as a markdown table, medians: N; simulation time (the run statistics'
``simulation_wall_s``: the step loop, without set-up and results); accepted steps;
right-hand-side (RHS) evaluations (those of output rows included: a row costs one unless a
step ends on its time); output rows; simulation microseconds per accepted step and body;
set-up time (the rest of ``jw.simulate``: assembly, the lock-up check, the results tables);
the child's peak resident memory; and the tip (the last bar's free end) at t = 1 s, to
compare formulations. Then each size's cost per step and body against N = 80's (or the
first size's): flat when the step loop costs linear time.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/chain.py                          # N = 10 ... 2,000, minutes
    .venv/bin/python benchmarks/chain.py --sizes 2 5 --repeats 1  # smoke
    .venv/bin/python benchmarks/chain.py --formulation baumgarte --integrator dopri5
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import statistics
import subprocess
import sys
import time

import jointwear as jw
from jointwear.model import Model, parse_model

MASS, LENGTH = 1.0, 0.1  # per bar [kg], [m]
GRAVITY = 9.81  # [m/s^2]
T_END = 1.0  # [s]
OUTPUT_INTERVAL = 1e-3  # [s]
SIZES = (10, 80, 320, 640, 2000)
REFERENCE_SIZE = 80  # the size the others' cost per step and body is compared with


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


def measure(n: int, args: argparse.Namespace) -> dict:
    """Load the kernels on a two-bar chain, then time ``args.repeats`` runs of the n-bar one."""
    jw.simulate(chain_model(2, args.angle, args.integrator, args.formulation, args.output_interval))
    model = chain_model(n, args.angle, args.integrator, args.formulation, args.output_interval)
    walls, simulations = [], []
    for _ in range(args.repeats):
        start = time.perf_counter()
        results = jw.simulate(model)
        walls.append(time.perf_counter() - start)
        simulations.append(results.summary["stats"]["simulation_wall_s"])
    stats = results.summary["stats"]
    t_last, x, y = tip(results, n)
    if results.status != "success" or abs(t_last - T_END) > 1e-9:
        print(f"N = {n}: {results.status} at t = {t_last:g} s: {results.message}", file=sys.stderr)
    simulation = statistics.median(simulations)
    return {
        "n": n,
        "simulation": simulation,
        "setup": statistics.median(w - s for w, s in zip(walls, simulations, strict=True)),
        "steps": stats["accepted_steps"],
        "rhs": stats["rhs_evaluations"],
        "rows": len(results.timeseries),
        "us_per_step_body": 1e6 * simulation / stats["accepted_steps"] / n,
        "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
        "tip": (x, y),
        "status": results.status,
    }


def in_child(n: int, argv: list[str]) -> dict:
    """``measure`` of size n in a fresh Python process (its own peak memory)."""
    command = [sys.executable, __file__, *argv, "--child", str(n)]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    sys.stderr.write(done.stderr)
    if done.returncode != 0:
        raise SystemExit(f"N = {n}: the child process failed (exit {done.returncode})")
    return json.loads(done.stdout.strip().splitlines()[-1])


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
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)  # one size, as JSON
    args = parser.parse_args()
    if args.child is not None:
        print(json.dumps(measure(args.child, args)))
        return

    print(
        f"N-link chain, {MASS:g} kg x {LENGTH:g} m bars from {args.angle:g} deg at rest, "
        f"{T_END:g} s, a row every {args.output_interval * 1e3:g} ms; integrator "
        f"{args.integrator or 'default'}, formulation {args.formulation or 'default'}; "
        f"median of {args.repeats} warm runs, each size in a process of its own\n"
    )
    print(
        "| N | simulation [s] | accepted steps | RHS evaluations | output rows "
        "| µs per step and body | set-up [s] | peak memory [MB] | tip x [m] | tip y [m] |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|")
    forwarded = sys.argv[1:]
    rows = []
    for n in args.sizes:
        row = in_child(n, forwarded)
        rows.append(row)
        flag = "" if row["status"] == "success" else f" ({row['status']})"
        print(
            f"| {n} | {row['simulation']:.4f} | {row['steps']} | {row['rhs']} | {row['rows']} | "
            f"{row['us_per_step_body']:.2f} | {row['setup']:.2f} | {row['peak_mb']:.0f} | "
            f"{row['tip'][0]:.9f} | {row['tip'][1]:.9f}{flag} |",
            flush=True,
        )
    reference = next((r for r in rows if r["n"] == REFERENCE_SIZE), rows[0])
    ratios = ", ".join(
        f"N = {r['n']}: {r['us_per_step_body'] / reference['us_per_step_body']:.2f}" for r in rows
    )
    print(f"\nµs per step and body against N = {reference['n']}'s: {ratios}")


if __name__ == "__main__":
    main()
