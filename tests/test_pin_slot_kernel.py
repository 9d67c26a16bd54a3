"""The pin-in-slot kernel called directly, against answers by hand (kernels.elements.pin_slot).

Bodies are (x, y, phi) in q; body -1 is the ground. Unless a test says otherwise the slot has
R_s = 10 mm, a gap of 0.1 mm and l = 20 mm, the pin a Hertz contact with K = 1e10 N/m^1.5.
"""

import math
from functools import partial

import numpy as np
import pytest
from numba import njit

from jointwear.kernels.elements import journal
from jointwear.kernels.elements import pin_slot as ps
from jointwear.kernels.laws.friction import FrictionLaw
from jointwear.kernels.laws.normal import Damping, ElasticLaw
from jointwear.kernels.laws.wear import WearLaw

R_S, GAP, HALF_LENGTH = 10e-3, 1e-4, 20e-3
R_P = R_S - GAP
K, EXPONENT, WIDTH = 1e10, 1.5, 0.01
MU, V_REG, K_WEAR, SHARE = 0.2, 1e-4, 1e-13, 0.3
E_STAR, MIN_SPEED, TOL = 1.1e11, 1e-4, 1e-10
approx = partial(pytest.approx, rel=1e-6, abs=0.0)  # relative only: volumes are 1e-14 m^3


def make(
    *, slot=-1, pin=0, centre=(0.0, 0.0), axis=0.0, pin_point=(0.0, 0.0), half_length=HALF_LENGTH,
    damping=Damping.NONE, restitution=1.0, friction_coefficient=MU, feedback=0,
    cells=(20, 12, 36), snapshots=0,
):  # fmt: skip
    """One joint's tables: the slot on body ``slot`` through ``centre`` along angle ``axis``."""
    ints = np.zeros(ps.N_INTS, dtype=np.int64)
    ints[[ps.I_SLOT, ps.I_PIN]] = slot, pin
    ints[ps.I_NORMAL] = ElasticLaw.HERTZ
    ints[ps.I_DAMPING] = damping
    ints[ps.I_FRICTION] = FrictionLaw.COULOMB
    ints[ps.I_WEAR] = WearLaw.ARCHARD
    ints[ps.I_FEEDBACK] = feedback
    ints[[ps.I_SEGMENTS, ps.I_END_SECTORS, ps.I_PIN_SECTORS]] = cells
    p = np.zeros(ps.N_PARAMS)
    p[[ps.P_C_X, ps.P_C_Y]] = centre
    p[[ps.P_U_X, ps.P_U_Y]] = math.cos(axis), math.sin(axis)
    p[[ps.P_P_X, ps.P_P_Y]] = pin_point
    p[ps.P_L], p[ps.P_RS], p[ps.P_RP], p[ps.P_C] = half_length, R_S, R_P, GAP
    p[ps.P_K], p[ps.P_EXP], p[ps.P_CE] = K, EXPONENT, restitution
    p[ps.P_CF], p[ps.P_F0] = friction_coefficient, V_REG
    p[ps.P_WEAR], p[ps.P_SHARE], p[ps.P_WIDTH] = K_WEAR, SHARE, WIDTH
    p[ps.P_ESTAR], p[ps.P_MIN_SPEED], p[ps.P_TOL] = E_STAR, MIN_SPEED, TOL
    return ps.make_tables(ints[None], p[None], snapshots)


def compiled(kernel):
    """A Python-callable twin of a kernel (the kernels carry no CPython wrapper)."""
    return njit(lambda *args: kernel(*args))


add_forces, begin_period, accumulate, write_outputs, elastic_energy, journal_forces = map(
    compiled,
    (ps.add_forces, ps.begin_period, ps.accumulate, ps.write_outputs, ps.elastic_energy,
     journal.add_forces),
)  # fmt: skip


def forces(tables, q, qd):
    """Generalised forces g of the joint at (q, q') [N, N, N m]."""
    table, state, _, scratch = tables
    g = np.zeros_like(q)
    add_forces(table, state, scratch, q, qd, g)
    return g


def pin_at(x, y, axis=0.0, centre=(0.0, 0.0), phi=0.0):
    """q of a pin body (centre at its origin) at (x, y) in a ground slot's (u, v) frame."""
    c, s = math.cos(axis), math.sin(axis)
    return np.array([centre[0] + c * x - s * y, centre[1] + s * x + c * y, phi])


def hertz(delta):
    return K * delta**EXPONENT


# ---------------------------------------------------------------- l = 0 is the revolute joint


