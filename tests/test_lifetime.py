"""Long-life wear (``jointwear.life`` and ``jointwear life``) against independent answers.

Two mechanisms:
- the paper's four-bar (examples/flores2009_fourbar.toml) with five times the paper's wear
  coefficient, so that 30 crank turns wear like 150 of the paper's (the clearance grows by
  about 13%): against the direct simulation of the same turns;
- a pressed rotor (ROTOR below): a disc on a clearance pin fixed to the ground, driven at
  10 rev/s and pressed down by a constant force, frictionless, with dampers that settle it.
  At rest its journal slides on the bearing's bottom at v = omega R_J under F_N = F, so
  Archard's law gives the worn volume in closed form (as in test_clearance_physics): from
  rest, k v (F t - c_d (c + delta)), the damper's impulse taken from F's.
"""

import json
import math
import os
import re
import signal
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from runs import whole_run
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.engine.simulate import simulate
from jointwear.io import append, write_text
from jointwear.joints.revolute.growth import clearance_growth
from jointwear.studies.life import files as lifetime_files
from jointwear.studies.life import update as lifetime_update
from jointwear.studies.life.settings import cycle_driver
from jointwear.studies.life.study import life
from jointwear.studies.sweep.study import sweep

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"
PENDULUM = ROOT / "examples" / "pendulum.toml"
FAST_WEAR = ["joints.coupler_follower.clearance.wear_coefficient=4e-13"]  # 5 x the paper's
PERIOD = 0.04  # one crank turn at 1500 rpm [s]

R_B, R_J, WIDTH, K_WEAR = 0.010, 0.0098, 0.020, 8e-14  # [m, m, m, 1/Pa]
C = R_B - R_J
FORCE, OMEGA = 1000.0, 20.0 * math.pi  # [N], 10 rev/s
ROTOR_PERIOD = 2.0 * math.pi / OMEGA  # 0.1 s
K_HERTZ = 579.6e9 / 5.46  # Table 2's internal-cylinder stiffness [N/m^1.5]
DELTA = (FORCE / K_HERTZ) ** (2.0 / 3.0)  # static penetration, 4.46e-6 m
DAMPING = 36700.0  # along the force: about critical for the contact [N s/m]
SECTOR = 2.0 * math.pi / 36
ROTOR = f"""
name = "pressed_rotor"
[ground.points]
pin = [0.0, 0.0]
above = [0.0, 1.0]
side = [1.0, 0.0]
[[bodies]]
name = "rotor"
mass = 1.0
inertia = 1e-4
position = [0.0, 0.0]
angle = 0.0
points = {{ c = [0.0, 0.0] }}
[[joints]]
name = "gap"
type = "revolute"
bodies = ["ground", "rotor"]     # the bearing fixed, the journal turning
points = ["pin", "c"]
[joints.clearance]
bearing_radius = {R_B}
journal_radius = {R_J}
width = {WIDTH}
youngs_modulus = 207e9
poisson_ratio = 0.3
restitution_coefficient = 0.9
friction_coefficient = 0.0
wear_coefficient = {K_WEAR}
[[drivers]]
name = "motor"
type = "angle"
body = "rotor"
function = {{ type = "constant_speed", speed = {OMEGA!r}, initial = 0.0 }}
[[forces]]
type = "point_force"
body = "rotor"
point = "c"
force = [0.0, {-FORCE}]
[[forces]]
type = "spring_damper"
bodies = ["ground", "rotor"]
points = ["above", "c"]
stiffness = 0.0
damping = {DAMPING}
free_length = 1.0
[[forces]]
type = "spring_damper"
bodies = ["ground", "rotor"]
points = ["side", "c"]
stiffness = 0.0
damping = 4470.0
free_length = 1.0
"""


@pytest.fixture
def rotor(tmp_path: Path) -> Path:
    path = tmp_path / "rotor.toml"
    path.write_text(ROTOR)
    return path


def final_profile(results) -> np.ndarray:
    """Depths [m] of the last update, in the wear table's order (joint, surface, sector)."""
    rows = results.profiles[results.profiles["update"] == results.profiles["update"].max()]
    return rows["depth_m"].to_numpy()


