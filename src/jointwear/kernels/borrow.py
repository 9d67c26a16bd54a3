"""Non-owning views of a run's arrays, for the compiled step loop.

numba counts references to every array it passes: each call of a compiled function that it
does not inline increments and decrements the count of every array in its arguments, with an
atomic operation each. The loop's state is several named tuples of about a hundred arrays in
all, so on the paper's four-bar these atomic operations took about half of the run time.

The arrays of a run are owned by the Python caller of ``loop.advance`` for the whole call, so
the loop can work on views without an owner (a null ``meminfo``, as ``numba.carray`` makes),
for which the reference counting is a null test. Nothing the loop returns is such a view.
"""

from numba import types
from numba.core import cgutils
from numba.extending import intrinsic


def _unowned(context, builder, ty, value):
    """The array ``value`` of type ``ty`` without its owner; other values unchanged."""
    if not isinstance(ty, types.Array):
        return value
    array = context.make_array(ty)(context, builder, value)
    array.meminfo = cgutils.get_null_value(array.meminfo.type)
    array.parent = cgutils.get_null_value(array.parent.type)
    return array._getvalue()


@intrinsic
def borrow(typingctx, record):
    """The named tuple ``record`` with each of its arrays replaced by a view without owner.

    The views are valid while the caller of the compiled function holds ``record``.
    """

    def codegen(context, builder, signature, args):
        (value,) = args
        for i, member in enumerate(signature.args[0].types):
            item = builder.extract_value(value, i)
            value = builder.insert_value(value, _unowned(context, builder, member, item), i)
        return value

    return record(record), codegen
