"""Named tuples of arrays turned into structs passed by reference, for the step loop.

numba passes a named tuple by value: every call of a compiled function that takes one unpacks
all its arrays into separate arguments, and counts a reference to each. The step loop's tables
hold about a hundred arrays, and the code for those calls was most of the loop's compile time
(tens of seconds) and much of its per-step overhead. A ``Struct`` (a numba ``StructRef``) holds
the same fields behind one pointer: a call passes one pointer, and reading a field is a load.

``to_struct(record)`` copies a named tuple's fields into a new ``Struct`` of the same kind (the
tuple class's name); kernels read its fields with the same attribute names. The arrays are
shared, not copied: writes into them through the struct are seen through the tuple the caller
kept (scalar fields are copies).
"""

from numba import njit, types
from numba.core import cgutils
from numba.core.errors import TypingError
from numba.experimental import structref
from numba.experimental.jitclass.base import imp_dtor
from numba.extending import intrinsic, overload


@structref.register
class Struct(types.StructRef):
    """The numba type of a struct: a kind (a named tuple class's name) and typed fields."""

    def __init__(self, kind: str, fields: tuple) -> None:
        self.kind = kind
        super().__init__(fields)
        self.name = f"{kind}{self._fields}"

    def preprocess_fields(self, fields: tuple) -> tuple:
        """Fields typed as the tuple holds them, without literal values."""
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


class StructProxy(structref.StructRefProxy):
    """A struct as Python sees it: an opaque handle to pass back into compiled code."""


structref.define_boxing(Struct, StructProxy)


def kind_of(record_type: types.Type) -> str:
    """The kind of a struct or named tuple type: the tuple class's name."""
    if isinstance(record_type, Struct):
        return record_type.kind
    return record_type.instance_class.__name__


@intrinsic
def _struct_from(typingctx, record):
    if not isinstance(record, types.BaseNamedTuple):
        raise TypingError(f"to_struct takes a named tuple, not {record}")
    struct_type = Struct(kind_of(record), tuple(zip(record.fields, record.types, strict=True)))

    def codegen(context, builder, signature, args):
        payload = context.data_model_manager[struct_type.get_data_type()].get_value_type()
        meminfo = context.nrt.meminfo_alloc_dtor(
            builder,
            context.get_constant(types.uintp, context.get_abi_sizeof(payload)),
            imp_dtor(context, builder.module, struct_type),
        )
        data = builder.bitcast(context.nrt.meminfo_data(builder, meminfo), payload.as_pointer())
        fields = cgutils.create_struct_proxy(struct_type.get_data_type())(
            context, builder, ref=data
        )
        for i, (name, typ) in enumerate(zip(record.fields, record.types, strict=True)):
            value = builder.extract_value(args[0], i)
            context.nrt.incref(builder, typ, value)
            setattr(fields, name, value)
        struct = context.make_helper(builder, struct_type)
        struct.meminfo = meminfo
        return struct._getvalue()

    return struct_type(record), codegen


@njit(cache=True)
def to_struct(record):
    """A new struct with the fields of the named tuple ``record`` (arrays shared)."""
    return _struct_from(record)


def by_kind(stub: object, implementations: dict) -> object:
    """Make ``stub`` dispatch, when compiled, to implementations[kind of its first argument].

    The choice is made by type at compile time: a run compiles only the implementation its
    tables call for, and the compiled code does not branch on it.
    """

    @overload(stub)
    def _dispatch(first, *args):
        function = implementations[kind_of(first)]
        return lambda first, *args: function(first, *args)

    return stub
