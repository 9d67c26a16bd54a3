"""The numba type behind ``structs``: a named tuple's fields behind one pointer (a StructRef).

It builds on numba's ``structref`` and on two of its internals (``cgutils``'s struct proxies and
jitclass's destructor, ``imp_dtor``): ``structs`` does without this module under
``JOINTWEAR_PLAIN_NUMBA``.
"""

from numba import njit, types
from numba.core import cgutils
from numba.core.errors import TypingError
from numba.experimental import structref
from numba.experimental.jitclass.base import imp_dtor
from numba.extending import intrinsic


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


@intrinsic
def _struct_from(typingctx, record):
    if not isinstance(record, types.BaseNamedTuple):
        raise TypingError(f"to_struct takes a named tuple, not {record}")
    struct_type = Struct(
        record.instance_class.__name__, tuple(zip(record.fields, record.types, strict=True))
    )

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


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def to_struct(record):
    """A new struct with the fields of the named tuple ``record`` (arrays shared)."""
    return _struct_from(record)
