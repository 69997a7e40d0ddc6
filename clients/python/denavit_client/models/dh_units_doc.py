from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..models.angle_unit import AngleUnit
from ..models.length_unit import LengthUnit
from ..types import UNSET, Unset

T = TypeVar("T", bound="DHUnitsDoc")


@_attrs_define
class DHUnitsDoc:
    """Units of the table's numbers (the service converts to SI on import).

    Attributes:
        length (LengthUnit | Unset):
        angle (AngleUnit | Unset):
    """

    length: LengthUnit | Unset = UNSET
    angle: AngleUnit | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        length: str | Unset = UNSET
        if not isinstance(self.length, Unset):
            length = self.length.value

        angle: str | Unset = UNSET
        if not isinstance(self.angle, Unset):
            angle = self.angle.value

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if length is not UNSET:
            field_dict["length"] = length
        if angle is not UNSET:
            field_dict["angle"] = angle

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        _length = d.pop("length", UNSET)
        length: LengthUnit | Unset
        if isinstance(_length, Unset):
            length = UNSET
        else:
            length = LengthUnit(_length)

        _angle = d.pop("angle", UNSET)
        angle: AngleUnit | Unset
        if isinstance(_angle, Unset):
            angle = UNSET
        else:
            angle = AngleUnit(_angle)

        dh_units_doc = cls(
            length=length,
            angle=angle,
        )

        return dh_units_doc
