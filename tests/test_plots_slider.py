"""Slider figures (translational clearance joints) and the slider in the animation."""

import math

import numpy as np
import pytest
from PIL import Image
from runs import EXAMPLES, drawn_per_metre, simulate_ok

import jointwear as jw
from jointwear.figures.animation import CLEARANCE_SHARE, mechanism_scene, save_animation
from jointwear.figures.crank import crank_abscissa
from jointwear.figures.folder import save_figures
from jointwear.figures.names import ALL_FIGURES
from jointwear.io import write_text
from jointwear.joints.revolute import KIND as REVOLUTE
from jointwear.joints.revolute.figures import plot_dynamics, plot_wear_sectors
from jointwear.joints.translational import KIND
from jointwear.joints.translational.figures import (
    plot_corner_forces,
    plot_guide_wear,
    plot_slider_motion,
    tilt_limit,
)
from jointwear.joints.translational.figures import (
    save_figures as save_slider_figures,
)

SLIDER_FIGURES = [name for name, _ in KIND.figures]

PISTON = EXAMPLES / "slider_crank_piston_clearance.toml"
# About 1.2 free-crank turns (the crank slows at mid-stroke); snapshots at 0.03 and 0.06 s.
SHORT = ["solver.t_end=0.08", "solver.output_interval=0.2 ms", "solver.wear_snapshot_interval=0.03"]
JOINT = "piston"
GAP, HALF_LENGTH, HALF_HEIGHT, GUIDE_HALF_LENGTH = 1e-3, 0.05, 0.025, 0.22  # [m], the example's
GUIDE_CENTRE = 0.306  # [m] global x of the guide's middle (its axis is global x)
CORNERS = ["rear_top", "front_top", "rear_bottom", "front_bottom"]  # the panels' order


@pytest.fixture(scope="module")
def piston():
    return simulate_ok(PISTON, SHORT)


@pytest.fixture(scope="module")
def unbounded():
    """The example with an unbounded guide, for less than a crank turn."""
    model = jw.load_model(PISTON, overrides=["solver.t_end=0.03", "solver.output_interval=0.5 ms"])
    joints = tuple(
        j.model_copy(update={"clearance": j.clearance.model_copy(update={"guide_length": None})})
        if j.name == JOINT
        else j
        for j in model.joints
    )
    res = jw.simulate(model.model_copy(update={"joints": joints}))
    assert res.status == "success", res.message
    return res


def rows(table, surface):
    picked = table[(table["joint"] == JOINT) & (table["surface"] == surface)]
    return picked.sort_values("sector")


def test_save_slider_figures_writes_every_png(piston, tmp_path):
    paths = save_slider_figures(piston, tmp_path / "figs")
    assert [p.name for p in paths] == [f"{name}.png" for name in SLIDER_FIGURES]
    for path in paths:
        with Image.open(path) as image:
            assert image.format == "PNG"
            assert min(image.size) > 600


def test_figure_folder_draws_the_slider_figures_only(piston, tmp_path):
    write_text(tmp_path / "fig8_wear_sectors.png", "left by a revolute run")  # jointwear's
    (tmp_path / "fig9_wear_polar.png").write_bytes(b"the user's own, of the same name")
    paths = save_figures(piston, tmp_path, animation=False)
    names = {p.name for p in paths}
    assert names == {"energy.png", *(f"{n}.png" for n in SLIDER_FIGURES)}
    assert names <= ALL_FIGURES
    assert not (tmp_path / "fig8_wear_sectors.png").exists()
    assert (tmp_path / "fig9_wear_polar.png").read_bytes() == b"the user's own, of the same name"


def test_no_slider_joints_no_figures(tmp_path):
    pendulum = simulate_ok(
        EXAMPLES / "pendulum.toml", ["solver.t_end=0.01", "solver.output_interval=0.002"]
    )
    assert save_slider_figures(pendulum, tmp_path / "none") == []
    assert not (tmp_path / "none").exists()
    with pytest.raises(ValueError, match="no translational clearance joints"):
        plot_slider_motion(pendulum)


