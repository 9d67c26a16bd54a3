"""The law dispatchers the contact elements call, and the laws registered from Python.

Each dispatcher here takes the kind's law table (``KindLaws``), the row and the law's code
before the family's arguments, and compiles for the codes the kind's rows use (its
``LawSet``): one branch per built-in law (``dispatch``, from the family's table in
``normal``, ``friction``, ``wear`` or ``lubrication``), and one to the row's user law where
the kind has any.

A user law is an ``@njit`` function registered under a name (its record:
``model.laws.user``). For each, jointwear compiles a C-callable wrapper of one fixed
signature, ``ARGUMENTS + N_KEYS`` floats to a float (``engine.user_laws``): the family's
arguments, padded with zeros to ``ARGUMENTS``, then the law's own parameters, padded to
``N_KEYS``. A kind's ``KindLaws`` holds per row the addresses of its user laws' wrappers and
their own parameters; from ``USER_CODE`` on, a code calls the row's wrapper through its
address (one indirect call; the address is data, so every user law runs in one compiled
loop, which is cached like any kernel).

| symbol | meaning | unit |
|---|---|---|
| laws | the kind's ``KindLaws`` | |
| row | the joint's row in its kind's tables | |
| law, damping | the law's code (``USER_CODE`` and above: registered from Python) | |
| q0..q5 | a user law's own parameters, in the order of its keys | SI |

The other arguments are the families' (``normal``, ``friction``, ``wear``, ``lubrication``).
"""

from typing import NamedTuple

import numpy as np
from numba import njit, types
from numba.experimental import function_type  # noqa: F401 - the model of FunctionPrototype
from numba.extending import intrinsic

from . import friction, lubrication, normal, wear
from .dispatch import compiled
from .lawset import LawSet

ARGUMENTS = 6  # family arguments of every wrapper (the elastic laws' six; fewer padded)
N_KEYS = 6  # most own parameters of a user law

# Columns of UserLaws.address: a row's wrapper of each function (0: none given).
A_FORCE = 0  # elastic force f(delta, k, n, e_star, d_r, width, q...) [N]
A_ENERGY = 1  # elastic energy, the same arguments [J]; 0: by quadrature of the force
A_HYSTERESIS = 2  # damping: hysteresis factor chi(c_e, q...) [-]
A_FRICTION = 3  # friction force f_t(v_t, f_n, c_f, q...) [N]
A_SLIDING = 4  # sliding speed s(v_t, q...) [m/s]; 0: abs(v_t), sticking only at rest
A_WEAR = 5  # wear coefficient dh/ds / p (mu, q...) [1/Pa]
N_ADDRESSES = 6

# First index of UserLaws.params: the family whose law's parameters these are.
F_NORMAL = 0
F_DAMPING = 1
F_FRICTION = 2
F_WEAR = 3
N_FAMILIES = 4


class KindLaws(NamedTuple):
    """The laws of one kind's rows: the codes compiled, and the user laws' wrappers."""

    used: LawSet  # per family, the codes the rows choose
    address: np.ndarray  # (rows, N_ADDRESSES) int64: each row's wrappers (0: none)
    params: np.ndarray  # (rows, N_FAMILIES, N_KEYS) the user laws' own parameters, SI


class UserLaws(NamedTuple):
    """The user laws of one kind's rows, as ``engine.user_laws`` gives them (Python)."""

    address: np.ndarray  # (rows, N_ADDRESSES) int64
    params: np.ndarray  # (rows, N_FAMILIES, N_KEYS)


def kind_laws(
    ints: np.ndarray, columns: dict[str, tuple[int, tuple[int, ...]]], user: UserLaws | None
) -> KindLaws:
    """The law table of a kind's rows (Python).

    ``columns``: per family key, the column of ``ints`` that holds the rows' codes and the
    family's laws on demand (``lawset``); ``user``: the rows' user laws, None where no row
    has one.
    """
    rows = ints.shape[0]
    if user is None:
        user = UserLaws(
            np.zeros((rows, N_ADDRESSES), np.int64), np.zeros((rows, N_FAMILIES, N_KEYS))
        )
    used = LawSet(
        {family: ints[:, column] for family, (column, _) in columns.items()},
        {family: on_demand for family, (_, on_demand) in columns.items()},
    )
    return KindLaws(used=used, address=user.address, params=user.params)


_SIGNATURE = types.FunctionPrototype(types.float64, (types.float64,) * (ARGUMENTS + N_KEYS))


