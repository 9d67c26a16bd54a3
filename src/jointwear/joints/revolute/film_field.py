"""The film pressure of a finite journal bearing at one output row, as the run's force had it.

The kernel reads the film force from an impedance table (``film.impedance``); here the
Reynolds equation is solved again for one row (``film.reynolds``, on the grid and with the
inlet the table was built with) from the row's own columns, as ``kernels.elements.journal``
``_film`` poses it:

- the film's eccentricity ratio eps = 1 - mean_gap(max(-delta, 0), sigma) / c, from the
  rough surfaces' mean gap (``kernels.laws.asperity.mean_gap``; a finite bearing has a
  roughness sigma), with c = abs(e) - delta the local clearance (the worn one);
- the squeeze velocity V from ``squeeze_vx``, ``squeeze_vy`` in (e_r, e_t): v_r as it is,
  v_t scaled by c eps / abs(e), since the kernel's wedge is c eps (gamma' - w / 2) with the
  film's eps, the column's e (gamma' - w / 2) with the geometric one (the same above a few
  sigma).

The pressure integrates to the row's film force within the table's interpolation error
(tests/test_film_figures.py). Only finite bearings: the short and long bearings are closed
forms of the two limits L / D -> 0 and infinity with the half-Sommerfeld film, whose forces
no finite film reproduces, and beyond ``film_breakdown`` they are held at eps_b and faded
out, a force without a pressure field behind it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ...film.reynolds import film_grid, solve_film
from ...kernels.laws.asperity import film_eccentricity
from ...model.laws.lubrication import reads_film_table
from ...results import Results


@dataclass(frozen=True)
class FilmField:
    """The pressure of a journal bearing's film at one output row.

    Attributes
    ----------
    joint
        The joint's name.
    time
        The row's time [s].
    eps
        The film's eccentricity ratio [-] (module docstring).
    clearance
        The local radial clearance c [m]; the film is h = c (1 - eps cos a).
    angle_faces
        Cell faces in the film angle a [rad], -pi to pi, counter-clockwise from the line of
        centres e_r (bearing centre to journal centre): the thinnest film at a = 0, the inlet
        (p = 0) at a = +-pi.
    axial_faces
        Cell faces across the whole width [m], -L / 2 to L / 2 (the solved half mirrored).
    pressure
        p per cell [Pa], shape (len(angle_faces) - 1, len(axial_faces) - 1).
    cavitated
        The cells where the film has cavitated, p = 0 (the Reynolds condition), same shape.
    line_of_centres
        The direction of e_r [rad], counter-clockwise from the global x axis.
    journal_radius
        R [m], the radius the pressure acts on.
    """

    joint: str
    time: float
    eps: float
    clearance: float
    angle_faces: NDArray[np.float64]
    axial_faces: NDArray[np.float64]
    pressure: NDArray[np.float64]
    cavitated: NDArray[np.bool_]
    line_of_centres: float
    journal_radius: float

    @property
    def film_min(self) -> float:
        """The thinnest film c (1 - eps) [m], at a = 0."""
        return self.clearance * (1.0 - self.eps)

    @property
    def force(self) -> tuple[float, float]:
        """(f_x, f_y) [N], the film force on the journal, -int p n dA, global axes.

        n = cos a e_r + sin a e_t, dA = R da dz; p constant over each cell, as the finite
        volumes hold it, and cos a, sin a integrated exactly over the cell.
        """
        a, width = self.angle_faces, np.diff(self.axial_faces)
        f_r = -self.journal_radius * np.diff(np.sin(a)) @ self.pressure @ width
        f_t = self.journal_radius * np.diff(np.cos(a)) @ self.pressure @ width
        cos, sin = math.cos(self.line_of_centres), math.sin(self.line_of_centres)
        return float(f_r * cos - f_t * sin), float(f_r * sin + f_t * cos)


def finite_bearings(results: Results) -> tuple[str, ...]:
    """The names of the run's revolute clearance joints that are finite journal bearings."""
    return tuple(
        joint.name
        for joint in results.model.joints_of("revolute")
        if reads_film_table(joint.clearance.lubrication)
    )


