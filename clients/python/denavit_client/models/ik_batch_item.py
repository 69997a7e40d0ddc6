from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ik_reason import IKReason
from ..models.ik_status import IKStatus

T = TypeVar("T", bound="IKBatchItem")


@_attrs_define
class IKBatchItem:
    """Result for one target.

    Attributes:
        success (bool):
        status (IKStatus):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        position_error (float):
        orientation_error (float):
        iterations (int):
        restarts (int):
        solve_time_ms (float):
        reason (IKReason | None): Why no solution was found (null on success): unreachable (the target position is
            beyond the chain's reach bound; the search is skipped) | joint_limits (reached only outside the limits, or the
            best configuration is pinned at a limit) | collision (every solution found collides) | singular (the search
            stalled at a singular configuration) | timeout (the time budget or max_iterations ended the search). See
            docs/ik.md.
        detail (None | str): The reason in a sentence, with numbers.
    """

    success: bool
    status: IKStatus
    q: list[float]
    position_error: float
    orientation_error: float
    iterations: int
    restarts: int
    solve_time_ms: float
    reason: IKReason | None
    detail: None | str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        success = self.success

        status = self.status.value

        q = self.q

        position_error = self.position_error

        orientation_error = self.orientation_error

        iterations = self.iterations

        restarts = self.restarts

        solve_time_ms = self.solve_time_ms

        reason: None | str
        if isinstance(self.reason, IKReason):
            reason = self.reason.value
        else:
            reason = self.reason

        detail: None | str
        detail = self.detail

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "success": success,
                "status": status,
                "q": q,
                "position_error": position_error,
                "orientation_error": orientation_error,
                "iterations": iterations,
                "restarts": restarts,
                "solve_time_ms": solve_time_ms,
                "reason": reason,
                "detail": detail,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        success = d.pop("success")

        status = IKStatus(d.pop("status"))

        q = cast(list[float], d.pop("q"))

        position_error = d.pop("position_error")

        orientation_error = d.pop("orientation_error")

        iterations = d.pop("iterations")

        restarts = d.pop("restarts")

        solve_time_ms = d.pop("solve_time_ms")

        def _parse_reason(data: object) -> IKReason | None:
            if data is None:
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                reason_type_0 = IKReason(data)

                return reason_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(IKReason | None, data)

        reason = _parse_reason(d.pop("reason"))

        def _parse_detail(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        detail = _parse_detail(d.pop("detail"))

        ik_batch_item = cls(
            success=success,
            status=status,
            q=q,
            position_error=position_error,
            orientation_error=orientation_error,
            iterations=iterations,
            restarts=restarts,
            solve_time_ms=solve_time_ms,
            reason=reason,
            detail=detail,
        )

        ik_batch_item.additional_properties = d
        return ik_batch_item

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