@pytest.mark.parametrize("psi", [(0.0, 7.0), (-1.0, 0.5), (2.0, 2.0), (0.31, 0.37)])
def test_clearance_growth_against_a_brute_force_search(psi):
    rng = np.random.default_rng(7)
    bearing, journal = rng.random(36) * 1e-5, rng.random(36) * 1e-5
    # The gap increase in every direction theta (bearing frame) at every relative angle psi,
    # the profiles interpolated periodically between the sector centres, on grids of 0.1
    # deg: at most the exact largest value, and below it by the profiles' slope (up to 1e-5
    # m per 10 deg sector) times the grids' half spacing, 1e-7 m at most.
    centres = (np.arange(36) + 0.5) * 2 * math.pi / 36
    theta = np.linspace(0.0, 2 * math.pi, 3601)[:, None]
    psis = np.linspace(psi[0], psi[1], max(2, round(math.degrees(psi[1] - psi[0]) * 10)))
    found = max(
        (np.interp(theta, centres, bearing, period=2 * math.pi)
         + np.interp(theta - block, centres, journal, period=2 * math.pi)).max()
        for block in np.array_split(psis, min(20, psis.size))
    )  # fmt: skip
    growth = clearance_growth(bearing, journal, psi)
    assert found - 1e-18 <= growth <= found + 1e-7
    if psi[1] - psi[0] >= 2 * math.pi:
        assert growth == bearing.max() + journal.max()


def test_without_extrapolation_it_is_the_direct_simulation(tmp_path):
    res = life(FOURBAR, tmp_path, cycles=5, overrides=FAST_WEAR, extrapolate=False, figures=False)
    assert res.status == "success", res.message
    # 2 settling turns, then one turn per update.
    assert res.table["cycles"].tolist() == [2, 3, 4, 5]
    assert res.table["extrapolated_cycles"].tolist() == [0, 0, 0, 0]
    assert res.table["simulated_cycles"].tolist() == [2, 3, 4, 5]  # no jumps, no resettling
    direct = jw.simulate(jw.load_model(FOURBAR, [*FAST_WEAR, f"solver.t_end={5 * PERIOD!r}"]))
    expected = direct.wear["depth_m"].to_numpy()
    # Restarts reproduce a continuous run to about 1e-4 of the deepest sector (measured
    # 4.5e-5); 1e-3, tighter than the 1 % asked of it.
    np.testing.assert_allclose(final_profile(res), expected, rtol=0, atol=1e-3 * expected.max())
    np.testing.assert_allclose(
        res.final.wear["revolute"].ravel(), expected, rtol=0, atol=1e-3 * expected.max()
    )
    joint = res.summary["clearance_joints"]["coupler_follower"]
    summary = whole_run(direct, "coupler_follower")
    assert joint["worn_volume_m3"] == pytest.approx(summary["worn_volume_m3"], rel=1e-2)


def test_an_update_that_does_not_settle_extrapolates_the_mean_of_its_second_half(tmp_path):
    # No two turns of the four-bar wear alike to 1e-12: the update runs its 4 turns (3 to 6)
    # and extrapolates the mean wear of turns 5 and 6 over the 2 turns left (6 turns of
    # about 0.6 µm, within the 8 µm of max_change).
    res = life(FOURBAR, tmp_path, cycles=8, overrides=FAST_WEAR, steady_tolerance=1e-12,
               max_update_cycles=4, max_change="4%", figures=False)  # fmt: skip
    assert res.status == "success", res.message
    table = res.table
    assert table["cycles"].tolist() == [2, 8]
    assert table["simulated_cycles"].tolist() == [2, 6]
    assert table["extrapolated_cycles"].tolist() == [0, 2]
    assert table["steady"].tolist() == [1, 0]
    assert res.summary["unsteady_updates"] == 1
    # Against the direct simulation: its wear after 6 turns plus twice its mean of turns 5-6.
    wear = {}
    for turns in (4, 6):
        model = jw.load_model(FOURBAR, [*FAST_WEAR, f"solver.t_end={turns * PERIOD!r}"])
        wear[turns] = jw.simulate(model).wear["depth_m"].to_numpy()
    expected = wear[6] + 2 * (wear[6] - wear[4]) / 2
    # Restarts reproduce a continuous run to about 1e-4 of the deepest sector (measured
    # 5.5e-5); 1e-3, while the 2 turns not extrapolated would be 25 % off.
    np.testing.assert_allclose(final_profile(res), expected, rtol=0, atol=1e-3 * expected.max())


