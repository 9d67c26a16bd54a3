"""The benchmark script runs end to end on a tiny case (its timings are not checked here)."""

import json
import subprocess
import sys
from pathlib import Path

BENCH = Path(__file__).parents[1] / "benchmarks" / "bench.py"


def test_benchmark_runs_on_a_short_case(tmp_path):
    out = tmp_path / "bench.json"
    args = ["--t-end", "0.01", "--repeats", "1", "--no-cold", "--out", str(out)]
    args += ["--growth-times", "0.005,0.01", "--growth-t-end", "0.005"]
    done = subprocess.run(
        [sys.executable, str(BENCH), *args], capture_output=True, text=True, timeout=600
    )
    assert done.returncode == 0, done.stderr
    report = json.loads(out.read_text())
    rows = {row["integrator"]: row for row in report["integrators"]}
    assert set(rows) == {"dopri5", "abm"}
    for row in rows.values():
        assert row["accepted_steps"] > 0 and row["rhs_evaluations"] > row["accepted_steps"]
        # The baseline solves the same case: same wear to a few per cent even this early.
        assert row["wear_profile_difference"] < 0.05
        assert row["max_force_difference"] < 0.05
    assert [r["t_end"] for r in report["growth"]["simulated_time"]] == [0.005, 0.01]
    assert [r["clearance_joints"] for r in report["growth"]["clearance_joints"]] == [1, 2, 4]


def test_studies_benchmark_runs_on_short_cases(tmp_path):
    out = tmp_path / "studies.json"
    args = ["--t-end", "0.01", "--repeats", "1", "--cycles", "6", "--out", str(out)]
    done = subprocess.run(
        [sys.executable, str(BENCH.with_name("bench_studies.py")), *args],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    report = json.loads(out.read_text())
    assert report["sweep"]["fewest_cases_succeeded"] == 9  # every sweep timed ran every case
    life = report["life"]
    assert (life["status"], life["cycles_reached"]) == ("success", 6)
    assert life["simulated_cycles"] <= 6 and life["max_wear_depth_journal_m"] > 0


def test_contact_laws_benchmark_prints_its_table():
    rows = _table_rows("contact_laws.py", "--t-end", "0.01", "--no-figure")
    names = [row.split(" | ")[0].removeprefix("| ") for row in rows]
    assert names == ["Hertz (paper)", "Johnson", "Liu et al.", "elastic foundation, h = 5 mm",
                     "Hertz, lubricated (SAE 30, short bearing)"]  # fmt: skip
    assert all(" kN | " in row and " µm | " in row for row in rows)


def test_chain_benchmark_prints_its_table():
    rows = _table_rows("chain.py", "--sizes", "2", "5", "--repeats", "1")
    assert [row.split(" | ")[0] for row in rows] == ["| 2", "| 5"]
    # 1 s at a row every 1 ms: 1001 rows, whatever the sizes
    assert all(row.split(" | ")[4] == "1001" for row in rows)


def test_setup_scaling_benchmark_prints_its_tables():
    # a chain set up dense (3 bars) and one sparse (45 bars: above 120 coordinates)
    rows = _table_rows("setup_scaling.py", "--sizes", "3", "45", "--signal", "--moments", "0.5")
    assert [row.split(" | ")[0] for row in rows[:2]] == ["| 3", "| 45"]
    assert all(len(row.split(" | ")) == 5 for row in rows[:2])  # N and four measures
    assert rows[2].startswith("| sent after") and rows[3].startswith("| 0.5 | ")


def _table_rows(script: str, *args: str) -> list[str]:
    """Run a benchmark script; the rows of the markdown table it prints, header left out."""
    done = subprocess.run(
        [sys.executable, str(BENCH.with_name(script)), *args],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return [line for line in done.stdout.splitlines() if line.startswith("| ")][1:]
