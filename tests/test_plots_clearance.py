"""Clearance figures (paper Figs. 7-10) and the mechanism animation: files and plotted data."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from PIL import Image
from runs import EXAMPLES, PER_METRE, drawn_per_metre, simulate_ok

from jointwear.figures.animation import save_animation
from jointwear.joints.revolute import KIND
from jointwear.joints.revolute.figures import (
    PROFILE_SHARE,
    plot_dynamics,
    plot_orbit,
    plot_wear_polar,
    plot_wear_profile,
    plot_wear_sectors,
    wear_exaggeration,
)
from jointwear.joints.revolute.figures import (
    save_figures as save_clearance_figures,
)

CLEARANCE_FIGURES = [name for name, _ in KIND.figures if name != "film_pressure"]  # a dry joint's
FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
# 2.5 crank turns; snapshots at 0.03, 0.06 and 0.09 s, so the end of the run is not one.
SHORT = ["solver.t_end=0.1", "solver.wear_snapshot_interval=0.03"]
JOINT = "coupler_follower"
FIGURES = ["fig7_dynamics", "fig7d_orbit", "fig8_wear_sectors", "fig9_wear_polar", "fig10_profile"]


@pytest.fixture(scope="module")
def fourbar():
    return simulate_ok(FOURBAR, SHORT)


@pytest.fixture(scope="module")
def ideal():
    return simulate_ok(FOURBAR, SHORT, ideal=True)


@pytest.fixture(scope="module")
def pendulum():
    return simulate_ok(
        EXAMPLES / "pendulum.toml", ["solver.t_end=0.1", "solver.output_interval=0.004"]
    )


def profile(table, surface):
    rows = table[(table["joint"] == JOINT) & (table["surface"] == surface)]
    return rows.sort_values("sector")["depth_m"].to_numpy()


def test_save_clearance_figures_writes_every_png(fourbar, ideal, tmp_path):
    paths = save_clearance_figures(fourbar, tmp_path / "figs", ideal)
    assert [p.name for p in paths] == [f"{name}.png" for name in FIGURES]
    for path in paths:
        with Image.open(path) as image:
            assert image.format == "PNG"
            assert min(image.size) > 600  # dpi 150 on figures of 5 inches and more


def test_no_clearance_joints_no_figures(pendulum, ideal, tmp_path):
    for results in (pendulum, ideal):
        assert save_clearance_figures(results, tmp_path / "none") == []
    assert not (tmp_path / "none").exists()


def test_dynamics_show_the_last_two_turns_of_both_runs(fourbar, ideal):
    fig = plot_dynamics(fourbar, ideal)
    velocity, acceleration, torque = fig.axes
    two_turns = 801  # 0.04 s a turn, rows every 0.1 ms, both ends
    ts, ts_ideal = fourbar.timeseries.tail(two_turns), ideal.timeseries.tail(two_turns)
    for ax, column in [(velocity, "omega_follower"), (acceleration, "alpha_follower")]:
        clearance_line, ideal_line = ax.lines
        np.testing.assert_array_equal(clearance_line.get_ydata(), ts[column])
        np.testing.assert_array_equal(ideal_line.get_ydata(), ts_ideal[column])
    np.testing.assert_array_equal(torque.lines[0].get_ydata(), ts["torque_motor"])
    angle = torque.lines[0].get_xdata()
    assert angle[0] == 0.0
    assert angle[-1] == pytest.approx(720.0, abs=1e-6)
    assert torque.get_ylabel() == "driving moment [N m]"


def test_dynamics_without_ideal_or_rotation(fourbar):
    assert all(len(ax.lines) == 1 for ax in plot_dynamics(fourbar).axes)
    slider = simulate_ok(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.012"])  # one turn
    velocity, acceleration, _ = plot_dynamics(slider).axes
    assert (velocity.get_title(loc="left"), velocity.get_ylabel()) == (
        "(a) slider x velocity",
        "x velocity [m/s]",
    )
    assert acceleration.get_ylabel() == "x acceleration [m/s²]"
    np.testing.assert_array_equal(velocity.lines[0].get_ydata(), slider.timeseries["vx_slider"])


def test_orbit_is_the_eccentricity_in_mm(fourbar):
    (ax,) = plot_orbit(fourbar).axes
    whole_run, last_turns, circle = ax.lines[:3]
    ts = fourbar.timeseries
    np.testing.assert_array_equal(whole_run.get_xdata(), ts[f"{JOINT}_ex"] * 1e3)
    np.testing.assert_array_equal(whole_run.get_ydata(), ts[f"{JOINT}_ey"] * 1e3)
    assert len(last_turns.get_xdata()) == 801
    radius = np.hypot(circle.get_xdata(), circle.get_ydata())
    np.testing.assert_allclose(radius, 0.2, rtol=1e-9)  # c = 10.0 mm - 9.8 mm


def test_sector_panels_hold_every_snapshot_and_the_end(fourbar):
    journal, bearing = plot_wear_sectors(fourbar).axes
    snapshots = fourbar.wear_snapshots
    times = sorted(snapshots["time_s"].unique())
    assert times == pytest.approx([0.03, 0.06, 0.09])
    for ax, surface in [(journal, "journal"), (bearing, "bearing")]:
        assert len(ax.lines) == 4
        per_m = drawn_per_metre(ax.get_ylabel())
        assert per_m == 1e9  # 2.5 turns wear the journal by about 0.3 µm: drawn in nm
        for line, time in zip(ax.lines, times, strict=False):
            depth = profile(snapshots[snapshots["time_s"] == time], surface)
            np.testing.assert_array_equal(line.get_ydata(), depth * per_m)
        np.testing.assert_array_equal(
            ax.lines[-1].get_ydata(), profile(fourbar.wear, surface) * per_m
        )
    labels = [text.get_text() for text in bearing.get_legend().get_texts()]
    assert labels == ["after 0.8 turns", "after 1.5 turns", "after 2.2 turns", "after 2.5 turns"]


def test_polar_radii_are_the_final_wear(fourbar):
    journal, bearing = plot_wear_polar(fourbar).axes
    for ax, surface in [(journal, "journal"), (bearing, "bearing")]:
        theta, radius = ax.lines[0].get_xdata(), ax.lines[0].get_ydata()
        depth = profile(fourbar.wear, surface) * drawn_per_metre(ax.get_title())
        np.testing.assert_array_equal(radius, [*depth, depth[0]])  # closed curve
        np.testing.assert_allclose(np.degrees(theta[:-1]), (np.arange(36) + 0.5) * 10.0)


def test_profile_exaggeration_draws_the_deepest_wear_at_15_percent(fourbar):
    scale = wear_exaggeration(fourbar, JOINT)
    deepest = fourbar.wear["depth_m"].max()
    assert deepest > 0.0
    assert scale * deepest / 9.8e-3 == pytest.approx(PROFILE_SHARE, rel=0.05)
    assert float(f"{scale:.2g}") == scale
    journal, bearing = plot_wear_profile(fourbar).axes
    for ax, surface, radius, sign in [(journal, "journal", 9.8, -1), (bearing, "bearing", 10.0, 1)]:
        nominal, worn = ax.lines[:2]
        np.testing.assert_allclose(np.hypot(nominal.get_xdata(), nominal.get_ydata()), radius)
        shift = sign * (np.hypot(worn.get_xdata(), worn.get_ydata()) - radius)
        assert shift.max() == pytest.approx(scale * profile(fourbar.wear, surface).max() * 1e3)
        assert f"wear × {scale:g}" in worn.get_label()


def test_animation_writes_a_gif_of_the_requested_frames(fourbar, tmp_path):
    path = save_animation(fourbar, tmp_path / "anim" / "fourbar.gif", frames=12, fps=20)
    with Image.open(path) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == 12
        assert gif.size == (640, 600)
        assert gif.info["duration"] == 50  # [ms] at 20 frames per second


def test_animation_without_crank_or_clearance(pendulum, tmp_path):
    path = save_animation(pendulum, tmp_path / "pendulum.gif", frames=50)
    with Image.open(path) as gif:
        assert gif.n_frames == 11  # the last 0.04 s, rows every 4 ms: fewer than asked


def test_figures_drawn_by_the_helper_process_are_those_drawn_here(fourbar, ideal, tmp_path):
    from jointwear.figures.render import drawing_helper

    alone = save_clearance_figures(fourbar, tmp_path / "alone", ideal)
    with drawing_helper():
        helped = save_clearance_figures(fourbar, tmp_path / "helped", ideal)
    assert [p.name for p in helped] == [p.name for p in alone]
    for mine, theirs in zip(alone, helped, strict=True):
        assert mine.read_bytes() == theirs.read_bytes(), mine.name


def test_only_the_papers_model_is_titled_after_the_papers_figures(fourbar, ideal):
    from jointwear.joints.revolute.figures import plot_orbit

    assert plot_orbit(fourbar).get_suptitle().endswith("(paper Fig. 7d)")
    other = replace(fourbar, model=fourbar.model.with_values({"name": "my_engine"}))
    assert "paper" not in plot_orbit(other).get_suptitle()


HELPED_RUN = """
import sys
import jointwear as jw
from jointwear.figures.render import drawing_helper

