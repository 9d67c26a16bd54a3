"""What a law registered from Python costs: the paper's four-bar with built-in and user laws.

The user laws are ``examples/user_laws.py``, the four built-in laws of the paper's four-bar
(Hertz, Lankarani-Nikravesh, Ambrosio, Archard) written again as a user would: each call goes
through its wrapper's address instead of the built-in dispatcher's branch. Both models run in
this process, warm (compiled, or loaded from the cache, before the timing), alternately, and
the median CPU and wall times of ``--repeats`` runs of each are reported; the two time series are
checked to be equal. A second table times the calls alone: the elastic force and the
friction force, each called 10^7 times in a compiled loop, built-in and user.

Usage (from the repository root)::

    .venv/bin/python benchmarks/user_law_cost.py               # t_end 0.2 s, 5 repeats
    .venv/bin/python benchmarks/user_law_cost.py --built-in-only   # also on a tree without them
"""

from __future__ import annotations

import argparse
import importlib.util
import statistics
import time
from pathlib import Path

import numpy as np

import jointwear as jw

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
CALLS = 10_000_000


def _user_laws() -> object:
    spec = importlib.util.spec_from_file_location("user_laws", ROOT / "examples" / "user_laws.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run_times(models: dict[str, jw.Model], repeats: int) -> dict[str, list[tuple]]:
    """(wall, CPU) times [s] of ``repeats`` warm runs of each model, alternately.

    The CPU time of this process is the steadier figure on a machine that runs others too.
    """
    series = {name: jw.simulate(model).timeseries for name, model in models.items()}  # warm-up
    first, *others = series.values()
    for other in others:  # the same run, or the timing compares different work
        assert np.array_equal(
            first.drop(columns="energy_contact"), other.drop(columns="energy_contact")
        )
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in models}
    for _ in range(repeats):
        for name, model in models.items():
            wall, cpu = time.perf_counter(), time.process_time()
            result = jw.simulate(model)
            times[name].append((time.perf_counter() - wall, time.process_time() - cpu))
            assert result.status == "success", result.message
    return times


def call_times() -> dict[str, float]:
    """Nanoseconds per call of the elastic and the friction force, built-in and user."""
    from numba import njit

    from jointwear.engine.user_laws import user_tables
    from jointwear.kernels.laws import user as dispatch

    @njit
    def forces(user, law, calls):
        total = 0.0
        for i in range(calls):
            delta = 1e-6 * (1.0 + (i % 100))
            total += dispatch.elastic_force(user, 0, law[0], delta, 1e11, 1.5, 1e11, 2e-4, 0.02)
            total += dispatch.tangential_force(user, 0, law[1], 1e-3 * (i % 50), 1e3, 0.1,
                                               1e-4, 1e-2, 0.0)  # fmt: skip
        return total

    laws = _user_laws()
    built_in = jw.load_model(FOURBAR)
    twin = laws.twin_model(0.1)
    cases = {}
    for name, model in (("built-in", built_in), ("user", twin)):
        clearance = model.joint("coupler_follower").clearance
        codes = np.array([
            clearance.chosen_laws()[i][1].code for i in (0, 2)
        ])  # fmt: skip
        user = user_tables(model)["revolute"]
        forces(user, codes, 10)  # compile
        start = time.perf_counter()
        forces(user, codes, CALLS)
        cases[name] = (time.perf_counter() - start) / (2 * CALLS) * 1e9
    return cases


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--t-end", type=float, default=0.2, help="simulated time [s]")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--built-in-only", action="store_true",
                        help="time the built-in laws only (a tree without user laws)")  # fmt: skip
    args = parser.parse_args()
    models = {"built-in laws": jw.load_model(FOURBAR).with_values({"solver.t_end": args.t_end})}
    if not args.built_in_only:
        laws = _user_laws()
        laws.register()
        models["user laws (examples/user_laws.py)"] = laws.twin_model(args.t_end)
    times = run_times(models, args.repeats)
    print(f"four-bar, t_end = {args.t_end:g} s, median of {args.repeats} warm runs\n")
    print("| laws | median CPU time | median wall time | CPU times of the runs |")
    print("|---|---|---|---|")
    for name, values in times.items():
        wall, cpu = (statistics.median(v) for v in zip(*values, strict=True))
        shown = ", ".join(f"{v[1]:.3f}" for v in values)
        print(f"| {name} | {cpu:.3f} s | {wall:.3f} s | {shown} |")
    if args.built_in_only:
        return
    calls = call_times()
    print(f"\n| calls (elastic and friction force, {CALLS:.0e} each) | time per call |")
    print("|---|---|")
    for name, value in calls.items():
        print(f"| {name} | {value:.1f} ns |")


if __name__ == "__main__":
    main()
