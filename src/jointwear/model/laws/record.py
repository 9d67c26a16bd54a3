"""The record of a law: everything about it, its kernel functions named, not imported.

A family (elastic, damping, friction, wear, wear distribution, lubrication) is a ``Family``:
the model-file key that chooses its law, its laws in code order, and the kernels'
dispatchers, each called as ``dispatcher(code, *arguments)``. A ``Law`` is a closed record:
its name and code, the keys it reads and how they are packed into the parameters the kernel
reads, its summary and citations, its validity ranges, its stiffness, the contact shapes it
applies to, and per dispatcher the kernel function the code reaches (``Kernel``). Nothing
here imports the kernels: ``Kernel.resolve`` does, when a caller asks.
"""

from collections.abc import Callable
from importlib import import_module
from typing import NamedTuple

CONFORMAL = "conformal"  # a journal in its bearing: a cylinder in a conforming cylindrical seat
CORNER_ON_FLAT = "corner_on_flat"  # a rounded corner, a line across the width, on a flat face
SHAPES = (CONFORMAL, CORNER_ON_FLAT)
SHAPE_NAMES = {CONFORMAL: "a journal in its bearing", CORNER_ON_FLAT: "a corner on a flat face"}

KERNEL_PACKAGE = "jointwear.kernels.laws"

# The records of laws registered from Python (``model.laws.user``): family key -> name -> Law.
REGISTERED: dict[str, dict[str, "Law"]] = {}


class Key(NamedTuple):
    """A model-file key that a law reads.

    ``unit`` is a pint unit string of the SI unit ("" for a plain number; "N/m^n" a plain
    number whose unit depends on the exponent); ``default`` None means the law cannot do
    without it (unless ``pack`` accepts an alternative); ``low`` and ``high`` bound the
    value, ``low`` exclusive when ``positive``.
    """

    name: str
    unit: str
    default: float | None
    low: float | None = 0.0
    positive: bool = False
    high: float | None = None
    help: str = ""


class Range(NamedTuple):
    """A quantity a law holds for only up to a limit; a run reports the time spent beyond it.

    ``name`` is the entry of ``outside_law_ranges`` in summary.json; ``limit`` the largest
    value, or the name of the law's key that sets it.
    """

    name: str
    limit: float | str


PENETRATION = "penetration_over_clearance"  # penetration / clearance [-]
HERTZ_PATCH = "hertz_half_width_over_journal_radius"  # Hertz half-width b / R_J [-]
ECCENTRICITY = "eccentricity_ratio"  # e / c of a lubricated journal [-]


class Contact(NamedTuple):
    """A contact as its element kind describes it to the laws (SI).

    ``relative_radius`` R* [m] is R_B R_J / (R_B - R_J) for a journal in its bearing and the
    corner's radius on a flat face (None: not given, so a stiffness must be); ``seat`` is
    (radius [m], Young's modulus [Pa], Poisson's ratio) of the body an elastic layer lines,
    None where there is none.
    """

    shape: str
    contact_modulus: float
    relative_radius: float | None
    clearance: float
    width: float
    seat: tuple[float, float, float] | None = None


class Stiffness(NamedTuple):
    """How a law's constant K (the kernels' ``k``) follows from its keys and the contact.

    ``formula(values, contact)`` [``unit``]; ``given_by`` names a key that, given, replaces
    the formula; ``citations`` per contact shape are those of the formula, cited when it is
    used.
    """

    formula: Callable[[dict, Contact], float]
    unit: str
    symbol: str  # how ``jointwear check`` names it
    citations: dict[str, tuple[str, ...]]
    given_by: str | None = None


class Kernel(NamedTuple):
    """The kernel function a dispatcher reaches for a law's code.

    ``function`` is "module:function" in ``jointwear.kernels.laws``; ``arguments`` are the
    names of the dispatcher's arguments it takes, in its order.
    """

    function: str
    arguments: tuple[str, ...]

    def resolve(self) -> Callable:
        """The compiled function (imports the kernels)."""
        return resolve(self.function)


def resolve(name: str) -> Callable:
    """The kernel function "module:function" of ``jointwear.kernels.laws`` (imports it)."""
    module, function = name.split(":")
    return getattr(import_module(f"{KERNEL_PACKAGE}.{module}"), function)


def _nothing(values: dict) -> tuple[float, ...]:
    return ()


class Law(NamedTuple):
    """One law of a family (module docstring).

    ``pack(values)`` turns the validated keys into the parameters the element reads, or
    raises ValueError saying what is missing; ``kernels`` has one entry per dispatcher of
    the family (none for a law that is the absence of one: the dispatcher returns its error
    value for that code and the element never calls it).
    """

    name: str
    code: int
    summary: str  # one line for ``jointwear check``: what the law computes
    citations: tuple[str, ...]  # keys of ``citations.REFERENCES``
    keys: tuple[Key, ...] = ()
    pack: Callable[[dict], tuple[float, ...]] = _nothing
    kernels: tuple[Kernel, ...] = ()
    ranges: tuple[Range, ...] = ()
    stiffness: Stiffness | None = None
    shapes: tuple[str, ...] = SHAPES  # the contacts it applies to
    shown: tuple[tuple[str, str], ...] = ()  # (label, unit) of packed parameters check shows


class Family(NamedTuple):
    """The laws chosen by one model-file key (module docstring)."""

    key: str  # the model-file key, e.g. "normal_law"
    title: str  # e.g. "normal", in ``jointwear check`` and ``law_parameters``
    laws: tuple[Law, ...]  # in code order
    default: str
    dispatchers: tuple[str, ...] = ()  # "module:function" in jointwear.kernels.laws

    @property
    def by_name(self) -> dict[str, Law]:
        """The family's laws by name: the built-in ones, then those registered from Python."""
        return {law.name: law for law in self.laws} | REGISTERED.get(self.key, {})


def family_keys(family: Family) -> dict[str, Key]:
    """Every key that some law of the family reads, by name (the first law's definition)."""
    keys: dict[str, Key] = {}
    for law in family.laws:
        for key in law.keys:
            keys.setdefault(key.name, key)
    return keys


def pack_in_order(*keys: Key) -> Callable[[dict], tuple[float, ...]]:
    """A ``pack`` that returns the keys' values in order, each required."""

    def pack(values: dict) -> tuple[float, ...]:
        missing = [k.name + (f" ({k.help})" if k.help else "") for k in keys
                   if values.get(k.name) is None]  # fmt: skip
        if missing:
            raise ValueError(f"needs {' and '.join(missing)}")
        return tuple(float(values[k.name]) for k in keys)

    return pack
