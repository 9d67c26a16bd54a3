"""Building blocks of the model-file schema: the table base class and shared field types."""

import math
import re
from typing import Annotated

from pydantic import AfterValidator, AllowInfNan, BaseModel, ConfigDict, Strict, model_validator

from .errors import did_you_mean, unknown


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
    """A table of the model file: immutable, unknown keys refused."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    @model_validator(mode="before")
    @classmethod
    def _known_keys(cls, data: object) -> object:
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
