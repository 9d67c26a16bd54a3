"""Integrator kernels (dopri5, abm, stepsize) driven by small pure-Python step loops."""

import inspect
import itertools
import math
from types import SimpleNamespace

import numba
import numpy as np
import pytest

from jointwear.kernels.integrate import abm, stepsize
from jointwear.kernels.integrate import rk as dp

TABLEAU = dp.DOPRI5
A, B, C, E = TABLEAU.a, TABLEAU.b, TABLEAU.c, TABLEAU.e
# The embedded 4th-order weights as published (Dormand and Prince 1980, Table 2).
BHAT = np.array([5179 / 57600, 0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40])

METHODS = ["dopri5", "abm"]

# --------------------------------------------------------------------------- problems


def harmonic(t, y, out):
    out[0] = y[1]
    out[1] = -y[0]


def harmonic_exact(t):
    return np.array([math.cos(t), -math.sin(t)])


ECC = 0.5
KEPLER_Y0 = np.array([1.0 - ECC, 0.0, 0.0, math.sqrt((1.0 + ECC) / (1.0 - ECC))])


def kepler(t, y, out):
    r3 = (y[0] * y[0] + y[1] * y[1]) ** 1.5
    out[0] = y[2]
    out[1] = y[3]
    out[2] = -y[0] / r3
    out[3] = -y[1] / r3


def kepler_exact(t):
    """Closed form from Kepler's equation E - e sin E = t (a = 1, GM = 1, pericentre at 0)."""
    ea = t
    for _ in range(60):
        ea -= (ea - ECC * math.sin(ea) - t) / (1.0 - ECC * math.cos(ea))
    b = math.sqrt(1.0 - ECC**2)
    ed = 1.0 / (1.0 - ECC * math.cos(ea))
    return np.array(
        [math.cos(ea) - ECC, b * math.sin(ea), -math.sin(ea) * ed, b * math.cos(ea) * ed]
    )


def test_kepler_closed_form_matches_dop853():
    from scipy.integrate import solve_ivp

    def fun(t, y):
        out = np.empty(4)
        kepler(t, y, out)
        return out

    t_eval = np.linspace(0.0, 2.0 * math.pi, 9)
    sol = solve_ivp(fun, (0.0, t_eval[-1]), KEPLER_Y0, "DOP853", t_eval, rtol=1e-13, atol=1e-13)
    exact = np.array([kepler_exact(t) for t in t_eval]).T
    assert np.abs(sol.y - exact).max() < 1e-10


PULSE_A = 100.0  # y' = a / (1 + a^2 (t-5)^2): a smooth step of width 1/a at t = 5


def pulse(t, y, out):
    out[0] = PULSE_A / (1.0 + (PULSE_A * (t - 5.0)) ** 2)


def pulse_exact(t):
    return np.array([math.atan(PULSE_A * (t - 5.0)) + math.atan(5.0 * PULSE_A)])


def exp_sin(t, y, out):  # y' = y cos t, y = exp(sin t)
    out[0] = y[0] * math.cos(t)


# --------------------------------------------------------------------------- drivers


def _collect(res, j, t_now, interp, dinterp):
    """Fill the outputs with t_out <= t_now from the dense output of the last step."""
    while j < len(res.t_out) and res.t_out[j] <= t_now:
        interp(res.t_out[j], res.y_out[j])
        dinterp(res.t_out[j], res.dy_out[j])
        j += 1
    return j


def _new_result(t_out, n):
    t_out = np.asarray(t_out, dtype=float)
    return SimpleNamespace(
        t_out=t_out,
        y_out=np.full((len(t_out), n), np.nan),
        dy_out=np.full((len(t_out), n), np.nan),
        n_accept=0,
        n_reject=0,
        orders=[],
        stop_times=[],
        right_end_exact=True,
    )


