"""The tolerance study of the four-bar with four clearance joints: the tables of docs/studies.md.

Reads a sampled study's folder (``jointwear sample``) and prints, as Markdown, the statistics
of its key outputs with their intervals and, per output, the inputs that move it most.

    jointwear sample examples/fourbar_four_clearances.toml \\
        --file examples/tolerances/fourbar_iso_fit.toml --out results/tolerances
    python benchmarks/tolerance_study.py results/tolerances

    jointwear sample examples/fourbar_four_clearances.toml \\
        --file examples/tolerances/fourbar_iso_fit.toml --out results/tolerances_life \\
        --n 32 --cycles 1000000 --max-change 2%
    python benchmarks/tolerance_study.py results/tolerances_life
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pandas as pd

from jointwear.figures.sample import key_outputs, owner
from jointwear.figures.sweep import quantity


def _input(path: str) -> str:
    parts = path.split(".")
    return f"{parts[1]} {parts[-1]}" if path.startswith("joints.") else path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="the sampled study's folder")
    parser.add_argument("--top", type=int, default=3, help="inputs shown per output")
    folder = parser.parse_args().folder
    plan = json.loads((folder / "sample.json").read_text())
    table = pd.read_csv(folder / "sample.csv")
    stats = pd.read_csv(folder / "statistics.csv").set_index("output")
    sensitivity = pd.read_csv(folder / "sensitivity.csv")
    statuses = ", ".join(f"{n} {status}" for status, n in table["status"].value_counts().items())
    print(f"{len(table)} cases ({plan['method']}, seed {plan['seed']}): {statuses}; "
          f"wall {table['wall_s'].sum():.0f} s summed over cases\n")  # fmt: skip
    print("| output | n | mean (95 % interval) | sd | P5 | P50 | P95 (95 % interval) |")
    print("|---|---|---|---|---|---|---|")
    shown = key_outputs(stats.reset_index())
    for output in shown:
        row = stats.loc[output]
        label, factor = quantity(output, abs(float(row["p95"])))
        v = {key: f"{row[key] * factor:.4g}" for key in row.index[2:]}
        n = f"{row['n']:.0f}" + ("" if row["n"] == row["cases"] else f"/{row['cases']:.0f}")
        print(
            f"| {owner(output)}: {label} | {n} | {v['mean']} {_interval(v, 'mean')} | "
            f"{v['std']} | {v['p5']} | {v['p50']} | {v['p95']} {_interval(v, 'p95')} |"
        )
    print(
        "\n| output | inputs that move it most (prcc, or rho where too few cases; 95 % interval) |"
    )
    print("|---|---|")
    for output in shown:
        rows = sensitivity[sensitivity["output"] == output]
        rows = rows.sort_values("effect", ascending=False)
        top = [_effect_text(row) for _, row in rows.head(3).iterrows()]
        label = quantity(output)[0].rpartition(" [")[0]
        print(f"| {owner(output)}: {label} | {'; '.join(top) or '-'} |")


def _interval(values: dict[str, str], key: str) -> str:
    low, high = values[f"{key}_low"], values[f"{key}_high"]
    return "(too few cases)" if low == "nan" else f"({low} to {high})"


def _effect_text(row: pd.Series) -> str:
    key = next(k for k in ("ST", "prcc", "rho") if k in row and pd.notna(row[k]))
    low, high = row[f"{key}_low"], row[f"{key}_high"]
    interval = "no interval" if pd.isna(low) else f"{low:+.2f} to {high:+.2f}"
    return f"{_input(row['input'])} {key} {row[key]:+.2f} ({interval})"


if __name__ == "__main__":
    main()
