from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

T = TypeVar("T", bound="DHTransformDoc")


@_attrs_define
class DHTransformDoc:
    """A fixed transform: translation ``xyz`` then rotation ``rpy`` (R = Rz·Ry·Rx).

    Attributes:
        xyz (list[float] | None | Unset):
        rpy (list[float] | None | Unset):
    """

    xyz: list[float] | None | Unset = UNSET
    rpy: list[float] | None | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        xyz: list[float] | None | Unset
        if isinstance(self.xyz, Unset):
            xyz = UNSET
        elif isinstance(self.xyz, list):
            xyz = self.xyz

        else:
            xyz = self.xyz

        rpy: list[float] | None | Unset
        if isinstance(self.rpy, Unset):
            rpy = UNSET
        elif isinstance(self.rpy, list):
            rpy = self.rpy

        else:
            rpy = self.rpy

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if xyz is not UNSET:
            field_dict["xyz"] = xyz
        if rpy is not UNSET:
            field_dict["rpy"] = rpy

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)

        def _parse_xyz(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                xyz_type_0 = cast(list[float], data)

                return xyz_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        xyz = _parse_xyz(d.pop("xyz", UNSET))

        def _parse_rpy(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rpy_type_0 = cast(list[float], data)

                return rpy_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        rpy = _parse_rpy(d.pop("rpy", UNSET))

        dh_transform_doc = cls(
            xyz=xyz,
            rpy=rpy,
        )

        return dh_transform_doc
