from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="GroupOut")


@_attrs_define
class GroupOut:
    """A planning group of the SRDF, resolved against the model.

    Attributes:
        name (str):
        joints (list[str]): Its configuration joints (actuated, no mimic followers), in joint order: a `q` of this
            length is accepted with `group`.
        tip (str): Its default frame: its chain's tip_link, else the parent_link of an end effector attached to it, else
            its deepest link.
    """

    name: str
    joints: list[str]
    tip: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        joints = self.joints

        tip = self.tip

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "joints": joints,
                "tip": tip,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        joints = cast(list[str], d.pop("joints"))

        tip = d.pop("tip")

        group_out = cls(
            name=name,
            joints=joints,
            tip=tip,
        )

        group_out.additional_properties = d
        return group_out

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
