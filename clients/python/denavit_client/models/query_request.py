from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.pose import Pose


T = TypeVar("T", bound="QueryRequest")


@_attrs_define
class QueryRequest:
    """Poses to look up in a map: ``poses``, or the compact ``positions``/``orientations``.

    Attributes:
        map_id (str): The map to query.
        poses (list[Pose] | None | Unset): Poses (root frame): each needs a position (`position` or `matrix`); without a
            rotation (`orientation`, `rpy` or `matrix`), any orientation (best over the voxel).
        positions (list[list[float]] | None | Unset): Compact form: N×3 positions (m).
        orientations (list[list[float]] | None | Unset): Compact form: N×4 quaternions [x, y, z, w] (omit: any
            orientation).
    """

    map_id: str
    poses: list[Pose] | None | Unset = UNSET
    positions: list[list[float]] | None | Unset = UNSET
    orientations: list[list[float]] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        map_id = self.map_id

        poses: list[dict[str, Any]] | None | Unset
        if isinstance(self.poses, Unset):
            poses = UNSET
        elif isinstance(self.poses, list):
            poses = []
            for poses_type_0_item_data in self.poses:
                poses_type_0_item = poses_type_0_item_data.to_dict()
                poses.append(poses_type_0_item)

        else:
            poses = self.poses

        positions: list[list[float]] | None | Unset
        if isinstance(self.positions, Unset):
            positions = UNSET
        elif isinstance(self.positions, list):
            positions = []
            for positions_type_0_item_data in self.positions:
                positions_type_0_item = positions_type_0_item_data

                positions.append(positions_type_0_item)

        else:
            positions = self.positions

        orientations: list[list[float]] | None | Unset
        if isinstance(self.orientations, Unset):
            orientations = UNSET
        elif isinstance(self.orientations, list):
            orientations = []
            for orientations_type_0_item_data in self.orientations:
                orientations_type_0_item = orientations_type_0_item_data

                orientations.append(orientations_type_0_item)

        else:
            orientations = self.orientations

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "map_id": map_id,
            }
        )
        if poses is not UNSET:
            field_dict["poses"] = poses
        if positions is not UNSET:
            field_dict["positions"] = positions
        if orientations is not UNSET:
            field_dict["orientations"] = orientations

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.pose import Pose  # noqa: PLC0415

        d = dict(src_dict)
        map_id = d.pop("map_id")

        def _parse_poses(data: object) -> list[Pose] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                poses_type_0 = []
                _poses_type_0 = data
                for poses_type_0_item_data in _poses_type_0:
                    poses_type_0_item = Pose.from_dict(poses_type_0_item_data)

                    poses_type_0.append(poses_type_0_item)

                return poses_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Pose] | None | Unset, data)

        poses = _parse_poses(d.pop("poses", UNSET))

        def _parse_positions(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                positions_type_0 = []
                _positions_type_0 = data
                for positions_type_0_item_data in _positions_type_0:
                    positions_type_0_item = cast(list[float], positions_type_0_item_data)

                    positions_type_0.append(positions_type_0_item)

                return positions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        positions = _parse_positions(d.pop("positions", UNSET))

        def _parse_orientations(data: object) -> list[list[float]] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                orientations_type_0 = []
                _orientations_type_0 = data
                for orientations_type_0_item_data in _orientations_type_0:
                    orientations_type_0_item = cast(list[float], orientations_type_0_item_data)

                    orientations_type_0.append(orientations_type_0_item)

                return orientations_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[list[float]] | None | Unset, data)

        orientations = _parse_orientations(d.pop("orientations", UNSET))

        query_request = cls(
            map_id=map_id,
            poses=poses,
            positions=positions,
            orientations=orientations,
        )

        return query_request
