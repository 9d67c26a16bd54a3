"""Functions f(x) for drivers and applied loads, with two derivatives, and their argument x.

| kind | params | f(x) |
|---|---|---|
| POLYNOMIAL | c_0 .. c_7 (SI) | sum_k c_k x^k |
| HARMONIC | offset, amplitude, omega, phase | offset + amplitude sin(omega x + phase) |
| SPLINE | data offset o, intervals n, period P (0: none) | the cubic of x's interval |
| FOURIER | data offset o, harmonics n, omega | mean + sum_k a_k cos(k w x) + b_k sin(k w x) |

A spline's data are its n + 1 breakpoints, then 4 n coefficients; a series' data are mean,
a_1, b_1, .. a_n, b_n.

A spline's interval i holds c3, c2, c1, c0 of c3 d^3 + c2 d^2 + c1 d + c0, d = x - x_i (scipy's
``PPoly`` coefficients). A periodic spline is evaluated at x wrapped into its first period; a
spline that is not periodic is NaN outside its breakpoints (the run stops as non-finite).

A function row's argument (``mech.function_argument``: kind, index, second body; geometry in
``mech.function_geometry``) is the time, a driver's prescribed value at that time, or a state
quantity: a body's angle or angular speed, a joint's slide or slide speed. ``value`` gives
F(t) = f(x(t)) and, for time and driver arguments, its time derivatives by the chain rule (a
state argument's own rates are not computed: only loads use them, and loads need no rate).
"""

import math

from numba import njit

from .codes import ArgumentKind, FunctionKind
from .kinematics import angle, angular_velocity, point_position, point_velocity, rotate


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def evaluate(kind, p, data, x):
    """Return f(x), f'(x), f''(x) for a function-table row (kind code, parameters, data)."""
    if kind == FunctionKind.HARMONIC:
        arg = p[2] * x + p[3]
        s = math.sin(arg)
        return p[0] + p[1] * s, p[1] * p[2] * math.cos(arg), -p[1] * p[2] * p[2] * s
    if kind == FunctionKind.SPLINE:
        return _spline(p, data, x)
    if kind == FunctionKind.FOURIER:
        return _fourier(p, data, x)
    f = 0.0
    fd = 0.0
    fdd = 0.0
    for k in range(p.shape[0] - 1, -1, -1):  # Horner on f, f', f''
        fdd = fdd * x + 2.0 * fd
        fd = fd * x + f
        f = f * x + p[k]
    return f, fd, fdd


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _spline(p, data, x):
    first = int(p[0])
    n = int(p[1])
    period = p[2]
    breaks = data[first : first + n + 1]
    if period > 0.0:
        x = breaks[0] + (x - breaks[0]) - period * math.floor((x - breaks[0]) / period)
    elif not breaks[0] <= x <= breaks[n]:
        return math.nan, math.nan, math.nan
    i = _interval(breaks, x)
    c = data[first + n + 1 + 4 * i : first + n + 5 + 4 * i]
    d = x - breaks[i]
    f = ((c[0] * d + c[1]) * d + c[2]) * d + c[3]
    return f, (3.0 * c[0] * d + 2.0 * c[1]) * d + c[2], 6.0 * c[0] * d + 2.0 * c[1]


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _interval(breaks, x):
    """The interval i, 0 <= i < n, with breaks[i] <= x < breaks[i + 1] (the last one closed).

    A bisection written out: numpy's searchsorted would make every process that loads the
    cached loop import numba's array-math module, and with it scipy's BLAS (0.2 s).
    """
    low = 0
    high = breaks.shape[0] - 1
    while high - low > 1:
        middle = (low + high) // 2
        if breaks[middle] <= x:
            low = middle
        else:
            high = middle
    return low


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _fourier(p, data, x):
    first = int(p[0])
    omega = p[2]
    c1 = math.cos(omega * x)
    s1 = math.sin(omega * x)
    ck, sk = c1, s1
    f = data[first]
    fd = 0.0
    fdd = 0.0
    for k in range(1, int(p[1]) + 1):
        a = data[first + 2 * k - 1]
        b = data[first + 2 * k]
        w = k * omega
        f += a * ck + b * sk
        fd += w * (b * ck - a * sk)
        fdd -= w * w * (a * ck + b * sk)
        ck, sk = ck * c1 - sk * s1, sk * c1 + ck * s1  # cos and sin of (k + 1) omega x
    return f, fd, fdd


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def argument(mech, fn, t, q, qd):
    """The argument x of function row fn at time t and state (q, qd), with x' and x''."""
    kind = mech.function_argument[fn, 0]
    i = mech.function_argument[fn, 1]
    if kind == ArgumentKind.TIME:
        return t, 1.0, 0.0
    if kind == ArgumentKind.DRIVER:  # a driver's own function is of time
        g = mech.driver_function[i]
        return evaluate(mech.function_kind[g], mech.function_param[g], mech.function_data, t)
    if kind == ArgumentKind.ANGLE:
        return angle(q, i), 0.0, 0.0
    if kind == ArgumentKind.ANGULAR_SPEED:
        return angular_velocity(qd, i), 0.0, 0.0
    if kind == ArgumentKind.SLIDE or kind == ArgumentKind.SLIDE_SPEED:
        slide, rate = _slide(mech.function_geometry[fn], i, mech.function_argument[fn, 2], q, qd)
        return (slide if kind == ArgumentKind.SLIDE else rate), 0.0, 0.0
    return math.nan, math.nan, math.nan


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def _slide(geometry, b1, b2, q, qd):
    """Slide [m] of point 2 of body b2 from point 1 of body b1 along b1's axis, and its rate.

    ``geometry`` holds point 1, point 2 (body frames) and the unit axis (b1's frame).
    """
    p1x, p1y = point_position(q, b1, geometry[0], geometry[1])
    p2x, p2y = point_position(q, b2, geometry[2], geometry[3])
    v1x, v1y = point_velocity(q, qd, b1, geometry[0], geometry[1])
    v2x, v2y = point_velocity(q, qd, b2, geometry[2], geometry[3])
    ux, uy = rotate(q, b1, geometry[4], geometry[5])
    w = angular_velocity(qd, b1)
    dx = p2x - p1x
    dy = p2y - p1y
    return dx * ux + dy * uy, (v2x - v1x) * ux + (v2y - v1y) * uy + w * (dy * ux - dx * uy)


@njit(cache=True, error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)
def value(mech, fn, t, q, qd):
    """F = f(x), F' and F'' [SI] of function row fn at time t, state (q, qd); 0 for fn < 0."""
    if fn < 0:
        return 0.0, 0.0, 0.0
    x, xd, xdd = argument(mech, fn, t, q, qd)
    f, fd, fdd = evaluate(mech.function_kind[fn], mech.function_param[fn], mech.function_data, x)
    return f, fd * xd, fdd * xd * xd + fd * xdd
