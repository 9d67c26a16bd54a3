"""Laws registered from Python (``jointwear.register_law``): calling them from the kernels.

A user law is an ``@njit`` function registered under a name (its record:
``model.laws.user``). For each, jointwear compiles a C-callable wrapper of one fixed
signature, ``ARGUMENTS + N_KEYS`` floats to a float (``engine.user_laws``): the family's
arguments, padded with zeros to ``ARGUMENTS``, then the law's own parameters, padded to
``N_KEYS``. A kind whose rows choose user laws gets a ``UserLaws`` table: per row, the
addresses of its laws' wrappers and their own parameters.

The dispatchers below take that table and the row before the built-in dispatcher's
arguments. A code below ``USER_CODE`` goes to the built-in dispatcher; from ``USER_CODE`` on,
the row's wrapper is called through its address (one indirect call; the address is data, so
every user law runs in one compiled loop, which is cached like any kernel).

Which of the two a kind gets is chosen when the loop compiles, by the table's type: for
``NoUserLaws`` each dispatcher is the built-in one, unchanged, so a run without user laws
compiles and steps as it did before user laws existed.

| symbol | meaning | unit |
|---|---|---|
| user | the kind's ``UserLaws`` or ``NoUserLaws`` | |
| row | the joint's row in its kind's tables | |
| law, damping | the law's code (``USER_CODE`` and above: registered from Python) | |
| q0..q5 | a user law's own parameters, in the order of its keys | SI |

The other arguments are the built-in dispatchers' (``normal``, ``friction``, ``wear``).
"""

from typing import NamedTuple

import numpy as np
from numba import njit, types
from numba.experimental import function_type  # noqa: F401 - the model of FunctionPrototype
from numba.extending import intrinsic, overload

from ..structs import kind_of
from . import friction, normal, wear

USER_CODE = 100  # law codes from here on are laws registered from Python
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


class UserLaws(NamedTuple):
    """The user laws of one kind's rows (a row without one has zeros)."""

    address: np.ndarray  # (rows, N_ADDRESSES) int64
    params: np.ndarray  # (rows, N_FAMILIES, N_KEYS) own parameters, SI


class NoUserLaws(NamedTuple):
    """No row of the kind chooses a user law: the dispatchers are the built-in ones."""

    rows: int


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


@njit(cache=True, no_cpython_wrapper=True)
def _call(user, row, function, family, a0, a1, a2, a3, a4, a5):
    """The row's wrapper of ``function`` at (a0..a5, its own parameters)."""
    q = user.params[row, family]
    arguments = (a0, a1, a2, a3, a4, a5, q[0], q[1], q[2], q[3], q[4], q[5])
    return _call_address(user.address[row, function], arguments)


def _by_table(stub: object, builtin: object, with_user: object) -> object:
    """Make ``stub(user, row, *args)`` compile to ``builtin(*args)`` for ``NoUserLaws``.

    And to ``with_user(user, row, *args)`` for ``UserLaws`` (``structs.by_kind``'s way).
    """

    @overload(stub)
    def _choose(user, row, *args):
        if kind_of(user) == NoUserLaws.__name__:
            return lambda user, row, *args: builtin(*args)
        return lambda user, row, *args: with_user(user, row, *args)

    return stub


@njit(cache=True, no_cpython_wrapper=True)
def _elastic_force(user, row, law, delta, k, n, e_star, d_r, width):
    if law < USER_CODE:
        return normal.elastic_force(law, delta, k, n, e_star, d_r, width)
    return _call(user, row, A_FORCE, F_NORMAL, delta, k, n, e_star, d_r, width)


