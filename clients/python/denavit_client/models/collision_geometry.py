from enum import StrEnum


class CollisionGeometry(StrEnum):
    CONVEX = "convex"
    MESH = "mesh"

    def __str__(self) -> str:
        return str(self.value)