def make_journal(slot, pin, centre, pin_point, damping, restitution):
    ints = np.zeros(journal.N_INTS, dtype=np.int64)
    ints[[journal.I_BEARING, journal.I_JOURNAL]] = slot, pin
    ints[journal.I_NORMAL] = ElasticLaw.HERTZ
    ints[journal.I_FRICTION] = FrictionLaw.COULOMB
    ints[journal.I_DAMPING] = damping
    ints[journal.I_FEEDBACK] = 1
    ints[journal.I_SECTORS] = 36
    p = np.zeros(journal.N_PARAMS)
    p[[journal.P_SB_X, journal.P_SB_Y]] = centre
    p[[journal.P_SJ_X, journal.P_SJ_Y]] = pin_point
    p[journal.P_RB], p[journal.P_RJ], p[journal.P_C] = R_S, R_P, GAP
    p[journal.P_K], p[journal.P_EXP], p[journal.P_CE] = K, EXPONENT, restitution
    p[journal.P_CF], p[journal.P_F0] = MU, V_REG
    p[journal.P_WIDTH], p[journal.P_ESTAR] = WIDTH, E_STAR
    p[journal.P_MIN_SPEED], p[journal.P_TOL] = MIN_SPEED, TOL
    return journal.make_tables(ints[None], p[None], 0)


@pytest.mark.parametrize("damping", [Damping.NONE, Damping.LANKARANI_NIKRAVESH])
@pytest.mark.parametrize("onset", [False, True])
def test_zero_length_slot_is_the_revolute_clearance_joint(damping, onset):
    """l = 0: add_forces equals the journal kernel's, for both bodies, to round-off.

    Same laws and state (a contact period under way or not; the pin worn like the journal,
    the ends and the bearing unworn), two moving bodies with offsets, eccentricities past the
    gap in eight directions, rotating and translating bodies.
    """
    centre, pin_point = (0.03, -0.01), (-0.02, 0.005)
    rng = np.random.default_rng(7)
    worn = rng.uniform(0.0, 5e-7, 36)
    touching = 0
    for i, direction in enumerate(np.linspace(0.1, 2 * math.pi + 0.1, 8, endpoint=False)):
        kinds = (
            make(slot=0, pin=1, centre=centre, pin_point=pin_point, half_length=0.0,
                 damping=damping, restitution=0.8, feedback=1),
            make_journal(0, 1, centre, pin_point, damping, 0.8),
        )  # fmt: skip
        kinds[0][1].wear[0, ps.PIN, :36] = worn
        kinds[1][1].wear[0, 1] = worn
        if onset:
            for state in (kinds[0][1], kinds[1][1]):
                state.contact_on[0], state.impact_speed[0] = 1, 0.3
        slot_q = np.array([0.1, 0.2, 0.4 + i])
        c, s = math.cos(slot_q[2]), math.sin(slot_q[2])
        bearing = slot_q[:2] + np.array(
            [c * centre[0] - s * centre[1], s * centre[0] + c * centre[1]]
        )
        e = GAP + 1e-6 * (1 + i)
        phi = -0.3 * i
        c, s = math.cos(phi), math.sin(phi)
        journal_centre = bearing + e * np.array([math.cos(direction), math.sin(direction)])
        offset = [c * pin_point[0] - s * pin_point[1], s * pin_point[0] + c * pin_point[1]]
        q = np.array([*slot_q, *(journal_centre - offset), phi])
        qd = rng.normal(0.0, 0.5, 6)
        g_slot = forces(kinds[0], q, qd)
        g_journal = np.zeros(6)
        table, state, _, scratch = kinds[1]
        journal_forces(table, state, scratch, q, qd, g_journal)
        touching += np.abs(g_journal).max() > 1.0  # (a receding damped contact may not push)
        scale = max(np.abs(g_journal).max(), 1.0)
        np.testing.assert_allclose(g_slot, g_journal, rtol=1e-12, atol=1e-12 * scale)
    assert touching >= 4


# ---------------------------------------------------------------- a pin on a side


