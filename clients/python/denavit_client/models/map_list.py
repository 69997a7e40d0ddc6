from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.map_info import MapInfo


T = TypeVar("T", bound="MapList")


@_attrs_define
class MapList:
    """
    Attributes:
        maps (list[MapInfo]):
    """

    maps: list[MapInfo]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        maps = []
        for maps_item_data in self.maps:
            maps_item = maps_item_data.to_dict()
            maps.append(maps_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "maps": maps,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.map_info import MapInfo  # noqa: PLC0415

        d = dict(src_dict)
        maps = []
        _maps = d.pop("maps")
        for maps_item_data in _maps:
            maps_item = MapInfo.from_dict(maps_item_data)

            maps.append(maps_item)

        map_list = cls(
            maps=maps,
        )

        map_list.additional_properties = d
        return map_list

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
