from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="Ellipsoid")


@_attrs_define
class Ellipsoid:
    """An ellipsoid in task space (the task's rows as coordinates).

    Attributes:
        axes (list[list[float]]): m unit axes (left singular vectors u_i).
        half_lengths (list[float | None]): Half-length along each axis; null = infinite (lost direction).
    """

    axes: list[list[float]]
    half_lengths: list[float | None]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        axes = []
        for axes_item_data in self.axes:
            axes_item = axes_item_data

            axes.append(axes_item)

        half_lengths = []
        for half_lengths_item_data in self.half_lengths:
            half_lengths_item: float | None
            half_lengths_item = half_lengths_item_data
            half_lengths.append(half_lengths_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "axes": axes,
                "half_lengths": half_lengths,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        axes = []
        _axes = d.pop("axes")
        for axes_item_data in _axes:
            axes_item = cast(list[float], axes_item_data)

            axes.append(axes_item)

        half_lengths = []
        _half_lengths = d.pop("half_lengths")
        for half_lengths_item_data in _half_lengths:

            def _parse_half_lengths_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            half_lengths_item = _parse_half_lengths_item(half_lengths_item_data)

            half_lengths.append(half_lengths_item)

        ellipsoid = cls(
            axes=axes,
            half_lengths=half_lengths,
        )

        ellipsoid.additional_properties = d
        return ellipsoid

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
