from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="FKBatchResponse")


@_attrs_define
class FKBatchResponse:
    """Compact arrays, row i for configuration i.

    Attributes:
        robot_id (str):
        frame (str):
        positions (list[list[float]]): N×3 positions (m) in the root frame.
        orientations (list[list[float]]): N×4 quaternions [x, y, z, w].
    """

    robot_id: str
    frame: str
    positions: list[list[float]]
    orientations: list[list[float]]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        positions = []
        for positions_item_data in self.positions:
            positions_item = positions_item_data

            positions.append(positions_item)

        orientations = []
        for orientations_item_data in self.orientations:
            orientations_item = orientations_item_data

            orientations.append(orientations_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "positions": positions,
                "orientations": orientations,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        positions = []
        _positions = d.pop("positions")
        for positions_item_data in _positions:
            positions_item = cast(list[float], positions_item_data)

            positions.append(positions_item)

        orientations = []
        _orientations = d.pop("orientations")
        for orientations_item_data in _orientations:
            orientations_item = cast(list[float], orientations_item_data)

            orientations.append(orientations_item)

        fk_batch_response = cls(
            robot_id=robot_id,
            frame=frame,
            positions=positions,
            orientations=orientations,
        )

        fk_batch_response.additional_properties = d
        return fk_batch_response

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
