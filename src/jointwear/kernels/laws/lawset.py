"""Which laws a kind's rows use: a constant the step loop is compiled for.

A ``LawSet`` holds, per family (its model-file key, e.g. "normal_law"), what decides the code
the loop compiles: which of the family's laws compiled only on demand the kind's rows use, and
whether they use laws registered from Python. Its numba type (``LawSetType``) carries that and
no data, so the law dispatchers (``dispatch``) compile a branch for every law but the unused
ones on demand, and a kind's optional parts (a film, an elastic foundation) compile only where
a row uses them. Each law set is its own specialisation of the loop, cached like any other.

The laws on demand are those whose code is large: the films and the elastic foundation.
The others compile in a few hundredths of a second each, and compile for every model, so
that models that differ only in them share one specialisation and its cache.
"""

from collections.abc import Iterable, Mapping

from numba import types
from numba.extending import NativeValue, box, models, register_model, typeof_impl, unbox

USER_CODE = 100  # law codes from here on are laws registered from Python


class LawSet:
    """What a kind's rows use of each family's laws (Python; module docstring).

    ``used``: per family, the codes the rows choose; ``on_demand``: per family, the codes
    compiled only where used.
    """

    def __init__(
        self, used: Mapping[str, Iterable[int]], on_demand: Mapping[str, Iterable[int]]
    ) -> None:
        families = []
        for family in sorted(set(used) | set(on_demand)):
            codes = {int(c) for c in used.get(family, ())}
            demand = tuple(sorted({int(c) for c in on_demand.get(family, ())}))
            kept = {c for c in codes if c in demand} | ({USER_CODE} if max(codes, default=0)
                                                        >= USER_CODE else set())  # fmt: skip
            families.append((family, tuple(sorted(kept)), demand))
        self.families = tuple(families)

    @classmethod
    def of_families(cls, families: tuple) -> "LawSet":
        """The law set whose ``families`` these are (as ``LawSetType`` holds them)."""
        law_set = cls.__new__(cls)
        law_set.families = families
        return law_set

    def __repr__(self) -> str:
        return f"LawSet{self.families}"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, LawSet) and other.families == self.families

    def __hash__(self) -> int:
        return hash(self.families)


class LawSetType(types.Type):
    """The numba type of a ``LawSet``: its families, as part of the type."""

    def __init__(self, families: tuple[tuple[str, tuple[int, ...], tuple[int, ...]], ...]) -> None:
        self.families = families
        super().__init__(name=f"LawSet{families}")

    def _family(self, family: str) -> tuple[tuple[int, ...], tuple[int, ...]]:
        for name, used, demand in self.families:
            if name == family:
                return used, demand
        return (), ()

    def compiles(self, family: str, code: int) -> bool:
        """Whether the law ``code`` of ``family`` is compiled: not on demand, or used."""
        used, demand = self._family(family)
        return code not in demand or code in used

    def uses(self, family: str, code: int) -> bool:
        """Whether a row uses the law on demand ``code`` of ``family``."""
        return code in self._family(family)[0]

    def with_user_laws(self, family: str) -> bool:
        """Whether a row's law of ``family`` is registered from Python."""
        return USER_CODE in self._family(family)[0]


@typeof_impl.register(LawSet)
def _typeof(value: LawSet, context: object) -> LawSetType:
    return LawSetType(value.families)


register_model(LawSetType)(models.OpaqueModel)


@unbox(LawSetType)
def _unbox(typ: LawSetType, obj: object, c: object) -> NativeValue:
    return NativeValue(c.context.get_constant_null(typ))  # the type is all there is


@box(LawSetType)
def _box(typ: LawSetType, value: object, c: object) -> object:
    """The same law set, rebuilt from the type (a named tuple returned to Python holds one)."""
    return c.pyapi.unserialize(c.pyapi.serialize_object(LawSet.of_families(typ.families)))
