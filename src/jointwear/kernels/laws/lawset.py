"""Which laws a kind's rows use: a constant the step loop is compiled for.

A ``LawSet`` holds, per family (its model-file key, e.g. "normal_law"), the codes of the laws
a contact kind's rows choose. Its numba type (``LawSetType``) carries those codes and no data,
so code compiled for one law set knows them as constants: the law dispatchers (``dispatch``)
compile a branch for each code used and for no other, and a kind's optional parts (a film, an
elastic foundation) compile only where a row uses them. Each law set is its own
specialisation of the loop, cached like any other.
"""

from collections.abc import Iterable, Mapping

from numba import types
from numba.extending import NativeValue, models, register_model, typeof_impl, unbox


class LawSet:
    """The codes each family's laws have in a kind's rows (Python)."""

    def __init__(self, codes: Mapping[str, Iterable[int]]) -> None:
        self.families = tuple(
            sorted(
                (family, tuple(sorted({int(c) for c in used}))) for family, used in codes.items()
            )
        )

    def __repr__(self) -> str:
        return f"LawSet({dict(self.families)})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, LawSet) and other.families == self.families

    def __hash__(self) -> int:
        return hash(self.families)


class LawSetType(types.Type):
    """The numba type of a ``LawSet``: its codes, as part of the type."""

    def __init__(self, families: tuple[tuple[str, tuple[int, ...]], ...]) -> None:
        self.families = families
        super().__init__(name=f"LawSet{families}")

    def codes(self, family: str) -> tuple[int, ...]:
        """The codes of ``family`` the rows use (none for a family the kind has not)."""
        return dict(self.families).get(family, ())


@typeof_impl.register(LawSet)
def _typeof(value: LawSet, context: object) -> LawSetType:
    return LawSetType(value.families)


register_model(LawSetType)(models.OpaqueModel)


@unbox(LawSetType)
def _unbox(typ: LawSetType, obj: object, c: object) -> NativeValue:
    return NativeValue(c.context.get_constant_null(typ))  # the type is all there is