if __name__ == "__main__":
    with drawing_helper():
        jw.run(sys.argv[1], sys.argv[2], overrides=["solver.t_end=0.1"])
    print(sorted(m for m in sys.modules if m.split(".")[0] == "matplotlib"))
"""


def test_a_run_whose_figures_the_helpers_draw_never_imports_matplotlib(tmp_path):
    import subprocess
    import sys

    script = tmp_path / "helped_run.py"
    script.write_text(HELPED_RUN)
    out = tmp_path / "out"
    done = subprocess.run(
        [sys.executable, str(script), str(FOURBAR), str(out)],
        capture_output=True, text=True, timeout=600, check=True,
    )  # fmt: skip
    assert done.stdout.strip() == "[]"  # matplotlib's import (~1 s) stays with the helpers
    written = {p.name for p in (out / "figures").glob("*.png")}
    assert written == {"energy.png", "cycle.png", *(f"{n}.png" for n in CLEARANCE_FIGURES)}


@pytest.mark.parametrize(
    ("largest_m", "unit"),
    [(2.9e-6, "µm"), (6.5e-11, "nm"), (3.0e-4, "µm"), (1.5e-3, "mm"), (5.0, "m"), (0.0, "µm")],
)
def test_wear_depths_are_drawn_in_the_unit_that_reads_below_a_thousand(largest_m, unit):
    from jointwear.figures.scaling import length_unit

    assert length_unit([-0.5 * largest_m, largest_m, np.nan]) == (unit, PER_METRE[unit])


@given(st.floats(min_value=1e-9, max_value=999.0))
def test_a_length_from_a_nanometre_up_reads_from_1_to_999_in_its_unit(largest_m):
    from jointwear.figures.scaling import length_unit

    assert 1.0 <= largest_m * length_unit([largest_m])[1] < 1000.0


def test_no_legend_of_the_run_figures_covers_an_axes(fourbar, ideal):
    from jointwear.figures.plan import figure_plan

    checked = set()
    for name, draw in figure_plan(fourbar, ideal).items():
        fig = draw()
        fig.draw_without_rendering()  # lays the figure out
        for legend in (ax.get_legend() for ax in fig.axes if ax.get_legend() is not None):
            checked.add(name)
            box = legend.get_window_extent()
            for ax in fig.axes:
                assert not box.overlaps(ax.get_window_extent()), (name, ax.get_title())
    assert checked == {"energy", "cycle", "fig7_dynamics", "fig7d_orbit", "fig8_wear_sectors",
                       "fig10_profile"}  # fmt: skip
