"""Headline figures of the single-cylinder engine example (the user guide's table).

Runs ``examples/single_cylinder_engine.toml`` (5 cycles of 720 deg at 3000 rpm) and prints,
over the cycles after the first: the peak gas force, the piston's slap (its largest lateral
contact force, impacts per cycle, time in contact, largest tilt), the wrist pin's largest
force, the work the gas does per cycle (its force times the piston's speed, and the p-V
integral of the table over the crank angle), the crank's mean torque, and the wear per cycle
of the liner and the skirt. Its life is ``jointwear life`` (docs/user-guide.md).

    python benchmarks/engine.py
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from scipy.integrate import trapezoid

import jointwear as jw

EXAMPLE = Path(__file__).parents[1] / "examples" / "single_cylinder_engine.toml"
GUIDE, SKIRT = ("guide_top", "guide_bottom"), ("slider_top", "slider_bottom")


def headline(results: jw.Results) -> dict[str, str]:
    """One run's figures, over its steady state (the cycles after the first)."""
    model = results.model
    cycle = model.cycle
    df = results.timeseries
    steady = df[df["time"] >= cycle * (1.0 - 1e-9)]
    cycles = (steady["time"].iloc[-1] - steady["time"].iloc[0]) / cycle
    liner = results.summary["clearance_joints"]["liner"]
    pin = results.summary["clearance_joints"]["wrist_pin"]
    axis_speed = -steady["vy_piston"]  # the liner's axis points down
    work = trapezoid(steady["load_gas_force"] * axis_speed, steady["time"]) / cycles
    driver = trapezoid(steady["torque_crank_angle"], steady["time"]) / (cycles * cycle)
    run_cycles = df["time"].iloc[-1] / cycle  # the wear is the whole run's
    surfaces = ("guide_top", "guide_bottom", "slider_top", "slider_bottom")
    wear = {s: liner[f"max_wear_depth_{s}_m"] for s in surfaces}
    return {
        "peak gas force": f"{df['load_gas_force'].max() / 1e3:.4g} kN",
        "liner: largest contact force": f"{liner['max_contact_force_n'] / 1e3:.4g} kN",
        "liner: impacts per cycle": f"{liner['impacts'] / cycles:.1f}",
        "liner: time in contact": f"{100 * liner['contact_time_fraction']:.1f} %",
        "piston: largest tilt": f"{np.abs(steady['liner_tilt']).max() * 1e3:.3g} mrad",
        "wrist pin: largest force": f"{pin['max_contact_force_n'] / 1e3:.4g} kN",
        "gas work per cycle": f"{work:.1f} J (mean {work / cycle / 1e3:.2f} kW)",
        "crank: mean driver torque": f"{driver:.2f} N m",
        "deepest wear per cycle, liner": _per_cycle(wear, GUIDE, run_cycles, liner),
        "deepest wear per cycle, skirt": _per_cycle(wear, SKIRT, run_cycles, liner),
    }


def _per_cycle(wear: dict, sides: tuple[str, str], cycles: float, joint: dict) -> str:
    side = max(sides, key=wear.get)
    where = joint[f"max_wear_position_{side}_m"] * 1e3
    per = wear[side] / cycles * 1e9
    return f"{per:.3g} nm ({side}, {where:+.1f} mm)"


def pv_work() -> float:
    """The table's p dV over one cycle [J], from the pressure curve and the crank geometry."""
    model = jw.load_model(EXAMPLE)
    gas = next(f for f in model.forces if f.type == "joint_pressure")
    x, p = np.asarray(gas.pressure.x), np.asarray(gas.pressure.y)
    theta = np.linspace(x[0], x[0] + gas.pressure.period, 200_001)
    from scipy.interpolate import PchipInterpolator

    wrapped = np.concatenate([x[-2:] - gas.pressure.period, x, x[:2] + gas.pressure.period])
    pressure = PchipInterpolator(wrapped, np.concatenate([p[-2:], p, p[:2]]))(theta)
    crank, rod = 0.04, 0.14
    pin = crank * np.cos(theta) + np.sqrt(rod**2 - (crank * np.sin(theta)) ** 2)
    volume = gas.area * (crank + rod - pin)
    return float(trapezoid(pressure * np.gradient(volume, theta), theta))


def main() -> None:
    """Run the example and print its table."""
    results = jw.simulate(jw.load_model(EXAMPLE))
    assert results.status == "success", results.message
    print("| figure | value |\n|---|---|")
    for key, value in headline(results).items():
        print(f"| {key} | {value} |")
    print(f"| p dV of the pressure table per cycle | {pv_work():.1f} J |")


if __name__ == "__main__":
    main()
