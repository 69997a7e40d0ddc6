from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.collision_geometry import CollisionGeometry

if TYPE_CHECKING:
    from ..models.pair_out import PairOut


T = TypeVar("T", bound="CollisionResponse")


@_attrs_define
class CollisionResponse:
    """The verdict for one configuration.

    Attributes:
        robot_id (str):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        geometry (CollisionGeometry):
        margin (float):
        in_collision (bool): Any pair closer than the margin.
        self_collision (bool): Two links of the robot collide.
        environment_collision (bool): A link collides with an obstacle.
        min_distance (float | None): Smallest distance (m) over the checked pairs with distances; otherwise over the
            pairs in collision (null when none).
        pairs (list[PairOut]): Pairs in collision, or every checked pair with distances; closest first.
        checked_pairs (int): Number of link/link and link/obstacle pairs checked.
    """

    robot_id: str
    q: list[float]
    geometry: CollisionGeometry
    margin: float
    in_collision: bool
    self_collision: bool
    environment_collision: bool
    min_distance: float | None
    pairs: list[PairOut]
    checked_pairs: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        q = self.q

        geometry = self.geometry.value

        margin = self.margin

        in_collision = self.in_collision

        self_collision = self.self_collision

        environment_collision = self.environment_collision

        min_distance: float | None
        min_distance = self.min_distance

        pairs = []
        for pairs_item_data in self.pairs:
            pairs_item = pairs_item_data.to_dict()
            pairs.append(pairs_item)

        checked_pairs = self.checked_pairs

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "q": q,
                "geometry": geometry,
                "margin": margin,
                "in_collision": in_collision,
                "self_collision": self_collision,
                "environment_collision": environment_collision,
                "min_distance": min_distance,
                "pairs": pairs,
                "checked_pairs": checked_pairs,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pair_out import PairOut  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        q = cast(list[float], d.pop("q"))

        geometry = CollisionGeometry(d.pop("geometry"))

        margin = d.pop("margin")

        in_collision = d.pop("in_collision")

        self_collision = d.pop("self_collision")

        environment_collision = d.pop("environment_collision")

        def _parse_min_distance(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        min_distance = _parse_min_distance(d.pop("min_distance"))

        pairs = []
        _pairs = d.pop("pairs")
        for pairs_item_data in _pairs:
            pairs_item = PairOut.from_dict(pairs_item_data)

            pairs.append(pairs_item)

        checked_pairs = d.pop("checked_pairs")

        collision_response = cls(
            robot_id=robot_id,
            q=q,
            geometry=geometry,
            margin=margin,
            in_collision=in_collision,
            self_collision=self_collision,
            environment_collision=environment_collision,
            min_distance=min_distance,
            pairs=pairs,
            checked_pairs=checked_pairs,
        )

        collision_response.additional_properties = d
        return collision_response

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
