from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Literal, TypeVar, cast

from attrs import define as _attrs_define

if TYPE_CHECKING:
    from ..models.target import Target


T = TypeVar("T", bound="ArcSegment")


@_attrs_define
class ArcSegment:
    """A circular arc from the previous pose through `via` to `to`; orientation by slerp to
    `via`'s on the first part of the arc and to `to`'s on the second.

        Attributes:
            type_ (Literal['arc']):
            via (Target): Desired placement of the frame in the root (world) frame.
            to (Target): Desired placement of the frame in the root (world) frame.
    """

    type_: Literal["arc"]
    via: Target
    to: Target

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
        from ..models.target import Target  # noqa: PLC0415

        d = dict(src_dict)
        type_ = cast(Literal["arc"], d.pop("type"))
        if type_ != "arc":
            raise ValueError(f"type must match const 'arc', got '{type_}'")

        via = Target.from_dict(d.pop("via"))

        to = Target.from_dict(d.pop("to"))

        arc_segment = cls(
            type_=type_,
            via=via,
            to=to,
        )

        return arc_segment
