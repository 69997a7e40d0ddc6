from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="MaxStep")


@_attrs_define
class MaxStep:
    """Largest Cartesian step between consecutive waypoints of the interpolated path.

    Attributes:
        position (float | Unset): Metres (default 0.01). Default: 0.01.
        orientation (float | Unset): Radians (default 0.05). Default: 0.05.
    """

    position: float | Unset = 0.01
    orientation: float | Unset = 0.05

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

        max_step = cls(
            position=position,
            orientation=orientation,
        )

        return max_step
