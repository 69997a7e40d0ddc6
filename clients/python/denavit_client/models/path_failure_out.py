from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.path_failure_reason import PathFailureReason

T = TypeVar("T", bound="PathFailureOut")


@_attrs_define
class PathFailureOut:
    """The first point that could not be reached, and why.

    Attributes:
        index (int): Index of the failed waypoint of the interpolated path.
        s (float): Its path parameter in [0, 1].
        reason (PathFailureReason):
        detail (str): What went wrong, with numbers.
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        position_error (float): Of q (m).
        orientation_error (float): Of q (rad).
    """

    index: int
    s: float
    reason: PathFailureReason
    detail: str
    q: list[float]
    position_error: float
    orientation_error: float
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        index = self.index

        s = self.s

        reason = self.reason.value

        detail = self.detail

        q = self.q

        position_error = self.position_error

        orientation_error = self.orientation_error

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "index": index,
                "s": s,
                "reason": reason,
                "detail": detail,
                "q": q,
                "position_error": position_error,
                "orientation_error": orientation_error,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        index = d.pop("index")

        s = d.pop("s")

        reason = PathFailureReason(d.pop("reason"))

        detail = d.pop("detail")

        q = cast(list[float], d.pop("q"))

        position_error = d.pop("position_error")

        orientation_error = d.pop("orientation_error")

        path_failure_out = cls(
            index=index,
            s=s,
            reason=reason,
            detail=detail,
            q=q,
            position_error=position_error,
            orientation_error=orientation_error,
        )

        path_failure_out.additional_properties = d
        return path_failure_out

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
