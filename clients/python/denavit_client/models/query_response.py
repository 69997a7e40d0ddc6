from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="QueryResponse")


@_attrs_define
class QueryResponse:
    """Entry i answers pose i.

    Attributes:
        map_id (str):
        reachable (list[bool]):
        manipulability (list[float | None]): Best Yoshikawa manipulability seen in the pose's cell; null if unreachable.
        in_bounds (list[bool]): Whether the position lies inside the map's box.
    """

    map_id: str
    reachable: list[bool]
    manipulability: list[float | None]
    in_bounds: list[bool]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        map_id = self.map_id

        reachable = self.reachable

        manipulability = []
        for manipulability_item_data in self.manipulability:
            manipulability_item: float | None
            manipulability_item = manipulability_item_data
            manipulability.append(manipulability_item)

        in_bounds = self.in_bounds

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "map_id": map_id,
                "reachable": reachable,
                "manipulability": manipulability,
                "in_bounds": in_bounds,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        map_id = d.pop("map_id")

        reachable = cast(list[bool], d.pop("reachable"))

        manipulability = []
        _manipulability = d.pop("manipulability")
        for manipulability_item_data in _manipulability:

            def _parse_manipulability_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            manipulability_item = _parse_manipulability_item(manipulability_item_data)

            manipulability.append(manipulability_item)

        in_bounds = cast(list[bool], d.pop("in_bounds"))

        query_response = cls(
            map_id=map_id,
            reachable=reachable,
            manipulability=manipulability,
            in_bounds=in_bounds,
        )

        query_response.additional_properties = d
        return query_response

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
