from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.collision_geometry import CollisionGeometry
from ..models.ik_mode import IKMode
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions
    from ..models.obstacle_in import ObstacleIn
    from ..models.pose import Pose
    from ..models.tolerance import Tolerance


T = TypeVar("T", bound="IKBatchRequest")


@_attrs_define
class IKBatchRequest:
    """Many targets for one frame.

    Attributes:
        targets (list[Pose]): Targets, solved in order. Each as `target` of /ik.
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
        seed (JointPositions | list[float] | None | str | Unset): Start configuration: one value per joint (joint order;
            with `group`, one per joint of the group is accepted too), joint → value (others: middle of their limits), or
            the name of a named state of the SRDF (e.g. "ready"; GET /robots/{id} lists them). Default: the middle of the
            joint limits. Values within ±10000 (rad or m), as every configuration. IK answers always hold every joint.
        chain_seeds (bool | Unset): Seed each target with the previous solution (trajectories); false: every target
            starts from `seed`, the targets are solved independently (spread over the server's batch worker processes), and
            with random_seed target i draws its restarts from its own generator, child i of SeedSequence(random_seed), so
            answers do not depend on how the batch is split. Default: True.
    """

    targets: list[Pose]
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
    seed: JointPositions | list[float] | None | str | Unset = UNSET
    chain_seeds: bool | Unset = True

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        targets = []
        for targets_item_data in self.targets:
            targets_item = targets_item_data.to_dict()
            targets.append(targets_item)

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

        seed: dict[str, Any] | list[float] | None | str | Unset
        if isinstance(self.seed, Unset):
            seed = UNSET
        elif isinstance(self.seed, list):
            seed = self.seed

        elif isinstance(self.seed, JointPositions):
            seed = self.seed.to_dict()
        else:
            seed = self.seed

        chain_seeds = self.chain_seeds

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "targets": targets,
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
        if seed is not UNSET:
            field_dict["seed"] = seed
        if chain_seeds is not UNSET:
            field_dict["chain_seeds"] = chain_seeds

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.obstacle_in import ObstacleIn  # noqa: PLC0415
        from ..models.pose import Pose  # noqa: PLC0415
        from ..models.tolerance import Tolerance  # noqa: PLC0415

        d = dict(src_dict)
        targets = []
        _targets = d.pop("targets")
        for targets_item_data in _targets:
            targets_item = Pose.from_dict(targets_item_data)

            targets.append(targets_item)

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

        def _parse_seed(data: object) -> JointPositions | list[float] | None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                seed_type_0 = cast(list[float], data)

                return seed_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                seed_type_1 = JointPositions.from_dict(data)

                return seed_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointPositions | list[float] | None | str | Unset, data)

        seed = _parse_seed(d.pop("seed", UNSET))

        chain_seeds = d.pop("chain_seeds", UNSET)

        ik_batch_request = cls(
            targets=targets,
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
            seed=seed,
            chain_seeds=chain_seeds,
        )

        return ik_batch_request
