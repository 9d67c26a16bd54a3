"""The unit of each column of a run's tables, read from its name.

Time-series columns are named after the model's bodies, drivers and joints
(``system.column_names``): ``<quantity>_<body>`` (``phi_follower``), ``torque_<driver>``,
``load_<load>_<quantity>`` (``load_gas_fx``), ``<joint>_<quantity>``
(``coupler_follower_fn``, its unit from the joint type: ``ClearanceKind.unit``); the model's
own names tell where the prefix or suffix ends, so a body or joint name with underscores is
read right. The other tables' columns end in their
unit (``depth_m``, ``angle_deg``, ``worn_volume_m3``).

Units are written as UDUNITS (netCDF's ``units`` attribute) reads them: ``m``, ``m/s``,
``m/s^2``, ``N m``; ``1`` for a dimensionless number or a count, ``""`` for a text column
(a name, not a quantity), ``"?"`` for a column this module does not know.
"""

from __future__ import annotations

from ..joints import BY_NAME
from ..mechanism.system import load_columns
from ..model import Model

TEXT = ""  # a column of names (joint, surface, event, ...)
UNKNOWN = "?"
BODY = {
    "x": "m",
    "y": "m",
    "phi": "rad",
    "vx": "m/s",
    "vy": "m/s",
    "omega": "rad/s",
    "ax": "m/s^2",
    "ay": "m/s^2",
    "alpha": "rad/s^2",
}  # <quantity>_<body>: system.BODY_COLUMNS
DRIVER = {"torque": "N m", "force": "N"}  # <kind>_<driver>
LOAD = {
    "fx": "N",
    "fy": "N",
    "force": "N",
    "torque": "N m",
    "pressure": "Pa",
}  # system.LOAD_QUANTITIES
IDEAL_JOINT = {"fx": "N", "fy": "N"}  # <joint>_<quantity>: an ideal joint's reaction
NAMED = {
    "time": "s",
    "constraint_violation": "m",  # 2-norm of the position constraints (m, and rad for angles)
    "cycle": "1",
    "sector": "1",
    "impacts": "1",
    "steady": "1",  # true or false
    "direction": TEXT,
    "event": TEXT,
    "joint": TEXT,
    "surface": TEXT,
    "contact": TEXT,
}  # whole names
SUFFIXES = (
    ("_m_s", "m/s"),
    ("_m3", "m^3"),
    ("_m", "m"),
    ("_deg", "deg"),
    ("_rad", "rad"),
    ("_s", "s"),
    ("_n", "N"),
    ("_j", "J"),
    ("_fraction", "1"),
)  # <quantity>_<unit>, the longer of two that overlap first
PREFIXES = (("energy_", "J"),)


def column_unit(column: str, model: Model | None = None) -> str:
    """The unit of a result column, from its name (and the model's names, if given).

    Parameters
    ----------
    column
        A column of any of a run's tables (``omega_crank``, ``depth_m``, ...).
    model
        The run's model: its body, driver and joint names tell a time-series column's
        quantity from its prefix or suffix.

    Returns
    -------
    str
        ``"m"``, ``"N m"``, ``"rad/s"``, ...; ``"1"`` dimensionless, ``""`` text, ``"?"``
        unknown.
    """
    if column in NAMED:
        return NAMED[column]
    if model is not None:
        unit = _model_unit(column, model)
        if unit is not None:
            return unit
    for prefix, unit in PREFIXES:
        if column.startswith(prefix):
            return unit
    for suffix, unit in SUFFIXES:
        if column.endswith(suffix):
            return unit
    return UNKNOWN


def _model_unit(column: str, model: Model) -> str | None:
    """The unit of a time-series column named after one of ``model``'s parts, or None."""
    loads = load_columns(model)
    if column in loads:
        return LOAD[loads[column]]
    bodies = {body.name for body in model.bodies}
    for quantity, unit in BODY.items():
        if column.startswith(f"{quantity}_") and column[len(quantity) + 1 :] in bodies:
            return unit
    drivers = {driver.name for driver in model.drivers}
    for kind, unit in DRIVER.items():
        if column.startswith(f"{kind}_") and column[len(kind) + 1 :] in drivers:
            return unit
    for joint in sorted(model.joints, key=lambda j: len(j.name), reverse=True):
        if not column.startswith(f"{joint.name}_"):
            continue
        quantity = column[len(joint.name) + 1 :]
        if joint.clearance is None:
            return IDEAL_JOINT.get(quantity)
        return BY_NAME[joint.type].unit(quantity)
    return None


def table_units(columns: list[str], model: Model | None = None) -> dict[str, str]:
    """Each column's unit (``column_unit``), in the table's order."""
    return {column: column_unit(column, model) for column in columns}
