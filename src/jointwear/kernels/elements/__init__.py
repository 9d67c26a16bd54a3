"""Contact elements: the registered kinds, and the interface the step loop sees.

A kind is one module (``journal``: the revolute clearance joint) giving four tables (fixed
table, restart state, log, scratch) and the functions below for its rows. Each element has
one or more *contact slots* (a journal one; a slider would have one per corner); the loop
locates the onset of every slot's contact period on the dense output and asks the kind what
happens then. The functions here fan out over the kinds, in registration order: to register
a kind, add its tables as fields of the four tuples and a line to each function.
"""

from typing import NamedTuple

from numba import njit

from . import journal
from .journal import JournalLog, JournalScratch, JournalState, JournalTable


class Elements(NamedTuple):
    """Every kind's table (fixed for a run)."""

    journal: JournalTable


class ElementState(NamedTuple):
    """Every kind's restart state."""

    journal: JournalState


class ElementLog(NamedTuple):
    """Every kind's totals and snapshots."""

    journal: JournalLog


class ElementScratch(NamedTuple):
    """Every kind's last evaluation."""

    journal: JournalScratch


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def slot_count(el):
    """Number of contact slots of all elements."""
    return el.journal.ints.shape[0]


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def add_forces(el, st, sc, q, qd, g):
    """Evaluate every element at (q, q') and add its contact forces to g [N, N, N m]."""
    journal.add_forces(el.journal, st.journal, sc.journal, q, qd, g)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def penetration_excess(el, st, sc, slot, q, qd):
    """Penetration of a contact slot beyond its contact tolerance at (q, q') [m]."""
    return journal.penetration_excess(el.journal, st.journal, sc.journal, slot, q, qd)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def tolerance(el, slot):
    """Contact tolerance of a slot [m]."""
    return journal.tolerance(el.journal, slot)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def in_contact(st, slot):
    """Whether a slot's contact period is under way."""
    return st.journal.contact_on[slot] == 1


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def begin_period(el, st, sc, log, slot, q, qd, info):
    """Open or close a slot's contact period at a step end; True when one opens (info filled)."""
    return journal.begin_period(el.journal, st.journal, sc.journal, log.journal, slot, q, qd, info)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def accumulate(el, st, sc, log, t_old, t_new, q_mid, qd_mid, snap_times, first):
    """Wear, totals and snapshots of the accepted step [t_old, t_new] [s], from its midpoint."""
    journal.accumulate(
        el.journal, st.journal, sc.journal, log.journal, t_old, t_new, q_mid, qd_mid,
        snap_times, first,
    )  # fmt: skip


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def write_outputs(el, sc, row, c):
    """Every element's time-series columns from its last evaluation; the next free column."""
    return journal.write_outputs(el.journal, sc.journal, row, c)


@njit(cache=True, no_cpython_wrapper=True, inline="always")
def elastic_energy(el, sc):
    """Elastic energy stored in the contacts of the last evaluation [J]."""
    return journal.elastic_energy(el.journal, sc.journal)
