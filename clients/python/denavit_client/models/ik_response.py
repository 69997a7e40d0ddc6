from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ik_mode import IKMode
from ..models.ik_reason import IKReason
from ..models.ik_status import IKStatus

if TYPE_CHECKING:
    from ..models.ik_solution_out import IKSolutionOut
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="IKResponse")


@_attrs_define
class IKResponse:
    """Result; no solution is not an error (success false, best configuration found).

    Attributes:
        robot_id (str):
        frame (str):
        mode (IKMode):
        success (bool):
        status (IKStatus):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        joint_positions (JointPositions): Joint name → value: rad for revolute and continuous joints, m for prismatic
            ones, each within ±10000 (a value beyond is a 422 naming `<field>.<joint>`).
        position_error (float): Of q: ‖p − p_t‖ (m).
        orientation_error (float): Of q: rotation angle to the target (rad).
        solutions (list[IKSolutionOut]): Distinct solutions, one per branch, in rank_by order.
        iterations (int):
        restarts (int):
        solve_time_ms (float):
        method (str): analytic | numeric | analytic+numeric
        reason (IKReason | None): Why no solution was found (null on success): unreachable (the target position is
            beyond the chain's reach bound; the search is skipped) | joint_limits (reached only outside the limits, or the
            best configuration is pinned at a limit) | collision (every solution found collides) | singular (the search
            stalled at a singular configuration) | timeout (the time budget or max_iterations ended the search). See
            docs/ik.md.
        detail (None | str): The reason in a sentence, with numbers.
        solver_version (str): The solver's name and version: with random_seed (and max_iterations), the same request
            gives the same answer, bit for bit, on any worker of the same solver_version.
    """

    robot_id: str
    frame: str
    mode: IKMode
    success: bool
    status: IKStatus
    q: list[float]
    joint_positions: JointPositions
    position_error: float
    orientation_error: float
    solutions: list[IKSolutionOut]
    iterations: int
    restarts: int
    solve_time_ms: float
    method: str
    reason: IKReason | None
    detail: None | str
    solver_version: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        mode = self.mode.value

        success = self.success

        status = self.status.value

        q = self.q

        joint_positions = self.joint_positions.to_dict()

        position_error = self.position_error

        orientation_error = self.orientation_error

        solutions = []
        for solutions_item_data in self.solutions:
            solutions_item = solutions_item_data.to_dict()
            solutions.append(solutions_item)

        iterations = self.iterations

        restarts = self.restarts

        solve_time_ms = self.solve_time_ms

        method = self.method

        reason: None | str
        if isinstance(self.reason, IKReason):
            reason = self.reason.value
        else:
            reason = self.reason

        detail: None | str
        detail = self.detail

        solver_version = self.solver_version

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "mode": mode,
                "success": success,
                "status": status,
                "q": q,
                "joint_positions": joint_positions,
                "position_error": position_error,
                "orientation_error": orientation_error,
                "solutions": solutions,
                "iterations": iterations,
                "restarts": restarts,
                "solve_time_ms": solve_time_ms,
                "method": method,
                "reason": reason,
                "detail": detail,
                "solver_version": solver_version,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.ik_solution_out import IKSolutionOut  # noqa: PLC0415
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        mode = IKMode(d.pop("mode"))

        success = d.pop("success")

        status = IKStatus(d.pop("status"))

        q = cast(list[float], d.pop("q"))

        joint_positions = JointPositions.from_dict(d.pop("joint_positions"))

        position_error = d.pop("position_error")

        orientation_error = d.pop("orientation_error")

        solutions = []
        _solutions = d.pop("solutions")
        for solutions_item_data in _solutions:
            solutions_item = IKSolutionOut.from_dict(solutions_item_data)

            solutions.append(solutions_item)

        iterations = d.pop("iterations")

        restarts = d.pop("restarts")

        solve_time_ms = d.pop("solve_time_ms")

        method = d.pop("method")

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

        solver_version = d.pop("solver_version")

        ik_response = cls(
            robot_id=robot_id,
            frame=frame,
            mode=mode,
            success=success,
            status=status,
            q=q,
            joint_positions=joint_positions,
            position_error=position_error,
            orientation_error=orientation_error,
            solutions=solutions,
            iterations=iterations,
            restarts=restarts,
            solve_time_ms=solve_time_ms,
            method=method,
            reason=reason,
            detail=detail,
            solver_version=solver_version,
        )

        ik_response.additional_properties = d
        return ik_response

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
