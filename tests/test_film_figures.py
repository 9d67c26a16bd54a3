"""The figures a tribologist reads of a lubricated joint: the film pressure and the Stribeck curve.

The film pressure is the Reynolds equation solved again at one output row
(``joints.revolute.film_field``); the independent answer it must meet is the film force the
run's kernel read from its interpolated impedance table at that row. The journal rig is that
of test_film_and_foundation_joints.py (Table 2's journal, 1 kg, turned at 200 rad/s) under a
load that rises until the asperities carry part of it, so the rows cover a full film, a
mixed one and overlapping mean planes. The Stribeck curve is drawn from tables built here.
"""

import math

import numpy as np
import pandas as pd
import pytest
from matplotlib.colors import to_rgba
from test_film_and_foundation_joints import R_J, WIDTH, bearing_model, run

from jointwear.figures.plan import figure_plan
from jointwear.figures.stribeck import REGIMES, plot_stribeck, regime, stribeck_joints
from jointwear.figures.sweep import save_sweep_figures
from jointwear.joints.revolute import KIND
from jointwear.joints.revolute.figures import plot_film_pressure
from jointwear.joints.revolute.film_field import film_field
from jointwear.model import parse_model

RAMP, RAMP_END = 20000.0, 0.1  # load rising at [N/s] for [s]: to 2 kN
THIN = 0.005  # viscosity [Pa s]
ROUGH = 0.5e-6  # combined roughness sigma [m]


def finite_model(**keys) -> dict:
    """The journal rig as a finite bearing with a mixed film, under the rising load."""
    data = bearing_model({"type": "polynomial", "coefficients": [0.0, -RAMP]}, RAMP_END)
    clearance = data["joints"][0]["clearance"]
    clearance.pop("film_breakdown", None)
    mixed = {"lubrication": "finite_bearing", "viscosity": THIN, "roughness": ROUGH}
    clearance.update({**mixed, "friction_coefficient": 0.1, **keys})
    data["solver"].update(rtol=1e-8, atol=1e-12)
    return data


@pytest.fixture(scope="module")
def ramp():
    return run(finite_model())


def integrated_force(field) -> np.ndarray:
    """-int p n dA over the field's cells [N], global axes, by this test's own sum.

    p is constant over a finite-volume cell; n = cos a e_r + sin a e_t integrates exactly
    over its angle: R (sin a1 - sin a0, cos a0 - cos a1) times its width.
    """
    a, z = field.angle_faces, field.axial_faces
    along = np.outer(np.sin(a[1:]) - np.sin(a[:-1]), np.diff(z))
    across = np.outer(np.cos(a[:-1]) - np.cos(a[1:]), np.diff(z))
    f_r = -R_J * np.sum(field.pressure * along)
    f_t = -R_J * np.sum(field.pressure * across)
    e_r = np.array([math.cos(field.line_of_centres), math.sin(field.line_of_centres)])
    e_t = np.array([-e_r[1], e_r[0]])
    return f_r * e_r + f_t * e_t


@pytest.mark.parametrize("lam", [8.0, 2.0, 0.5, -0.2])
def test_the_pressure_drawn_carries_the_film_force_the_run_had(ramp, lam):
    # The row nearest each film parameter lambda = -delta / sigma: a full film (8), the
    # asperities touching (2, 0.5) and the mean planes overlapping (-0.2), where the film
    # sees the rough surfaces' mean gap, not the geometric one. The run's force came from
    # the impedance table, the field from the Reynolds solver on the table's own grid: they
    # differ by the table's interpolation, which against direct solves at random directions
    # of V (L/D = 1.02) stays below 0.4 % up to eps = 0.998 and 0.7 % up to 0.9995 (the film
    # here: 1 - eps >= 0.4 sigma / c = 1e-3); 1 %.
    df = ramp.timeseries
    assert df["J_lambda"].min() < lam < df["J_lambda"].max()
    row = df.iloc[int(np.argmin(np.abs(df["J_lambda"].to_numpy() - lam)))]
    assert row["J_lambda"] == pytest.approx(lam, abs=0.5)  # the rows are 1e-4 s apart
    field = film_field(ramp, "J", float(row["time"]))
    assert field.time == row["time"]
    expected = np.array([row["J_film_fx"], row["J_film_fy"]])
    got = integrated_force(field)
    assert np.linalg.norm(got - expected) < 0.01 * np.linalg.norm(expected)
    assert np.allclose(field.force, got, rtol=1e-12, atol=1e-9 * np.linalg.norm(got))
    # the whole width, the solved half mirrored; nothing pulls; some of the film cavitates
    assert field.axial_faces[0] == pytest.approx(-WIDTH / 2) and field.axial_faces[-1] == WIDTH / 2
    np.testing.assert_array_equal(field.pressure, field.pressure[:, ::-1])
    assert field.pressure.min() == 0.0
    assert (field.pressure[field.cavitated] == 0.0).all() and field.cavitated.any()


def test_the_pressure_keeps_the_inlet_the_table_was_built_with():
    # A light steady load (1 N) in the same oil: the journal rides at eps 0.5 to 0.75 on a
    # mostly wedge film whose pressure reaches round to the thickest film, where the table's
    # film has its inlet (p = 0, film.reynolds supply=True). A periodic film without it
    # carries up to 4.5 % more at these rows; the table's interpolation error is below 0.2 %
    # here (as above); 1 %.
    data = bearing_model(1.0, 0.05)
    clearance = data["joints"][0]["clearance"]
    clearance.pop("film_breakdown", None)
    clearance.update(lubrication="finite_bearing", viscosity=THIN, roughness=ROUGH)
    light = run(data)
    df = light.timeseries
    for time in (0.02, 0.03, 0.04, 0.05):
        row = df.iloc[int(np.argmin(np.abs(df["time"].to_numpy() - time)))]
        field = film_field(light, "J", time)
        assert 0.5 < field.eps < 0.75
        expected = np.array([row["J_film_fx"], row["J_film_fy"]])
        assert np.linalg.norm(integrated_force(field) - expected) < 0.01 * np.linalg.norm(expected)


