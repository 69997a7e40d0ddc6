from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.obstacle_shape import ObstacleShape
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.pose import Pose


T = TypeVar("T", bound="ObstacleIn")


@_attrs_define
class ObstacleIn:
    """A box, sphere, cylinder or capsule in the robot's root frame.

    Attributes:
        name (str): Unique name in the set.
        shape (ObstacleShape):
        size (list[float] | None | Unset): box: full edge lengths [x, y, z] (m).
        radius (float | None | Unset): sphere, cylinder, capsule: radius (m).
        length (float | None | Unset): cylinder: full height along local z (m); capsule: length of the segment between
            the hemisphere centres (m).
        pose (None | Pose | Unset): Placement root ← obstacle; default the identity (a missing position is the origin, a
            missing rotation the identity).
    """

    name: str
    shape: ObstacleShape
    size: list[float] | None | Unset = UNSET
    radius: float | None | Unset = UNSET
    length: float | None | Unset = UNSET
    pose: None | Pose | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.pose import Pose  # noqa: PLC0415

        name = self.name

        shape = self.shape.value

        size: list[float] | None | Unset
        if isinstance(self.size, Unset):
            size = UNSET
        elif isinstance(self.size, list):
            size = self.size

        else:
            size = self.size

        radius: float | None | Unset
        if isinstance(self.radius, Unset):
            radius = UNSET
        else:
            radius = self.radius

        length: float | None | Unset
        if isinstance(self.length, Unset):
            length = UNSET
        else:
            length = self.length

        pose: dict[str, Any] | None | Unset
        if isinstance(self.pose, Unset):
            pose = UNSET
        elif isinstance(self.pose, Pose):
            pose = self.pose.to_dict()
        else:
            pose = self.pose

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
                "shape": shape,
            }
        )
        if size is not UNSET:
            field_dict["size"] = size
        if radius is not UNSET:
            field_dict["radius"] = radius
        if length is not UNSET:
            field_dict["length"] = length
        if pose is not UNSET:
            field_dict["pose"] = pose

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pose import Pose  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        shape = ObstacleShape(d.pop("shape"))

        def _parse_size(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                size_type_0 = cast(list[float], data)

                return size_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        size = _parse_size(d.pop("size", UNSET))

        def _parse_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        radius = _parse_radius(d.pop("radius", UNSET))

        def _parse_length(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        length = _parse_length(d.pop("length", UNSET))

        def _parse_pose(data: object) -> None | Pose | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                pose_type_0 = Pose.from_dict(data)

                return pose_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | Pose | Unset, data)

        pose = _parse_pose(d.pop("pose", UNSET))

        obstacle_in = cls(
            name=name,
            shape=shape,
            size=size,
            radius=radius,
            length=length,
            pose=pose,
        )

        return obstacle_in
