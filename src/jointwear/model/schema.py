"""The schema of a model file (docs/model-format.md), and its loading.

A validated :class:`Model` holds plain SI floats (tuples for vectors) and names; every
user-input problem is reported as a :class:`ModelError` with one line per problem.
"""

from collections.abc import Mapping, Sequence
from os import PathLike
from pathlib import Path
from types import MappingProxyType
from typing import Annotated

from pydantic import Field, ValidationError, model_validator

from .arguments import argument_problems
from .errors import TOO_DEEP, ModelError, from_validation_error
from .files import read_model_data
from .functions import longest_period
from .overrides import apply_changes, apply_overrides, parse_overrides
from .references import reference_problems
from .sections import (
    Body,
    Driver,
    Event,
    Ground,
    Joint,
    Load,
    Solver,
)
from .tables import JointTable, Table

# The model ---------------------------------------------------------------------------------


class Model(Table):
    """A whole model file, validated, in SI units.

    Built in Python from its tables (``Body``, ``RevoluteJoint``, ...) or from dicts of a
    file's keys, it is checked as a file is, names between tables too, and raises
    ``ModelError`` with the same lines (docs/python-models.md).

    Attributes
    ----------
    name
        The model's name.
    description
        One line about it.
    ground
        The fixed points [m] (a ``Ground``).
    bodies
        The moving bodies (``Body``), at least one.
    joints
        ``RevoluteJoint``, ``TranslationalJoint`` and ``PinInSlotJoint`` tables, ideal or
        with clearance.
    drivers
        ``AngleDriver`` [rad] and ``DistanceDriver`` [m] tables.
    forces
        ``Gravity`` [m/s^2], ``PointForce`` [N], ``AppliedTorque`` [N m], ``SpringDamper``
        and ``RotationalSpringDamper`` tables.
    solver
        Integration and output settings (a ``Solver``; times [s]).
    events
        ``Event`` tables: crossings of a body's coordinate [m or rad].
    """

    name: Annotated[str, Field(min_length=1)]
    description: str = ""
    ground: Ground = Field(default_factory=Ground)
    bodies: Annotated[tuple[Body, ...], Field(min_length=1)]
    joints: tuple[Joint, ...] = ()
    drivers: tuple[Driver, ...] = ()
    forces: tuple[Load, ...] = ()
    solver: Solver = Field(default_factory=Solver)
    events: tuple[Event, ...] = ()

    @model_validator(mode="after")
    def _check_references(self) -> "Model":
        problems = reference_problems(
            self.ground, self.bodies, self.joints, self.drivers, self.forces, self.events
        )
        if not problems:
            problems = argument_problems(self.drivers, self.bodies, self.joints, self.forces)
        if problems:
            raise ModelError(problems)
        return self

    @model_validator(mode="after")
    def _steady_state_in_the_run(self) -> "Model":
        cycles, t_end = self.solver.settle_cycles, self.solver.t_end
        if cycles is None:
            return self
        if self.cycle is None:
            raise ModelError([
                "solver.settle_cycles: the model has no periodic driver or load whose cycles "
                "could be counted; give solver.settle_time in seconds instead"
            ])  # fmt: skip
        if cycles * self.cycle >= t_end:
            raise ModelError([
                f"solver.settle_cycles: {cycles:g} cycles of {self.cycle:.6g} s leave nothing "
                f"of the run (t_end {t_end:g} s) for the steady state; need fewer than "
                f"{t_end / self.cycle:.6g}"
            ])  # fmt: skip
        return self

    def with_values(self, changes: Mapping[str, object] = MappingProxyType({})) -> "Model":
        """The model with values changed, validated again as a model file would be.

        ``changes`` maps dotted paths, as ``--set`` takes them
        (``"joints.coupler_follower.clearance.wear_coefficient"``, ``"bodies.crank.mass"``),
        to values: SI numbers, strings with units (``"3 kg"``) or pint Quantities; None
        removes the key (its default applies, or another key can replace it), as ``--set
        path=`` does. Changes apply in order.

        Raises
        ------
        ModelError
            One line per problem, as for a model file; a removed key that is not there.
        """
        data = apply_changes(self._data(), changes.items())
        return parse_model(data, name=self.name)

    def to_toml(self, path: "str | PathLike") -> Path:
        """Write the model as a TOML model file that ``load_model`` reads back to it.

        Every setting is written, defaults too, in SI units (m, kg, s, rad, N, Pa) at full
        precision; left out are keys not given (None) and the keys of the laws a clearance
        joint does not use (at their defaults: they change nothing).

        Returns
        -------
        Path
            The file written.
        """
        from .writing import model_toml

        unused = {
            i: {"clearance": joint.clearance.unused_law_keys()}
            for i, joint in enumerate(self.joints)
            if joint.clearance is not None
        }
        data = self.model_dump(mode="json", exclude_none=True, exclude={"joints": unused})
        path = Path(path)
        path.write_text(model_toml(data), encoding="utf-8")
        return path

    def _data(self) -> dict:
        """The model as the tables of a file: SI values, keys not given left out."""
        return self.model_dump(mode="json", exclude_none=True)

    @property
    def cycle(self) -> float | None:
        """The mechanism's cycle [s]: the longest period of its drivers and loads, if any."""
        return longest_period(self.drivers, self.forces)

    @property
    def body_names(self) -> tuple[str, ...]:
        """Names of the moving bodies, in file order."""
        return tuple(body.name for body in self.bodies)

    def body(self, name: str) -> Body:
        """Return the moving body called `name` (KeyError if there is none)."""
        return _named(self.bodies, name)

    def joint(self, name: str) -> JointTable:
        """Return the joint called `name` (KeyError if there is none)."""
        return _named(self.joints, name)

    @property
    def clearance_joints(self) -> tuple[JointTable, ...]:
        """The joints with clearance, of every type, in file order."""
        return tuple(j for j in self.joints if j.clearance is not None)

    def joints_of(self, joint_type: str) -> tuple[JointTable, ...]:
        """The joints of ``joint_type`` with clearance, in file order (their kernel's order)."""
        return tuple(j for j in self.joints if j.type == joint_type and j.clearance is not None)

    @property
    def has_clearance(self) -> bool:
        """Whether any joint has clearance."""
        return bool(self.clearance_joints)

    def ideal(self) -> "Model":
        """The same model with every clearance joint made ideal (journal and slider centred)."""
        joints = tuple(joint.model_copy(update={"clearance": None}) for joint in self.joints)
        return self.model_copy(update={"joints": joints})

    def point(self, body: str, name: str) -> tuple[float, float]:
        """Return point `name` of `body` [m]: global for ``"ground"``, else in the body frame."""
        points = self.ground.points if body == "ground" else self.body(body).points
        return points[name]


