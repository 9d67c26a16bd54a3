"""Contact elements: the registered kinds, and the interface the step loop sees.

A kind is one module (``journal``: the revolute clearance joint; ``slider``: the translational
one) giving four tables (fixed table, restart state, log, scratch) and the functions below for
its rows. Each element has one or more *contact slots* (a journal one; a slider eight: its
corners and the guide's edges); the loop
locates the onset of every slot's contact period on the dense output and asks the kind what
happens then. The functions here fan out over the kinds, in registration order: to register
a kind, add its tables as fields of the four tuples and a line to each function.
"""

from typing import NamedTuple

from numba import njit

from . import journal, slider
from .journal import JournalLog, JournalScratch, JournalState, JournalTable
from .slider import SliderLog, SliderScratch, SliderState, SliderTable


class Elements(NamedTuple):
    """Every kind's table (fixed for a run)."""

    journal: JournalTable
    slider: SliderTable


class ElementState(NamedTuple):
    """Every kind's restart state."""

    journal: JournalState
    slider: SliderState


class ElementLog(NamedTuple):
    """Every kind's totals and snapshots."""

    journal: JournalLog
    slider: SliderLog


class ElementScratch(NamedTuple):
    """Every kind's last evaluation."""

    journal: JournalScratch
    slider: SliderScratch


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def slot_count(el):
    """Number of contact slots of all elements: the journals', then the sliders'."""
    return el.journal.ints.shape[0] + slider.SLOTS * el.slider.ints.shape[0]


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def add_forces(el, st, sc, q, qd, g):
    """Evaluate every element at (q, q') and add its contact forces to g [N, N, N m]."""
    journal.add_forces(el.journal, st.journal, sc.journal, q, qd, g)
    slider.add_forces(el.slider, st.slider, sc.slider, q, qd, g)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def penetration_excess(el, st, sc, slot, q, qd):
    """Penetration of a contact slot beyond its contact tolerance at (q, q') [m]."""
    first = el.journal.ints.shape[0]
    if slot < first:
        return journal.penetration_excess(el.journal, st.journal, sc.journal, slot, q, qd)
    return slider.penetration_excess(el.slider, st.slider, sc.slider, slot - first, q, qd)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def tolerance(el, slot):
    """Contact tolerance of a slot [m]."""
    first = el.journal.ints.shape[0]
    if slot < first:
        return journal.tolerance(el.journal, slot)
    return slider.tolerance(el.slider, slot - first)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def in_contact(st, slot):
    """Whether a slot's contact period is under way."""
    first = st.journal.contact_on.shape[0]
    if slot < first:
        return st.journal.contact_on[slot] == 1
    return st.slider.contact_on[slot - first] == 1


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def begin_period(el, st, sc, log, slot, q, qd, info):
    """Open or close a slot's contact period at a step end; True when one opens (info filled)."""
    first = el.journal.ints.shape[0]
    if slot < first:
        return journal.begin_period(
            el.journal, st.journal, sc.journal, log.journal, slot, q, qd, info
        )
    return slider.begin_period(
        el.slider, st.slider, sc.slider, log.slider, slot - first, q, qd, info
    )


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def accumulate(el, st, sc, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear, totals and snapshots of the accepted step [t_old, t_new] [s], from its midpoint."""
    journal.accumulate(
        el.journal, st.journal, sc.journal, log.journal, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip
    slider.accumulate(
        el.slider, st.slider, sc.slider, log.slider, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def write_outputs(el, sc, row, c):
    """Every element's time-series columns from its last evaluation; the next free column."""
    c = journal.write_outputs(el.journal, sc.journal, row, c)
    return slider.write_outputs(el.slider, sc.slider, row, c)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def elastic_energy(el, sc):
    """Elastic energy stored in the contacts of the last evaluation [J]."""
    return journal.elastic_energy(el.journal, sc.journal) + slider.elastic_energy(
        el.slider, sc.slider
    )
