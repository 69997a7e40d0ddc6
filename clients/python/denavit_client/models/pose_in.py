from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="PoseIn")


@_attrs_define
class PoseIn:
    """A pose to look up; without orientation, any orientation (best over the voxel).

    Attributes:
        position (list[float]): [x, y, z] (m), root frame.
        orientation (list[float] | None | Unset): Unit quaternion [x, y, z, w].
    """

    position: list[float]
    orientation: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        position = self.position

        orientation: list[float] | None | Unset
        if isinstance(self.orientation, Unset):
            orientation = UNSET
        elif isinstance(self.orientation, list):
            orientation = self.orientation

        else:
            orientation = self.orientation

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "position": position,
            }
        )
        if orientation is not UNSET:
            field_dict["orientation"] = orientation

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        position = cast(list[float], d.pop("position"))

        def _parse_orientation(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                orientation_type_0 = cast(list[float], data)

                return orientation_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        orientation = _parse_orientation(d.pop("orientation", UNSET))

        pose_in = cls(
            position=position,
            orientation=orientation,
        )

        return pose_in
