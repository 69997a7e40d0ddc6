from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

if TYPE_CHECKING:
    from ..models.payload_out import PayloadOut


T = TypeVar("T", bound="DynamicsResponse")


@_attrs_define
class DynamicsResponse:
    """τ = M(q)·q̈ + C(q, q̇)·q̇ + g(q) + Jᵀ·F and its parts, over `joint_names` (the robot's
    joints, or with `group` the group's).

        Attributes:
            robot_id (str):
            q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
                joints, m for prismatic ones.
            joint_names (list[str]): The joints of every vector and matrix, in order.
            torques (list[float]): τ, the joint torques (N·m; N for prismatic).
            gravity_torques (list[float]): g(q): the torques holding the arm still.
            coriolis_torques (list[float]): C(q, q̇)·q̇: Coriolis and centrifugal.
            inertial_torques (list[float]): M(q)·q̈.
            wrench_torques (list[float]): Jᵀ·F (zeros without a wrench).
            mass_matrix (list[list[float]]): M(q), n×n, symmetric positive definite (kg·m², kg for prismatic joints).
            coriolis_matrix (list[list[float]]): C(q, q̇), n×n (Christoffel symbols: Ṁ − 2C is skew-symmetric).
            center_of_mass (list[float]): Centre of mass of the robot and payload (m, world frame).
            total_mass (float): Mass of the robot and payload (kg).
            effort_limits (list[float | None]): URDF effort limits (N·m, N); null where the URDF gives none.
            effort_ratios (list[float | None]): |τ| / effort limit; null where there is no limit.
            binding_joint (None | str): The joint with the largest effort ratio; null when no joint has a limit.
            payload (None | PayloadOut): The payload included, or null.
    """

    robot_id: str
    q: list[float]
    joint_names: list[str]
    torques: list[float]
    gravity_torques: list[float]
    coriolis_torques: list[float]
    inertial_torques: list[float]
    wrench_torques: list[float]
    mass_matrix: list[list[float]]
    coriolis_matrix: list[list[float]]
    center_of_mass: list[float]
    total_mass: float
    effort_limits: list[float | None]
    effort_ratios: list[float | None]
    binding_joint: None | str
    payload: None | PayloadOut
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.payload_out import PayloadOut  # noqa: PLC0415

        robot_id = self.robot_id

        q = self.q

        joint_names = self.joint_names

        torques = self.torques

        gravity_torques = self.gravity_torques

        coriolis_torques = self.coriolis_torques

        inertial_torques = self.inertial_torques

        wrench_torques = self.wrench_torques

        mass_matrix = []
        for mass_matrix_item_data in self.mass_matrix:
            mass_matrix_item = mass_matrix_item_data

            mass_matrix.append(mass_matrix_item)

        coriolis_matrix = []
        for coriolis_matrix_item_data in self.coriolis_matrix:
            coriolis_matrix_item = coriolis_matrix_item_data

            coriolis_matrix.append(coriolis_matrix_item)

        center_of_mass = self.center_of_mass

        total_mass = self.total_mass

        effort_limits = []
        for effort_limits_item_data in self.effort_limits:
            effort_limits_item: float | None
            effort_limits_item = effort_limits_item_data
            effort_limits.append(effort_limits_item)

        effort_ratios = []
        for effort_ratios_item_data in self.effort_ratios:
            effort_ratios_item: float | None
            effort_ratios_item = effort_ratios_item_data
            effort_ratios.append(effort_ratios_item)

        binding_joint: None | str
        binding_joint = self.binding_joint

        payload: dict[str, Any] | None
        if isinstance(self.payload, PayloadOut):
            payload = self.payload.to_dict()
        else:
            payload = self.payload

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "q": q,
                "joint_names": joint_names,
                "torques": torques,
                "gravity_torques": gravity_torques,
                "coriolis_torques": coriolis_torques,
                "inertial_torques": inertial_torques,
                "wrench_torques": wrench_torques,
                "mass_matrix": mass_matrix,
                "coriolis_matrix": coriolis_matrix,
                "center_of_mass": center_of_mass,
                "total_mass": total_mass,
                "effort_limits": effort_limits,
                "effort_ratios": effort_ratios,
                "binding_joint": binding_joint,
                "payload": payload,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.payload_out import PayloadOut  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        q = cast(list[float], d.pop("q"))

        joint_names = cast(list[str], d.pop("joint_names"))

        torques = cast(list[float], d.pop("torques"))

        gravity_torques = cast(list[float], d.pop("gravity_torques"))

        coriolis_torques = cast(list[float], d.pop("coriolis_torques"))

        inertial_torques = cast(list[float], d.pop("inertial_torques"))

        wrench_torques = cast(list[float], d.pop("wrench_torques"))

        mass_matrix = []
        _mass_matrix = d.pop("mass_matrix")
        for mass_matrix_item_data in _mass_matrix:
            mass_matrix_item = cast(list[float], mass_matrix_item_data)

            mass_matrix.append(mass_matrix_item)

        coriolis_matrix = []
        _coriolis_matrix = d.pop("coriolis_matrix")
        for coriolis_matrix_item_data in _coriolis_matrix:
            coriolis_matrix_item = cast(list[float], coriolis_matrix_item_data)

            coriolis_matrix.append(coriolis_matrix_item)

        center_of_mass = cast(list[float], d.pop("center_of_mass"))

        total_mass = d.pop("total_mass")

        effort_limits = []
        _effort_limits = d.pop("effort_limits")
        for effort_limits_item_data in _effort_limits:

            def _parse_effort_limits_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            effort_limits_item = _parse_effort_limits_item(effort_limits_item_data)

            effort_limits.append(effort_limits_item)

        effort_ratios = []
        _effort_ratios = d.pop("effort_ratios")
        for effort_ratios_item_data in _effort_ratios:

            def _parse_effort_ratios_item(data: object) -> float | None:
                if data is None:
                    return data
                return cast(float | None, data)

            effort_ratios_item = _parse_effort_ratios_item(effort_ratios_item_data)

            effort_ratios.append(effort_ratios_item)

        def _parse_binding_joint(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        binding_joint = _parse_binding_joint(d.pop("binding_joint"))

        def _parse_payload(data: object) -> None | PayloadOut:
            if data is None:
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                payload_type_0 = PayloadOut.from_dict(data)

                return payload_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PayloadOut, data)

        payload = _parse_payload(d.pop("payload"))

        dynamics_response = cls(
            robot_id=robot_id,
            q=q,
            joint_names=joint_names,
            torques=torques,
            gravity_torques=gravity_torques,
            coriolis_torques=coriolis_torques,
            inertial_torques=inertial_torques,
            wrench_torques=wrench_torques,
            mass_matrix=mass_matrix,
            coriolis_matrix=coriolis_matrix,
            center_of_mass=center_of_mass,
            total_mass=total_mass,
            effort_limits=effort_limits,
            effort_ratios=effort_ratios,
            binding_joint=binding_joint,
            payload=payload,
        )

        dynamics_response.additional_properties = d
        return dynamics_response

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
