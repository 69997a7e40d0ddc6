from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define
from attrs import field as _attrs_field

from ..models.reachability_sampling import ReachabilitySampling
from ..models.self_collision_mode import SelfCollisionMode

if TYPE_CHECKING:
    from ..models.map_bounds import MapBounds


T = TypeVar("T", bound="MapInfo")


@_attrs_define
class MapInfo:
    """A stored map's metadata.

    Attributes:
        map_id (str):
        robot_id (str):
        frame (str):
        created_at (str):
        bounds (MapBounds):
        voxel_size (float):
        shape (list[int]): Voxels along x, y, z.
        orientation_divisions (int):
        orientation_bins (int):
        cells (int):
        rows (list[str]):
        joints (list[str]): The sampled joints (those that move the frame).
        samples (int):
        sampling (ReachabilitySampling):
        seed (int):
        self_collision (SelfCollisionMode):
        samples_per_second (float | None):
        build_seconds (float | None):
        robot_fingerprint (str):
        reachable_cells (int):
        reachable_voxels (int):
        max_manipulability (float | None):
    """

    map_id: str
    robot_id: str
    frame: str
    created_at: str
    bounds: MapBounds
    voxel_size: float
    shape: list[int]
    orientation_divisions: int
    orientation_bins: int
    cells: int
    rows: list[str]
    joints: list[str]
    samples: int
    sampling: ReachabilitySampling
    seed: int
    self_collision: SelfCollisionMode
    samples_per_second: float | None
    build_seconds: float | None
    robot_fingerprint: str
    reachable_cells: int
    reachable_voxels: int
    max_manipulability: float | None
    additional_properties: dict[str, Any] = _attrs_field(init=False, factory=dict)

    def to_dict(self) -> dict[str, Any]:
        map_id = self.map_id

        robot_id = self.robot_id

        frame = self.frame

        created_at = self.created_at

        bounds = self.bounds.to_dict()

        voxel_size = self.voxel_size

        shape = self.shape

        orientation_divisions = self.orientation_divisions

        orientation_bins = self.orientation_bins

        cells = self.cells

        rows = self.rows

        joints = self.joints

        samples = self.samples

        sampling = self.sampling.value

        seed = self.seed

        self_collision = self.self_collision.value

        samples_per_second: float | None
        samples_per_second = self.samples_per_second

        build_seconds: float | None
        build_seconds = self.build_seconds

        robot_fingerprint = self.robot_fingerprint

        reachable_cells = self.reachable_cells

        reachable_voxels = self.reachable_voxels

        max_manipulability: float | None
        max_manipulability = self.max_manipulability

        field_dict: dict[str, Any] = {}
        field_dict.update(self.additional_properties)
        field_dict.update(
            {
                "map_id": map_id,
                "robot_id": robot_id,
                "frame": frame,
                "created_at": created_at,
                "bounds": bounds,
                "voxel_size": voxel_size,
                "shape": shape,
                "orientation_divisions": orientation_divisions,
                "orientation_bins": orientation_bins,
                "cells": cells,
                "rows": rows,
                "joints": joints,
                "samples": samples,
                "sampling": sampling,
                "seed": seed,
                "self_collision": self_collision,
                "samples_per_second": samples_per_second,
                "build_seconds": build_seconds,
                "robot_fingerprint": robot_fingerprint,
                "reachable_cells": reachable_cells,
                "reachable_voxels": reachable_voxels,
                "max_manipulability": max_manipulability,
            }
        )

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.map_bounds import MapBounds  # noqa: PLC0415

        d = dict(src_dict)
        map_id = d.pop("map_id")

        robot_id = d.pop("robot_id")

        frame = d.pop("frame")

        created_at = d.pop("created_at")

        bounds = MapBounds.from_dict(d.pop("bounds"))

        voxel_size = d.pop("voxel_size")

        shape = cast(list[int], d.pop("shape"))

        orientation_divisions = d.pop("orientation_divisions")

        orientation_bins = d.pop("orientation_bins")

        cells = d.pop("cells")

        rows = cast(list[str], d.pop("rows"))

        joints = cast(list[str], d.pop("joints"))

        samples = d.pop("samples")

        sampling = ReachabilitySampling(d.pop("sampling"))

        seed = d.pop("seed")

        self_collision = SelfCollisionMode(d.pop("self_collision"))

        def _parse_samples_per_second(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        samples_per_second = _parse_samples_per_second(d.pop("samples_per_second"))

        def _parse_build_seconds(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        build_seconds = _parse_build_seconds(d.pop("build_seconds"))

        robot_fingerprint = d.pop("robot_fingerprint")

        reachable_cells = d.pop("reachable_cells")

        reachable_voxels = d.pop("reachable_voxels")

        def _parse_max_manipulability(data: object) -> float | None:
            if data is None:
                return data
            return cast(float | None, data)

        max_manipulability = _parse_max_manipulability(d.pop("max_manipulability"))

        map_info = cls(
            map_id=map_id,
            robot_id=robot_id,
            frame=frame,
            created_at=created_at,
            bounds=bounds,
            voxel_size=voxel_size,
            shape=shape,
            orientation_divisions=orientation_divisions,
            orientation_bins=orientation_bins,
            cells=cells,
            rows=rows,
            joints=joints,
            samples=samples,
            sampling=sampling,
            seed=seed,
            self_collision=self_collision,
            samples_per_second=samples_per_second,
            build_seconds=build_seconds,
            robot_fingerprint=robot_fingerprint,
            reachable_cells=reachable_cells,
            reachable_voxels=reachable_voxels,
            max_manipulability=max_manipulability,
        )

        map_info.additional_properties = d
        return map_info

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
