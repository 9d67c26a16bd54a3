"""Non-owning views of a run's arrays, for the compiled step loop.

numba counts references to every array it passes: each call of a compiled function that it
does not inline increments and decrements the count of every array in its arguments, with an
atomic operation each. The loop's arguments are named tuples of several dozen arrays in all; on the
paper's four-bar these atomic operations once took about half of the run time.

The arrays of a run are owned by the Python caller of ``loop.advance`` for the whole call, so
the loop can work on views without an owner (a null ``meminfo``, as ``numba.carray`` makes),
for which the reference counting is a null test. Nothing the loop returns is such a view.
"""

from numba import types
from numba.core import cgutils
from numba.extending import intrinsic


def _unowned(context, builder, ty, value):
    """``value`` of type ``ty`` with every array in it (nested tuples too) without owner."""
    if isinstance(ty, types.BaseTuple):
        for i, member in enumerate(ty.types):
            item = builder.extract_value(value, i)
            value = builder.insert_value(value, _unowned(context, builder, member, item), i)
        return value
    if not isinstance(ty, types.Array):
        return value
    array = context.make_array(ty)(context, builder, value)
    array.meminfo = cgutils.get_null_value(array.meminfo.type)
    array.parent = cgutils.get_null_value(array.parent.type)
    return array._getvalue()


@intrinsic
def borrow(typingctx, record):
    """The (nested) named tuple ``record`` with each array replaced by a view without owner.

    The views are valid while the caller of the compiled function holds ``record``.
    """

    def codegen(context, builder, signature, args):
        return _unowned(context, builder, signature.args[0], args[0])

    return record(record), codegen
