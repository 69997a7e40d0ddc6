from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar, cast

from attrs import define as _attrs_define

from ..models.jacobian_part import JacobianPart
from ..models.reachability_sampling import ReachabilitySampling
from ..models.self_collision_mode import SelfCollisionMode
from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.bounds import Bounds


T = TypeVar("T", bound="BuildRequest")


@_attrs_define
class BuildRequest:
    """What to build: grid, orientation bins, manipulability rows, sampling.

    Attributes:
        frame (None | str | Unset): Frame whose poses are mapped; default the robot's end effector.
        voxel_size (float | None | Unset): Edge of a position voxel (m). Default: the box's longest edge / 24 (with the
            default box, the chain's total length / 12: a coarse map of any arm), larger by steps of 5 % when voxels ×
            orientation bins would exceed 16,777,216 cells.
        bounds (Bounds | None | Unset): Box to cover (m, root frame); default a box that contains every reachable
            position (centred on the chain's first joint, half-size the chain's total length).
        orientation_divisions (int | Unset): d: 4·d³ orientation bins (cubed 3-sphere, each ≈ 180°/d of rotation per
            axis); 0 = one bin (position-only map). Default: 4.
        part (JacobianPart | None | Unset): Manipulability rows: full (default) | translation | rotation.
        rows (list[int | str] | None | Unset): Explicit manipulability rows, e.g. ["vx", "vy"].
        samples (int | Unset): Joint-space samples (grid: rounded); the default builds in well under a second on a
            7-joint arm. Default: 200000.
        sampling (ReachabilitySampling | Unset):
        seed (int | Unset): Seed of the random samples. Default: 0.
        self_collision (SelfCollisionMode | Unset):
    """

    frame: None | str | Unset = UNSET
    voxel_size: float | None | Unset = UNSET
    bounds: Bounds | None | Unset = UNSET
    orientation_divisions: int | Unset = 4
    part: JacobianPart | None | Unset = UNSET
    rows: list[int | str] | None | Unset = UNSET
    samples: int | Unset = 200000
    sampling: ReachabilitySampling | Unset = UNSET
    seed: int | Unset = 0
    self_collision: SelfCollisionMode | Unset = UNSET

    def to_dict(self) -> dict[str, Any]:
        from ..models.bounds import Bounds  # noqa: PLC0415

        frame: None | str | Unset
        if isinstance(self.frame, Unset):
            frame = UNSET
        else:
            frame = self.frame

        voxel_size: float | None | Unset
        if isinstance(self.voxel_size, Unset):
            voxel_size = UNSET
        else:
            voxel_size = self.voxel_size

        bounds: dict[str, Any] | None | Unset
        if isinstance(self.bounds, Unset):
            bounds = UNSET
        elif isinstance(self.bounds, Bounds):
            bounds = self.bounds.to_dict()
        else:
            bounds = self.bounds

        orientation_divisions = self.orientation_divisions

        part: None | str | Unset
        if isinstance(self.part, Unset):
            part = UNSET
        elif isinstance(self.part, JacobianPart):
            part = self.part.value
        else:
            part = self.part

        rows: list[int | str] | None | Unset
        if isinstance(self.rows, Unset):
            rows = UNSET
        elif isinstance(self.rows, list):
            rows = []
            for rows_type_0_item_data in self.rows:
                rows_type_0_item: int | str
                rows_type_0_item = rows_type_0_item_data
                rows.append(rows_type_0_item)

        else:
            rows = self.rows

        samples = self.samples

        sampling: str | Unset = UNSET
        if not isinstance(self.sampling, Unset):
            sampling = self.sampling.value

        seed = self.seed

        self_collision: str | Unset = UNSET
        if not isinstance(self.self_collision, Unset):
            self_collision = self.self_collision.value

        field_dict: dict[str, Any] = {}

        field_dict.update({})
        if frame is not UNSET:
            field_dict["frame"] = frame
        if voxel_size is not UNSET:
            field_dict["voxel_size"] = voxel_size
        if bounds is not UNSET:
            field_dict["bounds"] = bounds
        if orientation_divisions is not UNSET:
            field_dict["orientation_divisions"] = orientation_divisions
        if part is not UNSET:
            field_dict["part"] = part
        if rows is not UNSET:
            field_dict["rows"] = rows
        if samples is not UNSET:
            field_dict["samples"] = samples
        if sampling is not UNSET:
            field_dict["sampling"] = sampling
        if seed is not UNSET:
            field_dict["seed"] = seed
        if self_collision is not UNSET:
            field_dict["self_collision"] = self_collision

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.bounds import Bounds  # noqa: PLC0415

        d = dict(src_dict)

        def _parse_frame(data: object) -> None | str | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(None | str | Unset, data)

        frame = _parse_frame(d.pop("frame", UNSET))

        def _parse_voxel_size(data: object) -> float | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            return cast(float | None | Unset, data)

        voxel_size = _parse_voxel_size(d.pop("voxel_size", UNSET))

        def _parse_bounds(data: object) -> Bounds | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, dict):
                    raise TypeError()
                bounds_type_0 = Bounds.from_dict(data)

                return bounds_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(Bounds | None | Unset, data)

        bounds = _parse_bounds(d.pop("bounds", UNSET))

        orientation_divisions = d.pop("orientation_divisions", UNSET)

        def _parse_part(data: object) -> JacobianPart | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, str):
                    raise TypeError()
                part_type_0 = JacobianPart(data)

                return part_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(JacobianPart | None | Unset, data)

        part = _parse_part(d.pop("part", UNSET))

        def _parse_rows(data: object) -> list[int | str] | None | Unset:
            if data is None:
                return data
            if isinstance(data, Unset):
                return data
            try:
                if not isinstance(data, list):
                    raise TypeError()
                rows_type_0 = []
                _rows_type_0 = data
                for rows_type_0_item_data in _rows_type_0:

                    def _parse_rows_type_0_item(data: object) -> int | str:
                        return cast(int | str, data)

                    rows_type_0_item = _parse_rows_type_0_item(rows_type_0_item_data)

                    rows_type_0.append(rows_type_0_item)

                return rows_type_0
            except (TypeError, ValueError, AttributeError, KeyError):
                pass
            return cast(list[int | str] | None | Unset, data)

        rows = _parse_rows(d.pop("rows", UNSET))

        samples = d.pop("samples", UNSET)

        _sampling = d.pop("sampling", UNSET)
        sampling: ReachabilitySampling | Unset
        if isinstance(_sampling, Unset):
            sampling = UNSET
        else:
            sampling = ReachabilitySampling(_sampling)

        seed = d.pop("seed", UNSET)

        _self_collision = d.pop("self_collision", UNSET)
        self_collision: SelfCollisionMode | Unset
        if isinstance(_self_collision, Unset):
            self_collision = UNSET
        else:
            self_collision = SelfCollisionMode(_self_collision)

        build_request = cls(
            frame=frame,
            voxel_size=voxel_size,
            bounds=bounds,
            orientation_divisions=orientation_divisions,
            part=part,
            rows=rows,
            samples=samples,
            sampling=sampling,
            seed=seed,
            self_collision=self_collision,
        )

        return build_request
