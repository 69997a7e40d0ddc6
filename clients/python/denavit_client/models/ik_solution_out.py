from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions


T = TypeVar("T", bound="IKSolutionOut")


@_attrs_define
class IKSolutionOut:
    """A verified solution.

    Attributes:
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        joint_positions (JointPositions): Joint name → value: rad for revolute and continuous joints, m for prismatic
            ones, each within ±10000 (a value beyond is a 422 naming `<field>.<joint>`).
        position_error (float): ‖p − p_t‖ (m), by forward kinematics.
        orientation_error (float): Rotation angle to the target (rad).
        branch (str): Its branch: flags such as "shoulder_left/elbow_up/wrist_noflip" (UR-type and spherical-wrist 6R
            arms; planar 2-link arms: "elbow_up"/"elbow_down"), else "cluster_<k>" (joint-space clusters, cluster_0 nearest
            the seed).
        seed_distance (float): Largest single-joint move from the seed (rad or m; continuous joints around the circle).
        manipulability (float): Yoshikawa measure ∏σ_i of the frame Jacobian over the moving joints.
        clearance (float | None): With obstacles: smallest robot–obstacle distance (m), else null.
    """

    q: list[float]
    joint_positions: JointPositions
    position_error: float
    orientation_error: float
    branch: str
    seed_distance: float
    manipulability: float
    clearance: float | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        q = self.q

        joint_positions = self.joint_positions.to_dict()

        position_error = self.position_error

        orientation_error = self.orientation_error

        branch = self.branch

        seed_distance = self.seed_distance

        manipulability = self.manipulability

        clearance: float | None
        clearance = self.clearance

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "q": q,
                "joint_positions": joint_positions,
                "position_error": position_error,
                "orientation_error": orientation_error,
                "branch": branch,
                "seed_distance": seed_distance,
                "manipulability": manipulability,
                "clearance": clearance,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415

        d = dict(src_dict)
        q = cast(list[float], d.pop("q"))

        joint_positions = JointPositions.from_dict(d.pop("joint_positions"))

        position_error = d.pop("position_error")

        orientation_error = d.pop("orientation_error")

        branch = d.pop("branch")

        seed_distance = d.pop("seed_distance")

        manipulability = d.pop("manipulability")

        def _parse_clearance(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        clearance = _parse_clearance(d.pop("clearance"))

        ik_solution_out = cls(
            q=q,
            joint_positions=joint_positions,
            position_error=position_error,
            orientation_error=orientation_error,
            branch=branch,
            seed_distance=seed_distance,
            manipulability=manipulability,
            clearance=clearance,
        )

        ik_solution_out.additional_properties = d
        return ik_solution_out

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
