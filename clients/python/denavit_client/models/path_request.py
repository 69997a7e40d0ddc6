from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.collision_geometry import CollisionGeometry
from ..models.ik_mode import IKMode
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.arc_segment import ArcSegment
    from ..models.joint_positions import JointPositions
    from ..models.line_segment import LineSegment
    from ..models.max_deviation import MaxDeviation
    from ..models.max_step import MaxStep
    from ..models.obstacle_in import ObstacleIn
    from ..models.pose import Pose
    from ..models.timing_in import TimingIn
    from ..models.tolerance import Tolerance


T = TypeVar("T", bound="PathRequest")


@_attrs_define
class PathRequest:
    """A Cartesian path from a start configuration: waypoints or segments (exactly one).

    Attributes:
        start (JointPositions | list[float] | str): Start configuration: one value per joint (joint order; with `group`,
            one per joint of the group is accepted too), joint → value (others: middle of their limits), or a named state of
            the SRDF (e.g. "ready"). The path starts at the frame's pose there; it is the first point of the answer.
        frame (None | str | Unset): Frame to place; default the end effector (with `group`: its tip).
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
        mode (IKMode | Unset):
        weights (list[float] | None | Unset): Non-negative weights of the error [px, py, pz, rx, ry, rz] (world axes); 0
            frees a component (not checked against the tolerance).
        tolerance (Tolerance | Unset): Success thresholds.
        timeout_ms (float | Unset): Time budget (ms) per target; capped by the server's ik_max_timeout_ms. Default: 5.0.
        max_iterations (int | None | Unset): Cap on solver iterations (Jacobian evaluations).
        avoid_collisions (bool | Unset): Return only solutions free of self-collision and of collision with `obstacles`
            / `scene` (other branches and restarts are searched within the budget). Default: False.
        obstacles (list[ObstacleIn] | None | Unset): With avoid_collisions: obstacles (root frame).
        scene (None | str | Unset): With avoid_collisions: a stored scene's name.
        margin (float | Unset): With avoid_collisions: clearance (m) a solution must keep. Default: 0.0.
        collision_geometry (CollisionGeometry | Unset):
        random_seed (int | None | Unset): Seed of the random restarts: the same request gives the same answer, bit for
            bit, on any worker (unless the time budget ends the search: give max_iterations for a budget that does not
            depend on the machine's speed). Default: a fixed table of restarts, also reproducible.
        waypoints (list[Pose] | None | Unset): Poses to pass through, joined by straight lines (instead of segments);
            each a Pose as the `target` of /ik (an FK pose as is; redundant fields must agree).
        segments (list[ArcSegment | LineSegment] | None | Unset): Lines and arcs, each from the previous segment's end
            (instead of waypoints). A target's missing orientation (mode position) or position (mode orientation) keeps the
            previous pose's.
        max_step (MaxStep | Unset): Largest Cartesian step between consecutive waypoints of the interpolated path.
        max_joint_step (float | Unset): Largest move of any one joint between consecutive points (rad or m, default
            0.1): a larger one is a jump (another branch, or a singularity), and the path stops there instead of returning
            it. Default: 0.1.
        max_deviation (MaxDeviation | Unset): Largest deviation from the Cartesian path of the joint-linear motion
            between two
            returned points (the path is densified until it holds).
        branch (None | str | Unset): Branch the whole path must stay on (the `branch` of an IK solution, e.g.
            "shoulder_left/elbow_up/wrist_noflip"); the start must be on it. Without it, the path keeps the start's branch
            anyway.
        timing (None | TimingIn | Unset): Time-parameterize the joint path (time-optimal under joint velocity and
            acceleration limits, at rest at both ends): the answer's `timing` holds the time, velocity and acceleration of
            every point.
    """

    start: JointPositions | list[float] | str
    frame: None | str | Unset = UNSET
    group: None | str | Unset = UNSET
    mode: IKMode | Unset = UNSET
    weights: list[float] | None | Unset = UNSET
    tolerance: Tolerance | Unset = UNSET
    timeout_ms: float | Unset = 5.0
    max_iterations: int | None | Unset = UNSET
    avoid_collisions: bool | Unset = False
    obstacles: list[ObstacleIn] | None | Unset = UNSET
    scene: None | str | Unset = UNSET
    margin: float | Unset = 0.0
    collision_geometry: CollisionGeometry | Unset = UNSET
    random_seed: int | None | Unset = UNSET
    waypoints: list[Pose] | None | Unset = UNSET
    segments: list[ArcSegment | LineSegment] | None | Unset = UNSET
    max_step: MaxStep | Unset = UNSET
    max_joint_step: float | Unset = 0.1
    max_deviation: MaxDeviation | Unset = UNSET
    branch: None | str | Unset = UNSET
    timing: None | TimingIn | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.line_segment import LineSegment  # noqa: PLC0415
        from ..models.timing_in import TimingIn  # noqa: PLC0415

        start: dict[str, Any] | list[float] | str
        if isinstance(self.start, list):
            start = self.start

        elif isinstance(self.start, JointPositions):
            start = self.start.to_dict()
        else:
            start = self.start

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        mode: str | Unset = UNSET
        if not isinstance(self.mode, Unset):
            mode = self.mode.value

        weights: list[float] | None | Unset
        if isinstance(self.weights, Unset):
            weights = UNSET
        elif isinstance(self.weights, list):
            weights = self.weights

        else:
            weights = self.weights

        tolerance: dict[str, Any] | Unset = UNSET
        if not isinstance(self.tolerance, Unset):
            tolerance = self.tolerance.to_dict()

        timeout_ms = self.timeout_ms

        max_iterations: int | None | Unset
        if isinstance(self.max_iterations, Unset):
            max_iterations = UNSET
        else:
            max_iterations = self.max_iterations

        avoid_collisions = self.avoid_collisions

        obstacles: list[dict[str, Any]] | None | Unset
        if isinstance(self.obstacles, Unset):
            obstacles = UNSET
        elif isinstance(self.obstacles, list):
            obstacles = []
            for obstacles_type_0_item_data in self.obstacles:
                obstacles_type_0_item = obstacles_type_0_item_data.to_dict()
                obstacles.append(obstacles_type_0_item)

        else:
            obstacles = self.obstacles

        scene: None | str | Unset
        if isinstance(self.scene, Unset):
            scene = UNSET
        else:
            scene = self.scene

        margin = self.margin

        collision_geometry: str | Unset = UNSET
        if not isinstance(self.collision_geometry, Unset):
            collision_geometry = self.collision_geometry.value

        random_seed: int | None | Unset
        if isinstance(self.random_seed, Unset):
            random_seed = UNSET
        else:
            random_seed = self.random_seed

        waypoints: list[dict[str, Any]] | None | Unset
        if isinstance(self.waypoints, Unset):
            waypoints = UNSET
        elif isinstance(self.waypoints, list):
            waypoints = []
            for waypoints_type_0_item_data in self.waypoints:
                waypoints_type_0_item = waypoints_type_0_item_data.to_dict()
                waypoints.append(waypoints_type_0_item)

        else:
            waypoints = self.waypoints

        segments: list[dict[str, Any]] | None | Unset
        if isinstance(self.segments, Unset):
            segments = UNSET
        elif isinstance(self.segments, list):
            segments = []
            for segments_type_0_item_data in self.segments:
                segments_type_0_item: dict[str, Any]
                if isinstance(segments_type_0_item_data, LineSegment):
                    segments_type_0_item = segments_type_0_item_data.to_dict()
                else:
                    segments_type_0_item = segments_type_0_item_data.to_dict()

                segments.append(segments_type_0_item)

        else:
            segments = self.segments

        max_step: dict[str, Any] | Unset = UNSET
        if not isinstance(self.max_step, Unset):
            max_step = self.max_step.to_dict()

        max_joint_step = self.max_joint_step

        max_deviation: dict[str, Any] | Unset = UNSET
        if not isinstance(self.max_deviation, Unset):
            max_deviation = self.max_deviation.to_dict()

        branch: None | str | Unset
        if isinstance(self.branch, Unset):
            branch = UNSET
        else:
            branch = self.branch

        timing: dict[str, Any] | None | Unset
        if isinstance(self.timing, Unset):
            timing = UNSET
        elif isinstance(self.timing, TimingIn):
            timing = self.timing.to_dict()
        else:
            timing = self.timing

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "start": start,
            }
        )
        if frame is not UNSET:
            field_dict["frame"] = frame
        if group is not UNSET:
            field_dict["group"] = group
        if mode is not UNSET:
            field_dict["mode"] = mode
        if weights is not UNSET:
            field_dict["weights"] = weights
        if tolerance is not UNSET:
            field_dict["tolerance"] = tolerance
        if timeout_ms is not UNSET:
            field_dict["timeout_ms"] = timeout_ms
        if max_iterations is not UNSET:
            field_dict["max_iterations"] = max_iterations
        if avoid_collisions is not UNSET:
            field_dict["avoid_collisions"] = avoid_collisions
        if obstacles is not UNSET:
            field_dict["obstacles"] = obstacles
        if scene is not UNSET:
            field_dict["scene"] = scene
        if margin is not UNSET:
            field_dict["margin"] = margin
        if collision_geometry is not UNSET:
            field_dict["collision_geometry"] = collision_geometry
        if random_seed is not UNSET:
            field_dict["random_seed"] = random_seed
        if waypoints is not UNSET:
            field_dict["waypoints"] = waypoints
        if segments is not UNSET:
            field_dict["segments"] = segments
        if max_step is not UNSET:
            field_dict["max_step"] = max_step
        if max_joint_step is not UNSET:
            field_dict["max_joint_step"] = max_joint_step
        if max_deviation is not UNSET:
            field_dict["max_deviation"] = max_deviation
        if branch is not UNSET:
            field_dict["branch"] = branch
        if timing is not UNSET:
            field_dict["timing"] = timing

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.arc_segment import ArcSegment  # noqa: PLC0415
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.line_segment import LineSegment  # noqa: PLC0415
        from ..models.max_deviation import MaxDeviation  # noqa: PLC0415
        from ..models.max_step import MaxStep  # noqa: PLC0415
        from ..models.obstacle_in import ObstacleIn  # noqa: PLC0415
        from ..models.pose import Pose  # noqa: PLC0415
        from ..models.timing_in import TimingIn  # noqa: PLC0415
        from ..models.tolerance import Tolerance  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_start(data: object) -> JointPositions | list[float] | str:
            try:
                if not isinstance(data, list):
                    raise TypeError()
                start_type_0 = cast(list[float], data)

                return start_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                start_type_1 = JointPositions.from_dict(data)

                return start_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointPositions | list[float] | str, data)

        start = _parse_start(d.pop("start"))

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        _mode = d.pop("mode", UNSET)
        mode: IKMode | Unset
        if isinstance(_mode, Unset):
            mode = UNSET
        else:
            mode = IKMode(_mode)

        def _parse_weights(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                weights_type_0 = cast(list[float], data)

                return weights_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        weights = _parse_weights(d.pop("weights", UNSET))

        _tolerance = d.pop("tolerance", UNSET)
        tolerance: Tolerance | Unset
        if isinstance(_tolerance, Unset):
            tolerance = UNSET
        else:
            tolerance = Tolerance.from_dict(_tolerance)

        timeout_ms = d.pop("timeout_ms", UNSET)

        def _parse_max_iterations(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        max_iterations = _parse_max_iterations(d.pop("max_iterations", UNSET))

        avoid_collisions = d.pop("avoid_collisions", UNSET)

        def _parse_obstacles(data: object) -> list[ObstacleIn] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                obstacles_type_0 = []
                _obstacles_type_0 = data
                for obstacles_type_0_item_data in _obstacles_type_0:
                    obstacles_type_0_item = ObstacleIn.from_dict(obstacles_type_0_item_data)

                    obstacles_type_0.append(obstacles_type_0_item)

                return obstacles_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ObstacleIn] | None | Unset, data)

        obstacles = _parse_obstacles(d.pop("obstacles", UNSET))

        def _parse_scene(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        scene = _parse_scene(d.pop("scene", UNSET))

        margin = d.pop("margin", UNSET)

        _collision_geometry = d.pop("collision_geometry", UNSET)
        collision_geometry: CollisionGeometry | Unset
        if isinstance(_collision_geometry, Unset):
            collision_geometry = UNSET
        else:
            collision_geometry = CollisionGeometry(_collision_geometry)

        def _parse_random_seed(data: object) -> int | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(int | None | Unset, data)

        random_seed = _parse_random_seed(d.pop("random_seed", UNSET))

        def _parse_waypoints(data: object) -> list[Pose] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                waypoints_type_0 = []
                _waypoints_type_0 = data
                for waypoints_type_0_item_data in _waypoints_type_0:
                    waypoints_type_0_item = Pose.from_dict(waypoints_type_0_item_data)

                    waypoints_type_0.append(waypoints_type_0_item)

                return waypoints_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[Pose] | None | Unset, data)

        waypoints = _parse_waypoints(d.pop("waypoints", UNSET))

        def _parse_segments(data: object) -> list[ArcSegment | LineSegment] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                segments_type_0 = []
                _segments_type_0 = data
                for segments_type_0_item_data in _segments_type_0:

                    def _parse_segments_type_0_item(data: object) -> ArcSegment | LineSegment:
                        try:
                            if not isinstance(data, dict):
                                raise TypeError()
                            segments_type_0_item_type_0 = LineSegment.from_dict(data)

                            return segments_type_0_item_type_0
                        except (TypeError, ValueError, AttributeError, KeyError):
                            pass
                        if not isinstance(data, dict):
                            raise TypeError()
                        segments_type_0_item_type_1 = ArcSegment.from_dict(data)

                        return segments_type_0_item_type_1

                    segments_type_0_item = _parse_segments_type_0_item(segments_type_0_item_data)

                    segments_type_0.append(segments_type_0_item)

                return segments_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[ArcSegment | LineSegment] | None | Unset, data)

        segments = _parse_segments(d.pop("segments", UNSET))

        _max_step = d.pop("max_step", UNSET)
        max_step: MaxStep | Unset
        if isinstance(_max_step, Unset):
            max_step = UNSET
        else:
            max_step = MaxStep.from_dict(_max_step)

        max_joint_step = d.pop("max_joint_step", UNSET)

        _max_deviation = d.pop("max_deviation", UNSET)
        max_deviation: MaxDeviation | Unset
        if isinstance(_max_deviation, Unset):
            max_deviation = UNSET
        else:
            max_deviation = MaxDeviation.from_dict(_max_deviation)

        def _parse_branch(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        branch = _parse_branch(d.pop("branch", UNSET))

        def _parse_timing(data: object) -> None | TimingIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                timing_type_0 = TimingIn.from_dict(data)

                return timing_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | TimingIn | Unset, data)

        timing = _parse_timing(d.pop("timing", UNSET))

        path_request = cls(
            start=start,
            frame=frame,
            group=group,
            mode=mode,
            weights=weights,
            tolerance=tolerance,
            timeout_ms=timeout_ms,
            max_iterations=max_iterations,
            avoid_collisions=avoid_collisions,
            obstacles=obstacles,
            scene=scene,
            margin=margin,
            collision_geometry=collision_geometry,
            random_seed=random_seed,
            waypoints=waypoints,
            segments=segments,
            max_step=max_step,
            max_joint_step=max_joint_step,
            max_deviation=max_deviation,
            branch=branch,
            timing=timing,
        )

        return path_request
