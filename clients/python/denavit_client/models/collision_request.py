from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.collision_geometry import CollisionGeometry
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions
    from ..models.obstacle_in import ObstacleIn


T = TypeVar("T", bound="CollisionRequest")


@_attrs_define
class CollisionRequest:
    """A configuration to check.

    Attributes:
        obstacles (list[ObstacleIn] | None | Unset): Obstacles in the robot's root frame.
        scene (None | str | Unset): Name of a stored scene (instead of obstacles).
        margin (float | Unset): Safety margin (m): pairs closer than this count as in collision. Default: 0.0.
        distances (bool | Unset): Compute every checked pair's distance and witness points (slower, especially with
            meshes). Default: False.
        geometry (CollisionGeometry | Unset):
        q (list[float] | None | Unset): One value per actuated joint, in the order of GET /robots/{id} (rad for revolute
            and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is
            accepted too.
        joint_positions (JointPositions | None | Unset): Joint name → value (rad or m); joints not given take their
            neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader +
            offset within 1e-9 (see mimic_joints of GET /robots/{id}).
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
    """

    obstacles: list[ObstacleIn] | None | Unset = UNSET
    scene: None | str | Unset = UNSET
    margin: float | Unset = 0.0
    distances: bool | Unset = False
    geometry: CollisionGeometry | Unset = UNSET
    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

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

        q: list[float] | None | Unset
        if isinstance(self.q, Unset):
            q = UNSET
        elif isinstance(self.q, list):
            q = self.q

        else:
            q = self.q

        joint_positions: dict[str, Any] | None | Unset
        if isinstance(self.joint_positions, Unset):
            joint_positions = UNSET
        elif isinstance(self.joint_positions, JointPositions):
            joint_positions = self.joint_positions.to_dict()
        else:
            joint_positions = self.joint_positions

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        field_dict: dict[str, Any] = {}

        field_dict.update({})
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
        if q is not UNSET:
            field_dict["q"] = q
        if joint_positions is not UNSET:
            field_dict["joint_positions"] = joint_positions
        if group is not UNSET:
            field_dict["group"] = group

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.obstacle_in import ObstacleIn  # noqa: PLC0415

        d = dict(src_dict)

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

        def _parse_q(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[float], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        q = _parse_q(d.pop("q", UNSET))

        def _parse_joint_positions(data: object) -> JointPositions | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                joint_positions_type_0 = JointPositions.from_dict(data)

                return joint_positions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointPositions | None | Unset, data)

        joint_positions = _parse_joint_positions(d.pop("joint_positions", UNSET))

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        collision_request = cls(
            obstacles=obstacles,
            scene=scene,
            margin=margin,
            distances=distances,
            geometry=geometry,
            q=q,
            joint_positions=joint_positions,
            group=group,
        )

        return collision_request
