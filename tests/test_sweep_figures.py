"""The comparison figures of a sweep, drawn from tables built here (no runs)."""

import itertools

import numpy as np
import pandas as pd
import pytest
from matplotlib.collections import PathCollection

from jointwear.figures.sweep import FIGURES_OF_MERIT, plot_sweep, save_sweep_figures
from jointwear.io import write_text

JOINTS = ("crank_coupler", "coupler_follower", "ground_follower")
CLEARANCE = "joints.coupler_follower.clearance.radial_clearance"
VISCOSITY = "joints.coupler_follower.clearance.viscosity"
FRICTION = "joints.coupler_follower.clearance.friction_coefficient"
FORCE = "coupler_follower.max_contact_force_n"


def results(cases: list[dict]) -> pd.DataFrame:
    """A sweep table of these varied values, with made-up headline columns for each joint."""
    table = pd.DataFrame(cases)
    rise = 1.0 + 0.3 * np.arange(len(table)) % 1.7
    for k, joint in enumerate(JOINTS):
        table[f"{joint}.max_contact_force_n"] = 5e4 * (k + 1) * rise
        table[f"{joint}.contact_time_fraction"] = 0.9 + 0.05 * rise
        table[f"{joint}.impacts"] = np.arange(len(table)) % 4
        table[f"{joint}.max_penetration_m"] = 2e-5 * rise
        table[f"{joint}.max_wear_depth_bearing_m"] = 1e-6 * rise
        table[f"{joint}.max_wear_depth_journal_m"] = 2e-6 * rise
        table[f"{joint}.worn_volume_m3"] = 6e-10 * rise
        table[f"{joint}.energy_dissipated_friction_j"] = 800.0 * rise
        table[f"{joint}.whole_run.max_contact_force_n"] = 6e4 * rise
        table[f"{joint}.outside_law_ranges.penetration_over_clearance.largest"] = 0.3 * rise
    return table


def texts(table: pd.DataFrame, path: str, unit: str = "", per_si: float = 1.0) -> dict:
    """The values of ``path`` as a sweep was given them (``"0.1 mm"`` for 1e-4 m)."""
    return {v: f"{v * per_si:g} {unit}".strip() for v in table[path]}


def tick_labels(ax) -> list[str]:
    return [t.get_text() for t in ax.get_xticklabels() if t.get_visible() and t.get_text()]


def overlapping_labels(figure) -> bool:
    """Whether any two shown x tick labels of a panel overlap, once the figure is laid out."""
    figure.draw_without_rendering()
    for ax in figure.axes:
        shown = [t for t in ax.get_xticklabels(which="both") if t.get_visible() and t.get_text()]
        boxes = sorted((t.get_window_extent() for t in shown), key=lambda box: box.x0)
        if any(b.x0 < a.x1 for a, b in itertools.pairwise(boxes)):
            return True
    return False


def test_values_spanning_more_than_a_decade_get_a_log_axis():
    wide = results([{VISCOSITY: v} for v in (0.01, 0.04, 0.4)])
    figure = plot_sweep(wide, [FORCE], {VISCOSITY: texts(wide, VISCOSITY, "Pa*s")})
    assert figure.axes[0].get_xscale() == "log"
    assert tick_labels(figure.axes[0]) == ["0.01", "0.04", "0.4"]
    narrow = results([{"bodies.crank.mass": m} for m in (1.0, 2.0, 3.0, 4.0, 5.0)])
    figure = plot_sweep(narrow, [FORCE], {"bodies.crank.mass": texts(narrow, "bodies.crank.mass")})
    assert figure.axes[0].get_xscale() == "linear"
    assert figure.axes[0].get_yscale() == "linear"  # the forces span less than a decade
    narrow[FORCE] = [1e3, 1e4, 2e4, 5e4, 1e5]
    figure = plot_sweep(narrow, [FORCE], {"bodies.crank.mass": texts(narrow, "bodies.crank.mass")})
    assert figure.axes[0].get_yscale() == "log"


def test_a_grid_draws_a_line_per_other_value_through_sorted_values_in_the_given_unit():
    given = [0.3e-3, 0.1e-3, 0.2e-3]  # not in order
    table = results([{CLEARANCE: c, FRICTION: f} for c, f in itertools.product(given, (0.1, 0.05))])
    sweep_texts = {CLEARANCE: texts(table, CLEARANCE, "mm", 1e3), FRICTION: texts(table, FRICTION)}
    figure = plot_sweep(table, [FORCE], sweep_texts)
    ax = figure.axes[0]
    assert len(ax.get_lines()) == 2  # one per friction coefficient
    for line in ax.get_lines():
        assert line.get_xdata().tolist() == pytest.approx([0.1, 0.2, 0.3])  # mm, sorted
    assert not ax.collections  # no scatter
    assert tick_labels(ax) == ["0.1", "0.2", "0.3"]
    assert figure.get_supxlabel().startswith("radial clearance [mm]")
    legend = figure.legends[0]
    assert [t.get_text() for t in legend.get_texts()] == [
        "friction coefficient 0.1",
        "friction coefficient 0.05",
    ]
    figure.draw_without_rendering()
    assert legend.get_window_extent().x0 >= ax.get_window_extent().x1  # it hides no point
    assert figure.bbox.contains(legend.get_window_extent().x1, legend.get_window_extent().y0)


