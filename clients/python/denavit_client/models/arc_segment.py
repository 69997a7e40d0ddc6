from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

if TYPE_CHECKING:
    from ..models.pose import Pose


T = TypeVar("T", bound="ArcSegment")


@_attrs_define
class ArcSegment:
    """A circular arc from the previous pose through `via` to `to`; orientation by slerp to
    `via`'s on the first part of the arc and to `to`'s on the second.

        Attributes:
            type_ (Literal['arc']):
            via (Pose): A frame's placement in the robot's root (world) frame, the same shape in and out.

                Answers fill all four fields. A request may give any subset that states what its
                endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
                ``orientation``: a rotation; reachability queries: a position, the rotation optional;
                obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
                request is a 422 naming them. An answer's pose can be sent back as is.
            to (Pose): A frame's placement in the robot's root (world) frame, the same shape in and out.

                Answers fill all four fields. A request may give any subset that states what its
                endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
                ``orientation``: a rotation; reachability queries: a position, the rotation optional;
                obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
                request is a 422 naming them. An answer's pose can be sent back as is.
    """

    type_: Literal["arc"]
    via: Pose
    to: Pose

    def to_dict(self) -> dict[str, Any]:
        type_ = self.type_

        via = self.via.to_dict()

        to = self.to.to_dict()

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "type": type_,
                "via": via,
                "to": to,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pose import Pose  # noqa: PLC0415

        d = dict(src_dict)
        type_ = cast(Literal["arc"], d.pop("type"))
        if type_ != "arc":
            raise ValueError(f"type must match const 'arc', got '{type_}'")

        via = Pose.from_dict(d.pop("via"))

        to = Pose.from_dict(d.pop("to"))

        arc_segment = cls(
            type_=type_,
            via=via,
            to=to,
        )

        return arc_segment
