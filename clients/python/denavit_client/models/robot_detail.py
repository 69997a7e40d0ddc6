from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.end_effector_out import EndEffectorOut
    from ..models.frame_out import FrameOut
    from ..models.group_out import GroupOut
    from ..models.joint_out import JointOut
    from ..models.mimic_joint_out import MimicJointOut
    from ..models.named_state_out import NamedStateOut
    from ..models.robot_files_out import RobotFilesOut


T = TypeVar("T", bound="RobotDetail")


@_attrs_define
class RobotDetail:
    """Everything a client needs to talk about a robot.

    Attributes:
        id (str):
        name (str):
        source (str):
        description (str):
        joints (list[JointOut]): Actuated joints in configuration order.
        mimic_joints (list[MimicJointOut]): Mimic joints (URDF <mimic>): not in configurations, moved by their leader. A
            joint_positions or seed map may name them (a ROS JointState of the whole robot) when the value is multiplier ×
            leader + offset within 1e-9 (the leader's value from the same map, else its default).
        frames (list[FrameOut]): Every named frame (links and fixed frames).
        end_effector (str): Default frame of fk, jacobian and ik (the default tip): the ee_frame given at upload (or the
            catalog's choice), else the parent_link of the SRDF's first end effector, else the tip of the longest serial
            chain that is not a gripper finger (a finger: a link moved by one of at least two sibling branches made only of
            prismatic and mimic joints; among links held by the same joint, a link without geometry such as a TCP or tool0
            first, then the farthest), else the deepest link.
        groups (list[GroupOut]): SRDF planning groups (`group` in requests).
        end_effectors (list[EndEffectorOut]): SRDF end effectors.
        named_states (list[NamedStateOut]): SRDF group states (IK seeds).
        neutral (list[float]): Neutral configuration (0, clipped to limits).
        has_collision_geometry (bool): Whether the URDF has <collision>.
        collision_pairs (list[list[str]]): Self-collision link pairs [a, b] that collision checks test (same-body,
            adjacent and SRDF-disabled pairs removed).
        files (None | RobotFilesOut | Unset): How the URDF's mesh URIs map to GET /robots/{robot_id}/files/{path}
            (catalog and package robots; null for others).
    """

    id: str
    name: str
    source: str
    description: str
    joints: list[JointOut]
    mimic_joints: list[MimicJointOut]
    frames: list[FrameOut]
    end_effector: str
    groups: list[GroupOut]
    end_effectors: list[EndEffectorOut]
    named_states: list[NamedStateOut]
    neutral: list[float]
    has_collision_geometry: bool
    collision_pairs: list[list[str]]
    files: None | RobotFilesOut | Unset = UNSET
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        from ..models.robot_files_out import RobotFilesOut  # noqa: PLC0415

        id = self.id

        name = self.name

        source = self.source

        description = self.description

        joints = []
        for joints_item_data in self.joints:
            joints_item = joints_item_data.to_dict()
            joints.append(joints_item)

        mimic_joints = []
        for mimic_joints_item_data in self.mimic_joints:
            mimic_joints_item = mimic_joints_item_data.to_dict()
            mimic_joints.append(mimic_joints_item)

        frames = []
        for frames_item_data in self.frames:
            frames_item = frames_item_data.to_dict()
            frames.append(frames_item)

        end_effector = self.end_effector

        groups = []
        for groups_item_data in self.groups:
            groups_item = groups_item_data.to_dict()
            groups.append(groups_item)

        end_effectors = []
        for end_effectors_item_data in self.end_effectors:
            end_effectors_item = end_effectors_item_data.to_dict()
            end_effectors.append(end_effectors_item)

        named_states = []
        for named_states_item_data in self.named_states:
            named_states_item = named_states_item_data.to_dict()
            named_states.append(named_states_item)

        neutral = self.neutral

        has_collision_geometry = self.has_collision_geometry

        collision_pairs = []
        for collision_pairs_item_data in self.collision_pairs:
            collision_pairs_item = collision_pairs_item_data

            collision_pairs.append(collision_pairs_item)

        files: dict[str, Any] | None | Unset
        if isinstance(self.files, Unset):
            files = UNSET
        elif isinstance(self.files, RobotFilesOut):
            files = self.files.to_dict()
        else:
            files = self.files

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "id": id,
                "name": name,
                "source": source,
                "description": description,
                "joints": joints,
                "mimic_joints": mimic_joints,
                "frames": frames,
                "end_effector": end_effector,
                "groups": groups,
                "end_effectors": end_effectors,
                "named_states": named_states,
                "neutral": neutral,
                "has_collision_geometry": has_collision_geometry,
                "collision_pairs": collision_pairs,
            }
        )
        if files is not UNSET:
            field_dict["files"] = files

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.end_effector_out import EndEffectorOut  # noqa: PLC0415
        from ..models.frame_out import FrameOut  # noqa: PLC0415
        from ..models.group_out import GroupOut  # noqa: PLC0415
        from ..models.joint_out import JointOut  # noqa: PLC0415
        from ..models.mimic_joint_out import MimicJointOut  # noqa: PLC0415
        from ..models.named_state_out import NamedStateOut  # noqa: PLC0415
        from ..models.robot_files_out import RobotFilesOut  # noqa: PLC0415

        d = dict(src_dict)
        id = d.pop("id")

        name = d.pop("name")

        source = d.pop("source")

        description = d.pop("description")

        joints = []
        _joints = d.pop("joints")
        for joints_item_data in _joints:
            joints_item = JointOut.from_dict(joints_item_data)

            joints.append(joints_item)

        mimic_joints = []
        _mimic_joints = d.pop("mimic_joints")
        for mimic_joints_item_data in _mimic_joints:
            mimic_joints_item = MimicJointOut.from_dict(mimic_joints_item_data)

            mimic_joints.append(mimic_joints_item)

        frames = []
        _frames = d.pop("frames")
        for frames_item_data in _frames:
            frames_item = FrameOut.from_dict(frames_item_data)

            frames.append(frames_item)

        end_effector = d.pop("end_effector")

        groups = []
        _groups = d.pop("groups")
        for groups_item_data in _groups:
            groups_item = GroupOut.from_dict(groups_item_data)

            groups.append(groups_item)

        end_effectors = []
        _end_effectors = d.pop("end_effectors")
        for end_effectors_item_data in _end_effectors:
            end_effectors_item = EndEffectorOut.from_dict(end_effectors_item_data)

            end_effectors.append(end_effectors_item)

        named_states = []
        _named_states = d.pop("named_states")
        for named_states_item_data in _named_states:
            named_states_item = NamedStateOut.from_dict(named_states_item_data)

            named_states.append(named_states_item)

        neutral = cast(list[float], d.pop("neutral"))

        has_collision_geometry = d.pop("has_collision_geometry")

        collision_pairs = []
        _collision_pairs = d.pop("collision_pairs")
        for collision_pairs_item_data in _collision_pairs:
            collision_pairs_item = cast(list[str], collision_pairs_item_data)

            collision_pairs.append(collision_pairs_item)

        def _parse_files(data: object) -> None | RobotFilesOut | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                files_type_0 = RobotFilesOut.from_dict(data)

                return files_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(None | RobotFilesOut | Unset, data)

        files = _parse_files(d.pop("files", UNSET))

        robot_detail = cls(
            id=id,
            name=name,
            source=source,
            description=description,
            joints=joints,
            mimic_joints=mimic_joints,
            frames=frames,
            end_effector=end_effector,
            groups=groups,
            end_effectors=end_effectors,
            named_states=named_states,
            neutral=neutral,
            has_collision_geometry=has_collision_geometry,
            collision_pairs=collision_pairs,
            files=files,
        )

        robot_detail.additional_properties = d
        return robot_detail

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
