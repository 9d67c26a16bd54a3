"""Named tuples of arrays turned into structs passed by reference, for the step loop.

numba passes a named tuple by value: every call of a compiled function that takes one unpacks
all its arrays into separate arguments, and counts a reference to each. The step loop's tables
hold about a hundred arrays, and the code for those calls was most of the loop's compile time
(tens of seconds) and much of its per-step overhead. A struct (``struct_ref.Struct``, a numba
``StructRef``) holds the same fields behind one pointer: a call passes one pointer, and reading
a field is a load.

``to_struct(record)`` copies a named tuple's fields into a new struct of the same kind (the
tuple class's name); kernels read its fields with the same attribute names. The arrays are
shared, not copied: writes into them through the struct are seen through the tuple the caller
kept (scalar fields are copies). A named tuple may hold structs (``to_struct`` of its fields
first); ``by_kind`` dispatches on the kind of a struct or a named tuple alike.

Under ``JOINTWEAR_PLAIN_NUMBA`` (``kernels/__init__.py``) ``to_struct`` returns the named tuple
itself and ``struct_ref`` is not imported: the same kernels run on plain numba features,
slower to compile and to step.
"""

from numba import njit, types
from numba.extending import overload

from . import PLAIN_NUMBA

if PLAIN_NUMBA:
    StructProxy = tuple  # what to_struct returns: the named tuple

    @njit(cache=True, no_cfunc_wrapper=True)
    def to_struct(record):
        """The named tuple ``record`` itself (``JOINTWEAR_PLAIN_NUMBA``)."""
        return record

else:
    from .struct_ref import StructProxy, to_struct

__all__ = ["JIT_OPTIONS", "StructProxy", "by_kind", "field_type", "kind_of", "to_struct"]

JIT_OPTIONS = {"no_cpython_wrapper": True, "no_cfunc_wrapper": True}  # of what stubs compile to


def kind_of(record_type: types.Type) -> str:
    """The kind of a struct or named tuple type: the tuple class's name."""
    if isinstance(record_type, types.BaseNamedTuple):
        return record_type.instance_class.__name__
    return record_type.kind


def field_type(record_type: types.Type, name: str) -> types.Type:
    """The type of field ``name`` of a struct or named tuple type."""
    if isinstance(record_type, types.BaseNamedTuple):
        return record_type.types[record_type.fields.index(name)]
    return record_type.field_dict[name]


def by_kind(stub: object, implementations: dict) -> object:
    """Make ``stub`` dispatch, when compiled, to implementations[kind of its first argument].

    The choice is made by type at compile time: a run compiles only the implementation its
    tables call for, and the compiled code does not branch on it. The implementation is
    compiled in the stub's place (its Python function, which takes the stub's arguments),
    with no call in between.
    """

    @overload(stub, strict=False, jit_options=JIT_OPTIONS)
    def _dispatch(first, *args):
        return implementations[kind_of(first)].py_func

    return stub
