from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

if TYPE_CHECKING:
    from ..models.target import Target


T = TypeVar("T", bound="LineSegment")


@_attrs_define
class LineSegment:
    """A straight line from the previous pose to `to` (orientation by slerp).

    Attributes:
        type_ (Literal['line']):
        to (Target): Desired placement of the frame in the root (world) frame.
    """

    type_: Literal["line"]
    to: Target

    def to_dict(self) -> dict[str, Any]:
        type_ = self.type_

        to = self.to.to_dict()

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "type": type_,
                "to": to,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.target import Target  # noqa: PLC0415

        d = dict(src_dict)
        type_ = cast(Literal["line"], d.pop("type"))
        if type_ != "line":
            raise ValueError(f"type must match const 'line', got '{type_}'")

        to = Target.from_dict(d.pop("to"))

        line_segment = cls(
            type_=type_,
            to=to,
        )

        return line_segment
