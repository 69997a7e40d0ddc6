from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar

from attrs import define as _attrs_define

from ..models.dh_units_doc_angle import DHUnitsDocAngle
from ..models.dh_units_doc_length import DHUnitsDocLength
from ..types import UNSET, Unset

T = TypeVar("T", bound="DHUnitsDoc")


@_attrs_define
class DHUnitsDoc:
    """Units of the table's numbers (the service converts to SI on import).

    Attributes:
        length (DHUnitsDocLength | Unset): Unit of a, d, xyz, limits. Default: DHUnitsDocLength.M.
        angle (DHUnitsDocAngle | Unset): Unit of alpha, theta, rpy, limits. Default: DHUnitsDocAngle.RAD.
    """

    length: DHUnitsDocLength | Unset = DHUnitsDocLength.M
    angle: DHUnitsDocAngle | Unset = DHUnitsDocAngle.RAD

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
        length: DHUnitsDocLength | Unset
        if isinstance(_length, Unset):
            length = UNSET
        else:
            length = DHUnitsDocLength(_length)

        _angle = d.pop("angle", UNSET)
        angle: DHUnitsDocAngle | Unset
        if isinstance(_angle, Unset):
            angle = UNSET
        else:
            angle = DHUnitsDocAngle(_angle)

        dh_units_doc = cls(
            length=length,
            angle=angle,
        )

        return dh_units_doc
