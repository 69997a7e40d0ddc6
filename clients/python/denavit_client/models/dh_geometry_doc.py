from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="DHGeometryDoc")


@_attrs_define
class DHGeometryDoc:
    """Generated capsule geometry.

    Attributes:
        radius (float | None | Unset): Capsule radius in metres (0: none). Default: 0.02.
    """

    radius: float | None | Unset = 0.02

    def to_dict(self) -> dict[str, Any]:
        radius: float | None | Unset
        if isinstance(self.radius, Unset):
            radius = UNSET
        else:
            radius = self.radius

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if radius is not UNSET:
            field_dict["radius"] = radius

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_radius(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        radius = _parse_radius(d.pop("radius", UNSET))

        dh_geometry_doc = cls(
            radius=radius,
        )

        return dh_geometry_doc