@pytest.mark.parametrize("sliding", [+1.0, -1.0])
def test_pin_pressed_on_a_side_by_hand(sliding):
    """Slot body and pin body both moving; delta, n, forces and moments against a hand sum.

    The slot body sits at r_s, angle 0.7; its centre line passes through C (body frame
    (0.01, 0.02)) along the body's 30 degree direction. The pin centre is at x = 0.3 l,
    y = -(c + delta0) (the -v side), the pin slides along u at +-0.5 m/s relative to the
    slot. Then n = -v, f_n = K delta0^1.5, and Coulomb friction mu f_n opposes the sliding;
    the output row holds them and the friction power mu f_n 0.5 m/s.
    """
    delta0, axis_body, phi_slot = 3e-6, math.radians(30.0), 0.7
    centre_body = np.array([0.01, 0.02])
    tables = make(slot=0, pin=1, centre=centre_body, axis=axis_body)
    r_slot = np.array([0.2, -0.1])
    rot = np.array([[math.cos(phi_slot), -math.sin(phi_slot)],
                    [math.sin(phi_slot), math.cos(phi_slot)]])  # fmt: skip
    u = rot @ [math.cos(axis_body), math.sin(axis_body)]
    v = np.array([-u[1], u[0]])
    c_global = r_slot + rot @ centre_body
    x, y = 0.3 * HALF_LENGTH, -(GAP + delta0)
    p_global = c_global + x * u + y * v
    q = np.array([*r_slot, phi_slot, *p_global, 1.3])
    qd = np.zeros(6)
    qd[3:5] = sliding * 0.5 * u  # the slot body at rest, the pin sliding along u
    g = forces(tables, q, qd)
    contact = tables[3].contact[0]
    assert contact[ps.C_SURFACE] == ps.SIDE_MINUS_V
    assert contact[ps.C_DELTA] == approx(delta0, rel=1e-9)
    np.testing.assert_allclose(contact[[ps.C_NX, ps.C_NY]], -v, atol=1e-12)
    f_n = hertz(delta0)
    n = -v
    on_pin = -f_n * n - sliding * MU * f_n * u  # friction against the pin's sliding
    at_pin = p_global + R_P * n
    q_point = c_global + x * u + R_S * n  # the slot's contact point
    np.testing.assert_allclose(g[3:5], on_pin, rtol=1e-9)
    np.testing.assert_allclose(g[0:2], -on_pin, rtol=1e-9)
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]  # noqa: E731
    assert g[5] == approx(cross(at_pin - p_global, on_pin), rel=1e-9)
    assert g[2] == approx(cross(q_point - r_slot, -on_pin), rel=1e-9)
    row = np.zeros(len(ps.OUTPUT_NAMES))
    write_outputs(tables[0], tables[3], row, 0)
    by_hand = {
        "along": x, "across": y, "fx": on_pin[0], "fy": on_pin[1], "fn": f_n, "vt": 0.5 * sliding,
        "friction_power": MU * f_n * 0.5, "damping_power": 0.0,
    }  # fmt: skip
    np.testing.assert_allclose(row, [by_hand[name] for name in ps.OUTPUT_NAMES], rtol=1e-9)


def test_an_end_by_hand():
    """A pin in the -u end at 40 degrees from the outward axis: delta, surface code, phi."""
    delta0, angle = 2e-6, math.radians(40.0)
    tables = make()
    radius = GAP + delta0
    # the -u end's outward axis is -u; phi turns it towards -v
    x = -HALF_LENGTH - radius * math.cos(angle)
    y = -radius * math.sin(angle)
    g = forces(tables, pin_at(x, y), np.zeros(3))
    contact = tables[3].contact[0]
    assert contact[ps.C_SURFACE] == ps.END_MINUS_U
    assert contact[ps.C_WHERE] == approx(angle, rel=1e-9)
    assert contact[ps.C_DELTA] == approx(delta0, rel=1e-9)
    n = np.array([-math.cos(angle), -math.sin(angle)])
    np.testing.assert_allclose(g[:2], -hertz(delta0) * n, rtol=1e-9)


@pytest.mark.parametrize("end", [+1.0, -1.0])
def test_continuous_from_side_to_end(end):
    """delta, n and the force across abs(x) = l: the jump over 2 eps is O(eps^2 / y)."""
    delta0, eps = 2e-6, 1e-9
    y = GAP + delta0
    results = []
    for x in (end * (HALF_LENGTH - eps), end * HALF_LENGTH, end * (HALF_LENGTH + eps)):
        tables = make(axis=0.4)
        g = forces(tables, pin_at(x, y, axis=0.4), np.zeros(3))
        results.append((tables[3].contact[0].copy(), g))
    surfaces = [c[ps.C_SURFACE] for c, _ in results]
    assert surfaces[0] == ps.SIDE_PLUS_V
    assert surfaces[2] == (ps.END_PLUS_U if end > 0 else ps.END_MINUS_U)
    deltas = np.array([c[ps.C_DELTA] for c, _ in results])
    assert np.ptp(deltas) <= eps**2 / y  # d = sqrt(y^2 + eps^2) beyond the side
    f = np.array([g[:2] for _, g in results])
    slope = 1.5 * hertz(delta0) / delta0 * eps**2 / y + hertz(delta0) * eps / y  # size, turning
    assert np.abs(f - f[0]).max() <= 2 * slope


