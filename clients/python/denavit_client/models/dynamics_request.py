from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.joint_positions import JointPositions
    from ..models.joint_rates import JointRates
    from ..models.payload_in import PayloadIn
    from ..models.wrench_in import WrenchIn


T = TypeVar("T", bound="DynamicsRequest")


@_attrs_define
class DynamicsRequest:
    """A state (q, q̇, q̈), an optional payload and an optional wrench.

    Attributes:
        q (list[float] | None | Unset): One value per actuated joint, in the order of GET /robots/{id} (rad for revolute
            and continuous joints, m for prismatic ones); with `group`, one per joint of the group (in the group's order) is
            accepted too.
        joint_positions (JointPositions | None | Unset): Joint name → value (rad or m); joints not given take their
            neutral value. Mimic joints may be named (a ROS JointState as is): their value must equal multiplier × leader +
            offset within 1e-9 (see mimic_joints of GET /robots/{id}).
        group (None | str | Unset): A planning group of the robot's SRDF (GET /robots/{id} lists them). With a group,
            the configuration may hold the group's joints only (in the group's order; the other joints at neutral, or at the
            seed's values for IK), the default frame is the group's tip, and Jacobians and IK move only the group's joints.
        velocities (JointRates | list[float] | None | Unset): Joint velocities q̇. One value per joint in joint order
            (with `group`: one per joint of the group, in its order, is accepted too; the others take 0), or a joint name →
            value map; zeros when absent. Each value within ±1e+06.
        accelerations (JointRates | list[float] | None | Unset): Joint accelerations q̈. One value per joint in joint
            order (with `group`: one per joint of the group, in its order, is accepted too; the others take 0), or a joint
            name → value map; zeros when absent. Each value within ±1e+06.
        payload (None | PayloadIn | Unset): A load fixed to a frame.
        wrench (None | Unset | WrenchIn): A wrench a frame exerts on its environment (adds Jᵀ·F).
    """

    q: list[float] | None | Unset = UNSET
    joint_positions: JointPositions | None | Unset = UNSET
    group: None | str | Unset = UNSET
    velocities: JointRates | list[float] | None | Unset = UNSET
    accelerations: JointRates | list[float] | None | Unset = UNSET
    payload: None | PayloadIn | Unset = UNSET
    wrench: None | Unset | WrenchIn = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.joint_rates import JointRates  # noqa: PLC0415
        from ..models.payload_in import PayloadIn  # noqa: PLC0415
        from ..models.wrench_in import WrenchIn  # noqa: PLC0415

        q: list[float] | None | Unset
        if isinstance(self.q, Unset):
            q = UNSET
        elif isinstance(self.q, list):
            q = self.q

        else:
            q = self.q

        joint_positions: dict[str, Any] | None | Unset
        if isinstance(self.joint_positions, Unset):
            joint_positions = UNSET
        elif isinstance(self.joint_positions, JointPositions):
            joint_positions = self.joint_positions.to_dict()
        else:
            joint_positions = self.joint_positions

        group: None | str | Unset
        if isinstance(self.group, Unset):
            group = UNSET
        else:
            group = self.group

        velocities: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.velocities, Unset):
            velocities = UNSET
        elif isinstance(self.velocities, list):
            velocities = self.velocities

        elif isinstance(self.velocities, JointRates):
            velocities = self.velocities.to_dict()
        else:
            velocities = self.velocities

        accelerations: dict[str, Any] | list[float] | None | Unset
        if isinstance(self.accelerations, Unset):
            accelerations = UNSET
        elif isinstance(self.accelerations, list):
            accelerations = self.accelerations

        elif isinstance(self.accelerations, JointRates):
            accelerations = self.accelerations.to_dict()
        else:
            accelerations = self.accelerations

        payload: dict[str, Any] | None | Unset
        if isinstance(self.payload, Unset):
            payload = UNSET
        elif isinstance(self.payload, PayloadIn):
            payload = self.payload.to_dict()
        else:
            payload = self.payload

        wrench: dict[str, Any] | None | Unset
        if isinstance(self.wrench, Unset):
            wrench = UNSET
        elif isinstance(self.wrench, WrenchIn):
            wrench = self.wrench.to_dict()
        else:
            wrench = self.wrench

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if q is not UNSET:
            field_dict["q"] = q
        if joint_positions is not UNSET:
            field_dict["joint_positions"] = joint_positions
        if group is not UNSET:
            field_dict["group"] = group
        if velocities is not UNSET:
            field_dict["velocities"] = velocities
        if accelerations is not UNSET:
            field_dict["accelerations"] = accelerations
        if payload is not UNSET:
            field_dict["payload"] = payload
        if wrench is not UNSET:
            field_dict["wrench"] = wrench

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.joint_positions import JointPositions  # noqa: PLC0415
        from ..models.joint_rates import JointRates  # noqa: PLC0415
        from ..models.payload_in import PayloadIn  # noqa: PLC0415
        from ..models.wrench_in import WrenchIn  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_q(data: object) -> list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                q_type_0 = cast(list[float], data)

                return q_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[float] | None | Unset, data)

        q = _parse_q(d.pop("q", UNSET))

        def _parse_joint_positions(data: object) -> JointPositions | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                joint_positions_type_0 = JointPositions.from_dict(data)

                return joint_positions_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointPositions | None | Unset, data)

        joint_positions = _parse_joint_positions(d.pop("joint_positions", UNSET))

        def _parse_group(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        group = _parse_group(d.pop("group", UNSET))

        def _parse_velocities(data: object) -> JointRates | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                velocities_type_0 = cast(list[float], data)

                return velocities_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                velocities_type_1 = JointRates.from_dict(data)

                return velocities_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointRates | list[float] | None | Unset, data)

        velocities = _parse_velocities(d.pop("velocities", UNSET))

        def _parse_accelerations(data: object) -> JointRates | list[float] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                accelerations_type_0 = cast(list[float], data)

                return accelerations_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                accelerations_type_1 = JointRates.from_dict(data)

                return accelerations_type_1
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JointRates | list[float] | None | Unset, data)

        accelerations = _parse_accelerations(d.pop("accelerations", UNSET))

        def _parse_payload(data: object) -> None | PayloadIn | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                payload_type_0 = PayloadIn.from_dict(data)

                return payload_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | PayloadIn | Unset, data)

        payload = _parse_payload(d.pop("payload", UNSET))

        def _parse_wrench(data: object) -> None | Unset | WrenchIn:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                wrench_type_0 = WrenchIn.from_dict(data)

                return wrench_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | Unset | WrenchIn, data)

        wrench = _parse_wrench(d.pop("wrench", UNSET))

        dynamics_request = cls(
            q=q,
            joint_positions=joint_positions,
            group=group,
            velocities=velocities,
            accelerations=accelerations,
            payload=payload,
            wrench=wrench,
        )

        return dynamics_request