def _named(items: Sequence, name: str):
    for item in items:
        if item.name == name:
            return item
    raise KeyError(name)


# Loading ----------------------------------------------------------------------------------


def parse_model(data: dict, name: str = "model") -> Model:
    """Validate a model given as a dict (a parsed TOML file or a saved model.json).

    Parameters
    ----------
    data
        The model's tables, values as in the model file.
    name
        Model name used when `data` has no ``name``.

    Raises
    ------
    ModelError
        With one line per problem found.
    """
    if isinstance(data, dict):
        data = {"name": name, **data}
    try:
        return Model.model_validate(data)
    except ValidationError as error:
        raise from_validation_error(error, data) from None


def load_model(path: "str | PathLike | Model", overrides: Sequence[str] = ()) -> Model:
    """Read a TOML model file, apply dotted ``path=value`` overrides, and validate it.

    The model name defaults to the file name without its suffix. A file may extend another
    (``model.files``). `path` may also be a results folder: its ``model.json``, the model it
    was run with; or a ``Model`` already built, to which the overrides are applied.

    Raises
    ------
    ModelError
        If the file cannot be read, is not valid TOML, or describes an invalid model.
    """
    if isinstance(path, Model):
        return path.with_values(dict(parse_overrides(overrides))) if overrides else path
    path = Path(path)
    try:
        data = read_model_data(path)
        return parse_model(apply_overrides(data, overrides), name=path.stem)
    except RecursionError:  # deep tables from dotted keys, in copying or validating them
        raise ModelError([f"{path}: {TOO_DEEP}"]) from None