@njit(cache=True, no_cpython_wrapper=True)
def _elastic_energy(user, row, law, delta, k, n, e_star, d_r, width):
    if law < USER_CODE:
        return normal.elastic_energy(law, delta, k, n, e_star, d_r, width)
    if delta <= 0.0:
        return 0.0
    if user.address[row, A_ENERGY] != 0:
        return _call(user, row, A_ENERGY, F_NORMAL, delta, k, n, e_star, d_r, width)
    energy = 0.0  # the integral of the force, as normal.liu_energy (s = delta t^2)
    for i in range(normal.GAUSS_NODES.shape[0]):
        t = normal.GAUSS_NODES[i]
        force = _call(user, row, A_FORCE, F_NORMAL, delta * t * t, k, n, e_star, d_r, width)
        energy += normal.GAUSS_WEIGHTS[i] * 2.0 * delta * t * force
    return energy


@njit(cache=True, no_cpython_wrapper=True)
def _damped(user, row, elastic, delta_dot, delta_dot_minus, damping, c_e):
    if damping < USER_CODE:
        return normal.damped(elastic, delta_dot, delta_dot_minus, damping, c_e)
    chi = _call(user, row, A_HYSTERESIS, F_DAMPING, c_e, 0.0, 0.0, 0.0, 0.0, 0.0)
    return normal.damped_by(elastic, delta_dot, delta_dot_minus, chi)


@njit(cache=True, no_cpython_wrapper=True)
def _tangential_force(user, row, law, v_t, f_n, c_f, p0, p1, p2):
    if law < USER_CODE:
        return friction.tangential_force(law, v_t, f_n, c_f, p0, p1, p2)
    return _call(user, row, A_FRICTION, F_FRICTION, v_t, f_n, c_f, 0.0, 0.0, 0.0)


@njit(cache=True, no_cpython_wrapper=True)
def _slip_speed(user, row, law, v_t, p0, p1, p2):
    if law < USER_CODE:
        return friction.slip_speed(law, v_t, p0, p1, p2)
    if user.address[row, A_SLIDING] == 0:
        return abs(v_t)
    return _call(user, row, A_SLIDING, F_FRICTION, v_t, 0.0, 0.0, 0.0, 0.0, 0.0)


@njit(cache=True, no_cpython_wrapper=True)
def _wear_coefficient(user, row, law, mu, p0):
    if law < USER_CODE:
        return wear.wear_coefficient(law, mu, p0)
    return _call(user, row, A_WEAR, F_WEAR, mu, 0.0, 0.0, 0.0, 0.0, 0.0)


def elastic_force(user, row, law, delta, k, n, e_star, d_r, width):
    """Elastic force [N]: ``normal.elastic_force``, or the row's user law (delta > 0 only)."""


def elastic_energy(user, row, law, delta, k, n, e_star, d_r, width):
    """Elastic energy [J]: ``normal.elastic_energy``, or the row's user law's.

    A user law without an energy function: its force integrated by Gauss-Legendre
    quadrature (exact for a power law of exponent up to 10).
    """


def damped(user, row, elastic, delta_dot, delta_dot_minus, damping, c_e):
    """Normal force [N]: ``normal.damped``, or with the row's user damping law's chi."""


def tangential_force(user, row, law, v_t, f_n, c_f, p0, p1, p2):
    """Friction force [N]: ``friction.tangential_force``, or the row's user law's."""


def slip_speed(user, row, law, v_t, p0, p1, p2):
    """Sliding speed [m/s]: ``friction.slip_speed``, or the row's user law's (abs(v_t))."""


def wear_coefficient(user, row, law, mu, p0):
    """Wear coefficient [1/Pa]: ``wear.wear_coefficient``, or the row's user law's."""


for _stub, _builtin, _with_user in (
    (elastic_force, normal.elastic_force, _elastic_force),
    (elastic_energy, normal.elastic_energy, _elastic_energy),
    (damped, normal.damped, _damped),
    (tangential_force, friction.tangential_force, _tangential_force),
    (slip_speed, friction.slip_speed, _slip_speed),
    (wear_coefficient, wear.wear_coefficient, _wear_coefficient),
):
    _by_table(_stub, _builtin, _with_user)
