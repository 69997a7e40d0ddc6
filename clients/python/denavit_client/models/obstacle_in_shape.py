from enum import StrEnum


class ObstacleInShape(StrEnum):
    BOX = "box"
    CAPSULE = "capsule"
    CYLINDER = "cylinder"
    SPHERE = "sphere"

    def __str__(self) -> str:
        return str(self.value)
