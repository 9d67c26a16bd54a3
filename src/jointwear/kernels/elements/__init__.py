"""Contact elements: the registered kinds, and the interface the step loop sees.

A kind is one module (``journal``: the revolute clearance joint; ``slider``: the translational
one; ``pin_slot``: the pin-in-slot one) giving four tables (fixed table, restart state, log,
scratch), ``SLOTS`` contact slots per element (a journal one; a slider eight: its corners and
the guide's edges; a pin in a slot one) and the functions below for its elements. The loop
numbers the slots of all kinds one after the other, in the order of ``Elements``' fields;
``_locate`` is the one place that maps a slot to its kind, and the functions here fan out to
the kinds.

A kind the model has no joints of gets ``NoElements`` in all four tuples: each function
below reaches a kind's own function through a stub that dispatches on its table's type when
compiled (``structs.by_kind``), and for ``NoElements`` that is a function doing nothing, so a
run compiles only the kinds its model has (one cached specialisation per combination).

To register a kind (its Python side: ``jointwear.joints``): add its module's tables as a
field of the four tuples, and its line to ``_locate`` and to each function below.
"""

from typing import NamedTuple

import numpy as np
from numba import njit

from ..structs import by_kind
from . import journal, pin_slot, slider


class Elements(NamedTuple):
    """Every kind's table (fixed for a run)."""

    journal: journal.JournalTable
    slider: slider.SliderTable
    pin_slot: pin_slot.PinSlotTable


class ElementState(NamedTuple):
    """Every kind's restart state."""

    journal: journal.JournalState
    slider: slider.SliderState
    pin_slot: pin_slot.PinSlotState


class ElementLog(NamedTuple):
    """Every kind's totals and snapshots."""

    journal: journal.JournalLog
    slider: slider.SliderLog
    pin_slot: pin_slot.PinSlotLog


class ElementScratch(NamedTuple):
    """Every kind's last evaluation."""

    journal: journal.JournalScratch
    slider: slider.SliderScratch
    pin_slot: pin_slot.PinSlotScratch


KERNELS = (journal, slider, pin_slot)  # in the order of the tuples' fields


class NoElements(NamedTuple):
    """All four tables of a kind the model has no joints of (its functions do nothing)."""

    ints: np.ndarray  # (0, 1) int64: no rows, so no slots
    contact_on: np.ndarray  # (0,) int64


