"""Laws registered from Python (``jointwear.register_law``) against their built-in twins.

The independent answer is the built-in law: a user's re-implementation (examples/user_laws.py,
written from the papers' formulas) must give its results. Each twin's arithmetic is the
built-in law's, operation for operation, so the runs agree to the last bit; the elastic
energy, which the user Hertz law leaves to quadrature, agrees to round-off (12-point
Gauss-Legendre is exact for K delta^1.5, whose integrand is a polynomial in t after
s = delta t^2).
"""

import importlib.util
import math
import os
import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from numba import njit
from typer.testing import CliRunner

import jointwear as jw
from jointwear.cli import app
from jointwear.engine.user_laws import user_tables
from jointwear.kernels.laws.dispatch import USER_CODE
from jointwear.kernels.laws.user import UserLaws
from jointwear.model import ModelError
from jointwear.model.laws import user as records

ROOT = Path(__file__).parents[1]
FOURBAR = ROOT / "examples" / "flores2009_fourbar.toml"


def _example(name: str) -> object:
    """An example script as a module that is not importable by name (as a notebook's code).

    So numba pickles its functions by value, and a Dask worker gets them with the cases.
    """
    spec = importlib.util.spec_from_file_location(name, ROOT / "examples" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


TWINS = _example("user_laws")
TWIN_KEYS = TWINS.KEYS
PAPER_WEAR = 'wear_coefficient = "8e-14 1/Pa"     # Archard, dimensional\n'
T_END = 0.05  # [s]: two crank turns, four impacts and the sliding after them
CLEARANCE = "joints.coupler_follower.clearance"


@pytest.fixture(scope="module", autouse=True)
def twins():
    """The user twins, registered for this module's tests only."""
    TWINS.register()
    yield
    TWINS.unregister()


def fourbar_text(laws: dict[str, str], keys: dict[str, str]) -> str:
    """The paper's four-bar with its clearance joint's laws and keys replaced."""
    text = FOURBAR.read_text()
    assert PAPER_WEAR in text
    lines = [f'{key} = "{value}"' for key, value in {**laws, **keys}.items()]
    return text.replace(PAPER_WEAR, "\n".join(lines) + "\n")


def parse(text: str) -> jw.Model:
    """The model of a model file's text."""
    return jw.parse_model(tomllib.loads(text))


USER_LAWS = {family: twin for family, (_, twin) in TWINS.LAWS.items()}


@pytest.fixture(scope="module")
def fourbar_runs(tmp_path_factory):
    """The four-bar with the built-in laws (simulate) and with their twins (run)."""
    folder = tmp_path_factory.mktemp("twins")
    path = folder / "twins.toml"
    path.write_text(fourbar_text(USER_LAWS, TWIN_KEYS))
    built_in = jw.simulate(jw.load_model(FOURBAR).with_values({"solver.t_end": T_END}))
    twins = jw.run(path, folder / "out", overrides=[f"solver.t_end={T_END}"], figures=False)
    assert built_in.status == twins.status == "success", twins.message
    return built_in, twins, folder


def assert_same_run(a: pd.DataFrame, b: pd.DataFrame, what: str = "") -> None:
    """The same time series, to the bit but the contact energy (to round-off, 1e-13)."""
    energy = "energy_contact"
    pd.testing.assert_frame_equal(
        a.drop(columns=energy), b.drop(columns=energy), check_exact=True, obj=what
    )
    np.testing.assert_allclose(b[energy], a[energy], rtol=1e-13, atol=1e-13 * a[energy].max())


def test_the_twins_give_the_built_in_laws_results(fourbar_runs):
    built_in, twins, _ = fourbar_runs
    a, b = built_in.timeseries, twins.timeseries
    assert a["coupler_follower_fn"].max() > 1e4  # impacts, and sliding under load
    assert_same_run(a, b)
    assert twins.summary["clearance_joints"] == built_in.summary["clearance_joints"]
    assert twins.wear.equals(built_in.wear)


def test_each_family_alone_gives_the_built_in_results():
    """One twin at a time: a row mixing built-in and user laws dispatches each by its code."""
    model = jw.load_model(FOURBAR).with_values({"solver.t_end": 0.02})
    reference = jw.simulate(model).timeseries
    for family, name in USER_LAWS.items():
        changes = {f"{CLEARANCE}.{family}": name}
        if family == "friction_law":
            changes |= {
                f"{CLEARANCE}.{key}": TWIN_KEYS[key] for key in ("still_speed", "full_speed")
            }
        if family == "wear_law":
            changes |= {f"{CLEARANCE}.wear_coefficient": None,
                        f"{CLEARANCE}.archard_k": TWIN_KEYS["archard_k"]}  # fmt: skip
        assert_same_run(reference, jw.simulate(model.with_values(changes)).timeseries, family)


def test_a_model_without_user_laws_keeps_the_built_in_tables():
    """No row with a user law: every kind gets none, and compiles the built-in dispatch."""
    tables = user_tables(jw.load_model(FOURBAR))
    assert all(t is None for t in tables.values())
    twin = parse(fourbar_text(USER_LAWS, TWIN_KEYS))
    tables = user_tables(twin)
    assert isinstance(tables["revolute"], UserLaws)
    assert tables["translational"] is None
    assert (tables["revolute"].address[0] != 0).sum() == 5  # force, chi, friction, sliding, wear
    np.testing.assert_array_equal(tables["revolute"].params[0, 2, :2], [1e-4, 1e-2])


def test_results_of_a_user_law_load_while_it_is_registered(fourbar_runs):
    _, twins, folder = fourbar_runs
    again = jw.load_results(folder / "out")
    assert again.model == twins.model
    records.unregister("user_archard")
    try:
        with pytest.raises(ModelError) as error:
            jw.load_results(folder / "out")
        assert str(error.value).startswith(
            "joints[2].clearance.wear_law: unknown wear law 'user_archard'; known wear laws are "
            "archard, reye"
        )
        assert "jointwear.register_law" in str(error.value)
    finally:
        TWINS.register()


def test_check_lists_a_user_law_with_its_keys(tmp_path):
    path = tmp_path / "twins.toml"
    path.write_text(fourbar_text(USER_LAWS, {**TWIN_KEYS, "still_speed": "0.1 mm/s"}))
    result = CliRunner().invoke(app, ["check", str(path)], env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    for text in (
        "user_ambrosio",
        "still_speed",
        "0.0001",
        "m/s",
        "user_hertz: K delta^n, as hertz",
    ):
        assert text in result.output
    # The stiffness by central difference, against hertz's K n delta^(n - 1).
    built_in = jw.load_model(FOURBAR).joint("coupler_follower").clearance
    twin = parse(path.read_text()).joint("coupler_follower").clearance
    for delta in (1e-6, 2e-5):
        force, slope = twin.elastic_force(delta)
        assert (force, slope) == pytest.approx(built_in.elastic_force(delta), rel=1e-8)


# Life runs and sweeps -------------------------------------------------------------------------


def test_a_life_run_with_a_user_wear_law_wears_as_archard(tmp_path):
    """The pressed rotor of test_lifetime, its Archard law given as a user law."""
    from test_lifetime import DAMPING, DELTA, FORCE, K_WEAR, OMEGA, ROTOR, ROTOR_PERIOD, C

    text = ROTOR.replace(
        f"wear_coefficient = {K_WEAR}", f'wear_law = "user_archard"\narchard_k = {K_WEAR}'
    )
    path = tmp_path / "rotor.toml"
    path.write_text(text)
    cycles = 1000
    res = jw.life(path, tmp_path / "life", cycles=cycles, max_change="4 um", feedback=False,
                  figures=False)  # fmt: skip
    assert res.status == "success", res.message
    exact = K_WEAR * OMEGA * 0.0098 * (FORCE * cycles * ROTOR_PERIOD - DAMPING * (C + DELTA))
    assert res.table["gap.worn_volume_m3"].iloc[-1] == pytest.approx(exact, rel=1e-6)


def test_a_sweep_runs_user_laws_in_local_processes_and_on_dask(tmp_path):
    """The laws travel with the cases: workers that registered nothing run them."""
    distributed = pytest.importorskip("dask.distributed")
    path = tmp_path / "twins.toml"
    path.write_text(fourbar_text(USER_LAWS, TWIN_KEYS))
    vary = {f"{CLEARANCE}.friction_coefficient": [0.05, 0.1]}
    settings = {"vary": vary, "overrides": ["solver.t_end=0.01"], "figures": False}
    built_in = jw.sweep(FOURBAR, tmp_path / "built_in", workers=1, **settings)
    local = jw.sweep(path, tmp_path / "local", workers=2, **settings)
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
        dashboard_address=None,
    ) as cluster, distributed.Client(cluster) as client:  # fmt: skip
        worker = next(iter(client.run(os.getpid).values()))
        assert worker != os.getpid()
        on_dask = jw.sweep(path, tmp_path / "dask", scheduler=cluster.scheduler_address, **settings)
    walls = ["wall_s", "simulation_wall_s"]
    expected = built_in.table.drop(columns=walls)
    for results in (local, on_dask):
        assert results.failed == []
        pd.testing.assert_frame_equal(results.table.drop(columns=walls), expected, check_exact=True)


# What users get wrong ------------------------------------------------------------------------


@njit
def _chi(c_e):
    return 0.5 * (1.0 - c_e)


@njit
def _friction(v_t, f_n, c_f, speed):
    return -c_f * f_n * math.tanh(v_t / speed)


def _plain(c_e):
    return 0.5 * (1.0 - c_e)


@njit
def _pair(mu):
    return (mu, mu)


@pytest.mark.parametrize(
    ("family", "name", "function", "options", "error", "words"),
    [
        ("lubrication", "mine", _chi, {}, ValueError,
         "family: 'lubrication' cannot have laws registered from Python"),
        ("damping", "hunt_crossley", _chi, {}, ValueError,
         "'hunt_crossley' is the name of a built-in law (damping)"),
        ("friction", "coulomb", _friction, {"keys": {"speed": "m/s"}}, ValueError,
         "'coulomb' is the name of a built-in law (friction_law)"),
        ("damping", "Mine", _chi, {}, ValueError, "is not a law name"),
        ("damping", "mine", _plain, {}, TypeError,
         "its hysteresis function '_plain' is not compiled; decorate it with @numba.njit"),
        ("friction", "mine", _friction, {"keys": {"speed": None}}, ValueError,
         "key 'speed' has no unit; give its SI unit"),
        ("friction", "mine", _friction, {"keys": ["speed"]}, ValueError,
         "keys must map each key's name to its SI unit"),
        ("friction", "mine", _friction, {"keys": {"speed": "mm/s"}}, ValueError,
         "'mm/s', which is 0.001 of the SI unit; declare the SI unit"),
        ("friction", "mine", _friction, {"keys": {"speed": "blorps"}}, ValueError,
         "'blorps', which cannot be read"),
        ("friction", "mine", _friction, {}, TypeError,
         "it must take 3: v_t, f_n, c_f (the family's arguments, then the law's keys"),
        ("friction", "mine", _friction, {"keys": {"width": "m"}}, ValueError,
         "key 'width' is a key of the clearance tables or of the built-in laws"),
        ("friction", "mine", _friction, {"keys": {"speed": "m/s"}, "energy": _chi},
         ValueError, "no energy function for this family; it takes force, sliding"),
        ("wear", "mine", _pair, {}, TypeError, "_pair does not compile to a float"),
        ("damping", "user_hertz", _chi, {}, ValueError,
         "'user_hertz' is already a normal_law registered from Python"),
    ],
)  # fmt: skip
def test_bad_registrations_say_what_is_wrong(family, name, function, options, error, words):
    with pytest.raises(error) as raised:
        jw.register_law(family, name, function, **options)
    assert words in str(raised.value)
    assert records.registered(name) is None or name == "user_hertz"


def test_a_key_declared_twice_must_agree():
    jw.register_law("friction", "tanh_friction", _friction, keys={"speed": "m/s"})
    try:
        with pytest.raises(ValueError, match="key 'speed' is a key of friction_law 'tanh_fr"):
            jw.register_law("damping", "speedy", njit(lambda c_e, speed: c_e), keys={"speed": ""})
        jw.register_law("damping", "speedy", njit(lambda c_e, speed: c_e), keys={"speed": "m/s"})
        jw.unregister_law("speedy")
    finally:
        jw.unregister_law("tanh_friction")
    with pytest.raises(KeyError, match="no law registered as 'tanh_friction'"):
        jw.unregister_law("tanh_friction")


@pytest.mark.parametrize(
    ("keys", "line"),
    [
        ({"still_speed": "1e-4 m/s"},
         "friction_law 'user_ambrosio': needs full_speed"),
        ({**TWIN_KEYS, "stil_speed": "1 m/s"},
         "unknown key 'stil_speed'; known keys are"),
        ({**TWIN_KEYS, "still_speed": "3 kg"},
         "joints[2].clearance.still_speed: '3 kg' has units of mass; expected a speed"),
        ({**TWIN_KEYS, "regularisation_speed": "1 mm/s"},
         "regularisation_speed is used by friction_law 'coulomb' only"),
    ],
)  # fmt: skip
def test_a_model_file_checks_user_keys_as_it_checks_built_in_ones(keys, line):
    with pytest.raises(ModelError) as error:
        parse(fourbar_text(USER_LAWS, keys))
    assert line in str(error.value)
    if "stil_speed" in line:
        assert "(did you mean 'still_speed'?)" in str(error.value)


def test_a_user_key_of_a_law_not_chosen_is_refused():
    laws = {**USER_LAWS, "friction_law": "ambrosio"}
    with pytest.raises(ModelError) as error:
        parse(fourbar_text(laws, TWIN_KEYS))
    assert (
        "still_speed is used by friction_law 'user_ambrosio' only, and this joint's "
        "friction_law is 'ambrosio'; remove it or choose another friction_law"
    ) in str(error.value)


def test_user_keys_are_read_in_any_unit_and_kept_in_si():
    model = parse(fourbar_text(USER_LAWS, {**TWIN_KEYS, "still_speed": "0.36 km/h"}))
    clearance = model.joint("coupler_follower").clearance
    law = clearance.chosen_laws()[2][1]
    assert law.code >= USER_CODE
    assert clearance.law_values(law)["still_speed"] == pytest.approx(0.1)
    assert model.model_dump()["joints"][2]["clearance"]["still_speed"] == pytest.approx(0.1)


def test_a_user_law_that_raises_stops_the_run_as_non_finite():
    @njit
    def fragile(v_t, f_n, c_f):
        if abs(v_t) > 0.5:
            raise ValueError("too fast")
        return -c_f * f_n * v_t

    jw.register_law("friction", "fragile", fragile)
    try:
        model = jw.load_model(FOURBAR).with_values(
            {"solver.t_end": 0.02, f"{CLEARANCE}.friction_law": "fragile"}
        )
        res = jw.simulate(model)
    finally:
        jw.unregister_law("fragile")
    assert res.status == "non_finite"
    assert "non-finite" in res.message


def test_the_kernel_and_record_constants_agree():
    from jointwear.kernels.laws import dispatch
    from jointwear.kernels.laws import user as kernel

    assert records.USER_CODE == dispatch.USER_CODE
    assert records.N_KEYS == kernel.N_KEYS
    arities = {len(role.arguments) for roles in records.ROLES.values() for role in roles}
    assert max(arities) == kernel.ARGUMENTS


def test_a_model_with_user_laws_round_trips_through_to_toml(tmp_path):
    model = parse(fourbar_text(USER_LAWS, {**TWIN_KEYS, "still_speed": "0.2 mm/s"}))
    model.to_toml(tmp_path / "again.toml")
    again = jw.load_model(tmp_path / "again.toml")
    assert again == model
    assert again.joint("coupler_follower").clearance.model_extra["still_speed"] == 2e-4