def test_free_crank_angle_is_the_abscissa(piston):
    ts = piston.timeseries
    x = crank_abscissa(piston)
    assert x.crank == "crank"
    np.testing.assert_allclose(x.values, np.degrees(ts["phi_crank"] - ts["phi_crank"].iloc[0]))
    assert 360.0 < x.values[-1] < 720.0


def test_motion_lines_are_the_time_series(piston):
    lateral, tilt = plot_slider_motion(piston).axes
    ts = piston.timeseries
    np.testing.assert_array_equal(lateral.lines[0].get_ydata(), ts[f"{JOINT}_lateral"] * 1e3)
    np.testing.assert_array_equal(tilt.lines[0].get_ydata(), ts[f"{JOINT}_tilt"] * 1e3)
    np.testing.assert_array_equal(lateral.lines[0].get_xdata(), crank_abscissa(piston).values)
    gap_lines = [line.get_ydata()[0] for line in lateral.lines[1:3]]
    assert gap_lines == pytest.approx([1.0, -1.0])  # ±c [mm]
    assert lateral.get_ylabel() == "lateral offset [mm]"
    assert tilt.get_ylabel() == "tilt [mrad]"
    assert "crank angle" in tilt.get_xlabel()
    # The slider stays in its guide: within the gap, give or take the contact's penetration.
    assert np.abs(ts[f"{JOINT}_lateral"]).max() == pytest.approx(GAP, rel=0.1)


def test_tilt_limit_puts_opposite_corners_on_both_surfaces(piston):
    clearance = piston.model.joint(JOINT).clearance
    t = tilt_limit(clearance)
    reach = HALF_LENGTH * math.sin(t) + HALF_HEIGHT * math.cos(t)
    assert reach == pytest.approx(HALF_HEIGHT + GAP, rel=1e-12)
    assert t == pytest.approx(2.0 * GAP / (2.0 * HALF_LENGTH), rel=0.01)


def test_corner_force_panels_hold_each_corner(piston):
    axes = plot_corner_forces(piston).axes
    ts = piston.timeseries
    assert len(axes) == 4
    for ax, corner in zip(axes, CORNERS, strict=True):
        assert ax.get_title(loc="left").startswith(f"{JOINT}: {corner} corner")
        np.testing.assert_array_equal(ax.lines[0].get_ydata(), ts[f"{JOINT}_fn_{corner}"])
        # The guide is long enough that its ends never touch: no edge lines.
        assert not ts[f"{JOINT}_fn_edge_{corner}"].any()
        assert len(ax.lines) == 1
    assert max(ts[f"{JOINT}_fn_{c}"].max() for c in CORNERS) > 0.0


def test_wear_lines_are_the_wear_table(piston):
    guide, slider = plot_guide_wear(piston).axes
    snapshots = piston.wear_snapshots
    times = sorted(snapshots["time_s"].unique())
    assert times == pytest.approx([0.03, 0.06])
    for ax, part in [(guide, "guide"), (slider, "slider")]:
        assert len(ax.lines) == 2 * (len(times) + 1)  # top and bottom: snapshots, then the end
        per_m = drawn_per_metre(ax.get_ylabel())
        assert per_m == 1e9  # depths of a few hundredths of a nanometre
        for side in ("top", "bottom"):
            surface = f"{part}_{side}"
            (final,) = [line for line in ax.lines if line.get_label() == surface]
            table = rows(piston.wear, surface)
            np.testing.assert_array_equal(final.get_ydata(), table["depth_m"] * per_m)
            np.testing.assert_array_equal(final.get_xdata(), table["position_m"] * 1e3)
            same = [line for line in ax.lines if line.get_color() == final.get_color()]
            for line, time in zip(same[:-1], times, strict=True):
                snap = rows(snapshots[snapshots["time_s"] == time], surface)
                np.testing.assert_array_equal(line.get_ydata(), snap["depth_m"] * per_m)
                assert line.get_alpha() < 1.0
    assert guide.get_xlim() == pytest.approx((-220.0, 220.0))
    assert slider.get_xlim() == pytest.approx((-50.0, 50.0))
    assert piston.wear["depth_m"].max() > 0.0


