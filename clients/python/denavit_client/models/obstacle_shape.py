from enum import StrEnum


class ObstacleShape(StrEnum):
    BOX = "box"
    CAPSULE = "capsule"
    CYLINDER = "cylinder"
    SPHERE = "sphere"

    def __str__(self) -> str:
        return str(self.value)
