from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define

T = TypeVar("T", bound="Bounds")


@_attrs_define
class Bounds:
    """An axis-aligned box of the root frame (m).

    Attributes:
        min_ (list[float]): [x, y, z] lower corner (m).
        max_ (list[float]): [x, y, z] upper corner (m); larger than min on every axis.
    """

    min_: list[float]
    max_: list[float]

    def to_dict(self) -> dict[str, Any]:
        min_ = self.min_

        max_ = self.max_

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "min": min_,
                "max": max_,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        min_ = cast(list[float], d.pop("min"))

        max_ = cast(list[float], d.pop("max"))

        bounds = cls(
            min_=min_,
            max_=max_,
        )

        return bounds
