from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="EndEffectorOut")


@_attrs_define
class EndEffectorOut:
    """An SRDF end effector: the tool group ``group`` attached at ``parent_link``.

    Attributes:
        name (str):
        parent_link (str):
        group (str):
        parent_group (None | str):
    """

    name: str
    parent_link: str
    group: str
    parent_group: None | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        parent_link = self.parent_link

        group = self.group

        parent_group: None | str
        parent_group = self.parent_group

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "name": name,
                "parent_link": parent_link,
                "group": group,
                "parent_group": parent_group,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        name = d.pop("name")

        parent_link = d.pop("parent_link")

        group = d.pop("group")

        def _parse_parent_group(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        parent_group = _parse_parent_group(d.pop("parent_group"))

        end_effector_out = cls(
            name=name,
            parent_link=parent_link,
            group=group,
            parent_group=parent_group,
        )

        end_effector_out.additional_properties = d
        return end_effector_out

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
