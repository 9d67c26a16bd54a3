"""``kernels.structs``: named tuples of arrays as structs passed by reference.

What its docstring promises, checked from compiled code and from Python: a struct has the
tuple's fields under the same names; its arrays are the tuple's (a write on either side is seen
on the other), kept alive by the struct alone; scalars keep their type and are copies; structs
nest; one type per kind and field types (not per scalar value); ``by_kind`` reaches each kind's
implementation, for structs and named tuples alike.

The struct-making kernel is compiled here without the cache (``njit(to_struct.py_func)``):
the cached one's index would otherwise name this module's tuple classes, which other processes
cannot import.
"""

import gc
from typing import NamedTuple

import numba
import numpy as np
import pytest
from numba import njit
from numba.core.errors import TypingError

from jointwear.kernels.structs import StructProxy, by_kind, kind_of, to_struct

make = njit(to_struct.py_func)


class Inner(NamedTuple):
    values: np.ndarray  # (n,) float64
    count: int


class Outer(NamedTuple):
    inner: object  # an Inner, as a struct
    table: np.ndarray  # (rows, columns) int64
    scale: float


@njit
def read(outer):
    """Every field through the nested struct, summed in one number."""
    return outer.scale * (outer.inner.values.sum() + outer.inner.count + outer.table.sum())


@njit
def write(outer):
    outer.inner.values[1] = 7.5
    outer.table[1, 0] = -3


def nested() -> tuple[Inner, Outer, StructProxy]:
    inner = Inner(values=np.array([1.0, 2.0, 3.0]), count=4)
    outer = Outer(inner=inner, table=np.arange(6).reshape(2, 3), scale=0.5)
    return inner, outer, make(outer._replace(inner=make(inner)))


def test_fields_read_in_a_kernel_are_the_tuples():
    _, _, struct = nested()
    assert isinstance(struct, StructProxy)
    # 0.5 (1 + 2 + 3 + 4 + 0 + 1 + ... + 5), by hand
    assert read(struct) == 0.5 * (6.0 + 4 + 15)


def test_arrays_are_shared_both_ways():
    inner, outer, struct = nested()
    write(struct)  # written in compiled code: seen through the tuples the caller kept
    assert inner.values.tolist() == [1.0, 7.5, 3.0]
    assert outer.table[1, 0] == -3
    inner.values[0] = 100.0  # written in Python: seen by compiled code
    assert read(struct) == 0.5 * (100.0 + 7.5 + 3.0 + 4 + 15 - 3 - 3)


def test_the_struct_keeps_its_arrays_alive():
    def only_the_struct():
        return make(Inner(values=np.full(1000, 2.0), count=1))

    struct = only_the_struct()
    gc.collect()
    np.full(1000, -1.0)  # would reuse freed memory
    assert njit(lambda s: s.values.sum())(struct) == 2000.0


def test_scalars_keep_their_type_and_are_copies():
    inner = Inner(values=np.zeros(2), count=3)
    struct = make(inner)
    kind = numba.typeof(struct)
    assert dict(kind.field_dict) == {
        "values": numba.typeof(inner.values),
        "count": numba.int64,
    }
    njit(lambda s: s.values.fill(s.count))(struct)
    assert inner.values.tolist() == [3.0, 3.0]


def test_one_type_per_kind_and_field_types():
    # Two scalar values, two array contents: one type, so compiled code specialises once.
    first = make(Inner(values=np.zeros(3), count=1))
    second = make(Inner(values=np.ones(5), count=2))
    assert numba.typeof(first) == numba.typeof(second)
    assert kind_of(numba.typeof(first)) == "Inner"
    count = njit(lambda s: s.count)
    assert (count(first), count(second)) == (1, 2)
    assert len(count.signatures) == 1
    other_kind = make(Outer(inner=first, table=np.zeros((1, 1), dtype=np.int64), scale=1.0))
    assert kind_of(numba.typeof(other_kind)) == "Outer"


def _stub(first, x):
    """Dispatched by kind (by_kind)."""


by_kind(_stub, {"Inner": njit(lambda s, x: s.count + x), "Outer": njit(lambda s, x: s.scale * x)})


@njit
def dispatch(record, x):
    return _stub(record, x)


def test_by_kind_reaches_each_kinds_implementation():
    inner, _, struct = nested()
    assert dispatch(make(inner), 1.0) == 5.0  # count + x
    assert dispatch(struct, 4.0) == 2.0  # scale * x
    assert dispatch(inner, 1.0) == 5.0  # a named tuple: the same kind
    assert kind_of(numba.typeof(inner)) == "Inner"


def test_only_a_named_tuple_becomes_a_struct():
    with pytest.raises(TypingError, match="to_struct takes a named tuple"):
        make((np.zeros(2), 1))
