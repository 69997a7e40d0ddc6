from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

if TYPE_CHECKING:
    from ..models.pose import Pose


T = TypeVar("T", bound="LineSegment")


@_attrs_define
class LineSegment:
    """A straight line from the previous pose to `to` (orientation by slerp).

    Attributes:
        type_ (Literal['line']):
        to (Pose): A frame's placement in the robot's root (world) frame, the same shape in and out.

            Answers fill all four fields. A request may give any subset that states what its
            endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
            ``orientation``: a rotation; reachability queries: a position, the rotation optional;
            obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
            request is a 422 naming them. An answer's pose can be sent back as is.
    """

    type_: Literal["line"]
    to: Pose

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
        from ..models.pose import Pose  # noqa: PLC0415

        d = dict(src_dict)
        type_ = cast(Literal["line"], d.pop("type"))
        if type_ != "line":
            raise ValueError(f"type must match const 'line', got '{type_}'")

        to = Pose.from_dict(d.pop("to"))

        line_segment = cls(
            type_=type_,
            to=to,
        )

        return line_segment
