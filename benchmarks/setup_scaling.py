"""How the set-up's cost grows with the size of a mechanism: the N-link chain (issue 32).

The chain of ``benchmarks/chain.py`` (``chain_model(n, 45, None, None, 1e-3)``: 1 kg, 0.1 m
bars at 45 degrees, at rest, ideal revolute joints, gravity), written to a TOML file per N.
For each N, each in a fresh process, the kernels' cache warm (a check of the smallest chain
first):

- ``check``: the wall time and peak memory (maximum resident set) of the whole process
  ``jointwear check chain_N.toml`` (start-up, reading, set-up, the printed tables);
- ``set-up``: ``engine.prepare.prepare`` alone (arrays, assembly, degrees of freedom and
  redundancy, lock-up check), timed in a process that has prepared a 60-link chain first, and
  that process's peak memory;
- with ``--run``: the wall time and peak memory of ``jointwear run chain_N.toml
  --no-figures`` (1 s simulated, a row every 1 ms, the results folder written);
- with ``--signal``: for the largest N, SIGTERM sent to ``jointwear check`` at
  ``--moments`` seconds after its start, and the time it took to exit after the signal (the
  largest over the moments is what a user waits at worst).

Printed as markdown tables. Each N runs ``--repeats`` times (medians); N = 2,000 before
issue 32 took minutes: ``--repeats 1``.

Usage (from the repository root)::

    .venv/bin/python benchmarks/setup_scaling.py                      # N = 10 ... 2,000
    .venv/bin/python benchmarks/setup_scaling.py --sizes 10 80 --run  # with 1 s runs
    .venv/bin/python benchmarks/setup_scaling.py --sizes 2000 --signal
    PYTHONPATH=../before/src .venv/bin/python benchmarks/setup_scaling.py  # another tree
"""

from __future__ import annotations

import argparse
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from chain import chain_model  # the benchmark next to this one

SIZES = (10, 80, 320, 640, 2000)
MOMENTS = (0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 6.0)  # [s] after the start of check
# In a fresh process: prepare a 60-link chain (kernels, and scipy.sparse for the sparse set-up
# loaded), then time prepare of FILE;
# prints the time [s] and the process's peak memory [MB].
SETUP = """
import resource, sys, time
sys.path.insert(0, sys.argv[2])
from chain import chain_model
from jointwear.engine.prepare import prepare
from jointwear.model import load_model
prepare(chain_model(60, 45.0, None, None, 1e-3))  # kernels and scipy.sparse loaded
model = load_model(sys.argv[1])
start = time.perf_counter()
prepare(model)
print(time.perf_counter() - start, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
"""


def jointwear(*args: str) -> list[str]:
    """The command line of ``jointwear args`` with this interpreter."""
    return [sys.executable, "-m", "jointwear", *args]


def whole_process(command: list[str]) -> tuple[float, float]:
    """Wall time [s] and peak memory [MB] of ``command`` run to its end (must succeed)."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}: exit {child.returncode}: {child.stderr.read()}")
    return wall, usage.ru_maxrss / 1024


def setup(path: Path) -> tuple[float, float]:
    """Time [s] of prepare alone and the peak memory [MB] of its process."""
    command = [sys.executable, "-c", SETUP, str(path), str(Path(__file__).parent)]
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    wall, peak = done.stdout.split()
    return float(wall), float(peak)


def signal_delay(path: Path, moment: float) -> tuple[float, int]:
    """SIGTERM to ``jointwear check path`` ``moment`` s after its start: seconds to its exit."""
    child = subprocess.Popen(
        jointwear("check", str(path)), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    time.sleep(moment)
    sent = time.perf_counter()
    child.send_signal(signal.SIGTERM)
    code = child.wait()
    return time.perf_counter() - sent, code


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=SIZES, help="numbers of bars")
    parser.add_argument("--repeats", type=int, default=1, help="runs per size (median)")
    parser.add_argument("--run", action="store_true", help="also time a 1 s run per size")
    parser.add_argument("--signal", action="store_true", help="SIGTERM to the largest check")
    parser.add_argument(
        "--moments", type=float, nargs="+", default=MOMENTS, help="[s] after check starts"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="setup_scaling_") as folder:
        measure(args, Path(folder))


def measure(args: argparse.Namespace, folder: Path) -> None:
    """Write the chains into ``folder``, measure them and print the tables."""
    paths = {}
    for n in args.sizes:
        paths[n] = chain_model(n, 45.0, None, None, 1e-3).to_toml(folder / f"chain_{n}.toml")
    whole_process(jointwear("check", str(paths[min(args.sizes)])))  # warm the kernels' cache

    print(f"N-link chain (benchmarks/chain.py), medians of {args.repeats}; peak memory is the")
    print("process's maximum resident set\n")
    header = "| N | check [s] | check peak [MB] | set-up [s] | set-up peak [MB] |"
    rule = "|---|---|---|---|---|"
    if args.run:
        header += " 1 s run [s] | run peak [MB] |"
        rule += "---|---|"
    print(header)
    print(rule, flush=True)
    for n in args.sizes:
        checks = [whole_process(jointwear("check", str(paths[n]))) for _ in range(args.repeats)]
        setups = [setup(paths[n]) for _ in range(args.repeats)]
        cells = [*_medians(checks), *_medians(setups)]
        if args.run:
            out = folder / f"run_{n}"
            run = jointwear("run", str(paths[n]), "--out", str(out), "--no-figures")
            cells += _medians([whole_process(run) for _ in range(args.repeats)])
        print(f"| {n} | " + " | ".join(f"{c:.3g}" for c in cells) + " |", flush=True)

    if args.signal:
        n = max(args.sizes)
        print(f"\nSIGTERM to `jointwear check` of the {n}-link chain\n")
        print("| sent after [s] | exit after the signal [s] | exit code |")
        print("|---|---|---|")
        for moment in args.moments:
            delay, code = signal_delay(paths[n], moment)
            print(f"| {moment:g} | {delay:.3f} | {code} |", flush=True)


def _medians(samples: list[tuple[float, float]]) -> list[float]:
    return [statistics.median(s[k] for s in samples) for k in range(2)]


if __name__ == "__main__":
    main()
