from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="Pose")


@_attrs_define
class Pose:
    """A frame's placement in the robot's root (world) frame.

    Attributes:
        position (list[float]): [x, y, z] in metres.
        orientation (list[float]): Unit quaternion [x, y, z, w], w ≥ 0.
        rpy (list[float]): [roll, pitch, yaw] in rad, R = Rz(yaw)·Ry(pitch)·Rx(roll).
        matrix (list[list[float]]): 4×4 homogeneous transform (metres).
    """

    position: list[float]
    orientation: list[float]
    rpy: list[float]
    matrix: list[list[float]]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        position = self.position

        orientation = self.orientation

        rpy = self.rpy

        matrix = []
        for matrix_item_data in self.matrix:
            matrix_item = matrix_item_data

            matrix.append(matrix_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "position": position,
                "orientation": orientation,
                "rpy": rpy,
                "matrix": matrix,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        position = cast(list[float], d.pop("position"))

        orientation = cast(list[float], d.pop("orientation"))

        rpy = cast(list[float], d.pop("rpy"))

        matrix = []
        _matrix = d.pop("matrix")
        for matrix_item_data in _matrix:
            matrix_item = cast(list[float], matrix_item_data)

            matrix.append(matrix_item)

        pose = cls(
            position=position,
            orientation=orientation,
            rpy=rpy,
            matrix=matrix,
        )

        pose.additional_properties = d
        return pose

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
