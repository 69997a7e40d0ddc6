from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.collision_geometry import CollisionGeometry
from ..types import UNSET, Unset

T = TypeVar("T", bound="CollisionBatchResponse")


@_attrs_define
class CollisionBatchResponse:
    """Compact per-configuration answers: entry i for configuration i.

    Attributes:
        robot_id (str):
        geometry (CollisionGeometry):
        margin (float):
        count (int):
        num_in_collision (int):
        first_collision (int | None): Index of the first colliding configuration.
        in_collision (list[bool]):
        self_collision (list[bool]):
        environment_collision (list[bool]):
        pairs (list[list[list[str]]]): Per configuration: colliding [a, b] pairs.
        min_distance (list[float] | None | Unset): Per configuration: smallest distance (m); only with distances.
    """

    robot_id: str
    geometry: CollisionGeometry
    margin: float
    count: int
    num_in_collision: int
    first_collision: int | None
    in_collision: list[bool]
    self_collision: list[bool]
    environment_collision: list[bool]
    pairs: list[list[list[str]]]
    min_distance: list[float] | None | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        geometry = self.geometry.value

        margin = self.margin

        count = self.count

        num_in_collision = self.num_in_collision

        first_collision: int | None
        first_collision = self.first_collision

        in_collision = self.in_collision

        self_collision = self.self_collision

        environment_collision = self.environment_collision

        pairs = []
        for pairs_item_data in self.pairs:
            pairs_item = []
            for pairs_item_item_data in pairs_item_data:
                pairs_item_item = pairs_item_item_data

                pairs_item.append(pairs_item_item)

            pairs.append(pairs_item)

        min_distance: list[float] | None | Unset
        if isinstance(self.min_distance, Unset):
            min_distance = UNSET
        elif isinstance(self.min_distance, list):
            min_distance = self.min_distance

        else:
            min_distance = self.min_distance

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "geometry": geometry,
                "margin": margin,
                "count": count,
                "num_in_collision": num_in_collision,
                "first_collision": first_collision,
                "in_collision": in_collision,
                "self_collision": self_collision,
                "environment_collision": environment_collision,
                "pairs": pairs,
            }
        )
        if min_distance is not UNSET:
            field_dict["min_distance"] = min_distance

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        geometry = CollisionGeometry(d.pop("geometry"))

        margin = d.pop("margin")

        count = d.pop("count")

        num_in_collision = d.pop("num_in_collision")

        def _parse_first_collision(data: object) -> int | None:
            if data is None:
                return data
            return cast(int | None, data)

        first_collision = _parse_first_collision(d.pop("first_collision"))

        in_collision = cast(list[bool], d.pop("in_collision"))

        self_collision = cast(list[bool], d.pop("self_collision"))

        environment_collision = cast(list[bool], d.pop("environment_collision"))

        pairs = []
        _pairs = d.pop("pairs")
        for pairs_item_data in _pairs:
            pairs_item = []
            _pairs_item = pairs_item_data
            for pairs_item_item_data in _pairs_item:
                pairs_item_item = cast(list[str], pairs_item_item_data)

                pairs_item.append(pairs_item_item)

            pairs.append(pairs_item)

        def _parse_min_distance(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                min_distance_type_0 = cast(list[float], data)

                return min_distance_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        min_distance = _parse_min_distance(d.pop("min_distance", UNSET))

        collision_batch_response = cls(
            robot_id=robot_id,
            geometry=geometry,
            margin=margin,
            count=count,
            num_in_collision=num_in_collision,
            first_collision=first_collision,
            in_collision=in_collision,
            self_collision=self_collision,
            environment_collision=environment_collision,
            pairs=pairs,
            min_distance=min_distance,
        )

        collision_batch_response.additional_properties = d
        return collision_batch_response

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
