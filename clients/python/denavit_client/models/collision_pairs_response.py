from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="CollisionPairsResponse")


@_attrs_define
class CollisionPairsResponse:
    """Which self-collision pairs are checked.

    Attributes:
        robot_id (str):
        links (list[str]): Links with collision geometry.
        pairs (list[list[str]]): Checked link pairs [a, b].
        srdf (bool): Whether an SRDF disabled pairs.
    """

    robot_id: str
    links: list[str]
    pairs: list[list[str]]
    srdf: bool
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        links = self.links

        pairs = []
        for pairs_item_data in self.pairs:
            pairs_item = pairs_item_data

            pairs.append(pairs_item)

        srdf = self.srdf

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "links": links,
                "pairs": pairs,
                "srdf": srdf,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        links = cast(list[str], d.pop("links"))

        pairs = []
        _pairs = d.pop("pairs")
        for pairs_item_data in _pairs:
            pairs_item = cast(list[str], pairs_item_data)

            pairs.append(pairs_item)

        srdf = d.pop("srdf")

        collision_pairs_response = cls(
            robot_id=robot_id,
            links=links,
            pairs=pairs,
            srdf=srdf,
        )

        collision_pairs_response.additional_properties = d
        return collision_pairs_response

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
