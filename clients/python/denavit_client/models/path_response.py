from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ik_mode import IKMode

if TYPE_CHECKING:
    from ..models.path_failure_out import PathFailureOut
    from ..models.path_point_out import PathPointOut
    from ..models.timing_out import TimingOut


T = TypeVar("T", bound="PathResponse")


@_attrs_define
class PathResponse:
    """The joint path as far as it goes; `failure` says where and why it stopped.

    Attributes:
        robot_id (str):
        frame (str):
        mode (IKMode):
        joint_names (list[str]):
        fraction (float): Path parameter s reached (1.0: the whole path).
        points (list[PathPointOut]): The start, then every accepted point.
        failure (None | PathFailureOut):
        branch (None | str): The start's branch label (null: no closed form).
        waypoints (int): Points of the interpolated path (before densifying).
        iterations (int): Solver iterations over the whole path.
        solve_time_ms (float):
        solver_version (str):
        timing (None | TimingOut): With the request's `timing`: times, velocities and accelerations of the points (null
            otherwise).
    """

    robot_id: str
    frame: str
    mode: IKMode
    joint_names: list[str]
    fraction: float
    points: list[PathPointOut]
    failure: None | PathFailureOut
    branch: None | str
    waypoints: int
    iterations: int
    solve_time_ms: float
    solver_version: str
    timing: None | TimingOut
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.path_failure_out import PathFailureOut  # noqa: PLC0415
        from ..models.timing_out import TimingOut  # noqa: PLC0415

        robot_id = self.robot_id

        frame = self.frame

        mode = self.mode.value

        joint_names = self.joint_names

        fraction = self.fraction

        points = []
        for points_item_data in self.points:
            points_item = points_item_data.to_dict()
            points.append(points_item)

        failure: dict[str, Any] | None
        if isinstance(self.failure, PathFailureOut):
            failure = self.failure.to_dict()
        else:
            failure = self.failure

        branch: None | str
        branch = self.branch

        waypoints = self.waypoints

        iterations = self.iterations

        solve_time_ms = self.solve_time_ms

        solver_version = self.solver_version

        timing: dict[str, Any] | None
        if isinstance(self.timing, TimingOut):
            timing = self.timing.to_dict()
        else:
            timing = self.timing

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "mode": mode,
                "joint_names": joint_names,
                "fraction": fraction,
                "points": points,
                "failure": failure,
                "branch": branch,
                "waypoints": waypoints,
                "iterations": iterations,
                "solve_time_ms": solve_time_ms,
                "solver_version": solver_version,
                "timing": timing,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.path_failure_out import PathFailureOut  # noqa: PLC0415
        from ..models.path_point_out import PathPointOut  # noqa: PLC0415
        from ..models.timing_out import TimingOut  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        mode = IKMode(d.pop("mode"))

        joint_names = cast(list[str], d.pop("joint_names"))

        fraction = d.pop("fraction")

        points = []
        _points = d.pop("points")
        for points_item_data in _points:
            points_item = PathPointOut.from_dict(points_item_data)

            points.append(points_item)

        def _parse_failure(data: object) -> None | PathFailureOut:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                failure_type_0 = PathFailureOut.from_dict(data)

                return failure_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PathFailureOut, data)

        failure = _parse_failure(d.pop("failure"))

        def _parse_branch(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        branch = _parse_branch(d.pop("branch"))

        waypoints = d.pop("waypoints")

        iterations = d.pop("iterations")

        solve_time_ms = d.pop("solve_time_ms")

        solver_version = d.pop("solver_version")

        def _parse_timing(data: object) -> None | TimingOut:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                timing_type_0 = TimingOut.from_dict(data)

                return timing_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TimingOut, data)

        timing = _parse_timing(d.pop("timing"))

        path_response = cls(
            robot_id=robot_id,
            frame=frame,
            mode=mode,
            joint_names=joint_names,
            fraction=fraction,
            points=points,
            failure=failure,
            branch=branch,
            waypoints=waypoints,
            iterations=iterations,
            solve_time_ms=solve_time_ms,
            solver_version=solver_version,
            timing=timing,
        )

        path_response.additional_properties = d
        return path_response

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