def peak_film_time(results: Results, joint: str) -> float:
    """The time [s] of the row with the largest film force of ``joint``.

    In the steady state if the summary has one (``steady_state.from_s``), else in the run.
    """
    ts = results.timeseries
    start = (results.summary.get("steady_state") or {}).get("from_s")
    rows = ts if start is None else ts[ts["time"] >= start - 1e-12]
    force = np.hypot(rows[f"{joint}_film_fx"], rows[f"{joint}_film_fy"]).to_numpy()
    return float(rows["time"].iloc[int(np.argmax(force))])


def film_field(results: Results, joint: str, time: float | None = None) -> FilmField:
    """The film pressure of finite-bearing ``joint`` at the output row nearest ``time`` [s].

    ``time`` None: the row of the largest film force (``peak_film_time``).

    Raises
    ------
    ValueError
        If ``joint`` is not a finite journal bearing of the run, or ``time`` is outside it.
    """
    bearings = finite_bearings(results)
    if joint not in bearings:
        allowed = ", ".join(bearings) if bearings else "none in this run"
        raise ValueError(
            f"joint {joint!r} is not a finite journal bearing (lubrication = "
            f'"finite_bearing"); the finite bearings are: {allowed}'
        )
    ts = results.timeseries
    times = ts["time"].to_numpy()
    if time is None:
        time = peak_film_time(results, joint)
    half_row = 0.5 * results.model.solver.output_interval
    if not times[0] - half_row <= time <= times[-1] + half_row:
        raise ValueError(
            f"time {time:g} s is outside the run; its rows span {times[0]:g} to {times[-1]:g} s"
        )
    row = ts.iloc[int(np.argmin(np.abs(times - time)))]
    c = results.model.joint(joint).clearance

    def column(quantity: str) -> float:
        return float(row[f"{joint}_{quantity}"])

    ex, ey, delta = column("ex"), column("ey"), column("delta")
    v_x, v_y = column("squeeze_vx"), column("squeeze_vy")
    e = math.hypot(ex, ey)
    gap = e - delta
    direction = _line_of_centres(ex, ey, v_x, v_y)
    eps = film_eccentricity(delta, gap, c.roughness)  # the kernel's own
    cos, sin = math.cos(direction), math.sin(direction)
    v_r = v_x * cos + v_y * sin
    v_t = (-v_x * sin + v_y * cos) * (gap * eps / e if e > 0.0 else 0.0)
    grid = film_grid(eps, c.width / (2.0 * c.journal_radius))  # the table's grid and inlet
    solution = solve_film(grid, v_r, v_t)
    scale = c.viscosity * c.journal_radius**2 / gap**3  # p = mu R^2 / c^3 P
    zeta = grid.axial_faces
    return FilmField(
        joint=joint,
        time=float(row["time"]),
        eps=eps,
        clearance=gap,
        angle_faces=grid.angle_faces,
        axial_faces=0.5 * c.width * np.concatenate([-zeta[:0:-1], zeta]),
        pressure=scale * _mirrored(solution.pressure),
        cavitated=_mirrored(solution.cavitated),
        line_of_centres=direction,
        journal_radius=c.journal_radius,
    )


def _mirrored(half: NDArray) -> NDArray:
    """A field over the half width 0 <= zeta <= 1 over the whole width, -1 to 1."""
    return np.concatenate([half[:, ::-1], half], axis=1)


def _line_of_centres(ex: float, ey: float, v_x: float, v_y: float) -> float:
    """The direction of e_r [rad]: as the kernel's ``_line_of_centres``.

    At the centre (e = 0) the squeeze velocity is de/dt, along which the journal leaves;
    at rest there, +x.
    """
    if ex or ey:
        return math.atan2(ey, ex)
    if v_x or v_y:
        return math.atan2(v_y, v_x)
    return 0.0
