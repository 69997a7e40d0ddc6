from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.jacobian_reference import JacobianReference

if TYPE_CHECKING:
    from ..models.ellipsoid import Ellipsoid


T = TypeVar("T", bound="ManipulabilityResponse")


@_attrs_define
class ManipulabilityResponse:
    """Manipulability measures of the task Jacobian J_t = J[rows][:, joints].

    Attributes:
        robot_id (str):
        frame (str):
        reference (JacobianReference):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        rows (list[str]): The task's Jacobian rows, in order.
        joints (list[str]): The task Jacobian's columns: the joints that move the frame.
        yoshikawa (float): ∏σ_i (= √det(J_t J_tᵀ) when rows ≤ joints).
        singular_values (list[float]): σ_1 ≥ … ≥ σ_p, p = min(rows, joints).
        min_singular_value (float):
        inverse_condition (float): σ_min / σ_max (0 for a zero Jacobian).
        condition_number (float | None): σ_max / σ_min; null when singular.
        det_jjt (float): det(J_t J_tᵀ); exactly 0 when rows > joints.
        rank (int):
        tolerance (float): Absolute threshold used for the rank: σ_i > this.
        relative_tolerance (float):
        singular (bool): rank < min(rows, joints).
        velocity_ellipsoid (Ellipsoid): An ellipsoid in task space (the task's rows as coordinates).
        force_ellipsoid (Ellipsoid): An ellipsoid in task space (the task's rows as coordinates).
        lost_directions (list[list[float]]): Orthonormal basis of the left null space: task directions the frame cannot
            move in (coordinates over `rows`).
        dependent_joints (list[str]): Joints whose columns take part in a linear dependency (null-space support).
        joint_null_space (list[list[float]]): Orthonormal basis of the null space: joint velocities (over `joints`) that
            do not move the task.
    """

    robot_id: str
    frame: str
    reference: JacobianReference
    q: list[float]
    rows: list[str]
    joints: list[str]
    yoshikawa: float
    singular_values: list[float]
    min_singular_value: float
    inverse_condition: float
    condition_number: float | None
    det_jjt: float
    rank: int
    tolerance: float
    relative_tolerance: float
    singular: bool
    velocity_ellipsoid: Ellipsoid
    force_ellipsoid: Ellipsoid
    lost_directions: list[list[float]]
    dependent_joints: list[str]
    joint_null_space: list[list[float]]
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        reference = self.reference.value

        q = self.q

        rows = self.rows

        joints = self.joints

        yoshikawa = self.yoshikawa

        singular_values = self.singular_values

        min_singular_value = self.min_singular_value

        inverse_condition = self.inverse_condition

        condition_number: float | None
        condition_number = self.condition_number

        det_jjt = self.det_jjt

        rank = self.rank

        tolerance = self.tolerance

        relative_tolerance = self.relative_tolerance

        singular = self.singular

        velocity_ellipsoid = self.velocity_ellipsoid.to_dict()

        force_ellipsoid = self.force_ellipsoid.to_dict()

        lost_directions = []
        for lost_directions_item_data in self.lost_directions:
            lost_directions_item = lost_directions_item_data

            lost_directions.append(lost_directions_item)

        dependent_joints = self.dependent_joints

        joint_null_space = []
        for joint_null_space_item_data in self.joint_null_space:
            joint_null_space_item = joint_null_space_item_data

            joint_null_space.append(joint_null_space_item)

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "reference": reference,
                "q": q,
                "rows": rows,
                "joints": joints,
                "yoshikawa": yoshikawa,
                "singular_values": singular_values,
                "min_singular_value": min_singular_value,
                "inverse_condition": inverse_condition,
                "condition_number": condition_number,
                "det_jjt": det_jjt,
                "rank": rank,
                "tolerance": tolerance,
                "relative_tolerance": relative_tolerance,
                "singular": singular,
                "velocity_ellipsoid": velocity_ellipsoid,
                "force_ellipsoid": force_ellipsoid,
                "lost_directions": lost_directions,
                "dependent_joints": dependent_joints,
                "joint_null_space": joint_null_space,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.ellipsoid import Ellipsoid  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        reference = JacobianReference(d.pop("reference"))

        q = cast(list[float], d.pop("q"))

        rows = cast(list[str], d.pop("rows"))

        joints = cast(list[str], d.pop("joints"))

        yoshikawa = d.pop("yoshikawa")

        singular_values = cast(list[float], d.pop("singular_values"))

        min_singular_value = d.pop("min_singular_value")

        inverse_condition = d.pop("inverse_condition")

        def _parse_condition_number(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        condition_number = _parse_condition_number(d.pop("condition_number"))

        det_jjt = d.pop("det_jjt")

        rank = d.pop("rank")

        tolerance = d.pop("tolerance")

        relative_tolerance = d.pop("relative_tolerance")

        singular = d.pop("singular")

        velocity_ellipsoid = Ellipsoid.from_dict(d.pop("velocity_ellipsoid"))

        force_ellipsoid = Ellipsoid.from_dict(d.pop("force_ellipsoid"))

        lost_directions = []
        _lost_directions = d.pop("lost_directions")
        for lost_directions_item_data in _lost_directions:
            lost_directions_item = cast(list[float], lost_directions_item_data)

            lost_directions.append(lost_directions_item)

        dependent_joints = cast(list[str], d.pop("dependent_joints"))

        joint_null_space = []
        _joint_null_space = d.pop("joint_null_space")
        for joint_null_space_item_data in _joint_null_space:
            joint_null_space_item = cast(list[float], joint_null_space_item_data)

            joint_null_space.append(joint_null_space_item)

        manipulability_response = cls(
            robot_id=robot_id,
            frame=frame,
            reference=reference,
            q=q,
            rows=rows,
            joints=joints,
            yoshikawa=yoshikawa,
            singular_values=singular_values,
            min_singular_value=min_singular_value,
            inverse_condition=inverse_condition,
            condition_number=condition_number,
            det_jjt=det_jjt,
            rank=rank,
            tolerance=tolerance,
            relative_tolerance=relative_tolerance,
            singular=singular,
            velocity_ellipsoid=velocity_ellipsoid,
            force_ellipsoid=force_ellipsoid,
            lost_directions=lost_directions,
            dependent_joints=dependent_joints,
            joint_null_space=joint_null_space,
        )

        manipulability_response.additional_properties = d
        return manipulability_response

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
