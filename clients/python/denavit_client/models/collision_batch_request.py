from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.collision_geometry import CollisionGeometry
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.obstacle_in import ObstacleIn


T = TypeVar("T", bound="CollisionBatchRequest")


@_attrs_define
class CollisionBatchRequest:
    """Many configurations (e.g. the waypoints of a trajectory).

    Attributes:
        configurations (list[list[float]]): N configurations, each one value per joint in joint order (rad, m); with
            `group`, rows of the group's joints only are accepted too (others neutral).
        obstacles (list[ObstacleIn] | None | Unset): Obstacles in the robot's root frame.
        scene (None | str | Unset): Name of a stored scene (instead of obstacles).
        margin (float | Unset): Safety margin (m): pairs closer than this count as in collision. Default: 0.0.
        distances (bool | Unset): Compute every checked pair's distance and witness points (slower, especially with
            meshes). Default: False.
        geometry (CollisionGeometry | Unset):
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
    """

    configurations: list[list[float]]
    obstacles: list[ObstacleIn] | None | Unset = UNSET
    scene: None | str | Unset = UNSET
    margin: float | Unset = 0.0
    distances: bool | Unset = False
    geometry: CollisionGeometry | Unset = UNSET
    group: None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        configurations = []
        for configurations_item_data in self.configurations:
            configurations_item = configurations_item_data

            configurations.append(configurations_item)

        obstacles: list[dict[str, Any]] | None | Unset
        if isinstance(self.obstacles, Unset):
            obstacles = UNSET
        elif isinstance(self.obstacles, list):
            obstacles = []
            for obstacles_type_0_item_data in self.obstacles:
                obstacles_type_0_item = obstacles_type_0_item_data.to_dict()
                obstacles.append(obstacles_type_0_item)

        else:
            obstacles = self.obstacles

        scene: None | str | Unset
        if isinstance(self.scene, Unset):
            scene = UNSET
        else:
            scene = self.scene

        margin = self.margin

        distances = self.distances

        geometry: str | Unset = UNSET
        if not isinstance(self.geometry, Unset):
            geometry = self.geometry.value

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "configurations": configurations,
            }
        )
        if obstacles is not UNSET:
            field_dict["obstacles"] = obstacles
        if scene is not UNSET:
            field_dict["scene"] = scene
        if margin is not UNSET:
            field_dict["margin"] = margin
        if distances is not UNSET:
            field_dict["distances"] = distances
        if geometry is not UNSET:
            field_dict["geometry"] = geometry
        if group is not UNSET:
            field_dict["group"] = group

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.obstacle_in import ObstacleIn  # noqa: PLC0415

        d = dict(src_dict)
        configurations = []
        _configurations = d.pop("configurations")
        for configurations_item_data in _configurations:
            configurations_item = cast(list[float], configurations_item_data)

            configurations.append(configurations_item)

        def _parse_obstacles(data: object) -> list[ObstacleIn] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                obstacles_type_0 = []
                _obstacles_type_0 = data
                for obstacles_type_0_item_data in _obstacles_type_0:
                    obstacles_type_0_item = ObstacleIn.from_dict(obstacles_type_0_item_data)

                    obstacles_type_0.append(obstacles_type_0_item)

                return obstacles_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ObstacleIn] | None | Unset, data)

        obstacles = _parse_obstacles(d.pop("obstacles", UNSET))

        def _parse_scene(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        scene = _parse_scene(d.pop("scene", UNSET))

        margin = d.pop("margin", UNSET)

        distances = d.pop("distances", UNSET)

        _geometry = d.pop("geometry", UNSET)
        geometry: CollisionGeometry | Unset
        if isinstance(_geometry, Unset):
            geometry = UNSET
        else:
            geometry = CollisionGeometry(_geometry)

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        collision_batch_request = cls(
            configurations=configurations,
            obstacles=obstacles,
            scene=scene,
            margin=margin,
            distances=distances,
            geometry=geometry,
            group=group,
        )

        return collision_batch_request
