from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="MimicJointOut")


@_attrs_define
class MimicJointOut:
    """A mimic joint: it follows its leader and is not a configuration entry.

    Attributes:
        name (str):
        type_ (str): revolute | prismatic (the URDF type).
        leader (str): The actuated joint it follows.
        multiplier (float): value = multiplier × value(leader) + offset.
        offset (float): Offset (rad or m).
    """

    name: str
    type_: str
    leader: str
    multiplier: float
    offset: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        type_ = self.type_

        leader = self.leader

        multiplier = self.multiplier

        offset = self.offset

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "type": type_,
                "leader": leader,
                "multiplier": multiplier,
                "offset": offset,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        type_ = d.pop("type")

        leader = d.pop("leader")

        multiplier = d.pop("multiplier")

        offset = d.pop("offset")

        mimic_joint_out = cls(
            name=name,
            type_=type_,
            leader=leader,
            multiplier=multiplier,
            offset=offset,
        )

        mimic_joint_out.additional_properties = d
        return mimic_joint_out

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