def drive_dopri5(f, t0, y0, stops, rtol, atol, h0, h_max, t_out):
    n = len(y0)
    res = _new_result(t_out, n)
    st = dp.make_rk_state(n)
    f0 = np.empty(n)
    ybuf = np.empty(n)

    def interp(t, out):
        dp.rk_interpolate(st, t, out)

    def dinterp(t, out):
        dp.rk_interpolate_derivative(st, t, out)

    j = 0
    for i, t_stop in enumerate(stops):
        t = t0 if i == 0 else st.scal[dp.S_T]
        y = np.array(y0, dtype=float) if i == 0 else st.y.copy()
        f(t, y, f0)
        dp.rk_start(st, t, y, f0, h0)
        j = _collect(res, j, t, interp, dinterp)
        while st.scal[dp.S_T] < t_stop:
            dp.rk_begin(st, h_max, 0.0, t_stop, t_stop)
            for s in range(1, 7):
                ts = dp.rk_stage(st, s)
                f(ts, st.ystage, st.k[s])
            err = dp.rk_error(st, rtol, atol)
            if err <= 1.0:
                dp.rk_accept(st, err)
                j = _collect(res, j, st.scal[dp.S_T], interp, dinterp)
                interp(st.scal[dp.S_T], ybuf)
                res.right_end_exact &= bool(np.all(ybuf == st.y))
            else:
                dp.rk_reject(st, err)
        res.stop_times.append(st.scal[dp.S_T])
    res.t, res.y = st.scal[dp.S_T], st.y.copy()
    res.n_accept, res.n_reject = int(st.count[dp.C_NACCEPT]), int(st.count[dp.C_NREJECT])
    return res


def drive_abm(f, t0, y0, stops, rtol, atol, h0, h_max, t_out):
    n = len(y0)
    res = _new_result(t_out, n)
    st = abm.make_abm_state(n)
    yp0, y_pred, yp_pred, y_corr, yp_corr, ybuf = (np.empty(n) for _ in range(6))

    def interp(t, out):
        abm.abm_interpolate(st, t, out)

    def dinterp(t, out):
        abm.abm_interpolate_derivative(st, t, out)

    j = 0
    for i, t_stop in enumerate(stops):
        t = t0 if i == 0 else st.scal[abm.S_T]
        y = np.array(y0, dtype=float) if i == 0 else st.y.copy()
        f(t, y, yp0)
        abm.abm_start(st, t, y, yp0, h0)
        j = _collect(res, j, t, interp, dinterp)
        while st.scal[abm.S_T] < t_stop:
            t_new = abm.abm_predict(st, h_max, 0.0, t_stop, t_stop, y_pred)
            f(t_new, y_pred, yp_pred)
            err = abm.abm_correct(st, yp_pred, rtol, atol, y_corr)
            if err <= 1.0:
                f(t_new, y_corr, yp_corr)
                res.orders.append((t_new, int(st.ints[abm.I_K])))
                abm.abm_accept(st, y_corr, yp_corr)
                j = _collect(res, j, st.scal[abm.S_T], interp, dinterp)
                interp(st.scal[abm.S_T], ybuf)
                res.right_end_exact &= bool(np.all(ybuf == st.y))
            else:
                abm.abm_reject(st)
        res.stop_times.append(st.scal[abm.S_T])
    res.t, res.y = st.scal[abm.S_T], st.y.copy()
    res.n_accept = int(st.ints[abm.I_NACCEPT])
    res.n_reject = int(st.ints[abm.I_NREJECT])
    return res


def integrate(
    method, f, t0, y0, t_end, rtol, atol=None, h0=1e-4, h_max=math.inf, restarts=(), t_out=()
):
    """Integrate to t_end, stopping exactly at (and restarting from) each time in restarts."""
    drive = drive_dopri5 if method == "dopri5" else drive_abm
    stops = [*sorted(restarts), t_end]
    return drive(f, t0, y0, stops, rtol, rtol if atol is None else atol, h0, h_max, t_out)


def slope(tols, errs):
    return np.polyfit(np.log(tols), np.log(errs), 1)[0]


# --------------------------------------------------------------------------- tableau


def tree_residuals(b, a, c, theta=1.0):
    """Residuals of the 8 order conditions up to order 4 for weights b (at fraction theta)."""
    ac = a @ c
    return np.array(
        [
            b.sum() - theta,
            b @ c - theta**2 / 2,
            b @ c**2 - theta**3 / 3,
            b @ ac - theta**3 / 6,
            b @ c**3 - theta**4 / 4,
            b @ (c * ac) - theta**4 / 8,
            b @ (a @ c**2) - theta**4 / 12,
            b @ (a @ ac) - theta**4 / 24,
        ]
    )