def test_unbounded_guide_shows_the_slider_only(unbounded, tmp_path):
    assert set(unbounded.wear["surface"]) == {"slider_top", "slider_bottom"}
    fig = plot_guide_wear(unbounded)
    (slider,) = fig.axes
    assert "unbounded" in slider.get_title() and "unbounded" in fig.get_suptitle()
    assert {line.get_label() for line in slider.lines} >= {"slider_top", "slider_bottom"}
    assert len(plot_corner_forces(unbounded).axes) == 4  # corners only: no edge columns
    lateral, tilt = plot_slider_motion(unbounded).axes
    assert crank_abscissa(unbounded).crank is None  # less than a turn: against time
    assert tilt.get_xlabel() == "time [s]"
    np.testing.assert_array_equal(lateral.lines[0].get_xdata(), unbounded.timeseries["time"])
    assert len(save_slider_figures(unbounded, tmp_path)) == 3


def frame_rows(results, scene):
    ts = results.timeseries
    picked = ts[ts["time"].isin(scene.times)]
    assert len(picked) == len(scene.times)
    return picked


def test_animation_draws_the_slider_magnified(piston, tmp_path):
    path = save_animation(piston, tmp_path / "piston.gif", frames=12)
    with Image.open(path) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == 12
    scene = mechanism_scene(piston, frames=12)
    ts = frame_rows(piston, scene)
    phi = ts["phi_crank"].to_numpy()
    last = piston.timeseries["phi_crank"].iloc[-1]
    assert phi[-1] == last and 2.0 * math.pi * 0.95 < last - phi[0] <= 2.0 * math.pi  # one turn
    # The mechanism spans about 0.612 m (crank tip at x = -0.153 m to the slider at 0.459 m).
    assert scene.scale == pytest.approx(CLEARANCE_SHARE * 0.612 / GAP, rel=0.05)
    ax = scene.figure.axes[0]
    (block,) = [p for p in ax.patches if p.get_width() == pytest.approx(2 * HALF_LENGTH)]
    rod = next(line for line in ax.lines if line.get_label() == "rod")
    drawn_half_height = HALF_HEIGHT + scene.scale * GAP
    for k in (0, 5, 11):
        scene.draw(k)
        row = ts.iloc[k]
        assert block.get_angle() == pytest.approx(math.degrees(scene.scale * row[f"{JOINT}_tilt"]))
        centre = block.get_corners().mean(axis=0)
        assert centre == pytest.approx(
            [row["x_slider"], scene.scale * row[f"{JOINT}_lateral"]], abs=1e-12
        )
        assert [rod.get_xdata()[-1], rod.get_ydata()[-1]] == pytest.approx(centre, abs=1e-12)
        guides = [line for line in ax.lines if line.get_color() == "k"]
        assert len(guides) == 2
        for line, side in zip(guides, (1.0, -1.0), strict=True):
            assert line.get_ydata() == pytest.approx([side * drawn_half_height] * 2)
            assert line.get_xdata() == pytest.approx(
                [GUIDE_CENTRE - GUIDE_HALF_LENGTH, GUIDE_CENTRE + GUIDE_HALF_LENGTH]
            )
    assert "× " in ax.get_title() and "gap 1 mm" in ax.get_title()


def test_animation_of_an_unbounded_guide_spans_the_travel(unbounded):
    scene = mechanism_scene(unbounded, frames=10, clearance_scale=10.0)
    ts = frame_rows(unbounded, scene)  # no crank turn: the last 0.04 s, the whole run here
    ax = scene.figure.axes[0]
    top = next(line for line in ax.lines if line.get_color() == "k")
    scene.draw(0)
    along = ts["x_slider"] - GUIDE_CENTRE
    assert top.get_xdata() == pytest.approx(
        [GUIDE_CENTRE + along.min() - HALF_LENGTH, GUIDE_CENTRE + along.max() + HALF_LENGTH]
    )
    assert top.get_ydata() == pytest.approx([HALF_HEIGHT + 10.0 * GAP] * 2)


