"""The registry of joint types with clearance: every kind gives what the rest of the code asks.

The rest of jointwear reaches a kind only through ``jointwear.joints.KINDS`` and the kernels'
fan-out (``kernels.elements``), so these check that both sides list the same kinds in the same
order, that each kind's compiled module and its Python side keep the contract of
``joints/kind.py``, and that a run's restart state round-trips per kind.
"""

import inspect
from importlib import import_module

import numpy as np
import pytest

from jointwear.engine.integrators import INTEGRATORS, make_integrator
from jointwear.joints import KINDS, TOTALS
from jointwear.kernels.codes import Method
from jointwear.kernels.elements import KERNELS, ElementLog, Elements, ElementScratch, ElementState
from jointwear.results.run_state import FIELDS, RunState, load_run_state

KERNEL_TOTALS = {  # TOTALS' names as each kernel spells its T_ constants
    "contact_time": "T_CONTACT_TIME",
    "max_fn": "T_MAX_FN",
    "max_delta": "T_MAX_DELTA",
    "impacts": "T_IMPACTS",
    "damping_energy": "T_DAMPING_ENERGY",
    "friction_energy": "T_FRICTION_ENERGY",
    "worn_volume": "T_WORN_VOLUME",
    "sliding": "T_SLIDING",
}


def test_both_sides_list_the_same_kinds_in_the_same_order():
    names = [kind.kernel for kind in KINDS]
    for table in (Elements, ElementState, ElementLog, ElementScratch):
        assert list(table._fields) == names
    assert [module.__name__.rsplit(".", 1)[1] for module in KERNELS] == names
    assert len({kind.name for kind in KINDS}) == len(KINDS)


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: k.name)
def test_each_kernel_keeps_the_common_totals_and_the_interface(kind):
    module = kind.module
    for name, index in TOTALS.items():
        assert getattr(module, KERNEL_TOTALS[name]) == index, name
    for constant in ("SLOTS", "N_INTS", "N_PARAMS", "N_IMPACT_INFO", "N_TOTALS",
                     "DEGREES_OF_FREEDOM"):  # fmt: skip
        assert isinstance(getattr(module, constant), int), constant
    _, state, log, _ = module.make_tables(
        np.zeros((2, module.N_INTS), dtype=np.int64), np.zeros((2, module.N_PARAMS)), 3
    )
    assert tuple(state._fields) == FIELDS
    assert state.contact_on.shape == state.impact_speed.shape == (2 * module.SLOTS,)
    assert state.wear.shape[0] == 2 and log.snapshots.shape[:2] == (3, 2)
    assert log.totals.shape == (2, module.N_TOTALS)
    for function in ("add_forces", "penetration_excess", "tolerance", "begin_period",
                     "accumulate", "write_outputs", "elastic_energy"):  # fmt: skip
        assert callable(getattr(module, function)), function


@pytest.mark.parametrize("kind", KINDS, ids=lambda k: k.name)
def test_each_kind_names_its_figures_and_animation(kind):
    figures = import_module(kind.figures_module)
    for _, function in kind.figures:
        assert callable(getattr(figures, function)), function
    assert "folder" in inspect.signature(figures.save_figures).parameters
    assert set(kind.figures_with_ideal) <= {name for name, _ in kind.figures}
    drawing = import_module(kind.animation_module)
    assert callable(drawing.actor) and callable(drawing.title)
    assert kind.surfaces and kind.ideal_rows
    assert set(kind.peaks) >= {TOTALS["max_fn"], TOTALS["max_delta"]}


def test_a_run_state_round_trips_per_kind_and_reads_the_older_layout(tmp_path):
    contacts = {
        "revolute": {"contact_on": np.array([1, 0]), "impact_speed": np.array([0.1, 0.0]),
                     "wear": np.arange(12.0).reshape(2, 2, 3)},
        "translational": {"contact_on": np.zeros(8, dtype=np.int64),
                          "impact_speed": np.zeros(8), "wear": np.ones((1, 4, 5))},
    }  # fmt: skip
    state = RunState(time=0.5, y=np.arange(6.0), contacts=contacts)
    state.save(tmp_path / "state.npz")
    back = load_run_state(tmp_path / "state.npz")
    assert back.time == 0.5
    for kind, fields in contacts.items():
        for name, value in fields.items():
            np.testing.assert_array_equal(back.contacts[kind][name], value)
    worn = state.with_wear({"revolute": 2.0 * contacts["revolute"]["wear"]})
    np.testing.assert_array_equal(worn.wear["revolute"], 2.0 * contacts["revolute"]["wear"])
    with pytest.raises(ValueError, match=r"wear\['revolute'\] has shape"):
        state.with_wear({"revolute": np.zeros(3)})
    old = {"time": 1.0, "y": np.zeros(6), "wear": np.ones((1, 2, 4)),
           "contact_on": np.zeros(1), "impact_speed": np.zeros(1)}  # fmt: skip
    with open(tmp_path / "old.npz", "wb") as f:
        np.savez(f, **old)
    legacy = load_run_state(tmp_path / "old.npz")
    np.testing.assert_array_equal(legacy.wear["revolute"], old["wear"])
    assert legacy.contacts["revolute"]["contact_on"].dtype == np.int64


def test_the_integrators_come_from_a_registry_that_refuses_an_unknown_method():
    assert set(INTEGRATORS) == set(Method)
    for method in Method:
        state = make_integrator(method, 6)
        assert state.y.shape == (6,)
    with pytest.raises(ValueError, match="no integrator for method 7; known: dopri5, abm"):
        make_integrator(7, 6)
