from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.job_status import JobStatus

if TYPE_CHECKING:
    from ..models.progress_out import ProgressOut


T = TypeVar("T", bound="JobResponse")


@_attrs_define
class JobResponse:
    """A build job.

    Attributes:
        job_id (str):
        robot_id (str):
        frame (str):
        status (JobStatus):
        map_id (None | str): The stored map, once done.
        error (None | str):
        progress (ProgressOut): How far a build is.
    """

    job_id: str
    robot_id: str
    frame: str
    status: JobStatus
    map_id: None | str
    error: None | str
    progress: ProgressOut
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        job_id = self.job_id

        robot_id = self.robot_id

        frame = self.frame

        status = self.status.value

        map_id: None | str
        map_id = self.map_id

        error: None | str
        error = self.error

        progress = self.progress.to_dict()

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "job_id": job_id,
                "robot_id": robot_id,
                "frame": frame,
                "status": status,
                "map_id": map_id,
                "error": error,
                "progress": progress,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.progress_out import ProgressOut  # noqa: PLC0415

        d = dict(src_dict)
        job_id = d.pop("job_id")

        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        status = JobStatus(d.pop("status"))

        def _parse_map_id(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        map_id = _parse_map_id(d.pop("map_id"))

        def _parse_error(data: object) -> None | str:
            if data is None:
                return data
            return cast(None | str, data)

        error = _parse_error(d.pop("error"))

        progress = ProgressOut.from_dict(d.pop("progress"))

        job_response = cls(
            job_id=job_id,
            robot_id=robot_id,
            frame=frame,
            status=status,
            map_id=map_id,
            error=error,
            progress=progress,
        )

        job_response.additional_properties = d
        return job_response

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
