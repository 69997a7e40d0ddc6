from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.jacobian_reference import JacobianReference

T = TypeVar("T", bound="StaticsResponse")


@_attrs_define
class StaticsResponse:
    """τ = Jᵀ·F, forward or least-squares inverse.

    Attributes:
        robot_id (str):
        frame (str):
        reference (JacobianReference):
        q (list[float]): One value per actuated joint in joint order (GET /robots/{id}): rad for revolute and continuous
            joints, m for prismatic ones.
        wrench (list[float]): [fx, fy, fz, mx, my, mz] (N, N·m).
        torques (list[float]): Jᵀ·F in joint order (N·m, N).
        joint_names (list[str]):
        residual (list[float]): Given torques − Jᵀ·F (zeros when the wrench was given).
        residual_norm (float):
        rank (int): Rank of the 6×n Jacobian (σ_i > 1e-10·σ_max).
    """

    robot_id: str
    frame: str
    reference: JacobianReference
    q: list[float]
    wrench: list[float]
    torques: list[float]
    joint_names: list[str]
    residual: list[float]
    residual_norm: float
    rank: int
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        reference = self.reference.value

        q = self.q

        wrench = self.wrench

        torques = self.torques

        joint_names = self.joint_names

        residual = self.residual

        residual_norm = self.residual_norm

        rank = self.rank

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "reference": reference,
                "q": q,
                "wrench": wrench,
                "torques": torques,
                "joint_names": joint_names,
                "residual": residual,
                "residual_norm": residual_norm,
                "rank": rank,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        reference = JacobianReference(d.pop("reference"))

        q = cast(list[float], d.pop("q"))

        wrench = cast(list[float], d.pop("wrench"))

        torques = cast(list[float], d.pop("torques"))

        joint_names = cast(list[str], d.pop("joint_names"))

        residual = cast(list[float], d.pop("residual"))

        residual_norm = d.pop("residual_norm")

        rank = d.pop("rank")

        statics_response = cls(
            robot_id=robot_id,
            frame=frame,
            reference=reference,
            q=q,
            wrench=wrench,
            torques=torques,
            joint_names=joint_names,
            residual=residual,
            residual_norm=residual_norm,
            rank=rank,
        )

        statics_response.additional_properties = d
        return statics_response

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