def test_extrapolation_converges_as_max_change_tightens(tmp_path):
    reference = final_profile(
        life(FOURBAR, tmp_path / "direct", cycles=30, overrides=FAST_WEAR, extrapolate=False,
             figures=False)
    )  # fmt: skip
    errors = {}
    for change in ("8%", "4%", "2%", "1%"):
        res = life(FOURBAR, tmp_path / change, cycles=30, overrides=FAST_WEAR, max_change=change,
                   figures=False)  # fmt: skip
        assert res.status == "success", res.message
        assert res.summary["cycles_reached"] == 30
        errors[change] = np.abs(final_profile(res) - reference).max() / reference.max()
        # No update that extrapolates changes a sector by more than its bound, simulated
        # cycles included: the share of the clearance, nominal plus growth as the
        # extrapolation starts (at most that at the update's end).
        depths = res.profiles.pivot_table("depth_m", "update", ["surface", "sector"])
        changes = depths.diff().max(axis=1).to_numpy()[1:]
        growth = res.table["coupler_follower.clearance_growth_m"].to_numpy()[1:]
        bounds = float(change[:-1]) / 100 * (C + growth)
        extrapolating = res.table["extrapolated_cycles"].to_numpy()[1:] > 0
        assert extrapolating.any()
        assert (changes <= bounds * (1 + 1e-9))[extrapolating].all()
    # The wear rate falls as the profile deepens, so extrapolating the rate measured at the
    # start of an update overshoots by about the update's share: first order. Measured
    # 2.9e-2, 1.5e-2, 7.7e-3, 2.0e-3.
    values = list(errors.values())
    assert values == sorted(values, reverse=True), errors
    assert errors["1%"] < 0.25 * errors["8%"], errors
    assert errors["1%"] < 0.008, errors


@pytest.mark.parametrize(("measure", "change"), [(1, "1 um"), (3, "4 um")])
def test_without_feedback_the_wear_is_linear_and_archard_exact(rotor, tmp_path, measure, change):
    # The model keeps wear_feedback's default (on); feedback=False switches it off.
    cycles = 1000
    res = life(rotor, tmp_path, cycles=cycles, max_change=change, feedback=False,
               measure_cycles=measure, figures=False)  # fmt: skip
    assert res.status == "success", res.message
    table = res.table
    assert table["cycles"].iloc[-1] == cycles
    assert table["extrapolated_cycles"].sum() > 0.85 * cycles  # mostly extrapolated
    # Two groups of `measure` turns per update: the second wears like the first, so it is
    # steady and measured.
    assert set(np.diff(table["simulated_cycles"])[:-1]) == {2 * measure}
    assert table["steady"].all()
    # Per-cycle wear is constant (the rotor is at rest in its steady state): the deepest
    # bearing sector gains share/2 k F v T / (R_B (2 pi / N) L) per turn (the patch straddles
    # the sector edge at 270 deg, half on each side). Measured 1.6e-8 apart; 1e-7.
    speed = OMEGA * R_J
    per_turn = K_WEAR * FORCE * speed * ROTOR_PERIOD
    rates = table["gap.wear_rate_m_per_cycle"].to_numpy()[1:]
    np.testing.assert_allclose(rates, 0.25 * per_turn / (R_B * SECTOR * WIDTH), rtol=1e-7)
    # So the profiles lie on a straight line in cycles after the settling turns: the
    # bearing's patch exactly (1.6e-8 again); the turning journal's sectors to the placement
    # of the steps, each of which puts its patch at the angle of its midpoint (a sector's
    # share off by up to 3e-4 in a turn, as in test_clearance_physics); 1e-3.
    profiles = res.profiles.pivot_table(index="update", columns=["surface", "sector"],
                                        values="depth_m")  # fmt: skip
    turns = table["cycles"].to_numpy()[1:, None] - 2
    for surface, rtol in (("bearing", 1e-7), ("journal", 1e-3)):
        depths = profiles[surface].to_numpy()
        gained = (depths[1:] - depths[0]) / turns
        np.testing.assert_allclose(gained, np.broadcast_to(gained[-1], gained.shape), rtol=rtol)
    # And the worn volume is Archard's over the whole run, from rest (the damper's impulse
    # c_d (c + delta) is taken from F's): 1e-6 (the landing's steps, measured 2e-8).
    exact = K_WEAR * speed * (FORCE * cycles * ROTOR_PERIOD - DAMPING * (C + DELTA))
    assert table["gap.worn_volume_m3"].iloc[-1] == pytest.approx(exact, rel=1e-6)
    assert res.summary["clearance_joints"]["gap"]["worn_volume_m3"] == pytest.approx(exact, 1e-6)


