"""Benchmark of the studies built on the engine (issue: long-life wear and parameter studies).

Two targets, measured with the numba cache warm:

- **sweep**: a 9-case sweep of 5-turn runs of the paper's four-bar (friction coefficient
  0.05/0.1/0.2 x bearing radius 10.0/10.1/10.2 mm, ``--no-figures``), run with
  ``--workers 1`` (one after the other, in the sweep's own process) and with the default
  (one local process per core), alternately, ``--repeats`` times each into fresh folders;
  the medians and their ratio (target: close to one half on two cores). Once as whole
  ``jointwear sweep`` processes (what a user waits for), once as ``jw.sweep`` calls in this
  process.
- **life**: the ``jointwear life`` process wearing the paper's four-bar over 1e6 crank cycles
  with the default settings (target: under 60 s); wall time, updates, simulated cycles and
  the reported status.
- **band** (on request, ``--band``): the million-turn example of docs/studies.md, ``jointwear life``
  at a thousand times the paper's wear coefficient's inverse (8e-17 1/Pa) with its default
  uncertainty band, as a process; beside it the direct run of every turn at the paper's
  coefficient (8e-14 1/Pa), its turns scaled by the thousand (the dynamics depend on the
  profiles, not on k): whether the band holds it, and the wall times. ``--direct-set`` adds
  direct runs with one setting changed each (another integrator, a tighter tolerance): the
  direct simulation's own scatter, which the band is held against too.
- **convergence** (on request): life runs over 1e6 turns at several ``--max-change``, at the
  paper's wear coefficient and a thousand times smaller, and the direct run (``--direct``):
  the turns at which the clearance has grown by 25, 50 and 75 %.

Usage (from the repository root, after ``make install``)::

    .venv/bin/python benchmarks/bench_studies.py               # both, a few minutes
    .venv/bin/python benchmarks/bench_studies.py --no-life --repeats 1 --t-end 0.02  # smoke
    .venv/bin/python benchmarks/bench_studies.py --no-sweep --no-life \
        --convergence 8%,4%,2%,1%,0.5% --direct                              # 6 minutes
    .venv/bin/python benchmarks/bench_studies.py --no-sweep --no-life --band  # 3 minutes
    .venv/bin/python benchmarks/bench_studies.py --no-sweep --no-life --band --direct \
        --direct-set solver.integrator=dopri5 --direct-set solver.rtol=5e-7   # 10 minutes
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

import jointwear as jw

ROOT = Path(__file__).resolve().parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
CLEARANCE = "joints.coupler_follower.clearance"
WEAR_COEFFICIENTS = ("8e-14 1/Pa", "8e-17 1/Pa")  # the paper's, and a thousand times smaller
VARY = [
    f"{CLEARANCE}.friction_coefficient=0.05,0.1,0.2",
    f"{CLEARANCE}.bearing_radius=10.0 mm,10.1 mm,10.2 mm",
]


def jointwear(*args: str) -> float:
    """Wall time [s] of one ``jointwear`` process; raises if it fails."""
    command = [sys.executable, "-m", "jointwear", *args]
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, cwd=ROOT)
    return time.perf_counter() - start


def sweep_times(t_end: float, repeats: int) -> dict:
    """Median wall times [s] of the sweep serial and on all cores, run alternately.

    Both as ``jointwear sweep`` processes and as ``jw.sweep`` calls in this process, whose
    kernels are loaded (the interpreter start and imports, about 1.5 s, are not spread
    over the cores).
    """
    vary = [arg for path in VARY for arg in ("--vary", path)]
    common = [str(FOURBAR), *vary, "--t-end", repr(t_end), "--no-figures"]
    in_process = {path: texts.split(",") for path, texts in (v.split("=") for v in VARY)}
    jw.simulate(jw.load_model(FOURBAR, ["solver.t_end=0.001"]))  # load the kernels
    times: dict[str, list[float]] = {}
    succeeded: list[int] = []
    with tempfile.TemporaryDirectory() as scratch:
        for repeat in range(repeats):
            for kind, workers in (("serial", 1), ("parallel", None)):
                out = Path(scratch) / f"{kind}{repeat}"
                extra = [] if workers is None else ["--workers", str(workers)]
                wall = jointwear("sweep", *common, "--out", str(out), *extra)
                times.setdefault(f"process_{kind}", []).append(wall)
                start = time.perf_counter()
                called = jw.sweep(
                    FOURBAR,
                    out.with_name(f"{out.name}_in_process"),
                    vary=in_process,
                    overrides=[f"solver.t_end={t_end!r}"],
                    workers=workers,
                    figures=False,
                )
                times.setdefault(f"call_{kind}", []).append(time.perf_counter() - start)
                for table in (pd.read_csv(out / "sweep.csv"), called.table):
                    succeeded.append(int((table["status"] == "success").sum()))
    report: dict = {"cases": 9, "t_end_s": t_end, "cores": os.cpu_count(), "times_s": times}
    report["fewest_cases_succeeded"] = min(succeeded)  # of any one sweep
    for way in ("process", "call"):
        serial, parallel = (statistics.median(times[f"{way}_{k}"]) for k in ("serial", "parallel"))
        report[way] = {"serial_s": serial, "parallel_s": parallel, "ratio": parallel / serial}
    return report


def life_run(cycles: int) -> dict:
    """Wall time [s] of the life run and what its summary reports."""
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "life"
        args = ["life", str(FOURBAR), "--cycles", str(cycles), "--out", str(out), "--no-figures"]
        command = [sys.executable, "-m", "jointwear", *args]
        start = time.perf_counter()
        process = subprocess.run(command, capture_output=True, cwd=ROOT)
        wall = time.perf_counter() - start
        if process.returncode not in (0, 1):  # 1: stopped early, e.g. at the clearance limit
            raise RuntimeError(process.stderr.decode())
        summary = json.loads((out / "summary.json").read_text())
    joint = summary["clearance_joints"]["coupler_follower"]
    return {
        "cycles_asked": cycles,
        "process_wall_s": wall,
        "status": summary["status"],
        "cycles_reached": summary["cycles_reached"],
        "updates": summary["updates"],
        "simulated_cycles": summary["simulated_cycles"],
        "simulated_wall_s": summary["wall_s"],
        "max_wear_depth_journal_m": joint["max_wear_depth_journal_m"],
        "cycles_to_clearance_growth_50pct": joint["cycles_to_clearance_growth_50pct"],
    }


def band_run(directs: list[dict] | None = None) -> dict:
    """The million-turn example with its band (a process), against the scaled direct runs.

    ``directs``: rows of ``convergence`` for direct runs at the paper's coefficient, the
    default settings' first; that one is run here if none is given.
    """
    scale = 1000  # 8e-14 / 8e-17
    with tempfile.TemporaryDirectory() as scratch:
        out = Path(scratch) / "life"
        k = f"{CLEARANCE}.wear_coefficient={WEAR_COEFFICIENTS[1]}"
        args = ["life", str(FOURBAR), "--cycles", "1000000", "--out", str(out), "--set", k]
        start = time.perf_counter()
        process = subprocess.run([sys.executable, "-m", "jointwear", *args], capture_output=True,
                                 cwd=ROOT)  # fmt: skip
        wall = time.perf_counter() - start
        if process.returncode != 0:
            raise RuntimeError(process.stderr.decode() or process.stdout.decode())
        summary = json.loads((out / "summary.json").read_text())
        band_rows = len(pd.read_csv(out / "life_band.csv"))
    directs = directs or convergence([], True)
    joint = summary["clearance_joints"]["coupler_follower"]["band"]
    half, growth = joint["cycles_to_clearance_growth_50pct"], joint["clearance_growth_m"]
    held = [
        {
            "direct": direct["max_change"],
            "50pct_scaled": direct["growth_at"][50] * scale,
            "growth_at_turn_1000_m": direct["growth_at_turn"],
            "holds_50pct": _within(direct["growth_at"][50] * scale, half),
            "holds_growth": _within(direct["growth_at_turn"], growth),
        }
        for direct in directs
    ]
    report = {
        "command": "jointwear "
        + " ".join([*args[:1], "examples/flores2009_fourbar.toml", *args[2:4], "--set", f"'{k}'"]),
        "process_wall_s": wall,
        "band": summary["band"],
        "single_run_wall_s": summary["wall_s"],
        "band_table_rows": band_rows,
        "cycles_to_clearance_growth_50pct": half,
        "clearance_growth_m": growth,
        "max_wear_depth_journal_m": joint["max_wear_depth_journal_m"],
        "directs_paper_k": directs,
        "held": held,
    }
    runs = ", ".join(
        f"{r['max_change']} {r['wall_s']:.1f} s ({r['status']})" for r in summary["band"]["runs"]
    )
    print(
        f"band, 1,000,000 turns at k 8e-17 1/Pa: 50% growth at {half['value']:,.0f} turns, band "
        f"{half['low']:,.0f} to {half['high']:,.0f}; growth at 10^6 turns "
        f"{growth['value'] * 1e6:.1f} um ({growth['low'] * 1e6:.1f} to "
        f"{growth['high'] * 1e6:.1f}); runs: {runs}; process {wall:.1f} s wall",
        flush=True,
    )
    for row in held:
        print(
            f"  {row['direct']}, at 8e-14 scaled: 50% at {row['50pct_scaled']:,.0f} turns "
            f"({'inside' if row['holds_50pct'] else 'OUTSIDE'} the band), growth "
            f"{row['growth_at_turn_1000_m'] * 1e6:.1f} um at turn 1000 "
            f"({'inside' if row['holds_growth'] else 'OUTSIDE'})",
            flush=True,
        )
    return report


def _within(x: float | None, band: dict) -> bool:
    """Whether ``x`` lies in ``band`` ({low, high}; a high of None: no upper end)."""
    high = math.inf if band["high"] is None else band["high"]
    return x is not None and band["low"] <= x <= high


def convergence(changes: list[str], direct: bool, variants: Sequence[str] = ()) -> list[dict]:
    """Life runs of the four-bar over 1e6 turns per ``--max-change`` (and, if ``direct``, with
    no extrapolation, also once per override of ``variants``), at the paper's wear coefficient
    and at one a thousand times smaller: when the clearance has grown by 25, 50 and 75 % of c,
    and where each run ended."""
    from jointwear.studies.life.records import cycles_at
    from jointwear.studies.life.study import life

    rows = []
    settings = [(k, change, True, []) for k in WEAR_COEFFICIENTS for change in changes]
    if direct:
        settings += [(WEAR_COEFFICIENTS[0], "direct", False, [])]
        settings += [(WEAR_COEFFICIENTS[0], f"direct {v}", False, [v]) for v in variants]
    with tempfile.TemporaryDirectory() as scratch:
        for k, change, extrapolate, extra in settings:
            folder = Path(scratch) / f"{len(rows)}"
            start = time.perf_counter()
            res = life(
                FOURBAR, folder, cycles=1_000_000, figures=False, extrapolate=extrapolate,
                max_change=change if extrapolate else "1%",
                overrides=[f"{CLEARANCE}.wear_coefficient={k}", *extra],
            )  # fmt: skip
            growth = res.table["coupler_follower.clearance_growth_m"] / 200e-6
            joint = res.summary["clearance_joints"]["coupler_follower"]
            rows.append(
                {
                    "wear_coefficient": k,
                    "max_change": change,
                    "status": res.status,
                    "cycles_reached": res.summary["cycles_reached"],
                    "updates": res.summary["updates"],
                    "simulated_cycles": res.summary["simulated_cycles"],
                    "growth_at": {
                        share: cycles_at(res.table["cycles"], growth, share / 100)
                        for share in (25, 50, 75)
                    },
                    "clearance_growth_m": joint["clearance_growth_m"],
                    "growth_at_turn": _growth_at(res.table, 1000),
                    "max_wear_depth_journal_m": joint["max_wear_depth_journal_m"],
                    "wall_s": time.perf_counter() - start,
                }
            )
            print(_convergence_line(rows[-1]), flush=True)
    return rows


def _growth_at(table: pd.DataFrame, turn: int) -> float | None:
    """Clearance growth [m] at ``turn`` (linear between rows); None if not reached."""
    cycles = table["cycles"].to_numpy()
    if not len(cycles) or cycles[-1] < turn:
        return None
    return float(np.interp(turn, cycles, table["coupler_follower.clearance_growth_m"]))


def _convergence_line(row: dict) -> str:
    at = ", ".join(
        f"{share}%: {'-' if c is None else f'{c:,.0f}'}" for share, c in row["growth_at"].items()
    )
    return (
        f"k {row['wear_coefficient']}, max-change {row['max_change']}: {row['status']} at "
        f"{row['cycles_reached']:,} turns, {row['updates']} updates "
        f"({row['simulated_cycles']} simulated); growth {at}; final growth "
        f"{row['clearance_growth_m'] * 1e6:.1f} um, journal "
        f"{row['max_wear_depth_journal_m'] * 1e6:.1f} um; {row['wall_s']:.1f} s"
    )


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=0.2, help="per sweep case [s]; 5 turns")
    parser.add_argument("--repeats", type=int, default=3, help="sweeps of each kind")
    parser.add_argument("--cycles", type=int, default=1_000_000, help="of the life run")
    parser.add_argument("--no-sweep", dest="sweep", action="store_false")
    parser.add_argument("--no-life", dest="life", action="store_false")
    parser.add_argument(
        "--convergence",
        default="",
        help="comma-separated --max-change values of a convergence study (e.g. 8%%,4%%,2%%,1%%,"
        "0.5%%); minutes",
    )
    parser.add_argument("--direct", action="store_true", help="with it, the direct run (3 min)")
    parser.add_argument(
        "--direct-set",
        action="append",
        default=[],
        metavar="OVERRIDE",
        help="with --direct, one more direct run with this setting (repeatable)",
    )
    parser.add_argument(
        "--band", action="store_true", help="the million-turn example's band against the direct run"
    )
    parser.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "studies.json")
    args = parser.parse_args(argv)
    jointwear("check", str(FOURBAR))  # a warm interpreter cache before anything is timed
    report: dict = {}
    if args.sweep:
        report["sweep"] = sweep = sweep_times(args.t_end, args.repeats)
        for way, label in (("process", "jointwear sweep process"), ("call", "jw.sweep call")):
            times = sweep[way]
            print(
                f"sweep, 9 cases of {args.t_end} s, {label}: serial {times['serial_s']:.2f} s, "
                f"parallel ({sweep['cores']} cores) {times['parallel_s']:.2f} s, "
                f"ratio {times['ratio']:.2f} (medians of {args.repeats})"
            )
    if args.life:
        report["life"] = life = life_run(args.cycles)
        print(
            f"life, {args.cycles:,} cycles asked: {life['status']} at {life['cycles_reached']:,}"
            f" cycles, {life['updates']} updates ({life['simulated_cycles']} simulated), "
            f"{life['process_wall_s']:.1f} s wall"
        )
    if args.convergence or args.direct:
        changes = [c for c in args.convergence.split(",") if c]
        report["convergence"] = convergence(changes, args.direct, args.direct_set)
    if args.band:
        rows = [r for r in report.get("convergence", []) if r["max_change"].startswith("direct")]
        report["band"] = band_run(rows)
    args.out.write_text(json.dumps(report, indent=2))
    return report


if __name__ == "__main__":
    main()