# ---------------------------------------------------------------- wear


@pytest.mark.parametrize("feedback", [0, 1])
def test_worn_depths_widen_the_gap(feedback):
    """Uniform worn depths on the slot's surfaces and the pin: delta falls by their sum.

    Side +v worn w_s, end -u worn w_e, pin worn w_p, all uniform (so their cell layout does
    not matter); without feedback delta is that of the unworn joint.
    """
    delta0, w_s, w_e, w_p = 3e-6, 1e-6, 0.5e-6, 0.25e-6
    tables = make(feedback=feedback)
    wear = tables[1].wear[0]
    wear[ps.SIDE_PLUS_V], wear[ps.END_MINUS_U], wear[ps.PIN] = w_s, w_e, w_p
    radius = GAP + delta0
    places = ((pin_at(0.5 * HALF_LENGTH, radius), w_s), (pin_at(-HALF_LENGTH - radius, 0.0), w_e))
    for q, w_slot in places:
        forces(tables, q, np.zeros(3))
        expected = delta0 - feedback * (w_slot + w_p)
        assert tables[3].contact[0, ps.C_DELTA] == approx(expected, rel=1e-9)


def slide(tables, path, steps, duration):
    """Accumulate ``steps`` equal steps over ``duration`` [s] along path(t) -> (q, qd)."""
    table, state, log, scratch = tables
    h = duration / steps
    for i in range(steps):
        q, qd = path((i + 0.5) * h)
        accumulate(table, state, scratch, log, i * h, (i + 1) * h, q, qd, np.zeros(0), 0)


def side_path(x0, speed, delta0, phi=-0.0873):
    """The pin (turned by phi, about -5 deg) pressed delta0 into the +v side, sliding along u."""
    return lambda t: (pin_at(x0 + speed * t, GAP + delta0, phi=phi), np.array([speed, 0.0, 0.0]))


def test_archard_along_a_side():
    """Worn volume k F s, split by the share, into the segments passed over and the pin's sector.

    The pin (not rotating) slides 16 mm along the +v side from x = -8 mm under F = K delta0^1.5;
    20 segments of 2 mm, 4 steps each, the steps aligned with them: each segment passed over
    gets (1 - share) k F / width, the others none; the pin's one sector (n = +v at 95 degrees
    in the pin's frame: sector 9 of 36) takes share k F s over its arc.
    """
    delta0, speed = 1e-6, 0.2
    f = hertz(delta0)
    s = 16e-3
    tables = make(feedback=0)
    slide(tables, side_path(-8e-3, speed, delta0), 32, s / speed)
    _, state, log, _ = tables
    totals = log.totals[0]
    assert totals[ps.T_WORN_VOLUME] == approx(K_WEAR * f * s, rel=1e-12)
    assert totals[ps.T_SLIDING] == approx(s, rel=1e-12)
    assert totals[ps.T_FRICTION_ENERGY] == approx(MU * f * s, rel=1e-12)
    assert totals[ps.T_CONTACT_TIME] == approx(s / speed, rel=1e-12)
    side = state.wear[0, ps.SIDE_PLUS_V, :20]
    expected = np.zeros(20)
    expected[6:14] = (1 - SHARE) * K_WEAR * f / WIDTH  # [-8, 8] mm of [-20, 20] mm
    np.testing.assert_allclose(side, expected, rtol=1e-12, atol=0.0)
    pin = state.wear[0, ps.PIN, :36]
    expected = np.zeros(36)
    expected[9] = SHARE * K_WEAR * f * s / (2 * math.pi * R_P / 36 * WIDTH)
    np.testing.assert_allclose(pin, expected, rtol=1e-12, atol=0.0)
    assert not state.wear[0, [ps.SIDE_MINUS_V, ps.END_PLUS_U, ps.END_MINUS_U]].any()


def around_the_end(delta0, angular_speed):
    """The pin pressed delta0 into the +u end, its centre turning about the end centre."""
    radius = GAP + delta0

    def path(t):
        a = -1.2 + angular_speed * t
        q = pin_at(HALF_LENGTH + radius * math.cos(a), radius * math.sin(a), phi=0.5 * t)
        qd = np.array([-radius * math.sin(a), radius * math.cos(a), 0.5]) * [
            angular_speed, angular_speed, 1.0,
        ]  # fmt: skip
        return q, qd

    return path


