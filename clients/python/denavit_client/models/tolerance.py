from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="Tolerance")


@_attrs_define
class Tolerance:
    """Success thresholds.

    Attributes:
        position (float | Unset): Largest position error ‖p − p_t‖ (m). Default: 1e-05.
        orientation (float | Unset): Largest rotation angle to the target (rad). Default: 1e-05.
    """

    position: float | Unset = 1e-05
    orientation: float | Unset = 1e-05

    def to_dict(self) -> dict[str, Any]:
        position = self.position

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
        position = d.pop("position", UNSET)

        orientation = d.pop("orientation", UNSET)

        tolerance = cls(
            position=position,
            orientation=orientation,
        )

        return tolerance