class Crash(Exception):
    pass


def torn_row(file) -> None:
    """Half a row, then the process dies."""
    file.write("4,101,1")
    raise Crash


@pytest.mark.parametrize("how", ["exception", "signal", "signal_in_a_cycle"])
def test_resume_gives_the_uninterrupted_run(tmp_path, monkeypatch, how):
    settings = {"cycles": 30, "overrides": FAST_WEAR, "max_change": "1%", "figures": False}
    whole = life(FOURBAR, tmp_path / "whole", **settings)
    assert whole.status == "success" and len(whole.table) > 5

    reports = []

    def stop_at_third(cycles: int, total: int) -> None:
        # The value's run reports after each of its updates (the band's runs beside it add
        # their cycles to the count, and report on their own once it has ended).
        reports.append(cycles)
        if len(reports) == 4:  # the third update after the settling
            if how == "exception":
                raise Crash  # as if the process died right after the update
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C: the run ends after this update

    folder = tmp_path / "parts"
    if how == "exception":
        with pytest.raises(Crash):
            life(FOURBAR, folder, **settings, progress=stop_at_third)
        # As if it died while writing the next update's rows, before its checkpoint.
        for name in ("life.csv", "profiles.csv"):
            with pytest.raises(Crash):
                append(folder / name, torn_row)
    elif how == "signal":
        stopped = life(FOURBAR, folder, **settings, progress=stop_at_third)
        assert stopped.status == "interrupted"
        assert "--resume" in stopped.message
        assert len(stopped.table) == 4
        assert json.loads((folder / "summary.json").read_text())["status"] == "interrupted"
    else:
        # Ctrl-C as the first cycle of the first update ends its run: that run has
        # finished, and the request must still stop the life run before the next cycle;
        # the update in progress is lost.
        runs = []

        def simulate_then_ctrl_c(*args, **kwargs):
            results = simulate(*args, **kwargs)
            runs.append(results.status)
            if len(runs) == 2:  # the settling run, then the update's first cycle
                os.kill(os.getpid(), signal.SIGINT)
            return results

        monkeypatch.setattr(lifetime_update, "simulate", simulate_then_ctrl_c)
        stopped = life(FOURBAR, folder, **settings)
        monkeypatch.undo()
        assert runs == ["success", "success"]
        assert stopped.status == "interrupted", stopped.message
        assert stopped.message.startswith("interrupted before cycles 3 to 4")
        assert stopped.table["cycles"].tolist() == [2]  # the settling only
    resumed = life(FOURBAR, folder, **settings, resume=True)
    assert resumed.status == "success"
    # The same runs from the same states: equal to the last bit, but for the wall times.
    columns = [c for c in whole.table.columns if c != "wall_s"]
    pd.testing.assert_frame_equal(resumed.table[columns], whole.table[columns], check_exact=True)
    pd.testing.assert_frame_equal(resumed.profiles, whole.profiles, check_exact=True)
    np.testing.assert_array_equal(resumed.final.wear["revolute"], whole.final.wear["revolute"])
    np.testing.assert_array_equal(resumed.final.y, whole.final.y)
    assert resumed.summary["wall_s"] > resumed.table["wall_s"].iloc[3]
    # The band's runs (beside the value's, where there are cores for them) stopped with it
    # and went on alike: the default bounds 0.5 % and 1 %.
    for name in ("band/0.5pct/life.csv", "band/1pct/life.csv", "life_band.csv"):
        parts, alone = (pd.read_csv(f / name) for f in (folder, tmp_path / "whole"))
        kept = [c for c in alone.columns if c != "wall_s"]
        pd.testing.assert_frame_equal(parts[kept], alone[kept], check_exact=True)


