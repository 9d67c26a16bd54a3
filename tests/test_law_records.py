"""The law records: every code reaches its own kernel function, an unknown code the error value.

Each family's dispatchers are evaluated through the dispatch and through the function the
record names, at a few sample points; the two must agree exactly, and the laws of a family
must differ at those points (so that a dispatch that reached another law would be seen).
"""

import math
from pathlib import Path

import numpy as np
import pytest
from numba import njit

import jointwear as jw
from jointwear.citations import REFERENCES
from jointwear.film.impedance import impedance_table
from jointwear.joints.revolute.schema import RevoluteClearance as Clearance
from jointwear.kernels.laws.lawset import LawSet
from jointwear.kernels.laws.user import COMPILED, kind_laws
from jointwear.model.clearance import _KEY_TYPES
from jointwear.model.laws import EVERY, NORMAL
from jointwear.model.laws.record import ECCENTRICITY, HERTZ_PATCH, PENETRATION, SHAPES, resolve

FOURBAR = Path(__file__).parents[1] / "examples" / "flores2009_fourbar.toml"
# Sample values of every dispatcher argument, three points each. The friction speeds put
# v_t below v0 (Ambrosio sticks), between v0 and dv (stick-slip sticks) and above both.
SAMPLES = {
    "delta": (2e-6, 2e-5, 9e-5), "k": (1e10, 2e10, 3e10), "n": (1.5, 1.5, 1.2),
    "e_star": (1.137e11, 1e11, 7e10), "d_r": (2e-4, 2e-4, 1e-4), "width": (0.02, 0.01, 0.03),
    "c_e": (0.9, 0.6, 0.3),
    "v_t": (5e-4, 5e-3, -0.5), "f_n": (100.0, 250.0, 1e3), "c_f": (0.1, 0.2, 0.3),
    "p0": (1e-3, 1e-3, 1e-3), "p1": (1e-2, 1e-2, 1e-2), "p2": (2e-2, 2e-2, 2e-2),
    "mu": (0.1, 0.2, 0.3),
    "eps": (0.3, 0.5, 0.8), "eps_dot": (0.1, -2.0, 5.0), "gamma_dot": (1.0, -3.0, 10.0),
    "w": (100.0, 50.0, -20.0), "r": (0.01, 0.02, 0.01), "c": (1e-4, 2e-4, 5e-5),
    "table": (impedance_table(1.0),) * 3,  # the finite bearing's, L / D = 1
}  # fmt: skip
POINTS = range(3)
DISPATCHED = [family for family in EVERY if family.dispatchers]


def arguments(dispatcher) -> tuple[str, ...]:
    """The dispatcher's argument names after the code."""
    return dispatcher.arguments


def through_dispatch(dispatcher, code: int) -> list:
    names = arguments(dispatcher)
    return [dispatcher(code, *(SAMPLES[n][i] for n in names)) for i in POINTS]


def as_floats(values: list) -> np.ndarray:
    return np.array(values, dtype=float).reshape(len(values), -1)


@pytest.mark.parametrize("family", DISPATCHED, ids=lambda f: f.key)
def test_every_code_reaches_its_own_function(family):
    for position, name in enumerate(family.dispatchers):
        dispatcher = resolve(name)
        seen = {}
        for law in (law for law in family.laws if law.kernels):
            kernel = law.kernels[position]
            assert set(kernel.arguments) <= set(arguments(dispatcher)), kernel
            function = kernel.resolve()
            direct = [function(*(SAMPLES[n][i] for n in kernel.arguments)) for i in POINTS]
            got = as_floats(through_dispatch(dispatcher, law.code))
            assert np.isfinite(got).all(), (name, law.name, got)
            np.testing.assert_array_equal(got, as_floats(direct), err_msg=f"{name} {law.name}")
            seen[law.name] = got
        for a, b in ((a, b) for a in seen for b in seen if a < b):  # the check has power
            assert not np.array_equal(seen[a], seen[b]), f"{name}: {a} and {b} agree"


@pytest.mark.parametrize("family", DISPATCHED, ids=lambda f: f.key)
def test_a_code_without_a_law_gives_the_error_value(family):
    """An unknown code, and a law that is the absence of one (a dry joint), give NaN."""
    codes = [-1, len(family.laws), 99, *(law.code for law in family.laws if not law.kernels)]
    for name in family.dispatchers:
        for code in codes:
            assert np.isnan(as_floats(through_dispatch(resolve(name), code))).all(), (name, code)