@pytest.mark.parametrize("cells", [(1, 1, 1), (7, 5, 13), (40, 33, 64)])
def test_worn_volume_does_not_depend_on_the_cells(cells):
    """A side slide, then a sweep round an end: each surface's cells hold its share exactly.

    The volume per surface is sum(depth x cell length x width); the slot's surfaces together
    hold (1 - share) of T_WORN_VOLUME and the pin share of it, whatever the cell counts; and
    T_WORN_VOLUME is the same for every count, k sum(F ds) of the two phases.
    """
    tables = make(cells=cells, feedback=0)
    slide(tables, side_path(-15e-3, 0.3, 1e-6), 50, 0.08)
    slide(tables, around_the_end(2e-6, 40.0), 60, 0.06)
    _, state, log, _ = tables
    total = log.totals[0, ps.T_WORN_VOLUME]
    lengths = (2 * HALF_LENGTH, 2 * HALF_LENGTH, math.pi * R_S, math.pi * R_S, 2 * math.pi * R_P)
    counts = (cells[0], cells[0], cells[1], cells[1], cells[2])
    volumes = [
        state.wear[0, i, : counts[i]].sum() * lengths[i] / counts[i] * WIDTH for i in range(5)
    ]
    assert sum(volumes[:4]) == approx((1 - SHARE) * total, rel=1e-12)
    assert volumes[ps.PIN] == approx(SHARE * total, rel=1e-12)
    assert volumes[ps.SIDE_PLUS_V] > 0 and volumes[ps.END_PLUS_U] > 0
    # the same total whatever the cells: k F s of the side plus k int F ds round the end
    side = hertz(1e-6) * 0.3 * 0.08
    v_t = 40.0 * (GAP + 2e-6) + 0.5 * R_P  # t . (v_P - v_Q) + omega_pin R_p
    end = hertz(2e-6) * v_t * 0.06
    assert total == approx(K_WEAR * (side + end), rel=1e-9)


# ---------------------------------------------------------------- periods and energy


def test_begin_period_opens_past_the_tolerance_and_records_the_impact():
    """Below the tolerance nothing opens; past it the period opens with its impact info."""
    table, state, log, scratch = make()
    info = np.zeros(ps.N_IMPACT_INFO)
    angle = math.radians(-25.0)
    qd = np.array([-0.4, -0.1, 0.0])  # approaching the -u end
    for delta, opens in ((0.5 * TOL, False), (3 * TOL, True)):
        radius = GAP + delta
        q = pin_at(-HALF_LENGTH - radius * math.cos(angle), -radius * math.sin(angle))
        assert begin_period(table, state, scratch, log, 0, q, qd, info) == opens
    n = np.array([-math.cos(angle), -math.sin(angle)])
    speed = n @ qd[:2]
    assert state.contact_on[0] == 1
    assert state.impact_speed[0] == approx(speed, rel=1e-12)
    assert info[ps.IMPACT_SPEED] == approx(speed, rel=1e-12)
    assert info[ps.IMPACT_SURFACE] == ps.END_MINUS_U
    assert info[ps.IMPACT_WHERE] == approx(angle, rel=1e-9)
    assert info[ps.IMPACT_DELTA] == approx(3 * TOL, rel=1e-3)
    assert log.totals[0, ps.T_IMPACTS] == 1
    q = pin_at(0.0, GAP - 1e-7)  # clear of the wall: the period closes
    assert not begin_period(table, state, scratch, log, 0, q, qd, info)
    assert state.contact_on[0] == 0


def test_damping_power_while_the_force_is_clamped():
    """Receding fast with overlap: f_n = 0, and the damping power is -f_e delta_dot > 0."""
    table, state, log, scratch = tables = make(damping=Damping.LANKARANI_NIKRAVESH, restitution=0.5)
    state.contact_on[0], state.impact_speed[0] = 1, 0.1
    delta0, receding = 1e-6, -1.0  # chi = 0.5625: the factor 1 + chi (-10) < 0
    q, qd = pin_at(0.0, GAP + delta0), np.array([0.0, receding, 0.0])
    forces(tables, q, qd)
    row = np.zeros(len(ps.OUTPUT_NAMES))
    assert write_outputs(table, scratch, row, 0) == len(ps.OUTPUT_NAMES)
    c = scratch.contact[0]
    assert c[ps.C_FN] == 0.0
    power = row[ps.OUTPUT_NAMES.index("damping_power")]
    assert power == approx(-hertz(delta0) * receding, rel=1e-9)
    accumulate(table, state, scratch, log, 0.0, 1e-6, q, qd, np.zeros(0), 0)
    assert log.totals[0, ps.T_DAMPING_ENERGY] == approx(power * 1e-6, rel=1e-12)
    assert elastic_energy(table, scratch) == approx(hertz(delta0) * delta0 / 2.5)