def test_resume_refuses_other_settings_and_empty_folders(tmp_path):
    life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, figures=False)
    with pytest.raises(jw.ModelError) as error:
        life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, max_change="2%", resume=True)
    [line] = error.value.problems
    assert line.startswith("max_change: '2%' differs from the '0.25%'")
    with pytest.raises(jw.ModelError, match=r"^max_growth: 0.5 differs from the 1.0"):
        life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, max_growth=0.5, resume=True)
    with pytest.raises(jw.ModelError) as error:
        life(FOURBAR, tmp_path, cycles=3, resume=True)
    assert error.value.problems[0].startswith("model: the model (after --set) differs")
    with pytest.raises(jw.ModelError) as error:
        life(FOURBAR, tmp_path / "empty", cycles=3, resume=True)
    assert "holds no life run to resume" in error.value.problems[0]


def test_a_stop_asked_as_the_last_update_ends_does_not_undo_success(tmp_path):
    def ctrl_c_at_the_end(cycles: int, total: int) -> None:
        if cycles == total:
            os.kill(os.getpid(), signal.SIGINT)

    res = life(FOURBAR, tmp_path, cycles=4, overrides=FAST_WEAR, figures=False,
               progress=ctrl_c_at_the_end)  # fmt: skip
    assert (res.status, res.summary["cycles_reached"]) == ("success", 4)


@pytest.mark.parametrize(
    ("file", "damage"),
    [
        ("checkpoint/checkpoint.json", b"[]"),
        ("checkpoint/checkpoint.json", b'{"update": 1}'),
        ("checkpoint/state_000001.npz", b"PK\x03\x04 cut short"),
        ("life.csv", b""),
        ("life.csv", b"update,cycles,simulated_cycles\n0,2,2\n"),
    ],
    ids=["not-a-record", "keys-missing", "state-cut-short", "table-emptied", "older-columns"],
)
def test_a_damaged_run_is_a_one_line_error_on_resume(tmp_path, file, damage):
    life(FOURBAR, tmp_path, cycles=4, overrides=FAST_WEAR, figures=False)
    assert (tmp_path / "checkpoint" / "state_000001.npz").is_file()
    (tmp_path / file).write_bytes(damage)
    with pytest.raises(jw.ModelError) as error:
        life(FOURBAR, tmp_path, cycles=4, overrides=FAST_WEAR, figures=False, resume=True)
    [line] = error.value.problems
    assert line.startswith(f"out: the life run in {tmp_path} is damaged and cannot be resumed")


def test_bad_settings_and_models_are_model_errors(tmp_path):
    with pytest.raises(jw.ModelError) as error:
        life(FOURBAR, tmp_path, cycles=0, measure_cycles=1.5, max_change="2 kg", max_growth=0,
             steady_tolerance=1.0, max_update_cycles=1)  # fmt: skip
    lines = error.value.problems
    assert [line.split(":")[0] for line in lines] == [
        "cycles",
        "measure_cycles",
        "max_update_cycles",
        "steady_tolerance",
        "max_change",
        "max_growth",
    ]
    assert "has units of mass; expected a length" in lines[4]
    for change in ("0%", "150%", "x%", "-1 um"):
        with pytest.raises(jw.ModelError, match="max_change: "):
            life(FOURBAR, tmp_path, cycles=10, max_change=change)
    with pytest.raises(jw.ModelError) as error:
        life(PENDULUM, tmp_path, cycles=10)
    assert [line.split(":")[0] for line in error.value.problems] == ["drivers", "joints"]
    polynomial = 'drivers.motor.function={type="polynomial", coefficients=[0.0, 1.0]}'
    with pytest.raises(jw.ModelError, match=r"^drivers\[0\]: a polynomial function of time"):
        life(FOURBAR, tmp_path, cycles=10, overrides=[polynomial])
    torque = (
        'forces=[{{type="torque", body="follower", torque={{type="harmonic", amplitude=1.0, '
        'angular_frequency="{} rpm"}}}}]'
    )
    with pytest.raises(jw.ModelError, match=r"^forces\[0\]: its period 0.03 s does not divide"):
        life(FOURBAR, tmp_path, cycles=10, overrides=[torque.format(2000)])
    # A load twice as fast as the crank repeats within its turn.
    assert cycle_driver(jw.load_model(FOURBAR, [torque.format(3000)])) == ("motor", PERIOD)