def test_animation_draws_an_ideal_slider_on_its_guide():
    from jointwear.joints.translational.animation import IDEAL_SLIDER_ASPECT, IDEAL_SLIDER_SHARE

    ideal = simulate_ok(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.012"])  # one turn
    scene = mechanism_scene(ideal, frames=10)
    ts = frame_rows(ideal, scene)
    ax = scene.figure.axes[0]
    # Crank 0.05 m and rod 0.12 m in line on the x axis: the points sweep x from -0.05 to 0.17
    # (10 frames of a turn pass the crank's dead centre within 18°: 1.1 % of the 0.22 m).
    (block,) = ax.patches
    length = block.get_width()
    assert length == pytest.approx(IDEAL_SLIDER_SHARE * 0.22, rel=0.02)
    assert block.get_height() == pytest.approx(IDEAL_SLIDER_ASPECT * length, rel=1e-12)
    guides = [line for line in ax.lines if line.get_color() == "k"]
    assert len(guides) == 2
    travel = [ts["x_slider"].min() - 0.5 * length, ts["x_slider"].max() + 0.5 * length]
    for k in (0, 4, 9):
        scene.draw(k)
        centre = block.get_corners().mean(axis=0)
        assert centre == pytest.approx([ts["x_slider"].iloc[k], 0.0], abs=1e-12)
        assert block.get_angle() == 0.0
        for line, side in zip(guides, (1.0, -1.0), strict=True):  # the axis is global x
            assert line.get_xdata() == pytest.approx(travel)
            assert line.get_ydata() == pytest.approx([side * 0.5 * block.get_height()] * 2)


def test_revolute_and_slider_clearances_draw_both_sets(tmp_path):
    pin = "joints.crank_rod.clearance"
    both = simulate_ok(
        PISTON,
        [
            "solver.t_end=0.02",
            "solver.output_interval=0.5 ms",
            f"{pin}.bearing_radius='10 mm'",
            f"{pin}.journal_radius='9.5 mm'",
            f"{pin}.width='40 mm'",
            f"{pin}.youngs_modulus='207 GPa'",
            f"{pin}.poisson_ratio=0.3",
            f"{pin}.restitution_coefficient=0.9",
            f"{pin}.friction_coefficient=0.01",
            f"{pin}.wear_coefficient='8e-14 1/Pa'",
        ],
    )
    assert set(both.wear["surface"]) >= {"journal", "bearing", "guide_top", "slider_top"}
    paths = save_figures(both, tmp_path, animation=False)
    both_kinds = [*REVOLUTE.figures, *KIND.figures]  # but a finite bearing's: the pin is dry
    expected = {f"{name}.png" for name, _ in both_kinds} - {"film_pressure.png"}
    assert {p.name for p in paths} == {"energy.png", *expected}
    velocity = plot_dynamics(both).axes[0]  # the slider tilts, but its x motion is the output
    assert velocity.get_ylabel() == "x velocity [m/s]"
    ax = plot_wear_sectors(both).axes[0]  # the journal
    journal = both.wear[both.wear["surface"] == "journal"].sort_values("sector")["depth_m"]
    np.testing.assert_array_equal(
        ax.lines[-1].get_ydata(), journal * drawn_per_metre(ax.get_ylabel())
    )


def test_one_turn_leaves_out_bodies_that_do_not_turn():
    from jointwear.figures.run import plot_cycle

    engine = simulate_ok(EXAMPLES / "slider_crank.toml", ["solver.t_end=0.03"])
    labels = [line.get_label() for line in plot_cycle(engine).axes[0].get_lines()]
    assert labels[0] == "rod"  # it turns; the slider only slides
    assert "slider" not in labels
    assert np.abs(engine.timeseries["omega_slider"]).max() < 1e-9
