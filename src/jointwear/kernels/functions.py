"""Functions of time f(t) for drivers and applied loads, with two derivatives.

| kind | params | f(t) |
|---|---|---|
| POLYNOMIAL | c_0 .. c_7 (SI) | sum_k c_k t^k |
| HARMONIC | offset, amplitude, omega [rad/s], phase [rad] | offset + amplitude sin(omega t + phi) |
"""

import math

from numba import njit

from .codes import FunctionKind


@njit(cache=True)
def evaluate(kind, p, t):
    """Return f(t), f'(t), f''(t) for a function-table row (kind code, parameters)."""
    if kind == FunctionKind.HARMONIC:
        arg = p[2] * t + p[3]
        s = math.sin(arg)
        return p[0] + p[1] * s, p[1] * p[2] * math.cos(arg), -p[1] * p[2] * p[2] * s
    f = 0.0
    fd = 0.0
    fdd = 0.0
    for k in range(p.shape[0] - 1, -1, -1):  # Horner on f, f', f''
        fdd = fdd * t + 2.0 * fd
        fd = fd * t + f
        f = f * t + p[k]
    return f, fd, fdd
