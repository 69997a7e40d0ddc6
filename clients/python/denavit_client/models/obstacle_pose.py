from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="ObstaclePose")


@_attrs_define
class ObstaclePose:
    """Placement of an obstacle in the robot's root frame.

    Attributes:
        position (list[float] | Unset): Centre [x, y, z] (m).
        orientation (list[float] | Unset): Unit quaternion [x, y, z, w] (root ← obstacle).
    """

    position: list[float] | Unset = UNSET
    orientation: list[float] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        position: list[float] | Unset = UNSET
        if not isinstance(self.position, Unset):
            position = self.position

        orientation: list[float] | Unset = UNSET
        if not isinstance(self.orientation, Unset):
            orientation = self.orientation

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if position is not UNSET:
            field_dict["position"] = position
        if orientation is not UNSET:
            field_dict["orientation"] = orientation

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        position = cast(list[float], d.pop("position", UNSET))

        orientation = cast(list[float], d.pop("orientation", UNSET))

        obstacle_pose = cls(
            position=position,
            orientation=orientation,
        )

        return obstacle_pose
