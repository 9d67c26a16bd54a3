"""Removing a key: ``--set path=``, an extending file's ``unset``, ``with_values`` with None;
and Archard's K with the hardness H in place of k = K / H."""

import numpy as np
import pytest
from runs import EXAMPLES
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app

FOURBAR = EXAMPLES / "flores2009_fourbar.toml"
WEAR = "joints.coupler_follower.clearance"
K, H = 2e-4, 2.5e9  # Archard's dimensionless K and a hardened steel's H [Pa]: k = 8e-14 1/Pa


def test_set_with_nothing_after_the_equals_sign_removes_the_key():
    model = jw.load_model(FOURBAR, ["solver.formulation=", "forces.0="])
    assert model.solver.formulation == "augmented_lagrangian"  # the default; the file's baumgarte
    assert model.forces == ()  # an array item is removed by its index (or name)
    assert jw.load_model(FOURBAR, ['description=""']).description == ""  # an empty string


def test_removing_a_key_that_is_not_there_names_the_path():
    with pytest.raises(jw.ModelError) as caught:
        jw.load_model(FOURBAR, ["solver.rtool="])
    assert caught.value.problems == [
        "solver.rtool: no key 'rtool' to remove; the keys there are integrator, formulation, "
        "t_end, output_interval, wear_snapshot_interval"
    ]
    with pytest.raises(jw.ModelError) as caught:
        jw.load_model(FOURBAR, [f"{WEAR}.lubricant.viscosity="])
    assert caught.value.problems[0].startswith(
        f"{WEAR}.lubricant: no key 'lubricant' to remove; the keys there are bearing_radius"
    )
    with pytest.raises(jw.ModelError, match=r"forces.wind: no item 'wind'"):
        jw.load_model(FOURBAR, ["forces.wind="])


def test_the_command_line_removes_a_key():
    result = CliRunner().invoke(app, ["check", str(FOURBAR), "--set", f"{WEAR}.sectors="])
    assert result.exit_code == 0, result.output
    result = CliRunner().invoke(app, ["check", str(FOURBAR), "--set", f"{WEAR}.sector="])
    assert result.exit_code == 2
    assert f"{WEAR}.sector: no key 'sector' to remove" in result.output
    assert "(did you mean 'sectors'?)" in result.output


def test_with_values_none_removes_a_key():
    model = jw.load_model(FOURBAR)
    by_hardness = model.with_values(
        {
            f"{WEAR}.wear_coefficient": None,
            f"{WEAR}.dimensionless_wear_coefficient": K,
            f"{WEAR}.hardness": "2.5 GPa",
        }
    )
    clearance = by_hardness.joint("coupler_follower").clearance
    assert (clearance.wear_coefficient, clearance.hardness) == (None, H)
    with pytest.raises(jw.ModelError, match=f"{WEAR}.wear_coefficient: no key"):
        by_hardness.with_values({f"{WEAR}.wear_coefficient": None})  # not given any more


def extending_file(tmp_path, unset: str) -> str:
    path = tmp_path / "by_hardness.toml"
    path.write_text(
        f'extends = "{FOURBAR}"\n'
        f"{unset}\n"
        f"[set.{WEAR}]\n"
        f"dimensionless_wear_coefficient = {K!r}\n"
        'hardness = "2.5 GPa"\n'
    )
    return path


def test_an_extending_file_switches_to_k_and_hardness_and_wears_as_k_over_h(tmp_path):
    with pytest.raises(jw.ModelError, match="give wear_coefficient, or dimensionless_wear_"):
        jw.load_model(extending_file(tmp_path, ""))  # both ways: refused
    short = ["solver.t_end=0.01", "solver.wear_snapshot_interval=0.01"]
    path = extending_file(tmp_path, f'unset = ["{WEAR}.wear_coefficient"]')
    by_hardness = jw.simulate(jw.load_model(path, short))
    by_k = jw.simulate(jw.load_model(FOURBAR, [*short, f"{WEAR}.wear_coefficient={K / H!r}"]))
    assert by_hardness.status == by_k.status == "success"
    depth, expected = by_hardness.wear["depth_m"].to_numpy(), by_k.wear["depth_m"].to_numpy()
    assert expected.max() > 0.0
    np.testing.assert_allclose(depth, expected, rtol=1e-12, atol=1e-12 * expected.max())
