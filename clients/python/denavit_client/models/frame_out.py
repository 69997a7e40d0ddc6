from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="FrameOut")


@_attrs_define
class FrameOut:
    """A named frame.

    Attributes:
        name (str):
        kind (str): link | fixed (URDF fixed joint) | joint.
        parent_joint (None | str): The actuated joint that moves it, if any.
    """

    name: str
    kind: str
    parent_joint: None | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        kind = self.kind

        parent_joint: None | str
        parent_joint = self.parent_joint

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "kind": kind,
                "parent_joint": parent_joint,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        kind = d.pop("kind")

        def _parse_parent_joint(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        parent_joint = _parse_parent_joint(d.pop("parent_joint"))

        frame_out = cls(
            name=name,
            kind=kind,
            parent_joint=parent_joint,
        )

        frame_out.additional_properties = d
        return frame_out

    @property
    def additional_keys(self) -> list[str]:
        return list(self.additional_properties.keys())

    def __getitem__(self, key: str) -> Any:
        return self.additional_properties[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.additional_properties[key] = value

    def __delitem__(self, key: str) -> None:
        del self.additional_properties[key]

    def __contains__(self, key: str) -> bool:
        return key in self.additional_properties