def no_elements() -> NoElements:
    """The tables of an absent kind (Python)."""
    return NoElements(ints=np.zeros((0, 1), dtype=np.int64), contact_on=np.zeros(0, np.int64))


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_forces(table, state, scratch, q, qd, g):
    return None


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_excess(table, state, scratch, k, q, qd):
    return 0.0


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_tolerance(table, k):
    return 0.0


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_period(table, state, scratch, log, k, q, qd, info):
    return False


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_accumulation(table, state, scratch, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    return None


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_outputs(table, scratch, row, c):
    return c


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _no_energy(table, scratch):
    return 0.0


def _each_kind(name: str, absent: object) -> dict:
    """Kernel function ``name`` of every kind, by its table's type name, and ``absent``."""
    tables = [cls.__name__ for cls in Elements.__annotations__.values()]
    kinds = {table: getattr(module, name) for table, module in zip(tables, KERNELS, strict=True)}
    return {**kinds, NoElements.__name__: absent}


def _kind_add_forces(table, state, scratch, q, qd, g):
    """A kind's ``add_forces`` (``structs.by_kind``: chosen by the table's type)."""


def _kind_penetration_excess(table, state, scratch, k, q, qd):
    """A kind's ``penetration_excess``."""


def _kind_tolerance(table, k):
    """A kind's ``tolerance``."""


def _kind_begin_period(table, state, scratch, log, k, q, qd, info):
    """A kind's ``begin_period``."""


def _kind_accumulate(table, state, scratch, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """A kind's ``accumulate``."""


def _kind_write_outputs(table, scratch, row, c):
    """A kind's ``write_outputs``."""


def _kind_elastic_energy(table, scratch):
    """A kind's ``elastic_energy``."""


for _stub, _absent in (
    (_kind_add_forces, _no_forces),
    (_kind_penetration_excess, _no_excess),
    (_kind_tolerance, _no_tolerance),
    (_kind_begin_period, _no_period),
    (_kind_accumulate, _no_accumulation),
    (_kind_write_outputs, _no_outputs),
    (_kind_elastic_energy, _no_energy),
):
    by_kind(_stub, _each_kind(_stub.__name__.removeprefix("_kind_"), _absent))


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def slot_count(el):
    """Number of contact slots of all elements."""
    return (
        journal.SLOTS * el.journal.ints.shape[0]
        + slider.SLOTS * el.slider.ints.shape[0]
        + pin_slot.SLOTS * el.pin_slot.ints.shape[0]
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def _locate(el, slot):
    """(kind, slot among that kind's) of a slot: kinds in field order, SLOTS per element."""
    first = journal.SLOTS * el.journal.ints.shape[0]
    if slot < first:
        return 0, slot
    second = first + slider.SLOTS * el.slider.ints.shape[0]
    if slot < second:
        return 1, slot - first
    return 2, slot - second


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def owner(el, slot):
    """(kind, element within its kind) of a slot: where the loop logs an onset."""
    kind, local = _locate(el, slot)
    if kind == 0:
        return kind, local // journal.SLOTS
    if kind == 1:
        return kind, local // slider.SLOTS
    return kind, local // pin_slot.SLOTS


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def add_forces(el, st, sc, q, qd, g):
    """Evaluate every element at (q, q') and add its contact forces to g [N, N, N m]."""
    _kind_add_forces(el.journal, st.journal, sc.journal, q, qd, g)
    _kind_add_forces(el.slider, st.slider, sc.slider, q, qd, g)
    _kind_add_forces(el.pin_slot, st.pin_slot, sc.pin_slot, q, qd, g)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def penetration_excess(el, st, sc, slot, q, qd):
    """Penetration of a contact slot beyond its contact tolerance at (q, q') [m]."""
    kind, local = _locate(el, slot)
    if kind == 0:
        return _kind_penetration_excess(el.journal, st.journal, sc.journal, local, q, qd)
    if kind == 1:
        return _kind_penetration_excess(el.slider, st.slider, sc.slider, local, q, qd)
    return _kind_penetration_excess(el.pin_slot, st.pin_slot, sc.pin_slot, local, q, qd)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def tolerance(el, slot):
    """Contact tolerance of a slot [m]."""
    kind, local = _locate(el, slot)
    if kind == 0:
        return _kind_tolerance(el.journal, local)
    if kind == 1:
        return _kind_tolerance(el.slider, local)
    return _kind_tolerance(el.pin_slot, local)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def in_contact(el, st, slot):
    """Whether a slot's contact period is under way."""
    kind, local = _locate(el, slot)
    if kind == 0:
        return st.journal.contact_on[local] == 1
    if kind == 1:
        return st.slider.contact_on[local] == 1
    return st.pin_slot.contact_on[local] == 1


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def begin_period(el, st, sc, log, slot, q, qd, info):
    """Open or close a slot's contact period at a step end; True when one opens (info filled)."""
    kind, local = _locate(el, slot)
    if kind == 0:
        return _kind_begin_period(
            el.journal, st.journal, sc.journal, log.journal, local, q, qd, info
        )
    if kind == 1:
        return _kind_begin_period(el.slider, st.slider, sc.slider, log.slider, local, q, qd, info)
    return _kind_begin_period(
        el.pin_slot, st.pin_slot, sc.pin_slot, log.pin_slot, local, q, qd, info
    )


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def accumulate(el, st, sc, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear, totals and snapshots of the accepted step [t_old, t_new] [s], from its midpoint."""
    _kind_accumulate(
        el.journal, st.journal, sc.journal, log.journal, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip
    _kind_accumulate(
        el.slider, st.slider, sc.slider, log.slider, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip
    _kind_accumulate(
        el.pin_slot, st.pin_slot, sc.pin_slot, log.pin_slot, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def write_outputs(el, sc, row, c):
    """Every element's time-series columns from its last evaluation; the next free column."""
    c = _kind_write_outputs(el.journal, sc.journal, row, c)
    c = _kind_write_outputs(el.slider, sc.slider, row, c)
    return _kind_write_outputs(el.pin_slot, sc.pin_slot, row, c)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True, inline="always")
def elastic_energy(el, sc):
    """Elastic energy stored in the contacts of the last evaluation [J]."""
    return (
        _kind_elastic_energy(el.journal, sc.journal)
        + _kind_elastic_energy(el.slider, sc.slider)
        + _kind_elastic_energy(el.pin_slot, sc.pin_slot)
    )
