"""Whole-process times of the command line, one or more checkouts side by side (issue: the core).

For each checkout (a repository root with its own ``.venv``), in turns so that a noisy machine
weighs on all alike: ``jointwear --help``, ``jointwear check`` of the paper's four-bar,
``jointwear run --t-end 1 --no-figures --no-ideal`` and the default ``jointwear run`` of
``make run``, warm (medians of ``--repeats``), and the
cold first run ``run --t-end 0.01 --no-figures --no-ideal`` with an empty numba cache (compile
included; median of ``--cold-repeats``), with the peak memory of each process.

Usage (from the repository root)::

    .venv/bin/python benchmarks/bench_startup.py                       # this checkout
    .venv/bin/python benchmarks/bench_startup.py . ../main-before      # side by side
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
from pathlib import Path

MODEL = "examples/flores2009_fourbar.toml"
COMMANDS = {
    "help": ["--help"],
    "check": ["check", MODEL],
    "run_1s": ["run", MODEL, "--t-end", "1", "--no-figures", "--no-ideal"],
    "make_run": ["run", MODEL],  # what `make run` does: figures and the ideal companion
}
COLD = ["run", MODEL, "--t-end", "0.01", "--no-figures", "--no-ideal"]
# Runs the command in a child and prints its wall time [s] and peak resident memory [MB].
MEASURE = """
import resource, subprocess, sys, time
start = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(time.perf_counter() - start, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024)
"""


def measure(root: Path, args: list[str], env: dict[str, str]) -> tuple[float, float]:
    """Wall time [s] and peak memory [MB] of ``jointwear args`` run in ``root``."""
    command = [sys.executable, "-c", MEASURE, str(root / ".venv" / "bin" / "jointwear"), *args]
    out = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True, check=True)
    wall, peak = out.stdout.split()
    return float(wall), float(peak)


def bench(roots: list[Path], repeats: int, cold_repeats: int, out_dir: Path) -> dict:
    """Medians per checkout and command: {root: {command: {"s": ..., "peak_mb": ...}}}."""
    samples: dict[str, dict[str, list]] = {str(r): {} for r in roots}
    for root in roots:  # warm the caches first
        measure(root, [*COMMANDS["run_1s"], "--out", str(out_dir / "warm")], dict(os.environ))
    for _ in range(repeats):
        for root in roots:
            for name, args in COMMANDS.items():
                if name.startswith("run"):
                    args = [*args, "--out", str(out_dir / name)]
                runs = samples[str(root)].setdefault(name, [])
                runs.append(measure(root, args, dict(os.environ)))
    for _ in range(cold_repeats):
        for root in roots:
            with tempfile.TemporaryDirectory() as cache:
                env = {**os.environ, "NUMBA_CACHE_DIR": cache}
                args = [*COLD, "--out", str(out_dir / "cold")]
                samples[str(root)].setdefault("cold_0.01s", []).append(measure(root, args, env))
    return {
        root: {
            name: {
                "s": statistics.median(s for s, _ in runs),
                "peak_mb": max(m for _, m in runs),
                "runs": len(runs),
            }
            for name, runs in by_command.items()
        }
        for root, by_command in samples.items()
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("roots", nargs="*", type=Path, default=[Path(".")])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--cold-repeats", type=int, default=3)
    parser.add_argument("--json", type=Path, default=Path("benchmarks/startup.json"))
    args = parser.parse_args()
    roots = [r.resolve() for r in args.roots]
    started = time.perf_counter()
    with tempfile.TemporaryDirectory() as out_dir:
        table = bench(roots, args.repeats, args.cold_repeats, Path(out_dir))
    names = [*COMMANDS, "cold_0.01s"] if args.cold_repeats else list(COMMANDS)
    print(f"{'checkout':40s}" + "".join(f"{n:>20s}" for n in names))
    for root, row in table.items():
        cells = "".join(f"{row[n]['s']:9.2f} s {row[n]['peak_mb']:5.0f} MB" for n in names)
        print(f"{Path(root).name:40s}{cells}")
    print(f"({time.perf_counter() - started:.0f} s; medians; peak memory the largest)")
    args.json.write_text(json.dumps(table, indent=2) + "\n")


if __name__ == "__main__":
    main()