def test_tableau_structure():
    np.testing.assert_allclose(A.sum(axis=1), C, atol=1e-15)
    assert np.all(np.triu(A) == 0.0)  # explicit
    assert np.array_equal(A[6], B) and C[6] == 1.0  # FSAL
    assert math.isclose(B.sum(), 1.0, abs_tol=1e-15)
    assert math.isclose(BHAT.sum(), 1.0, abs_tol=1e-15)
    np.testing.assert_allclose(E, B - BHAT)
    assert abs(E.sum()) < 1e-15


@pytest.mark.parametrize("q", [1, 2, 3, 4, 5])
def test_quadrature_order_conditions(q):
    assert math.isclose(B @ C ** (q - 1), 1.0 / q, abs_tol=1e-14)
    if q <= 4:
        assert math.isclose(BHAT @ C ** (q - 1), 1.0 / q, abs_tol=1e-14)
    else:  # the embedded solution is only of order 4
        assert abs(BHAT @ C**4 - 0.2) > 1e-6


def test_tree_order_conditions_up_to_4():
    np.testing.assert_allclose(tree_residuals(B, A, C), 0.0, atol=1e-14)
    np.testing.assert_allclose(tree_residuals(BHAT, A, C), 0.0, atol=1e-14)


@pytest.mark.parametrize("theta", [0.1, 0.5, 0.77, 1.0])
def test_dense_output_weights_satisfy_order_4(theta):
    # The continuous extension's weights b_i(theta) = sum_p P[i, p] theta^(p+1).
    b = TABLEAU.p @ theta ** np.arange(1, TABLEAU.p.shape[1] + 1)
    np.testing.assert_allclose(tree_residuals(b, A, C, theta), 0.0, atol=1e-13)


# --------------------------------------------------------------------------- dopri5 single steps


class Step:
    """Dense output of one accepted step of length h from t0, at the fraction theta."""

    def __init__(self, st, t0, h):
        self.st, self.t0, self.h = st, t0, h

    def value(self, theta, out):
        dp.rk_interpolate(self.st, self.t0 + theta * self.h, out)

    def slope(self, theta, out):
        dp.rk_interpolate_derivative(self.st, self.t0 + theta * self.h, out)


def one_step(f, t0, y0, h):
    n = len(y0)
    st, f0 = dp.make_rk_state(n), np.empty(n)
    f(t0, y0, f0)
    dp.rk_start(st, t0, y0, f0, h)
    dp.rk_begin(st, h, 0.0, t0 + 10.0 * h, t0 + 10.0 * h)
    for s in range(1, 7):
        ts = dp.rk_stage(st, s)
        f(ts, st.ystage, st.k[s])
    err = dp.rk_error(st, 1.0, 1.0)
    err_vector = st.err.copy()
    dp.rk_accept(st, err)
    return st.y.copy(), err_vector, Step(st, t0, h)


def test_dense_output_endpoints_exact():
    y0 = np.array([1.3])
    y1, _, rcont = one_step(exp_sin, 0.4, y0, 0.3)
    out = np.empty(1)
    rcont.value(0.0, out)
    assert out[0] == y0[0]
    rcont.value(1.0, out)
    assert out[0] == y1[0]
    # the derivative matches f at both ends (Hermite conditions)
    f = np.empty(1)
    for theta, t, y in ((0.0, 0.4, y0), (1.0, 0.7, y1)):
        rcont.slope(theta, out)
        exp_sin(t, y, f)
        assert math.isclose(out[0], f[0], rel_tol=1e-13)


