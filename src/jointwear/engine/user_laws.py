"""Laws from Python: registering a compiled function as a law, and its arrays for a run.

``register_law`` checks the user's ``@njit`` functions, compiles for each a C-callable
wrapper of the kernels' one signature (``kernels.laws.user``) and adds the law's record
(``model.laws.user``): model files then name it like a built-in law. ``user_tables`` gives
each joint type's ``UserLaws`` for a run: per row, the wrappers' addresses and the law's own
parameters; a type none of whose rows chooses a user law gets None, and its compiled code
is that of the built-in laws alone.

The wrappers live as long as the process (an address must outlive every run that holds it).
A law travels to other processes with the sweep's cases (``UserLaw`` pickles with its
functions, as numba pickles them: by value when defined in the script or notebook itself,
by reference when imported from a module, which the workers must then be able to import) and
``install`` registers it there.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from typing import NamedTuple

import numpy as np

from ..kernels.laws import user as kernel
from ..model.laws import user as records
from ..model.laws.record import Key

# Where each function goes in UserLaws: (family, role) -> column of ``address``.
_COLUMNS = {
    ("normal_law", "force"): kernel.A_FORCE,
    ("normal_law", "energy"): kernel.A_ENERGY,
    ("damping", "hysteresis"): kernel.A_HYSTERESIS,
    ("friction_law", "force"): kernel.A_FRICTION,
    ("friction_law", "sliding"): kernel.A_SLIDING,
    ("wear_law", "coefficient"): kernel.A_WEAR,
}  # "stiffness" is called from Python only (``jointwear check``)
_FAMILIES = {
    "normal_law": kernel.F_NORMAL,
    "damping": kernel.F_DAMPING,
    "friction_law": kernel.F_FRICTION,
    "wear_law": kernel.F_WEAR,
}
_WRAPPERS: dict[records.UserLaw, dict[str, object]] = {}  # per law, its cfunc per role


class LawKey(NamedTuple):
    """A key of a law registered from Python, beyond its unit (``register_law``'s ``keys``).

    ``unit``: its SI unit as pint writes it ("m/s", "Pa", "" for a plain number);
    ``default``: its value when the model file does not give it (None: required); ``low``,
    ``high``: bounds of its SI value, ``low`` exclusive when ``positive``; ``help``: what
    it is, in the message when it is missing.
    """

    unit: str
    default: float | None = None
    low: float | None = None
    high: float | None = None
    positive: bool = False
    help: str = ""


def register_law(
    family: str,
    name: str,
    function: Callable,
    *,
    keys: Mapping[str, str | LawKey] | None = None,
    summary: str = "",
    energy: Callable | None = None,
    stiffness: Callable | None = None,
    sliding: Callable | None = None,
) -> None:
    """Register a numba-compiled function as a law that model files can name.

    Parameters
    ----------
    family
        The model-file key that chooses it, or that family's title: ``"normal_law"``
        (``"normal"``), ``"damping"``, ``"friction_law"`` (``"friction"``) or
        ``"wear_law"`` (``"wear"``).
    name
        Its name in model files (lowercase, digits, _): not a built-in law's. Registering
        a name again replaces that law (the same family only).
    function
        An ``@numba.njit`` function returning a float: the elastic force [N], the hysteresis
        factor chi [-], the friction force [N] or the wear coefficient dh/ds / p [1/Pa]. It
        takes the arguments the family's built-in laws are given (docs/user-laws.md):
        ``(delta, k, n, e_star, d_r, width)``, ``(c_e)``, ``(v_t, f_n, c_f)`` or ``(mu)``,
        then the values of its ``keys`` in their order (SI).
    keys
        Its own keys, in the order the function takes them: name -> SI unit (``"m/s"``,
        ``""`` for a plain number) or ``LawKey``. A model file gives them in the joint's
        clearance table, with any unit of the same kind; all are required unless a
        ``LawKey`` gives a default. At most six.
    summary
        One line on what it computes, for ``jointwear check``.
    energy, stiffness
        Elastic laws only: the elastic energy [J] and the stiffness dF/d(delta) [N/m], with
        the force's arguments. Without them the energy is the force integrated by Gauss-Legendre
        quadrature, and ``check`` shows the force's central difference.
    sliding
        Friction laws only: the speed at which the contact slides (and wears) [m/s], with
        arguments ``(v_t)`` and the keys. Without it: ``abs(v_t)``.

    Raises
    ------
    ValueError
        If the family, name or keys cannot be registered (the message says why).
    TypeError
        If a function is not numba-compiled, takes other arguments, or does not compile to
        a float of floats.
    """
    from numba.extending import is_jitted

    key = records.family_key(family)
    main = records.ROLES[key][0].name  # force, hysteresis or coefficient
    more = {"energy": energy, "stiffness": stiffness, "sliding": sliding}
    given = {main: function} | {role: f for role, f in more.items() if f is not None}
    where = f"{key} '{name}'"
    for role, f in given.items():
        if not is_jitted(f):
            raise TypeError(
                f"{where}: its {role} function {getattr(f, '__name__', f)!r} is not compiled; "
                "decorate it with @numba.njit (the run calls it from compiled code)"
            )
    law = records.UserLaw(key, name, tuple(given.items()), _keys(where, keys), summary)
    records.check(law)
    _compile(law)
    records.register(law)


def unregister_law(name: str) -> None:
    """Remove the law registered from Python as ``name``.

    Raises
    ------
    KeyError
        If no law of that name was registered.
    """
    if records.registered(name) is None:
        known = ", ".join(law.name for law in records.registered_laws()) or "none"
        raise KeyError(f"no law registered as {name!r}; registered: {known}")
    records.unregister(name)


def _keys(where: str, keys: Mapping[str, str | LawKey] | None) -> tuple[Key, ...]:
    """The ``Key`` records of a registration's ``keys``."""
    if keys is None:
        return ()
    if not isinstance(keys, Mapping):
        raise ValueError(
            f"{where}: keys must map each key's name to its SI unit, e.g. "
            "{'stribeck_speed': 'm/s'} ('' for a plain number)"
        )
    records_ = []
    for name, declared in keys.items():
        spec = declared if isinstance(declared, LawKey) else LawKey(declared)
        records_.append(
            Key(name, spec.unit, spec.default, spec.low, spec.positive, spec.high, spec.help)
        )
    return tuple(records_)


def _compile(law: records.UserLaw) -> dict[str, object]:
    """The law's C-callable wrappers by role, compiled once per process."""
    if law not in _WRAPPERS:
        roles = {role.name: role for role in records.ROLES[law.family]}
        wrappers = {}
        for role, function in law.functions:
            if (law.family, role) in _COLUMNS:
                wrappers[role] = _wrapper(
                    f"{law.family} '{law.name}'", function, len(roles[role].arguments),
                    len(law.keys),
                )  # fmt: skip
        _WRAPPERS[law] = wrappers
    return _WRAPPERS[law]


def _wrapper(where: str, function: Callable, arguments: int, keys: int) -> object:
    """A cfunc of the kernels' signature calling ``function`` with its arguments and keys.

    It takes ``ARGUMENTS`` family arguments and ``N_KEYS`` parameters and passes the first
    ``arguments`` and ``keys`` of them on; an exception in ``function`` gives NaN, which the
    run's non-finite check reports.
    """
    from numba import cfunc, types
    from numba.core.errors import NumbaError

    signature = types.float64(*(types.float64,) * (kernel.ARGUMENTS + kernel.N_KEYS))

    def call(a0, a1, a2, a3, a4, a5, q0, q1, q2, q3, q4, q5):
        values = (a0, a1, a2, a3, a4, a5)[:arguments] + (q0, q1, q2, q3, q4, q5)[:keys]
        try:
            return function(*values)
        except Exception:
            return math.nan

    try:
        return cfunc(signature)(call)
    except NumbaError as error:
        reason = str(error).strip().splitlines()[0]
        raise TypeError(
            f"{where}: {function.__name__} does not compile to a float of float arguments "
            f"({reason})"
        ) from None


def install(laws: Iterable[records.UserLaw]) -> None:
    """Register ``laws`` in this process (a sweep's worker); the same ones again: nothing."""
    for law in laws:
        if records.registered(law.name) != law:
            records.check(law)
            _compile(law)
            records.register(law)


def user_tables(model: object) -> dict[str, kernel.UserLaws | None]:
    """Per joint type with clearance, its rows' user laws (``kernels.laws.user``)."""
    from ..joints import KINDS

    return {kind.name: _table([j.clearance for j in kind.joints(model)]) for kind in KINDS}


def _table(clearances: list) -> kernel.UserLaws | None:
    rows = len(clearances)
    chosen = [
        [(family, records.registered(getattr(c, family))) for family in records.FAMILIES]
        for c in clearances
    ]
    if not any(law is not None for row in chosen for _, law in row):
        return None
    address = np.zeros((rows, kernel.N_ADDRESSES), dtype=np.int64)
    params = np.zeros((rows, kernel.N_FAMILIES, kernel.N_KEYS))
    for i, (clearance, row) in enumerate(zip(clearances, chosen, strict=True)):
        for family, law in row:
            if law is None:
                continue
            for role, wrapper in _compile(law).items():
                address[i, _COLUMNS[family, role]] = wrapper.address
            values = clearance.law_values(records.FAMILIES[family].by_name[law.name])
            own = [values[key.name] for key in law.keys]
            params[i, _FAMILIES[family], : len(own)] = own
    return kernel.UserLaws(address=address, params=params)