@intrinsic
def _call_address(typingctx, address, arguments):
    """Call the C function at ``address`` (an integer) with the floats of ``arguments``."""
    if not isinstance(address, types.Integer) or arguments != types.UniTuple(
        types.float64, ARGUMENTS + N_KEYS
    ):
        return None

    def codegen(context, builder, signature, values):
        pointer = builder.inttoptr(values[0], context.get_function_pointer_type(_SIGNATURE))
        floats = [builder.extract_value(values[1], i) for i in range(ARGUMENTS + N_KEYS)]
        return context.call_function_pointer(builder, pointer, floats)

    return types.float64(address, arguments), codegen


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _call(laws, row, function, family, a0, a1, a2, a3, a4, a5):
    """The row's wrapper of ``function`` at (a0..a5, its own parameters)."""
    q = laws.params[row, family]
    arguments = (a0, a1, a2, a3, a4, a5, q[0], q[1], q[2], q[3], q[4], q[5])
    return _call_address(laws.address[row, function], arguments)


# The user laws' branches of the dispatchers (``dispatch.compiled``): codes >= USER_CODE.


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_force(laws, row, law, delta, k, n, e_star, d_r, width):
    return _call(laws, row, A_FORCE, F_NORMAL, delta, k, n, e_star, d_r, width)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_energy(laws, row, law, delta, k, n, e_star, d_r, width):
    if delta <= 0.0:
        return 0.0
    if laws.address[row, A_ENERGY] != 0:
        return _call(laws, row, A_ENERGY, F_NORMAL, delta, k, n, e_star, d_r, width)
    energy = 0.0  # the integral of the force, as normal.liu_energy
    for i in range(normal.GAUSS_NODES.shape[0]):
        s, weight = normal.quadrature_node(delta, i)
        energy += weight * _call(laws, row, A_FORCE, F_NORMAL, s, k, n, e_star, d_r, width)
    return energy


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_hysteresis(laws, row, law, c_e):
    return _call(laws, row, A_HYSTERESIS, F_DAMPING, c_e, 0.0, 0.0, 0.0, 0.0, 0.0)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_friction(laws, row, law, v_t, f_n, c_f, p0, p1, p2):
    return _call(laws, row, A_FRICTION, F_FRICTION, v_t, f_n, c_f, 0.0, 0.0, 0.0)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_sliding(laws, row, law, v_t, p0, p1, p2):
    if laws.address[row, A_SLIDING] == 0:
        return abs(v_t)
    return _call(laws, row, A_SLIDING, F_FRICTION, v_t, 0.0, 0.0, 0.0, 0.0, 0.0)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _user_wear(laws, row, law, mu, p0):
    return _call(laws, row, A_WEAR, F_WEAR, mu, 0.0, 0.0, 0.0, 0.0, 0.0)


def elastic_force(laws, row, law, delta, k, n, e_star, d_r, width):
    """Elastic force [N] of the row's normal law (delta > 0 only, for a user law)."""


def elastic_energy(laws, row, law, delta, k, n, e_star, d_r, width):
    """Elastic energy [J] of the row's normal law.

    A user law without an energy function: its force integrated by Gauss-Legendre
    quadrature (exact for a power law of exponent up to 10).
    """


def hysteresis_factor(laws, row, damping, c_e):
    """Hysteresis factor chi [-] of the row's damping law."""


def tangential_force(laws, row, law, v_t, f_n, c_f, p0, p1, p2):
    """Friction force [N] of the row's friction law."""


def slip_speed(laws, row, law, v_t, p0, p1, p2):
    """Sliding speed [m/s] of the row's friction law (a user law without one: abs(v_t))."""


def wear_coefficient(laws, row, law, mu, p0):
    """Wear coefficient [1/Pa] of the row's wear law."""


def film_force_components(laws, row, law, table, eps, eps_dot, gamma_dot, w, mu, r, width, c):
    """Film force (f_r, f_t) [N] of the row's lubrication law (no user laws)."""


# Each dispatcher here, the family's table it compiles from, and its user laws' branch.
COMPILED = (
    (elastic_force, normal.elastic_force, _user_force),
    (elastic_energy, normal.elastic_energy, _user_energy),
    (hysteresis_factor, normal.hysteresis_factor, _user_hysteresis),
    (tangential_force, friction.tangential_force, _user_friction),
    (slip_speed, friction.slip_speed, _user_sliding),
    (wear_coefficient, wear.wear_coefficient, _user_wear),
    (film_force_components, lubrication.film_force_components, None),
)
for _stub, _dispatch, _user in COMPILED:
    compiled(_stub, _dispatch, _user)


@njit(cache=True, no_cpython_wrapper=True, no_cfunc_wrapper=True)
def damped(laws, row, elastic, delta_dot, delta_dot_minus, damping, c_e):
    """Normal force [N]: the elastic force with the row's damping law (``normal.damped_by``)."""
    chi = hysteresis_factor(laws, row, damping, c_e)
    return normal.damped_by(elastic, delta_dot, delta_dot_minus, chi)
