from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.ik_mode import IKMode

if TYPE_CHECKING:
    from ..models.ik_batch_item import IKBatchItem


T = TypeVar("T", bound="IKBatchResponse")


@_attrs_define
class IKBatchResponse:
    """Results in target order.

    Attributes:
        robot_id (str):
        frame (str):
        mode (IKMode):
        joint_names (list[str]):
        solved (int): How many targets succeeded.
        results (list[IKBatchItem]):
        total_time_ms (float):
        solver_version (str): The solver's name and version: with random_seed (and max_iterations), the same request
            gives the same answer, bit for bit, on any worker of the same solver_version.
    """

    robot_id: str
    frame: str
    mode: IKMode
    joint_names: list[str]
    solved: int
    results: list[IKBatchItem]
    total_time_ms: float
    solver_version: str
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        robot_id = self.robot_id

        frame = self.frame

        mode = self.mode.value

        joint_names = self.joint_names

        solved = self.solved

        results = []
        for results_item_data in self.results:
            results_item = results_item_data.to_dict()
            results.append(results_item)

        total_time_ms = self.total_time_ms

        solver_version = self.solver_version

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "robot_id": robot_id,
                "frame": frame,
                "mode": mode,
                "joint_names": joint_names,
                "solved": solved,
                "results": results,
                "total_time_ms": total_time_ms,
                "solver_version": solver_version,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.ik_batch_item import IKBatchItem  # noqa: PLC0415

        d = dict(src_dict)
        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        mode = IKMode(d.pop("mode"))

        joint_names = cast(list[str], d.pop("joint_names"))

        solved = d.pop("solved")

        results = []
        _results = d.pop("results")
        for results_item_data in _results:
            results_item = IKBatchItem.from_dict(results_item_data)

            results.append(results_item)

        total_time_ms = d.pop("total_time_ms")

        solver_version = d.pop("solver_version")

        ik_batch_response = cls(
            robot_id=robot_id,
            frame=frame,
            mode=mode,
            joint_names=joint_names,
            solved=solved,
            results=results,
            total_time_ms=total_time_ms,
            solver_version=solver_version,
        )

        ik_batch_response.additional_properties = d
        return ik_batch_response

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
