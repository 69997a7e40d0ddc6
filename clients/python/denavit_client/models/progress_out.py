from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

T = TypeVar("T", bound="ProgressOut")


@_attrs_define
class ProgressOut:
    """How far a build is.

    Attributes:
        percent (float):
        samples_done (int):
        samples_total (int):
        samples_per_second (float | None):
        elapsed_seconds (float):
        eta_seconds (float | None): Seconds left at the current rate.
    """

    percent: float
    samples_done: int
    samples_total: int
    samples_per_second: float | None
    elapsed_seconds: float
    eta_seconds: float | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        percent = self.percent

        samples_done = self.samples_done

        samples_total = self.samples_total

        samples_per_second: float | None
        samples_per_second = self.samples_per_second

        elapsed_seconds = self.elapsed_seconds

        eta_seconds: float | None
        eta_seconds = self.eta_seconds

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "percent": percent,
                "samples_done": samples_done,
                "samples_total": samples_total,
                "samples_per_second": samples_per_second,
                "elapsed_seconds": elapsed_seconds,
                "eta_seconds": eta_seconds,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        percent = d.pop("percent")

        samples_done = d.pop("samples_done")

        samples_total = d.pop("samples_total")

        def _parse_samples_per_second(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        samples_per_second = _parse_samples_per_second(d.pop("samples_per_second"))

        elapsed_seconds = d.pop("elapsed_seconds")

        def _parse_eta_seconds(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        eta_seconds = _parse_eta_seconds(d.pop("eta_seconds"))

        progress_out = cls(
            percent=percent,
            samples_done=samples_done,
            samples_total=samples_total,
            samples_per_second=samples_per_second,
            elapsed_seconds=elapsed_seconds,
            eta_seconds=eta_seconds,
        )

        progress_out.additional_properties = d
        return progress_out

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