def test_dopri5_local_orders():
    """Local errors: solution O(h^6), estimate O(h^5), dense output O(h^5), its slope O(h^4)."""
    t0 = 0.5
    hs = np.array([0.2, 0.1, 0.05, 0.025])
    thetas = np.linspace(0.0, 1.0, 21)
    e_sol, e_est, e_den, e_der = [], [], [], []
    out = np.empty(1)
    for h in hs:
        y1, err, rcont = one_step(exp_sin, t0, np.array([math.exp(math.sin(t0))]), h)
        e_sol.append(abs(y1[0] - math.exp(math.sin(t0 + h))))
        e_est.append(abs(err[0]))
        den, der = 0.0, 0.0
        for th in thetas:
            t = t0 + th * h
            rcont.value(th, out)
            den = max(den, abs(out[0] - math.exp(math.sin(t))))
            rcont.slope(th, out)
            der = max(der, abs(out[0] - math.cos(t) * math.exp(math.sin(t))))
        e_den.append(den)
        e_der.append(der)
    assert slope(hs, e_sol) > 5.6
    assert 4.4 < slope(hs, e_est) < 5.5
    assert 4.7 < slope(hs, e_den) < 5.6  # continuous extension of order 4
    assert 3.7 < slope(hs, e_der) < 4.7


# --------------------------------------------------------------------------- stepsize


def test_error_norm():
    err = np.array([1e-6, -2e-6])
    y0 = np.array([0.0, 10.0])
    y1 = np.array([-1.0, 2.0])
    got = stepsize.error_norm(err, y0, y1, 1e-3, 1e-6)
    want = math.sqrt(((1e-6 / 1.001e-3) ** 2 + (2e-6 / 1.0001e-2) ** 2) / 2)
    assert math.isclose(got, want, rel_tol=1e-14)
    assert math.isnan(stepsize.error_norm(np.array([np.nan]), y0[:1], y1[:1], 1e-3, 1e-6))


def test_pi_controller():
    assert stepsize.pi_factor(0.0, 1.0, 4, 0.04) == stepsize.FAC_MAX
    assert stepsize.pi_factor(1e12, 1.0, 4, 0.04) == stepsize.FAC_MIN
    assert stepsize.pi_factor(np.nan, 1.0, 4, 0.04) == stepsize.FAC_MIN
    # alpha = 1/5 - 0.75 * 0.04, beta = 0.04 (Hairer II.4)
    want = 0.9 * 0.5 ** (-(0.2 - 0.03)) * 0.3**0.04
    assert math.isclose(stepsize.pi_factor(0.5, 0.3, 4, 0.04), want, rel_tol=1e-14)
    assert stepsize.reject_factor(3.0, 4) < 1.0
    assert stepsize.reject_factor(np.inf, 4) == stepsize.FAC_MIN


def test_clip_step():
    def clip(t, h, h_min, h_max, t_stop, t_land=None):
        return stepsize.clip_step(t, h, h_min, h_max, t_stop, t_stop if t_land is None else t_land)

    assert clip(0.0, 5.0, 0.0, 1.0, 10.0) == 1.0
    assert clip(0.0, 1e-9, 1e-6, 1.0, 10.0) == 1e-6
    assert clip(0.1, 1.0, 0.0, 10.0, 0.3) == 0.3 - 0.1  # lands on t_stop
    assert clip(0.0, 1.0, 0.0, 10.0, 1.005) == 1.005  # no sliver left
    assert clip(0.0, 1.0, 0.0, 10.0, 1.05) == 1.0
    # an output row is landed on when the step shrinks by at most LAND_SHORTEN or grows by 1 %
    shortest = 1.0 - stepsize.LAND_SHORTEN
    assert clip(0.0, 1.0, 0.0, 10.0, 10.0, shortest + 0.01) == shortest + 0.01
    assert clip(0.0, 1.0, 0.0, 10.0, 10.0, 1.005) == 1.005
    assert clip(0.0, 1.0, 0.0, 10.0, 10.0, shortest - 0.01) == 1.0
    assert clip(0.0, 1.0, 0.0, 10.0, 10.0, 1.05) == 1.0
    assert clip(0.0, 1.0, 0.0, 1.0, 10.0, 1.005) == 1.0  # not past h_max
    assert clip(0.0, 1e-6, 1e-6, 1.0, 10.0, 0.95e-6) == 1e-6  # not below h_min
    # the end time is exact on either target
    t, t_land = 0.1, 0.3
    h = clip(t, 0.2, 0.0, 1.0, 10.0, t_land)
    assert stepsize.step_end(t, h, 10.0, t_land) == t_land
    assert stepsize.step_end(t, 0.05, 10.0, t_land) == t + 0.05


