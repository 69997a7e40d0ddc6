from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="Pose")


@_attrs_define
class Pose:
    """A frame's placement in the robot's root (world) frame, the same shape in and out.

    Answers fill all four fields. A request may give any subset that states what its
    endpoint needs (IK mode ``pose``: a position and a rotation; ``position``: a position;
    ``orientation``: a rotation; reachability queries: a position, the rotation optional;
    obstacles: default the identity); given fields must agree within 1e-9 (m, rad) or the
    request is a 422 naming them. An answer's pose can be sent back as is.

        Attributes:
            position (list[float] | Unset): [x, y, z] in metres. A position is given by `position` or `matrix`.
            orientation (list[float] | Unset): Quaternion [x, y, z, w] (answers: unit, w ≥ 0); normalised if |q| is within
                1e-3 of 1; q and −q are the same rotation. A rotation is given by `orientation`, `rpy` or `matrix`.
            rpy (list[float] | Unset): [roll, pitch, yaw] in rad, R = Rz(yaw)·Ry(pitch)·Rx(roll).
            matrix (list[list[float]] | Unset): 4×4 homogeneous transform root ← frame (metres): a rigid transform
                (orthonormal rotation within 1e-6, determinant +1, last row [0, 0, 0, 1]).
    """

    position: list[float] | Unset = UNSET
    orientation: list[float] | Unset = UNSET
    rpy: list[float] | Unset = UNSET
    matrix: list[list[float]] | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        position: list[float] | Unset = UNSET
        if not isinstance(self.position, Unset):
            position = self.position

        orientation: list[float] | Unset = UNSET
        if not isinstance(self.orientation, Unset):
            orientation = self.orientation

        rpy: list[float] | Unset = UNSET
        if not isinstance(self.rpy, Unset):
            rpy = self.rpy

        matrix: list[list[float]] | Unset = UNSET
        if not isinstance(self.matrix, Unset):
            matrix = []
            for matrix_item_data in self.matrix:
                matrix_item = matrix_item_data

                matrix.append(matrix_item)

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if position is not UNSET:
            field_dict["position"] = position
        if orientation is not UNSET:
            field_dict["orientation"] = orientation
        if rpy is not UNSET:
            field_dict["rpy"] = rpy
        if matrix is not UNSET:
            field_dict["matrix"] = matrix

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        position = cast(list[float], d.pop("position", UNSET))

        orientation = cast(list[float], d.pop("orientation", UNSET))

        rpy = cast(list[float], d.pop("rpy", UNSET))

        _matrix = d.pop("matrix", UNSET)
        matrix: list[list[float]] | Unset = UNSET
        if _matrix is not UNSET:
            matrix = []
            for matrix_item_data in _matrix:
                matrix_item = cast(list[float], matrix_item_data)

                matrix.append(matrix_item)

        pose = cls(
            position=position,
            orientation=orientation,
            rpy=rpy,
            matrix=matrix,
        )

        return pose
