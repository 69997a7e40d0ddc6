from enum import StrEnum


class SelfCollisionMode(StrEnum):
    CONVEX = "convex"
    IGNORE = "ignore"
    MESH = "mesh"

    def __str__(self) -> str:
        return str(self.value)