def test_the_clearance_limit_stops_the_run_honestly(tmp_path):
    # 20 % growth at most: the settling turns and a few updates, then the stop, before the
    # update that would pass it (the folder keeps everything up to there).
    res = life(FOURBAR, tmp_path, cycles=10**6, overrides=FAST_WEAR, max_growth=0.2)
    assert res.status == "clearance_limit"
    assert "of the nominal 200 µm, between cycles" in res.message
    assert "past max_growth 0.2." in res.message
    joint = res.summary["clearance_joints"]["coupler_follower"]
    assert 0.1 < joint["clearance_growth_fraction"] <= 0.2
    assert res.summary["cycles_reached"] < 10**6
    assert (tmp_path / "figures" / "life_wear.png").is_file()
    assert (tmp_path / "figures" / "life_profiles.png").is_file()
    # A larger limit may be given on --resume: the run goes on as if it had been given at
    # the start, and its next update is the one that passed 20 %.
    settings = {"cycles": 10**6, "overrides": FAST_WEAR, "max_growth": 0.3, "figures": False}
    resumed = life(FOURBAR, tmp_path, **settings, resume=True)
    whole = life(FOURBAR, tmp_path / "whole", **settings)
    assert resumed.status == whole.status == "clearance_limit"
    columns = [c for c in whole.table.columns if c != "wall_s"]
    pd.testing.assert_frame_equal(resumed.table[columns], whole.table[columns], check_exact=True)
    growth = whole.table["coupler_follower.clearance_growth_m"].to_numpy() / 200e-6
    stop = len(res.table)
    assert growth[stop - 1] <= 0.2 < growth[stop] <= 0.3


def test_a_fresh_run_that_dies_at_its_start_leaves_no_checkpoint_to_resume(tmp_path, monkeypatch):
    life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, figures=False)

    def die(*args, **kwargs):
        raise Crash

    monkeypatch.setattr(lifetime_files, "save_checkpoint", die)
    with pytest.raises(Crash):  # the earlier run's files are gone, the new checkpoint unwritten
        life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, figures=False)
    monkeypatch.undo()
    with pytest.raises(jw.ModelError, match="holds no life run to resume"):
        life(FOURBAR, tmp_path, cycles=3, overrides=FAST_WEAR, resume=True)


def test_a_journal_worn_through_stops_the_run(tmp_path):
    # The rotor on a 0.5 mm pin, worn fast (k = 1e-9 1/Pa): the turning journal loses
    # share k F v T / (2 pi R_J L) = 25 µm a turn all round (v = omega R_J), through its
    # radius after 20 turns.
    thin = ROTOR.replace(f"bearing_radius = {R_B}", "bearing_radius = 0.0007")
    thin = thin.replace(f"journal_radius = {R_J}", "journal_radius = 0.0005")
    thin = thin.replace(f"wear_coefficient = {K_WEAR}", "wear_coefficient = 1e-9")
    (tmp_path / "thin.toml").write_text(thin)
    # Without feedback: at this rate the wear fed back after every step makes the steps tiny.
    res = life(tmp_path / "thin.toml", tmp_path / "out", cycles=1000, max_change="50%",
               max_growth=100.0, feedback=False, figures=False)  # fmt: skip
    assert res.status == "worn_through"
    found = re.fullmatch(
        r"gap: the journal would be worn ([\d.]+) mm deep between cycles (\d+) and (\d+), "
        r"through its radius 0\.5 mm",
        res.message,
    )
    assert found, res.message
    depth, first, last = float(found[1]), int(found[2]), int(found[3])
    assert depth >= 0.5
    assert first < 0.0005 / 25e-6 <= last  # the update that reaches turn 20 stopped the run
    depth = res.summary["clearance_joints"]["gap"]["max_wear_depth_journal_m"]
    assert depth == pytest.approx(first * 25e-6, rel=0.05)  # the landing's turns aside
    assert res.summary["cycles_reached"] < 20


