"""Law dispatch from a family's table of laws, compiled for the codes a kind uses.

A family's kernel module lists, per dispatcher, the law each code reaches and the arguments it
takes (a ``Dispatch``, e.g. ``normal.elastic_force``; the records in ``model.laws`` name the
same functions, as tests/test_law_records.py checks). From that one table:

- ``compiled(stub, dispatch, user)`` makes ``stub(laws, row, code, *arguments)`` compile, for
  the ``LawSet`` of the kind's law table ``laws`` (``lawset``), to one branch per law it
  compiles (all but the laws on demand no row uses), each calling its law's function with
  its own arguments; to ``user(laws, row, code, *arguments)`` for the codes of laws
  registered from Python (from ``USER_CODE`` on), where the kind has any; and to the
  family's error value for any other code. No branch can reach another law.
- ``dispatch(code, *arguments)`` calls the same law from Python, uncompiled (``check``, tests).
"""

from collections.abc import Callable

from numba.extending import overload

from ..structs import JIT_OPTIONS, field_type
from .lawset import USER_CODE


class Dispatch:
    """One dispatcher of a family: per code, the law's function and the arguments it takes.

    ``arguments``: the dispatcher's argument names after the code, space-separated; each
    law's are a subset, in its function's order. ``error``: what a code without a law gives
    (NaN, or a tuple of NaN).
    """

    def __init__(
        self, family: str, laws: dict[int, tuple[Callable, str]], arguments: str, error: object
    ) -> None:
        self.family = family
        self.laws = {int(code): (function, tuple(names.split())) for code, (function, names)
                     in laws.items()}  # fmt: skip
        self.arguments = tuple(arguments.split())
        self.error = error
        for function, names in self.laws.values():
            if not set(names) <= set(self.arguments):
                raise ValueError(f"{function.__name__} takes {names}, not in {self.arguments}")

    def __call__(self, code: int, *arguments: float) -> object:
        """The law of ``code`` at ``arguments`` (Python; the error value for another code)."""
        if int(code) not in self.laws:
            return self.error
        function, names = self.laws[int(code)]
        values = dict(zip(self.arguments, arguments, strict=True))
        return function(*(values[name] for name in names))

    def source(self, name: str, codes: tuple[int, ...], user: bool) -> str:
        """Python source of ``name(laws, row, law, *arguments)`` for the laws of ``codes``."""
        head = ", ".join(("laws", "row", "law", *self.arguments))
        lines = [f"def {name}({head}):"]
        for code in codes:
            _, names = self.laws[code]
            lines += [
                f"    if law == {code}:",
                f"        return law_{code}({', '.join(names)})",
            ]
        if user:
            lines += [f"    if law >= {USER_CODE}:", f"        return user({head})"]
        lines.append("    return error")
        return "\n".join(lines)

    def namespace(self, user: Callable | None) -> dict:
        """The names the source reads."""
        return {"error": self.error, "user": user} | {
            f"law_{code}": function for code, (function, _) in self.laws.items()
        }


def compiled(stub: Callable, dispatch: Dispatch, user: Callable | None = None) -> Callable:
    """Make ``stub(laws, row, law, *arguments)`` compile to ``dispatch``'s used branches.

    ``user``: the branch for laws registered from Python, None where the family has none.
    """

    @overload(stub, strict=False, jit_options=JIT_OPTIONS)
    def _for_codes(laws, row, law, *arguments):
        used = field_type(laws, "used")
        codes = tuple(c for c in dispatch.laws if used.compiles(dispatch.family, c))
        with_user = user is not None and used.with_user_laws(dispatch.family)
        namespace = dispatch.namespace(user)
        exec(dispatch.source(stub.__name__, codes, with_user), namespace)
        return namespace[stub.__name__]

    return stub


def if_used(stub: Callable, family: str, codes: tuple[int, ...], function: Callable,
            absent: Callable) -> Callable:  # fmt: skip
    """Make ``stub(table, *arguments)`` compile to ``function`` where the kind uses a law.

    ``table``: a kind's table, with its law table in ``laws``; ``function`` where a row uses
    any of the laws on demand ``codes`` of ``family``, else ``absent`` (same
    arguments, doing nothing): a kind's optional part, such as its film, compiles only for
    the models that have it.
    """

    @overload(stub, strict=False, jit_options=JIT_OPTIONS)
    def _choose(table, *arguments):
        used = field_type(field_type(table, "laws"), "used")
        return (function if any(used.uses(family, c) for c in codes) else absent).py_func

    return stub
