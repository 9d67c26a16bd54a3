"""Benchmark of the paper's four-bar with its clearance joint and wear (issue: speed).

Prints one table and writes it as JSON. For each integrator, at the model's default
tolerances: warm simulation wall time (kernels cached; median of ``--repeats`` runs in this
process), cold wall time (a fresh numba cache in a child process, compile included), the
whole ``jointwear run --no-figures`` process warm (median), steps, right-hand-side
evaluations, microseconds per evaluation, peak memory, and the results that matter. Side by
side, the hand-written numpy + scipy baseline (``baseline_scipy.py``) of the same case with
the same tolerances, and how far its answers are from jointwear's. Then the growth of the
wall time with the simulated time and with the number of clearance joints.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/bench.py                    # the full benchmark, minutes
    .venv/bin/python benchmarks/bench.py --t-end 0.01 --repeats 1 --no-cold --no-growth  # smoke
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

import jointwear as jw
from jointwear.model import parse_model

ROOT = Path(__file__).resolve().parents[1]

FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
INTEGRATORS = {"dopri5": "RK45", "abm": "LSODA"}  # jointwear method: the baseline's nearest
GROWTH_JOINTS = {  # clearance joints of the four-bar, one, two and all four
    1: ("coupler_follower",),
    2: ("coupler_follower", "crank_coupler"),
    4: ("coupler_follower", "crank_coupler", "ground_crank", "ground_follower"),
}
CHILD = """
import json, resource, sys, time
start = time.perf_counter()
{body}
print(json.dumps({{"process_s": time.perf_counter() - start,
                  "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  **extra}}))
"""
SIMULATE_CHILD = """
import jointwear as jw
r = jw.simulate(jw.load_model({path!r}, {overrides!r}))
extra = {{"simulation_wall_s": r.summary["stats"]["simulation_wall_s"]}}
"""
RUN_CHILD = """
from jointwear.cli import app
try:
    app({args!r}, standalone_mode=False)
except SystemExit:
    pass
extra = {{}}
"""


def fourbar_with_clearances(joints: tuple[str, ...], t_end: float) -> jw.Model:
    """The paper's four-bar with Table 2's clearance in each of ``joints``, run to t_end [s].

    Each joint's first body carries the bearing (the ground, for the ground pivots).
    """
    data = tomllib.loads(FOURBAR.read_text())
    table = next(j for j in data["joints"] if j["name"] == "coupler_follower")["clearance"]
    for joint in data["joints"]:
        joint.pop("clearance", None)
        if joint["name"] in joints:
            joint["clearance"] = dict(table)
    data["solver"]["t_end"] = t_end
    return parse_model(data, name=f"fourbar_{len(joints)}_clearances")


def child(code: str, env: dict | None = None) -> dict:
    """Run ``code`` in a fresh Python; return the JSON it prints last."""
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True
    )
    return json.loads(done.stdout.strip().splitlines()[-1])


def warm(model: jw.Model, repeats: int) -> tuple[float, jw.Results]:
    """Median simulation wall time [s] of ``repeats`` runs, and the last results."""
    jw.simulate(model)  # compile or load the kernels
    walls, results = [], None
    for _ in range(repeats):
        results = jw.simulate(model)
        walls.append(results.summary["stats"]["simulation_wall_s"])
    return statistics.median(walls), results


def headline(results: jw.Results) -> dict:
    """The results that matter, of the four-bar's clearance joint, over the whole run."""
    joint = results.summary["clearance_joints"]["coupler_follower"]
    joint = {**joint, **joint["whole_run"]}  # as the baseline counts them
    return {
        "max_contact_force_n": joint["max_contact_force_n"],
        "max_wear_depth_journal_m": joint["max_wear_depth_journal_m"],
        "worn_volume_m3": joint["worn_volume_m3"],
    }


def wear_difference(results: jw.Results, baseline: dict) -> float:
    """Largest difference of the wear profiles (both surfaces), over the largest depth [-]."""
    wear = results.wear
    ours = np.concatenate([
        wear[wear["surface"] == "journal"]["depth_m"].to_numpy(),
        wear[wear["surface"] == "bearing"]["depth_m"].to_numpy(),
    ])  # fmt: skip
    theirs = np.concatenate([baseline["wear_journal"], baseline["wear_bearing"]])
    return float(np.abs(ours - theirs).max() / np.abs(ours).max())


def integrator_row(integrator: str, args: argparse.Namespace) -> dict:
    """Every figure of one integrator, and of its baseline pair."""
    overrides = [f"solver.t_end={args.t_end}", f"solver.integrator={integrator}"]
    model = jw.load_model(FOURBAR, overrides)
    wall, results = warm(model, args.repeats)
    stats = results.summary["stats"]
    row = {
        "integrator": integrator,
        "warm_simulation_s": wall,
        "accepted_steps": stats["accepted_steps"],
        "rejected_steps": stats["rejected_steps"],
        "rhs_evaluations": stats["rhs_evaluations"],
        "us_per_rhs": wall / stats["rhs_evaluations"] * 1e6,
        **headline(results),
    }
    if args.cold:
        with tempfile.TemporaryDirectory() as cache:
            env = {**os.environ, "NUMBA_CACHE_DIR": cache}
            code = CHILD.format(body=SIMULATE_CHILD.format(path=str(FOURBAR), overrides=overrides))
            cold = child(code, env)
        row["cold_simulation_s"] = cold["simulation_wall_s"]
        row["cold_process_s"] = cold["process_s"]
        row["cold_peak_mb"] = cold["peak_mb"]
        processes = []
        for _ in range(args.repeats):
            with tempfile.TemporaryDirectory() as out:
                cli = ["run", str(FOURBAR), "--out", out, "--no-figures", "--no-ideal"]
                cli += ["--set", f"solver.integrator={integrator}", "--t-end", str(args.t_end)]
                processes.append(child(CHILD.format(body=RUN_CHILD.format(args=cli))))
        row["warm_process_s"] = statistics.median(p["process_s"] for p in processes)
        row["warm_peak_mb"] = max(p["peak_mb"] for p in processes)
    if args.baseline:
        sys.path.insert(0, str(ROOT / "benchmarks"))  # benchmarks/ is not a package
        from baseline_scipy import simulate_baseline

        solver = model.solver
        base = simulate_baseline(
            t_end=args.t_end,
            rtol=solver.rtol,
            atol=solver.atol,
            method=INTEGRATORS[integrator],
            max_step=solver.max_step,
        )
        row["baseline_method"] = INTEGRATORS[integrator]
        row["baseline_wall_s"] = base["wall_s"]
        row["baseline_rhs_evaluations"] = base["rhs_evaluations"]
        row["speedup"] = base["wall_s"] / wall
        row["wear_profile_difference"] = wear_difference(results, base)
        row["max_force_difference"] = abs(
            base["max_contact_force_n"] / row["max_contact_force_n"] - 1.0
        )
    return row


def growth(args: argparse.Namespace) -> dict:
    """Warm wall time against simulated time and against the number of clearance joints."""
    by_time = []
    for t_end in args.growth_times:
        wall, results = warm(jw.load_model(FOURBAR, [f"solver.t_end={t_end}"]), args.repeats)
        by_time.append({"t_end": t_end, "warm_simulation_s": wall, "per_simulated_s": wall / t_end})
    by_joints = []
    for count, names in GROWTH_JOINTS.items():
        model = fourbar_with_clearances(names, args.growth_t_end)
        wall, results = warm(model, args.repeats)
        stats = results.summary["stats"]
        by_joints.append({
            "clearance_joints": count,
            "t_end": args.growth_t_end,
            "warm_simulation_s": wall,
            "accepted_steps": stats["accepted_steps"],
            "us_per_rhs": wall / stats["rhs_evaluations"] * 1e6,
        })  # fmt: skip
    return {"simulated_time": by_time, "clearance_joints": by_joints}


def table(rows: list[dict]) -> str:
    """The rows as an aligned text table (keys as columns)."""
    keys = list(dict.fromkeys(k for row in rows for k in row))
    cells = [[_cell(row.get(k)) for k in keys] for row in rows]
    widths = [max(len(k), *(len(c[i]) for c in cells)) for i, k in enumerate(keys)]
    lines = ["  ".join(k.rjust(w) for k, w in zip(keys, widths, strict=True))]
    lines += ["  ".join(c.rjust(w) for c, w in zip(cell, widths, strict=True)) for cell in cells]
    return "\n".join(lines)


def _cell(value: object) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    return str(value)


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=1.0, help="simulated time [s]")
    parser.add_argument("--repeats", type=int, default=5, help="runs per median")
    parser.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "results.json")
    parser.add_argument("--no-cold", dest="cold", action="store_false", help="skip cold runs")
    parser.add_argument("--no-baseline", dest="baseline", action="store_false")
    parser.add_argument("--no-growth", dest="growth", action="store_false")
    parser.add_argument("--growth-t-end", type=float, default=0.25, help="[s], joint growth")
    parser.add_argument(
        "--growth-times",
        type=lambda text: [float(t) for t in text.split(",")],
        default=[0.25, 0.5, 1.0, 2.0],
        help="simulated times of the growth study [s], comma-separated",
    )
    args = parser.parse_args(argv)
    started = time.perf_counter()
    rows = [integrator_row(integrator, args) for integrator in INTEGRATORS]
    report = {"jointwear_version": jw.__version__, "t_end": args.t_end, "integrators": rows}
    print(table(rows))
    if args.growth:
        report["growth"] = growth(args)
        print(table(report["growth"]["simulated_time"]))
        print(table(report["growth"]["clearance_joints"]))
    report["benchmark_wall_s"] = time.perf_counter() - started
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(report, indent=2))
    print(f"written to {args.out}")
    return report


if __name__ == "__main__":
    main()