def test_a_linked_design_is_drawn_as_points_coloured_by_the_second_value():
    rng = np.random.default_rng(28)
    clearances, frictions = rng.uniform(0.05e-3, 0.5e-3, 50), rng.uniform(0.02, 0.2, 50)
    table = results(
        [{CLEARANCE: c, FRICTION: f} for c, f in zip(clearances, frictions, strict=True)]
    )
    sweep_texts = {CLEARANCE: texts(table, CLEARANCE, "mm", 1e3), FRICTION: texts(table, FRICTION)}
    figure = plot_sweep(table, [f"{joint}.max_contact_force_n" for joint in JOINTS], sweep_texts)
    panels = [ax for ax in figure.axes if ax.get_title()]
    assert [ax.get_title() for ax in panels] == list(JOINTS)
    for ax in panels:
        assert not ax.get_lines()  # no line joins the cases
        (points,) = ax.collections
        assert isinstance(points, PathCollection)
        assert len(points.get_offsets()) == 50
        assert points.get_array().tolist() == pytest.approx(frictions)  # the colour
    colour_bar = next(ax for ax in figure.axes if not ax.get_title())
    assert colour_bar.get_ylabel() == "friction coefficient"
    assert len(tick_labels(panels[-1])) <= 12
    assert not overlapping_labels(figure)


def test_a_partial_product_is_no_grid():
    cases = [(0.1e-3, "abm"), (0.2e-3, "abm"), (0.1e-3, "dopri5")]
    table = results([{CLEARANCE: c, "solver.integrator": i} for c, i in cases])
    sweep_texts = {
        CLEARANCE: texts(table, CLEARANCE, "mm", 1e3),
        "solver.integrator": {"abm": "abm", "dopri5": "dopri5"},
    }
    figure = plot_sweep(table, [FORCE], sweep_texts)
    ax = figure.axes[0]
    assert not ax.get_lines()
    assert [len(points.get_offsets()) for points in ax.collections] == [2, 1]
    assert [t.get_text() for t in figure.legends[0].get_texts()] == ["abm", "dopri5"]


@pytest.mark.parametrize(
    "values",
    [
        np.linspace(0.01, 0.3, 50),  # many: the axis' own ticks
        np.array([0.010, 0.0101, 0.0102, 0.0103, 0.0104, 0.2]),  # few but crowded
    ],
)
def test_numeric_tick_labels_do_not_overlap(values):
    table = results([{FRICTION: v} for v in values])
    figure = plot_sweep(table, [FORCE], {FRICTION: texts(table, FRICTION)})
    assert not overlapping_labels(figure)
    assert 2 <= len(tick_labels(figure.axes[0])) <= 12


def test_many_category_labels_do_not_overlap():
    names = [f"integrator_{k}" for k in range(60)]
    table = results([{"solver.integrator": name} for name in names])
    forces = [f"{joint}.max_contact_force_n" for joint in JOINTS]  # panels that share x
    figure = plot_sweep(table, forces, {"solver.integrator": {n: n for n in names}})
    assert not overlapping_labels(figure)
    shown = tick_labels(figure.axes[-1])
    assert 2 <= len(shown) < 60  # every n-th
    assert set(shown) <= set(names)


def test_a_figure_per_figure_of_merit_with_a_panel_per_joint(tmp_path):
    table = results([{VISCOSITY: v, FRICTION: f} for v in (0.01, 0.04, 0.4) for f in (0.0, 0.1)])
    sweep_texts = {VISCOSITY: texts(table, VISCOSITY, "Pa*s"), FRICTION: texts(table, FRICTION)}
    for joint in JOINTS:  # always in contact, but for rounding: no figure
        table[f"{joint}.contact_time_fraction"] = [1.0, 1.0 - 2e-16] * 3
    write_text(tmp_path / "coupler_follower.max_penetration_m.png", "")  # an older sweep's
    written = save_sweep_figures(table, JOINTS, sweep_texts, tmp_path)
    names = ["max_contact_force", "max_wear_depth", "worn_volume"]
    assert [p.name for p in written] == [f"{name}.png" for name in names]
    assert len(written) <= len(FIGURES_OF_MERIT)
    assert sorted(tmp_path.glob("*.png")) == sorted(written)
    force = plot_sweep(table, [f"{joint}.max_contact_force_n" for joint in JOINTS], sweep_texts)
    assert [ax.get_title() for ax in force.axes] == list(JOINTS)
