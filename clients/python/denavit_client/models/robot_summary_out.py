from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

T = TypeVar("T", bound="RobotSummaryOut")


@_attrs_define
class RobotSummaryOut:
    """One robot in the list.

    Attributes:
        id (str): Robot id, used in every /robots/{robot_id} URL.
        name (str): Human-readable name.
        source (str): example-robot-data | dh | upload | package.
        joints (int): Number of actuated joints (length of a configuration).
        description (str | Unset): Short description. Default: ''.
    """

    id: str
    name: str
    source: str
    joints: int
    description: str | Unset = ""
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        id = self.id

        name = self.name

        source = self.source

        joints = self.joints

        description = self.description

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "id": id,
                "name": name,
                "source": source,
                "joints": joints,
            }
        )
        if description is not UNSET:
            field_dict["description"] = description

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        id = d.pop("id")

        name = d.pop("name")

        source = d.pop("source")

        joints = d.pop("joints")

        description = d.pop("description", UNSET)

        robot_summary_out = cls(
            id=id,
            name=name,
            source=source,
            joints=joints,
            description=description,
        )

        robot_summary_out.additional_properties = d
        return robot_summary_out

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