def test_by_default_the_row_of_the_largest_film_force_of_the_steady_state(ramp):
    df = ramp.timeseries
    start = ramp.summary["steady_state"]["from_s"]
    assert start is not None  # the driver's turns repeat: a steady state after the first
    rows = df[df["time"] >= start]
    force = np.hypot(rows["J_film_fx"], rows["J_film_fy"]).to_numpy()
    assert film_field(ramp, "J").time == rows["time"].iloc[int(np.argmax(force))]
    figure = plot_film_pressure(ramp)
    title = figure.subfigs[0].get_suptitle()
    assert f"t = {rows['time'].iloc[int(np.argmax(force))] * 1e3:.4g} ms" in title
    assert "largest film force of the steady state" in title
    assert f"force {force.max() / 1e3:.3g} kN" in title


def test_the_figure_is_drawn_for_finite_bearings_only(ramp):
    assert "film_pressure" in figure_plan(ramp)
    finite = parse_model(finite_model())
    short = finite_model(lubrication="short_bearing")
    short["joints"][0]["clearance"].pop("roughness")
    dry = finite_model(lubrication="none")
    for key in ("roughness", "viscosity"):
        dry["joints"][0]["clearance"].pop(key)
    assert KIND.draws("film_pressure", finite)
    assert not KIND.draws("film_pressure", parse_model(short))
    assert not KIND.draws("film_pressure", parse_model(dry))
    assert KIND.draws("fig7d_orbit", parse_model(dry))


def test_a_joint_or_time_the_figure_cannot_show_is_refused(ramp):
    with pytest.raises(ValueError, match=r"'motor' is not a finite journal bearing.*: J$"):
        plot_film_pressure(ramp, joint="motor")
    with pytest.raises(
        ValueError, match=r"time 0\.2 s is outside the run; its rows span 0 to 0\.1"
    ):
        plot_film_pressure(ramp, time=0.2)


# The Stribeck curve from a sweep table -----------------------------------------------------

VISCOSITY = "joints.pin.clearance.viscosity"


def sweep_table(hersey, friction, lam) -> pd.DataFrame:
    """A sweep table of one lubricated joint ``pin``: its film columns, in the given order."""
    return pd.DataFrame({
        VISCOSITY: np.geomspace(1e-3, 1.0, len(hersey)),
        "pin.film.hersey_number": hersey,
        "pin.film.friction_coefficient": friction,
        "pin.film.min_lambda": lam,
        "pin.film.asperity_load_share": np.linspace(0.4, 0.0, len(hersey)),
        "pin.max_contact_force_n": np.linspace(1e3, 2e3, len(hersey)),
    })  # fmt: skip


def test_the_regimes_change_at_lambda_1_and_3():
    assert [regime(x) for x in (-2.0, 0.999, 1.0, 2.999, 3.0, 50.0)] == [0, 0, 1, 1, 2, 2]


def test_the_stribeck_curve_is_friction_against_hersey_coloured_by_regime():
    hersey = [3e-6, 1e-8, 1e-7, 1e-6]  # not in order
    friction = [0.02, 0.1, 0.01, 0.005]
    lam = [8.0, -0.5, 1.5, 3.5]
    figure = plot_stribeck(sweep_table(hersey, friction, lam), ["pin"])
    (ax,) = figure.axes
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"  # f spans 20x
    (points,) = ax.collections
    np.testing.assert_allclose(points.get_offsets(), [[1e-8, 0.1], [1e-7, 0.01], [1e-6, 0.005],
                                                      [3e-6, 0.02]])  # fmt: skip
    expected = [REGIMES[k][2] for k in (0, 1, 2, 2)]  # boundary, mixed, hydrodynamic twice
    np.testing.assert_allclose(points.get_facecolors(), [to_rgba(c) for c in expected])
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == [name for _, name, _ in REGIMES]


def test_without_lambda_the_points_show_the_asperity_share():
    table = sweep_table([1e-8, 1e-7, 1e-6], [0.1, 0.02, 0.01], [np.nan] * 3)
    figure = plot_stribeck(table, ["pin"])
    colour_bar = figure.axes[1]
    assert colour_bar.get_ylabel() == "asperity load share [%]"
    np.testing.assert_allclose(figure.axes[0].collections[0].get_array(), [40.0, 20.0, 0.0])


def test_a_sweep_draws_the_curve_from_three_finite_cases(tmp_path):
    table = sweep_table([1e-8, 1e-7, np.nan, 1e-6], [0.1, 0.02, 0.01, np.nan], [0.5, 2.0, 4.0, 5.0])
    assert stribeck_joints(table, ["pin"]) == []  # two cases with both numbers
    table.loc[2, "pin.film.hersey_number"] = 3e-7
    assert stribeck_joints(table, ["pin"]) == ["pin"]
    notes = {v: f"{v:.3g} Pa*s" for v in table[VISCOSITY]}
    written = save_sweep_figures(table, ["pin"], {VISCOSITY: notes}, tmp_path)
    names = {p.name for p in written}
    assert {"stribeck.png", "friction_coefficient.png", "asperity_load_share.png"} <= names
    assert all(p.stat().st_size > 5000 for p in written)
