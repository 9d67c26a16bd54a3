"""Laws registered from Python: their records beside the built-in ones (numba-free).

``jointwear.register_law`` (``engine.user_laws``) checks the user's compiled functions and
compiles their wrappers; this module keeps what a model file needs of a registered law: its
``UserLaw`` (family, name, functions, own keys), its ``Law`` record in ``record.REGISTERED``
(which ``Family.by_name`` reads, so a model file names it like a built-in law) and the
keys of all of them (``own_keys``), which clearance tables accept besides their fields.

A user law's functions take the arguments its family's dispatcher gives the built-in laws,
then the values of its own keys, in the order they were declared (SI):

| family | function | arguments before its keys | returns |
|---|---|---|---|
| normal_law | force (energy, stiffness) | delta, k, n, e_star, d_r, width | N (J, N/m) |
| damping | hysteresis: chi | c_e | - |
| friction_law | force (sliding: speed) | v_t, f_n, c_f (v_t) | N (m/s) |
| wear_law | coefficient: dh/ds / p | mu | 1/Pa |

The symbols are those of ``kernels.laws.normal``, ``friction`` and ``wear``: k and n are
Hertz's K and exponent, from the keys ``contact_stiffness`` (or the stiffness formula) and
``exponent``, which every user elastic law reads as ``hertz`` does; c_e is the
``restitution_coefficient``, which every user damping law reads. A normal-force function is
called with delta > 0 only; without ``energy`` the elastic energy is its force integrated by
quadrature, without ``sliding`` a contact slides whenever v_t is not zero.
"""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Callable
from itertools import count
from typing import NamedTuple

from ...units import unit_of
from . import EVERY
from .friction import FRICTION
from .normal import DAMPING, DEPTH_LIMIT, NORMAL, RESTITUTION
from .record import PENETRATION, REGISTERED, Family, Key, Law, Range, pack_in_order
from .wear import WEAR

USER_CODE = 100  # law codes from here on are registered laws (kernels.laws.user.USER_CODE)
N_KEYS = 6  # most keys of a user law's own (kernels.laws.user.N_KEYS)


class Role(NamedTuple):
    """One function a user law of a family gives: its name and its arguments before the keys."""

    name: str
    arguments: tuple[str, ...]


_CONTACT = ("delta", "k", "n", "e_star", "d_r", "width")
ROLES: dict[str, tuple[Role, ...]] = {  # per family, the required function first
    NORMAL.key: (Role("force", _CONTACT), Role("energy", _CONTACT), Role("stiffness", _CONTACT)),
    DAMPING.key: (Role("hysteresis", ("c_e",)),),
    FRICTION.key: (Role("force", ("v_t", "f_n", "c_f")), Role("sliding", ("v_t",))),
    WEAR.key: (Role("coefficient", ("mu",)),),
}
FAMILIES: dict[str, Family] = {f.key: f for f in (NORMAL, DAMPING, FRICTION, WEAR)}
_BY_TITLE = {f.title: f.key for f in FAMILIES.values()}  # "friction" -> "friction_law"


class UserLaw(NamedTuple):
    """A law registered from Python (module docstring); it pickles with its functions."""

    family: str  # the model-file key that chooses it: normal_law, damping, ...
    name: str
    functions: tuple[tuple[str, Callable], ...]  # (role, compiled function), ROLES' first first
    keys: tuple[Key, ...]  # its own keys, in the order its functions take their values
    summary: str = ""

    def function(self, role: str) -> Callable | None:
        """The compiled function of ``role`` ("force", "energy", ...), None if not given."""
        return dict(self.functions).get(role)


_LAWS: dict[str, UserLaw] = {}  # by name (names are unique across families)
_CODES = count(USER_CODE)  # never reused, so a code names one registration per process


def family_key(family: str) -> str:
    """The model-file key of a family given by key or title ("friction" -> "friction_law")."""
    key = _BY_TITLE.get(family, family)
    if key not in FAMILIES:
        known = ", ".join(f"'{k}'" for k in FAMILIES)
        raise ValueError(
            f"family: {family!r} cannot have laws registered from Python; the families that "
            f"can are {known}"
        )
    return key