def invoke(*args: object):
    return CliRunner().invoke(app, [str(a) for a in args])


def test_cli_life_writes_the_folder(tmp_path):
    result = invoke("life", FOURBAR, "--cycles", 12, "--out", tmp_path, "--set", FAST_WEAR[0],
                    "--max-change", "4%")  # fmt: skip
    assert result.exit_code == 0, result.output
    assert result.output.startswith("success: reached 12 cycles; 12 cycles in ")
    assert "coupler_follower: max wear depth journal" in result.output
    for name in ("life.csv", "profiles.csv", "summary.json", "model.json",
                 "figures/life_wear.png", "figures/life_profiles.png",
                 "checkpoint/checkpoint.json"):  # fmt: skip
        assert (tmp_path / name).is_file(), name
    summary = json.loads((tmp_path / "summary.json").read_text())
    table = pd.read_csv(tmp_path / "life.csv")
    assert summary["updates"] == table["update"].iloc[-1] and summary["cycles_reached"] == 12
    # Hours of operation: crank turns of 40 ms.
    np.testing.assert_allclose(table["hours"], table["cycles"] * PERIOD / 3600, rtol=1e-12)
    assert summary["hours_reached"] == pytest.approx(12 * PERIOD / 3600, rel=1e-12)
    assert f"{12 * PERIOD / 3600:.3g} hours of operation" in result.output
    profiles = pd.read_csv(tmp_path / "profiles.csv")
    assert len(profiles) == len(table) * 2 * 36
    again = invoke("life", FOURBAR, "--cycles", 12, "--out", tmp_path, "--set", FAST_WEAR[0],
                   "--max-change", "4%", "--resume")  # fmt: skip
    assert again.exit_code == 0, again.output
    assert (
        pd.read_csv(tmp_path / "life.csv")
        .drop(columns="wall_s")
        .equals(table.drop(columns="wall_s"))
    )


def test_cli_life_exit_codes(tmp_path):
    bad = invoke("life", FOURBAR, "--cycles", 10, "--out", tmp_path, "--max-change", "2 kg")
    assert bad.exit_code == 2
    assert bad.output.startswith("max_change: '2 kg' has units of mass")
    assert "Traceback" not in bad.output
    stopped = invoke("life", FOURBAR, "--cycles", 10**6, "--out", tmp_path, "--set",
                     FAST_WEAR[0], "--max-growth", 0.05, "--no-figures")  # fmt: skip
    assert stopped.exit_code == 1
    assert stopped.output.startswith("clearance_limit: coupler_follower: the effective clearance")
    assert not (tmp_path / "figures").exists()
    # An earlier run's figures do not stay beside a new run's tables.
    (tmp_path / "figures").mkdir()
    write_text(tmp_path / "figures" / "life_wear.png", "an earlier run's")
    again = invoke("life", FOURBAR, "--cycles", 2, "--out", tmp_path, "--no-figures")
    assert again.exit_code == 0, again.output
    assert not (tmp_path / "figures" / "life_wear.png").exists()
    # A file of the user's of that name is never replaced: the run is refused before it starts.
    (tmp_path / "figures" / "life_wear.png").write_bytes(b"the user's")
    refused = invoke("life", FOURBAR, "--cycles", 2, "--out", tmp_path)
    assert refused.exit_code == 2
    assert "life_wear.png exists and was not written by jointwear" in refused.output
    assert (tmp_path / "figures" / "life_wear.png").read_bytes() == b"the user's"


def test_sweep_of_life_runs_tabulates_their_summaries(tmp_path):
    vary = {"joints.coupler_follower.clearance.wear_coefficient": ["4e-13 1/Pa", "8e-13 1/Pa"]}
    results = sweep(FOURBAR, tmp_path, vary=vary, cycles=4, workers=1, figures=False)
    table = results.table
    assert table["status"].tolist() == ["success", "success"]
    assert table["cycles_reached"].tolist() == [4, 4]
    growth = table["coupler_follower.clearance_growth_m"].to_numpy()
    # Twice the coefficient, twice the wear (the worn profiles barely change the dynamics in
    # 4 turns): 2 to 1 %.
    assert growth[1] / growth[0] == pytest.approx(2.0, rel=1e-2)
