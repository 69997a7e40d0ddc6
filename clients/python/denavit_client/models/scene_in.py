from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, TypeVar

from attrs import define as _attrs_define

from ..types import UNSET, Unset

if TYPE_CHECKING:
    from ..models.obstacle_in import ObstacleIn


T = TypeVar("T", bound="SceneIn")


@_attrs_define
class SceneIn:
    """A new scene.

    Attributes:
        name (str): Scene name (1-64 of A-Z a-z 0-9 _ -).
        obstacles (list[ObstacleIn]): The obstacles.
        description (str | Unset):  Default: ''.
    """

    name: str
    obstacles: list[ObstacleIn]
    description: str | Unset = ""

    def to_dict(self) -> dict[str, Any]:
        name = self.name

        obstacles = []
        for obstacles_item_data in self.obstacles:
            obstacles_item = obstacles_item_data.to_dict()
            obstacles.append(obstacles_item)

        description = self.description

        field_dict: dict[str, Any] = {}

        field_dict.update(
            {
                "name": name,
                "obstacles": obstacles,
            }
        )
        if description is not UNSET:
            field_dict["description"] = description

        return field_dict

    @classmethod
    def from_dict(cls: type[T], src_dict: Mapping[str, Any]) -> T:
        from ..models.obstacle_in import ObstacleIn  # noqa: PLC0415

        d = dict(src_dict)
        name = d.pop("name")

        obstacles = []
        _obstacles = d.pop("obstacles")
        for obstacles_item_data in _obstacles:
            obstacles_item = ObstacleIn.from_dict(obstacles_item_data)

            obstacles.append(obstacles_item)

        description = d.pop("description", UNSET)

        scene_in = cls(
            name=name,
            obstacles=obstacles,
            description=description,
        )

        return scene_in
