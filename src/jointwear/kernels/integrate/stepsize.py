"""Error norms and step-size control shared by the integrator kernels.

Norm
    ``error_norm`` is the root-mean-square of ``err_i / (atol + rtol * max(|y0_i|, |y1_i|))``;
    a step is acceptable when the norm is at most 1.

PI controller
    ``pi_factor`` is the proportional-integral controller of Gustafsson as given in Hairer,
    Norsett & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed. (1993), sec. II.4,
    eq. (4.13')::

        h_new / h = SAFETY * err**(-alpha) * err_prev**beta,   alpha = 1/(q+1) - 0.75 beta

    where ``q`` is the order of the embedded (lower-order) solution, so that the error
    estimate behaves like ``h**(q+1)``; ``err_prev`` is the norm of the last *accepted* step
    (floored at ``ERR_PREV_MIN``). The factor is clipped to ``[FAC_MIN, FAC_MAX]``. After a
    rejection ``reject_factor`` (pure I-control, never above 1) is used instead.

Step clipping
    ``clip_step`` applies the step bounds and shortens (or stretches by at most 1 %) the
    step so that it ends exactly on a stop time; it also lands on an output row's time when
    that shortens the step by at most ``LAND_SHORTEN`` (the row then reuses the step's last
    evaluation instead of one of its own).
"""

import math

import numpy as np
from numba import njit

SAFETY = 0.9
FAC_MIN = 0.2
FAC_MAX = 10.0
BETA_DOPRI5 = 0.04  # PI gain for the 5(4) pair (Hairer II.4)
ERR_PREV_MIN = 1.0e-4
STRETCH = 1.01  # a step may grow by this factor to land on the stop time
ROUNDING = 1.0 + 1e-12  # h_max may be exceeded by this factor to land on a time [-]
LAND_SHORTEN = 0.1  # a step may shrink by this fraction of itself to land on an output row


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def error_norm(err: np.ndarray, y0: np.ndarray, y1: np.ndarray, rtol: float, atol: float) -> float:
    """Weighted RMS norm of an error vector.

    Parameters
    ----------
    err : ndarray, shape (n,)
        Local error estimate, in the units of ``y``.
    y0, y1 : ndarray, shape (n,)
        Solution at the start and at the end of the step.
    rtol : float
        Relative tolerance [-].
    atol : float
        Absolute tolerance, in the units of ``y``.

    Returns
    -------
    float
        ``sqrt(mean((err_i / (atol + rtol * max(|y0_i|, |y1_i|)))**2))``; 0 when ``n == 0``;
        NaN or inf when ``err`` is not finite.
    """
    n = err.shape[0]
    if n == 0:
        return 0.0
    s = 0.0
    for i in range(n):
        w = atol + rtol * max(abs(y0[i]), abs(y1[i]))
        r = err[i] / w
        s += r * r
    return math.sqrt(s / n)


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def pi_factor(err: float, err_prev: float, order: int, beta: float) -> float:
    """Step-size factor ``h_new / h`` after an accepted step (PI control).

    Parameters
    ----------
    err : float
        Error norm of the step just accepted (normalised: 1 is the tolerance).
    err_prev : float
        Error norm of the previous accepted step (use ``ERR_PREV_MIN`` at a start).
    order : int
        Order ``q`` of the embedded solution; the estimate scales like ``h**(q+1)``.
    beta : float
        Integral gain (``BETA_DOPRI5`` for the 5(4) pair, 0 for plain I-control).

    Returns
    -------
    float
        Factor in ``[FAC_MIN, FAC_MAX]``; ``FAC_MAX`` when ``err == 0``, ``FAC_MIN`` when
        ``err`` is not finite.
    """
    if not err <= 1.0e300:  # NaN or inf
        return FAC_MIN
    if err == 0.0:
        return FAC_MAX
    alpha = 1.0 / (order + 1.0) - 0.75 * beta
    ep = max(err_prev, ERR_PREV_MIN)
    fac = SAFETY * err ** (-alpha) * ep**beta
    return min(FAC_MAX, max(FAC_MIN, fac))


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def reject_factor(err: float, order: int) -> float:
    """Step-size factor ``h_new / h`` after a rejected step (I-control, at most 1).

    Parameters
    ----------
    err : float
        Error norm of the rejected step (> 1, or not finite).
    order : int
        Order ``q`` of the embedded solution, as for ``pi_factor``.

    Returns
    -------
    float
        ``min(1, max(FAC_MIN, SAFETY * err**(-1/(q+1))))``; ``FAC_MIN`` if ``err`` is not
        finite.
    """
    if not err <= 1.0e300:
        return FAC_MIN
    if err <= 0.0:
        return 1.0
    fac = SAFETY * err ** (-1.0 / (order + 1.0))
    return min(1.0, max(FAC_MIN, fac))


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def clip_step(
    t: float, h: float, h_min: float, h_max: float, t_stop: float, t_land: float
) -> float:
    """Bound a proposed step; land it on ``t_stop`` if near, and on ``t_land`` if cheap.

    Parameters
    ----------
    t : float
        Current time [s].
    h : float
        Proposed step [s] (> 0).
    h_min, h_max : float
        Step bounds [s]; ``h_min`` yields to ``t_stop`` (a last step may be shorter).
    t_stop : float
        Time the integration must not pass [s] (> ``t``).
    t_land : float
        Time a step should end on when it costs little (an output row) [s] (> ``t``).

    Returns
    -------
    float
        The step to take. If ``t_stop - t <= min(STRETCH * h, ROUNDING * h_max)`` (after
        bounding ``h``) the result is ``t_stop - t``: the step ends on the stop time and no
        sliver of a step is left over. Otherwise ``t_land - t`` if it is that close too, at
        least ``h_min``, and either at least ``(1 - LAND_SHORTEN) * h`` or the proposal was
        cut to ``h_max`` (a shortening that lasts: the steps after it land again, so give
        ``t_land`` only when rows are at least ``h_max`` apart). ``step_end`` gives the exact
        end time.
    """
    limited = h >= h_max
    h = min(max(h, h_min), h_max)
    reach = min(STRETCH * h, h_max * ROUNDING)
    if t_stop - t <= reach:
        return t_stop - t
    land = t_land - t
    if h_min <= land <= reach and (limited or land >= (1.0 - LAND_SHORTEN) * h):
        return land
    return h


@njit(cache=True, error_model="numpy", no_cfunc_wrapper=True)
def step_end(t: float, h: float, t_stop: float, t_land: float) -> float:
    """End time of the step ``h`` from ``t`` returned by ``clip_step`` [s].

    ``t_stop`` or ``t_land`` exactly when the step was clipped to end there, else ``t + h``.
    """
    if h == t_stop - t:
        return t_stop
    if h == t_land - t:
        return t_land
    return t + h
