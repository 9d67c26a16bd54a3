"""A revolute clearance joint's time series a tribologist reads: pressure, pV, power.

From each row's normal and friction force and sliding speed (the joint's own columns):

- ``<joint>_p_max``, ``<joint>_p_mean`` [Pa]: the peak and mean pressure of a Hertz line
  contact of the nominal radii under the normal force, p_max = 2 F / (pi b L) and
  p_mean = F / (2 b L) over the half-width b (Johnson 1985, sec. 4.2). For the conformal and
  elastic-foundation laws it is the Hertz estimate, not their own pressure field;
- ``<joint>_pv`` [Pa m/s]: p_mean times the sliding speed, the usual wear severity of a
  bearing (the product Archard's law integrates);
- ``<joint>_friction_power`` [W]: |friction force x sliding speed|, the heat the contact
  makes;
- ``<joint>_damping_power`` [W]: the normal force's damped part times the penetration rate,
  (F_n - F_elastic) d(delta)/dt, what the contact law's hysteresis dissipates (the compiled
  loop sums the same product into the summary's ``energy_dissipated_damping_j``). While F_n
  is clamped at zero with the surfaces still overlapping, it is the elastic energy released,
  F_elastic |d(delta)/dt|.

A lubricated joint also has, from its film columns:

- ``<joint>_asperity_share`` [-]: the solid contact's share of the load, F_n / (F_n +
  |F_film|) (0 while neither carries any);
- ``<joint>_friction_coefficient`` [-]: the friction power, boundary (friction_power) plus
  the film's (film_power less the radial squeeze's -f_r d(delta)/dt, which is not
  friction), over the whole load |F_n n + F_t t + F_film| times the sliding speed R_J
  |omega_J - omega_B|: for a steadily loaded bearing, the classic T_J / (R W), and the same
  in any frame. NaN where the journal does not turn in its bearing or nothing is loaded;
- ``<joint>_lambda`` [-] (with a roughness sigma): the film thickness over sigma, -delta /
  sigma, negative where the mean planes overlap.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

COLUMNS = ("p_max", "p_mean", "pv", "friction_power", "damping_power")  # after the joint's own


def tribology_columns(joint: object, timeseries: pd.DataFrame) -> dict[str, np.ndarray]:
    """The ``COLUMNS`` of one revolute clearance joint, one value per row of ``timeseries``."""
    c, name = joint.clearance, joint.name
    force = timeseries[f"{name}_fn"].to_numpy()
    speed = np.abs(timeseries[f"{name}_vt"].to_numpy())
    # Half-width and peak pressure grow as the square root of the force: those at 1 N,
    # scaled, are the line contact's at every row.
    unit_width, unit_peak = c.hertz_patch(1.0)
    root = np.sqrt(np.maximum(force, 0.0))
    half_width, peak = unit_width * root, unit_peak * root
    loaded = half_width > 0.0
    mean = np.zeros_like(force)
    mean[loaded] = force[loaded] / (2.0 * half_width[loaded] * c.width)
    elastic = timeseries[f"{name}_fn_elastic"].to_numpy()  # > 0 while they overlap
    rate = timeseries[f"{name}_delta_dot"].to_numpy()
    friction_power = np.abs(timeseries[f"{name}_ft"].to_numpy()) * speed
    columns = {
        f"{name}_p_max": peak,
        f"{name}_p_mean": mean,
        f"{name}_pv": mean * speed,
        f"{name}_friction_power": friction_power,
        f"{name}_damping_power": np.where(elastic > 0.0, (force - elastic) * rate, 0.0),
    }
    if c.lubricated:
        columns |= _film_columns(joint, timeseries, friction_power)
    return columns


def _film_columns(
    joint: object, timeseries: pd.DataFrame, friction_power: np.ndarray
) -> dict[str, np.ndarray]:
    """A lubricated joint's asperity_share, friction_coefficient (and lambda), per row."""
    c, name = joint.clearance, joint.name
    quantities = ("fn", "fx", "fy", "ex", "ey", "film_fx", "film_fy", "film_power", "delta")
    column = {q: timeseries[f"{name}_{q}"].to_numpy() for q in quantities}
    film = np.hypot(column["film_fx"], column["film_fy"])
    carried = column["fn"] + film
    share = np.divide(column["fn"], carried, out=np.zeros_like(carried), where=carried > 0.0)
    w_b, w_j = (timeseries[f"omega_{body}"].to_numpy() if body != "ground" else 0.0
                for body in joint.bodies)  # fmt: skip
    sliding = c.journal_radius * np.abs(w_j - w_b) * np.ones(len(timeseries))
    load = np.hypot(column["fx"] + column["film_fx"], column["fy"] + column["film_fy"])
    moved = load * sliding
    e = np.hypot(column["ex"], column["ey"])
    pushed = column["ex"] * column["film_fx"] + column["ey"] * column["film_fy"]
    radial = np.divide(pushed, e, out=np.zeros_like(e), where=e > 0.0)
    rate = timeseries[f"{name}_delta_dot"].to_numpy()
    power = friction_power + column["film_power"] + radial * rate
    coefficient = np.divide(power, moved, out=np.full_like(moved, np.nan), where=moved > 0.0)
    columns = {f"{name}_asperity_share": share, f"{name}_friction_coefficient": coefficient}
    roughness = getattr(c, "roughness", None)
    if roughness:
        columns[f"{name}_lambda"] = -column["delta"] / roughness
    return columns