# --------------------------------------------------------------------------- both methods


def check_convergence(method, tols, errs):
    """Errors fall as rtol tightens, roughly in proportion (slope of log err vs log rtol ~ 1).

    The ABM step policy of Shampine & Gordon keeps h unchanged while the error estimate is
    anywhere in (2**-(k+1), 1] x 1/2, so its error-vs-tolerance curve is a staircase: only
    monotonicity and the overall slope are asked of it.
    """
    assert all(e2 < e1 for e1, e2 in itertools.pairwise(errs)), errs
    if method == "dopri5":
        assert all(e2 < e1 / 10 for e1, e2 in itertools.pairwise(errs)), errs
    assert 0.75 < slope(tols, errs) < 1.35, errs
    assert max(e / t for e, t in zip(errs, tols, strict=True)) < 1000, errs


@pytest.mark.parametrize("method", METHODS)
def test_harmonic_convergence(method):
    tols = [1e-4, 1e-6, 1e-8, 1e-10]
    t_end = 20.0 * math.pi  # 10 periods
    errs = []
    for tol in tols:
        r = integrate(method, harmonic, 0.0, [1.0, 0.0], t_end, tol)
        assert r.t == t_end
        errs.append(np.abs(r.y - harmonic_exact(t_end)).max())
    check_convergence(method, tols, errs)


@pytest.mark.parametrize("method", METHODS)
def test_kepler_convergence(method):
    tols = [1e-6, 1e-8, 1e-10]
    t_end = 2.0 * math.pi  # one orbit, e = 0.5
    errs = []
    for tol in tols:
        r = integrate(method, kepler, 0.0, KEPLER_Y0, t_end, tol)
        errs.append(np.abs(r.y - kepler_exact(t_end)).max())
    check_convergence(method, tols, errs)


@pytest.mark.parametrize("method", METHODS)
def test_interpolation_accuracy(method):
    tol = 1e-8
    t_out = np.linspace(0.0, 6.0 * math.pi, 401)
    r = integrate(method, harmonic, 0.0, [1.0, 0.0], t_out[-1], tol, t_out=t_out)
    exact = np.array([harmonic_exact(t) for t in t_out])
    dexact = np.column_stack([exact[:, 1], -exact[:, 0]])
    end_err = np.abs(r.y - exact[-1]).max()
    assert np.abs(r.y_out - exact).max() < max(3.0 * end_err, 100 * tol)
    assert np.abs(r.dy_out - dexact).max() < 1000 * tol
    assert r.right_end_exact
    # outputs between the steps are not worse than the steps themselves, roughly
    assert np.abs(r.y_out - exact).max() < 1e-6


@pytest.mark.parametrize("method", METHODS)
def test_stop_exactly_and_restart(method):
    tol = 1e-9
    restarts = [0.1 + 0.2, 1.234567, 7.7]  # 0.1 + 0.2 is not 0.3: must be hit bit for bit
    t_end = 4.0 * math.pi
    r = integrate(method, kepler, 0.0, KEPLER_Y0, t_end, tol, restarts=restarts)
    assert r.stop_times == [*restarts, t_end]
    ref = integrate(method, kepler, 0.0, KEPLER_Y0, t_end, tol)
    exact = kepler_exact(t_end)
    err, err_ref = np.abs(r.y - exact).max(), np.abs(ref.y - exact).max()
    assert err < max(10 * err_ref, 1e-6)
    if method == "abm":  # each restart drops to order 1, which then climbs again
        for t_restart in restarts:
            after = [k for t, k in r.orders if t > t_restart]
            assert after[0] == 1
            assert max(after[:40]) >= 5


@pytest.mark.parametrize("method", METHODS)
def test_sharp_transient_rejections(method):
    tol = 1e-7
    r = integrate(method, pulse, 0.0, [0.0], 10.0, tol, h0=1e-3)
    assert r.n_reject > 0
    assert abs(r.y[0] - pulse_exact(10.0)[0]) < 100 * tol


@pytest.mark.parametrize("method", METHODS)
def test_h_max_respected(method):
    r = integrate(method, harmonic, 0.0, [1.0, 0.0], 2.0, 1e-6, h_max=0.05)
    assert r.n_accept >= 40