def _compiled_call(stub):
    """``stub(laws, 0, code, *arguments)`` compiled (a fresh harness per dispatcher)."""

    @njit
    def call(laws, code, arguments):
        return stub(laws, 0, code, *arguments)

    return call


@pytest.mark.parametrize("entry", COMPILED, ids=lambda e: e[0].__name__)
def test_the_compiled_dispatch_reaches_the_same_law_and_only_the_codes_used(entry):
    """Compiled for all of a family's codes, each code gives what the table's law gives;
    with every law on demand and one used, every other code gives the error value (its
    branch is not there).
    """
    stub, dispatch, _ = entry
    call = _compiled_call(stub)
    codes = tuple(dispatch.laws)
    no_user = kind_laws(np.zeros((1, 0), dtype=np.int64), {}, None)
    for used in (codes, *((code,) for code in codes)):
        law_set = LawSet({dispatch.family: used}, {dispatch.family: codes})
        laws = no_user._replace(used=law_set)
        for code, i in ((code, i) for code in codes for i in POINTS):
            values = tuple(SAMPLES[n][i] for n in dispatch.arguments)
            got = as_floats([call(laws, code, values)])
            want = as_floats([dispatch(code if code in used else -1, *values)])
            np.testing.assert_array_equal(got, want, err_msg=f"{stub.__name__} {code} {used}")


@pytest.mark.parametrize("family", EVERY, ids=lambda f: f.key)
def test_every_record_is_complete(family):
    assert [law.code for law in family.laws] == list(range(len(family.laws)))
    assert family.default in family.by_name
    assert len(family.by_name) == len(family.laws)
    for law in family.laws:
        assert len(law.kernels) in (0, len(family.dispatchers)), law.name
        assert law.summary and set(law.citations) <= set(REFERENCES), law.name
        assert law.shapes and set(law.shapes) <= set(SHAPES), law.name
        assert all(key.unit in _KEY_TYPES for key in law.keys), law.name
        key_names = {key.name for key in law.keys}
        for name, limit in law.ranges:
            assert name in (PENETRATION, HERTZ_PATCH, ECCENTRICITY), (law.name, name)
            assert limit in key_names if isinstance(limit, str) else 0.0 < limit < 1.0
        if law.stiffness is not None:
            assert law.stiffness.given_by in (None, *key_names)
            assert set(law.stiffness.citations) <= set(SHAPES)


def test_the_elastic_laws_stiffness_and_energy_follow_from_their_force():
    """An independent check of the three elastic dispatchers: dF/d(delta) and U = int F."""
    force, stiffness, energy = (resolve(n) for n in NORMAL.dispatchers)
    args = (1e10, 1.5, 1.137e11, 2e-4, 0.02)
    for law in NORMAL.laws:
        delta, h = 3e-5, 1e-9
        slope = (force(law.code, delta + h, *args) - force(law.code, delta - h, *args)) / (2 * h)
        # central difference: error h^2 F''' / 6, about 1e-8 of the slope here
        assert stiffness(law.code, delta, *args) == pytest.approx(slope, rel=1e-6), law.name
        steps = np.linspace(0.0, delta, 2001)
        values = [force(law.code, x, *args) for x in steps]
        # trapezoid rule on F ~ delta^1.5: error below 1e-6 of U with 2000 cells
        area = float(np.trapezoid(values, steps))
        assert energy(law.code, delta, *args) == pytest.approx(area, rel=1e-6), law.name
    assert math.isnan(force(len(NORMAL.laws), 1e-5, *args))


@pytest.mark.parametrize("family", ["normal_law", "damping", "friction_law", "wear_law"])
def test_an_unknown_code_stops_a_run_as_non_finite(monkeypatch, family):
    """A law code without a branch reaches the step loop as NaN, which the run catches."""
    chosen = Clearance.chosen_laws

    def unknown(self):
        return [(f, law._replace(code=99) if f.key == family else law) for f, law in chosen(self)]

    monkeypatch.setattr(Clearance, "chosen_laws", unknown)
    result = jw.simulate(jw.load_model(FOURBAR, ["solver.t_end=0.005"]))  # in contact at once
    assert result.status == "non_finite", result.message
