from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="Target")


@_attrs_define
class Target:
    """Desired placement of the frame in the root (world) frame.

    Attributes:
        position (list[float] | None | Unset): [x, y, z] in metres.
        orientation (list[float] | None | Unset): Quaternion [x, y, z, w]; normalised if |q| is within 1e-3 of 1.
        matrix (list[list[float]] | None | Unset): 4×4 homogeneous transform (instead of position/orientation).
    """

    position: list[float] | None | Unset = UNSET
    orientation: list[float] | None | Unset = UNSET
    matrix: list[list[float]] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        position: list[float] | None | Unset
        if isinstance(self.position, Unset):
            position = UNSET
        elif isinstance(self.position, list):
            position = self.position

        else:
            position = self.position

        orientation: list[float] | None | Unset
        if isinstance(self.orientation, Unset):
            orientation = UNSET
        elif isinstance(self.orientation, list):
            orientation = self.orientation

        else:
            orientation = self.orientation

        matrix: list[list[float]] | None | Unset
        if isinstance(self.matrix, Unset):
            matrix = UNSET
        elif isinstance(self.matrix, list):
            matrix = []
            for matrix_type_0_item_data in self.matrix:
                matrix_type_0_item = matrix_type_0_item_data

                matrix.append(matrix_type_0_item)

        else:
            matrix = self.matrix

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if position is not UNSET:
            field_dict["position"] = position
        if orientation is not UNSET:
            field_dict["orientation"] = orientation
        if matrix is not UNSET:
            field_dict["matrix"] = matrix

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_position(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                position_type_0 = cast(list[float], data)

                return position_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        position = _parse_position(d.pop("position", UNSET))

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

        def _parse_matrix(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                matrix_type_0 = []
                _matrix_type_0 = data
                for matrix_type_0_item_data in _matrix_type_0:
                    matrix_type_0_item = cast(list[float], matrix_type_0_item_data)

                    matrix_type_0.append(matrix_type_0_item)

                return matrix_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        matrix = _parse_matrix(d.pop("matrix", UNSET))

        target = cls(
            position=position,
            orientation=orientation,
            matrix=matrix,
        )

        return target