def test_methods_agree():
    tol = 1e-9
    t_out = np.linspace(0.0, 2.0 * math.pi, 37)
    a = integrate("dopri5", kepler, 0.0, KEPLER_Y0, t_out[-1], tol, t_out=t_out)
    b = integrate("abm", kepler, 0.0, KEPLER_Y0, t_out[-1], tol, t_out=t_out)
    exact = np.array([kepler_exact(t) for t in t_out])
    assert np.abs(a.y_out - exact).max() < 2e-6
    assert np.abs(b.y_out - exact).max() < 2e-6
    assert np.abs(a.y_out - b.y_out).max() < 2e-6


# --------------------------------------------------------------------------- abm specifics


def test_abm_order_rises():
    r = integrate("abm", harmonic, 0.0, [1.0, 0.0], 10.0, 1e-8)
    orders = [k for _, k in r.orders]
    assert orders[:4] == [1, 2, 3, 4]  # start phase: one order up per step
    assert max(orders) >= 8
    assert r.n_accept < 300


def test_abm_constant_step_coefficients():
    """With equal steps g_i are the Adams-Bashforth coefficients gamma_{i-1}."""
    st = abm.make_abm_state(1)
    h = 0.01
    abm.abm_start(st, 0.0, np.zeros(1), np.ones(1), h)  # fictitious history has equal steps
    st.ints[abm.I_K] = 7
    abm.abm_predict(st, h, 0.0, 1.0, 1.0, np.empty(1))
    gamma = [1, 1 / 2, 5 / 12, 3 / 8, 251 / 720, 95 / 288, 19087 / 60480, 5257 / 17280]
    np.testing.assert_allclose(st.g[:8], gamma, rtol=1e-14)


def test_abm_interpolation_unchanged_by_rejected_attempts():
    st = abm.make_abm_state(2)
    y, yp, yq, ypq, yc, ypc = (np.empty(2) for _ in range(6))
    y[:] = [1.0, 0.0]
    harmonic(0.0, y, yp)
    abm.abm_start(st, 0.0, y, yp, 1e-3)
    for _ in range(12):
        t_new = abm.abm_predict(st, math.inf, 0.0, 10.0, 10.0, yq)
        harmonic(t_new, yq, ypq)
        abm.abm_correct(st, ypq, 1e-8, 1e-8, yc)
        harmonic(t_new, yc, ypc)
        abm.abm_accept(st, yc, ypc)
    t_mid = st.scal[abm.S_T] - 0.5 * st.scal[abm.S_HOLD]
    before, after = np.empty(2), np.empty(2)
    abm.abm_interpolate(st, t_mid, before)
    st.scal[abm.S_HNEXT] *= 50.0  # a step far too long
    t_new = abm.abm_predict(st, math.inf, 0.0, 10.0, 10.0, yq)
    harmonic(t_new, yq, ypq)
    assert abm.abm_correct(st, ypq, 1e-8, 1e-8, yc) > 1.0
    abm.abm_reject(st)
    abm.abm_interpolate(st, t_mid, after)
    assert np.array_equal(before, after)
    np.testing.assert_allclose(before, harmonic_exact(t_mid), atol=1e-8)


def test_nonfinite_error_is_rejected():
    st = dp.make_rk_state(1)
    dp.rk_start(st, 0.0, np.ones(1), np.ones(1), 0.1)
    dp.rk_begin(st, 1.0, 0.0, 1.0, 1.0)
    st.k[1:] = np.nan
    err = dp.rk_error(st, 1e-6, 1e-6)
    assert not err <= 1.0
    assert math.isclose(dp.rk_reject(st, err), 0.1 * stepsize.FAC_MIN)


@pytest.mark.parametrize("module", [stepsize, dp, abm])
def test_kernels_are_cached_njit(module):
    for name, obj in vars(module).items():
        if inspect.isfunction(obj) and obj.__module__ == module.__name__:
            assert name.startswith("make_"), name  # plain Python only for allocation
        elif isinstance(obj, numba.core.registry.CPUDispatcher):
            assert obj._cache.__class__.__name__ != "NullCache", name