def check(law: UserLaw) -> None:
    """Raise ValueError or TypeError if ``law`` cannot be registered (messages name the cause)."""
    where = f"{law.family} '{law.name}'"
    _check_name(law.name, law.family)
    roles = {role.name: role for role in ROLES[law.family]}
    for role, function in law.functions:
        if role not in roles:
            allowed = ", ".join(roles)
            raise ValueError(f"{where}: no {role} function for this family; it takes {allowed}")
        _check_arity(where, roles[role], function, law.keys)
    if len(law.keys) > N_KEYS:
        raise ValueError(
            f"{where}: {len(law.keys)} keys; a law registered from Python has {N_KEYS} at most"
        )
    for key in law.keys:
        _check_key(where, key, law)


def _check_name(name: str, family: str) -> None:
    if not isinstance(name, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", name):
        raise ValueError(
            f"name: {name!r} is not a law name; use lowercase letters, digits and _, starting "
            "with a letter"
        )
    for built_in in EVERY:
        if any(law.name == name for law in built_in.laws):
            raise ValueError(
                f"name: '{name}' is the name of a built-in law ({built_in.key}); choose "
                "another name"
            )
    other = _LAWS.get(name)
    if other is not None and other.family != family:
        raise ValueError(
            f"name: '{name}' is already a {other.family} registered from Python; choose "
            "another name, or unregister it first (jointwear.unregister_law)"
        )


def _check_arity(where: str, role: Role, function: Callable, keys: tuple[Key, ...]) -> None:
    """The function must take the role's arguments, then one value per key."""
    python = getattr(function, "py_func", function)
    parameters = inspect.signature(python).parameters.values()
    positional = [p for p in parameters if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    wanted = (*role.arguments, *(key.name for key in keys))
    if len(positional) != len(wanted) or len(positional) != len(parameters):
        raise TypeError(
            f"{where}: its {role.name} function {python.__name__}"
            f"{inspect.signature(python)} takes {len(positional)} arguments; it must take "
            f"{len(wanted)}: {', '.join(wanted)} (the family's arguments, then the law's keys "
            "in the order given)"
        )


def _check_key(where: str, key: Key, law: UserLaw) -> None:
    if not isinstance(key.name, str) or not re.fullmatch(r"[a-z][a-z0-9_]*", key.name):
        raise ValueError(
            f"{where}: key {key.name!r} is not a key name; use lowercase letters, digits and _, "
            "starting with a letter"
        )
    _check_unit(where, key)
    if key.name in _clearance_fields():
        raise ValueError(
            f"{where}: key '{key.name}' is a key of the clearance tables or of the built-in "
            "laws; choose another name"
        )
    for other_law in _LAWS.values():
        other = next((k for k in other_law.keys if k.name == key.name), None)
        if other is not None and other != key and other_law.name != law.name:
            raise ValueError(
                f"{where}: key '{key.name}' is a key of {other_law.family} '{other_law.name}' "
                f"too, declared otherwise ({other}); declare it the same way or rename it"
            )


def _check_unit(where: str, key: Key) -> None:
    """The unit must be SI: the law receives SI values (files may give any unit pint reads)."""
    if not isinstance(key.unit, str):
        raise ValueError(
            f"{where}: key '{key.name}' has no unit; give its SI unit as text, e.g. "
            "keys={'stribeck_speed': 'm/s'} ('' for a plain number)"
        )
    if key.unit == "":
        return
    size = unit_of(f"1 {key.unit}")
    if size is None:
        raise ValueError(
            f"{where}: key '{key.name}' has the unit {key.unit!r}, which cannot be read; give "
            "an SI unit such as 'm', 'm/s', 'Pa', 'N/m' ('' for a plain number)"
        )
    if not math.isclose(size[1], 1.0, rel_tol=1e-12):
        raise ValueError(
            f"{where}: key '{key.name}' has the unit {key.unit!r}, which is {size[1]:g} of the "
            "SI unit; declare the SI unit (the law receives SI values; files may still give "
            "any unit of the same kind)"
        )


def _clearance_fields() -> set[str]:
    """The keys of every joint type's clearance table (imports the joint types)."""
    from ...joints import KINDS
    from ..clearance import ClearanceTable

    tables = [ClearanceTable]
    for kind in KINDS:
        annotation = kind.schema.model_fields["clearance"].annotation
        tables += [t for t in getattr(annotation, "__args__", (annotation,)) if t is not type(None)]
    return {name for table in tables for name in table.model_fields}


def register(law: UserLaw) -> None:
    """Add ``law``, which ``check`` accepted, replacing a law of the same name and family."""
    code = next(_CODES)
    _LAWS[law.name] = law
    REGISTERED.setdefault(law.family, {})[law.name] = _record(law, code)


def unregister(name: str) -> None:
    """Remove the law registered as ``name``; KeyError if there is none."""
    law = _LAWS.pop(name)
    del REGISTERED[law.family][name]


def registered(name: str) -> UserLaw | None:
    """The law registered as ``name``, None if there is none."""
    return _LAWS.get(name)


def registered_laws() -> tuple[UserLaw, ...]:
    """Every law registered from Python, in registration order."""
    return tuple(_LAWS.values())


def used_laws(model: object) -> tuple[UserLaw, ...]:
    """The registered laws that ``model``'s clearance joints choose."""
    names = {
        getattr(joint.clearance, family) for joint in model.clearance_joints for family in FAMILIES
    }
    return tuple(law for law in _LAWS.values() if law.name in names)


def own_keys() -> dict[str, Key]:
    """The own keys of every registered law, by name."""
    return {key.name: key for law in _LAWS.values() for key in law.keys}


def readers(key: str) -> list[UserLaw]:
    """The registered laws that read the key ``key``."""
    return [law for law in _LAWS.values() if any(k.name == key for k in law.keys)]


# The records ---------------------------------------------------------------------------------

_FAMILY_KEYS = {NORMAL.key: NORMAL.by_name["hertz"].keys, DAMPING.key: (RESTITUTION,)}
_FAMILY_PACKS: dict[str, Callable[[dict], tuple[float, ...]]] = {
    NORMAL.key: NORMAL.by_name["hertz"].pack,  # k and n: Hertz's stiffness and exponent
    DAMPING.key: pack_in_order(RESTITUTION),  # c_e
    FRICTION.key: lambda values: (0.0, 0.0, 0.0),  # the built-in laws' slots, unused
    WEAR.key: lambda values: (0.0,),
}


def _record(law: UserLaw, code: int) -> Law:
    """The ``Law`` record of a registered law (``record.Law``)."""
    own = pack_in_order(*law.keys)
    family_pack = _FAMILY_PACKS[law.family]

    def pack(values: dict) -> tuple[float, ...]:
        own(values)  # raises ValueError("needs ...") for a missing key
        return family_pack(values)

    function = law.functions[0][1]
    summary = law.summary or f"registered from Python: {getattr(function, '__name__', function)}"
    normal = law.family == NORMAL.key
    return Law(
        law.name,
        code,
        summary,
        (),
        keys=(*_FAMILY_KEYS.get(law.family, ()), *law.keys),
        pack=pack,
        ranges=(Range(PENETRATION, DEPTH_LIMIT),) if normal else (),
        stiffness=NORMAL.by_name["hertz"].stiffness if normal else None,
    )


def elastic_force(law: UserLaw, arguments: tuple[float, ...], values: dict) -> tuple[float, float]:
    """(force [N], stiffness dF/d(delta) [N/m]) of a user elastic law, called from Python.

    ``arguments``: delta, k, n, e_star, d_r, width (SI); ``values``: its keys' values. The
    stiffness is its ``stiffness`` function's, else the force's central difference over
    1e-6 delta.
    """
    own = tuple(values[key.name] for key in law.keys)
    force = law.function("force")
    delta, rest = arguments[0], arguments[1:]
    stiffness = law.function("stiffness")
    if stiffness is not None:
        return force(*arguments, *own), stiffness(*arguments, *own)
    step = 1e-6 * delta
    slope = (force(delta + step, *rest, *own) - force(delta - step, *rest, *own)) / (2.0 * step)
    return force(*arguments, *own), slope
