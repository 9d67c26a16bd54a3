"""Building blocks of the model-file schema: the table base class and shared field types."""

import math
import re
from typing import Annotated

from pydantic import (
    AfterValidator,
    AllowInfNan,
    BaseModel,
    ConfigDict,
    Strict,
    ValidationError,
    model_validator,
)

from .errors import did_you_mean, from_validation_error, unknown


def one_of(table: dict[str, object], what: str) -> AfterValidator:
    """Validator of a name that must be a key of `table` (``what`` names it in errors)."""

    def check(value: str) -> str:
        if value not in table:
            raise ValueError(unknown(what, value, list(table), f"known {what}s"))
        return value

    return AfterValidator(check)


def _check_name(name: str) -> str:
    if not re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name):
        raise ValueError(
            f"{name!r} is not a valid name; use letters, digits and _, starting with a letter"
        )
    if name == "ground":
        raise ValueError("'ground' is reserved; choose another name")
    return name


Name = Annotated[str, AfterValidator(_check_name)]
Number = Annotated[float, Strict(), AllowInfNan(False)]


class Table(BaseModel):
    """A table of the model file: immutable, unknown keys refused.

    Built in Python, ``Table(key=value, ...)`` takes the values a file would (SI numbers,
    strings with units, pint Quantities) and raises ``ModelError`` with the same lines as
    ``load_model`` gives, their paths starting at this table.
    """

    model_config = ConfigDict(extra="forbid", frozen=True)

    def __init__(self, /, **data: object) -> None:
        try:
            super().__init__(**data)
        except ValidationError as error:
            raise from_validation_error(error, data, type(self).__name__) from None

    # Validates as pydantic's own: a table inside another is validated without this __init__,
    # so that its problems reach the outer table's message with their whole path (pydantic
    # marks its BaseModel.__init__, and RootModel's, the same way).
    __init__.__pydantic_base_init__ = True  # type: ignore[attr-defined]

    @model_validator(mode="before")
    @classmethod
    def _known_keys(cls, data: object) -> object:
        if isinstance(data, Table) and cls is not type(data) and issubclass(cls, type(data)):
            # A general table where this, its version for one quantity, is wanted (a
            # Harmonic as an angle driver's function): its values are read as this one's.
            data = dict(data)
        if isinstance(data, dict):
            known = cls.known_keys()
            extra = [key for key in data if key not in known]
            if extra:
                hint = did_you_mean(extra[0], known) if len(extra) == 1 else ""
                raise ValueError(
                    f"unknown key{'s' * (len(extra) > 1)} {', '.join(map(repr, extra))}; "
                    f"known keys are {', '.join(known)}{hint}"
                )
        return data

    @classmethod
    def known_keys(cls) -> list[str]:
        """The keys the table accepts: its fields."""
        return list(cls.model_fields)


class JointTable(Table):
    """A joint: its name, the two bodies it joins and a point of each.

    Each joint type (``joints.KINDS``) subclasses it with its ``type``.
    """

    name: Name
    bodies: tuple[str, str]
    points: tuple[str, str]


def unit_axis(axis: tuple[float, float]) -> tuple[float, float]:
    """The axis as a unit vector (any non-zero length is a direction)."""
    length = math.hypot(*axis)
    if length == 0.0:
        raise ValueError("the axis has zero length; give a direction, e.g. [1.0, 0.0]")
    return (axis[0] / length, axis[1] / length)
